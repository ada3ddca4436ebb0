#include "simulation/BakeDialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace rl {

namespace {
// An hour at 240 Hz; more would hold gigabytes for a large scene.
constexpr int kMaxFrames = 864000;
} // namespace

BakeDialog::BakeDialog(double fps, int lastFrame, QWidget* parent) : QDialog(parent), m_fps(fps) {
    setObjectName("BakeDialog");
    setWindowTitle(tr("Bake"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Records the simulation from the edit pose (frame 0) in the background. The timeline "
                                "plays and scrubs the result."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* form = new QFormLayout;
    m_seconds = new QDoubleSpinBox(this);
    m_seconds->setObjectName("BakeSeconds");
    m_seconds->setDecimals(3);
    m_seconds->setRange(1.0 / fps, kMaxFrames / fps);
    m_seconds->setSuffix(tr(" s"));
    m_lastFrame = new QSpinBox(this);
    m_lastFrame->setObjectName("BakeLastFrame");
    m_lastFrame->setRange(1, kMaxFrames);
    m_lastFrame->setValue(lastFrame);
    m_seconds->setValue(lastFrame / fps);
    form->addRow(tr("&Duration:"), m_seconds);
    auto* range = new QHBoxLayout;
    range->addWidget(new QLabel(tr("0 to"), this));
    range->addWidget(m_lastFrame, 1);
    // A label made by addRow(QString, QLayout*) has no buddy and would show the ampersand.
    auto* framesLabel = new QLabel(tr("&Frames:"), this);
    framesLabel->setBuddy(m_lastFrame);
    form->addRow(framesLabel, range);
    form->addRow(tr("Frame rate:"), new QLabel(tr("%1 Hz (the scene's world settings)").arg(fps), this));
    layout->addLayout(form);

    connect(m_seconds, &QDoubleSpinBox::valueChanged, this, [this](double seconds) {
        if (m_syncing)
            return;
        m_syncing = true;
        m_lastFrame->setValue(std::max(1, static_cast<int>(std::lround(seconds * m_fps))));
        m_syncing = false;
    });
    connect(m_lastFrame, &QSpinBox::valueChanged, this, [this](int frame) {
        if (m_syncing)
            return;
        m_syncing = true;
        m_seconds->setValue(frame / m_fps);
        m_syncing = false;
    });

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Bake"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

int BakeDialog::lastFrame() const {
    return m_lastFrame->value();
}

} // namespace rl
