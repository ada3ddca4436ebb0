#include "simulation/BakeDialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {
// An hour at 240 Hz; more would hold gigabytes for a large scene.
constexpr int kMaxFrames = 864000;
} // namespace

BakeDialog::BakeDialog(double fps, int firstFrame, int lastFrame, QWidget* parent) : QDialog(parent), m_fps(fps) {
    setObjectName("BakeDialog");
    setWindowTitle(tr("Bake"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Records the simulation in the background, starting from the edit pose at the first "
                                "frame; before it the bodies hold the edit pose. The timeline plays and scrubs the "
                                "result."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* form = new QFormLayout;
    m_firstFrame = new QSpinBox(this);
    m_firstFrame->setObjectName("BakeFirstFrame");
    m_firstFrame->setRange(0, kMaxFrames - 1);
    m_firstFrame->setValue(std::clamp(firstFrame, 0, kMaxFrames - 1));
    m_lastFrame = new QSpinBox(this);
    m_lastFrame->setObjectName("BakeLastFrame");
    m_lastFrame->setRange(m_firstFrame->value() + 1, kMaxFrames);
    m_lastFrame->setValue(lastFrame);
    m_seconds = new QDoubleSpinBox(this);
    m_seconds->setObjectName("BakeSeconds");
    m_seconds->setDecimals(3);
    m_seconds->setRange(1.0 / fps, kMaxFrames / fps);
    m_seconds->setSuffix(tr(" s"));
    m_seconds->setValue((m_lastFrame->value() - m_firstFrame->value()) / fps);
    auto* range = new QHBoxLayout;
    range->addWidget(m_firstFrame, 1);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_lastFrame, 1);
    // A label made by addRow(QString, QLayout*) has no buddy and would show the ampersand.
    auto* framesLabel = new QLabel(tr("&Frames:"), this);
    framesLabel->setBuddy(m_firstFrame);
    form->addRow(framesLabel, range);
    form->addRow(tr("&Duration:"), m_seconds);
    form->addRow(tr("Frame rate:"), new QLabel(tr("%1 Hz (the scene's world settings)").arg(fps), this));
    layout->addLayout(form);

    // The duration is simulated time, from the first frame to the last. Moving the first frame keeps the last
    // (as Blender's frame range does) unless the range would become empty.
    connect(m_seconds, &QDoubleSpinBox::valueChanged, this, [this](double seconds) {
        if (m_syncing)
            return;
        m_syncing = true;
        const int wanted = m_firstFrame->value() + std::max(1, static_cast<int>(std::lround(seconds * m_fps)));
        m_lastFrame->setValue(wanted);
        if (m_lastFrame->value() != wanted) // past the longest bake: the duration shows what will be baked
            m_seconds->setValue((m_lastFrame->value() - m_firstFrame->value()) / m_fps);
        m_syncing = false;
    });
    connect(m_lastFrame, &QSpinBox::valueChanged, this, [this](int frame) {
        if (m_syncing)
            return;
        m_syncing = true;
        m_seconds->setValue((frame - m_firstFrame->value()) / m_fps);
        m_syncing = false;
    });
    connect(m_firstFrame, &QSpinBox::valueChanged, this, [this](int frame) {
        if (m_syncing)
            return;
        m_syncing = true;
        m_lastFrame->setMinimum(frame + 1); // moves the last frame up when it was not after the first
        m_seconds->setValue((m_lastFrame->value() - frame) / m_fps);
        m_syncing = false;
    });

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Bake"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

int BakeDialog::firstFrame() const {
    return m_firstFrame->value();
}

int BakeDialog::lastFrame() const {
    return m_lastFrame->value();
}

} // namespace rl
