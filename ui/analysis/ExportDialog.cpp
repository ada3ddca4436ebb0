#include "analysis/ExportDialog.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace rl {

ExportDialog::ExportDialog(ExportRequest::Format format, size_t frameCount, size_t bodyCount, double fps,
                           bool hasVelocities, const QList<int>& selection, const QString& suggestedPath,
                           QWidget* parent)
    : QDialog(parent), m_frameCount(frameCount), m_bodyCount(bodyCount), m_fps(fps), m_hasVelocities(hasVelocities),
      m_selection(selection) {
    setObjectName("ExportDialog");
    setWindowTitle(tr("Export Bake"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_format = new QComboBox(this);
    m_format->setObjectName("ExportFormat");
    m_format->addItem(tr("RigidLab bake (.bake)"), static_cast<int>(ExportRequest::Format::Bake));
    m_format->addItem(tr("CSV table (.csv)"), static_cast<int>(ExportRequest::Format::Csv));
    m_format->setCurrentIndex(format == ExportRequest::Format::Bake ? 0 : 1);
    form->addRow(tr("&Format:"), m_format);

    auto* pathRow = new QHBoxLayout;
    m_path = new QLineEdit(suggestedPath, this);
    m_path->setObjectName("ExportPath");
    m_path->setMinimumWidth(360);
    auto* browse = new QPushButton(tr("Browse…"), this);
    browse->setObjectName("ExportBrowse");
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);
    auto* fileLabel = new QLabel(tr("&File:"), this);
    fileLabel->setBuddy(m_path);
    form->addRow(fileLabel, pathRow);
    layout->addLayout(form);

    m_csvGroup = new QGroupBox(tr("CSV rows"), this);
    auto* csv = new QFormLayout(m_csvGroup);
    auto* bodies = new QVBoxLayout;
    m_allBodies = new QRadioButton(tr("All %n bodies", "", static_cast<int>(bodyCount)), m_csvGroup);
    m_allBodies->setObjectName("ExportAllBodies");
    m_selectedBodies = new QRadioButton(tr("Selected bodies (%n)", "", static_cast<int>(selection.size())), m_csvGroup);
    m_selectedBodies->setObjectName("ExportSelectedBodies");
    m_selectedBodies->setEnabled(!selection.isEmpty());
    m_allBodies->setChecked(true);
    // Radio buttons with one parent are exclusive together: bodies and frames are two separate choices.
    auto* bodyChoice = new QButtonGroup(this);
    bodyChoice->addButton(m_allBodies);
    bodyChoice->addButton(m_selectedBodies);
    bodies->addWidget(m_allBodies);
    bodies->addWidget(m_selectedBodies);
    csv->addRow(tr("Bodies:"), bodies);

    auto* frames = new QVBoxLayout;
    const int last = static_cast<int>(frameCount > 0 ? frameCount - 1 : 0);
    m_allFrames = new QRadioButton(tr("All frames (0 to %1)").arg(last), m_csvGroup);
    m_allFrames->setObjectName("ExportAllFrames");
    m_allFrames->setChecked(true);
    auto* rangeRow = new QHBoxLayout;
    m_frameRange = new QRadioButton(tr("Frames"), m_csvGroup);
    m_frameRange->setObjectName("ExportFrameRange");
    m_firstFrame = new QSpinBox(m_csvGroup);
    m_firstFrame->setObjectName("ExportFirstFrame");
    m_lastFrame = new QSpinBox(m_csvGroup);
    m_lastFrame->setObjectName("ExportLastFrame");
    for (QSpinBox* box : {m_firstFrame, m_lastFrame})
        box->setRange(0, last);
    m_lastFrame->setValue(last);
    auto* frameChoice = new QButtonGroup(this);
    frameChoice->addButton(m_allFrames);
    frameChoice->addButton(m_frameRange);
    rangeRow->addWidget(m_frameRange);
    rangeRow->addWidget(m_firstFrame);
    rangeRow->addWidget(new QLabel(tr("to"), m_csvGroup));
    rangeRow->addWidget(m_lastFrame);
    rangeRow->addStretch(1);
    frames->addWidget(m_allFrames);
    frames->addLayout(rangeRow);
    csv->addRow(tr("Frames:"), frames);
    layout->addWidget(m_csvGroup);

    m_summary = new QLabel(this);
    m_summary->setObjectName("ExportSummary");
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton* ok = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    ok->setObjectName("ExportOk");
    ok->setDefault(true);
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_format, &QComboBox::currentIndexChanged, this, [this] {
        // Keep the file name's suffix in step with the format.
        QFileInfo info(m_path->text());
        if (!m_path->text().isEmpty()) {
            const QString suffix = request().format == ExportRequest::Format::Bake ? "bake" : "csv";
            m_path->setText(info.path() + QLatin1Char('/') + info.completeBaseName() + QLatin1Char('.') + suffix);
        }
        updateState();
    });
    for (QRadioButton* r : {m_allBodies, m_selectedBodies, m_allFrames, m_frameRange})
        connect(r, &QRadioButton::toggled, this, &ExportDialog::updateState);
    for (QSpinBox* box : {m_firstFrame, m_lastFrame})
        connect(box, &QSpinBox::valueChanged, this, &ExportDialog::updateState);
    connect(m_path, &QLineEdit::textChanged, this, &ExportDialog::updateState);
    updateState();
}

ExportRequest ExportDialog::request() const {
    ExportRequest r;
    r.format = static_cast<ExportRequest::Format>(m_format->currentData().toInt());
    r.path = m_path->text().trimmed();
    if (r.format == ExportRequest::Format::Csv) {
        if (m_selectedBodies->isChecked())
            for (int body : m_selection)
                if (body >= 0 && static_cast<size_t>(body) < m_bodyCount)
                    r.bodies.push_back(static_cast<size_t>(body));
        if (m_frameRange->isChecked()) {
            r.firstFrame = static_cast<size_t>(m_firstFrame->value());
            r.lastFrame = static_cast<size_t>(m_lastFrame->value());
        }
    }
    return r;
}

void ExportDialog::updateState() {
    const ExportRequest r = request();
    const bool csv = r.format == ExportRequest::Format::Csv;
    m_csvGroup->setEnabled(csv);
    m_firstFrame->setEnabled(m_frameRange->isChecked());
    m_lastFrame->setEnabled(m_frameRange->isChecked());
    if (csv) {
        const size_t bodies = r.bodies.empty() ? m_bodyCount : r.bodies.size();
        const size_t last = std::min(r.lastFrame, m_frameCount > 0 ? m_frameCount - 1 : 0);
        const size_t frames = last >= r.firstFrame ? last - r.firstFrame + 1 : 0;
        const QString rows = tr("%1 rows: %2 frames (%3 s to %4 s) × %5 bodies.")
                                 .arg(static_cast<qulonglong>(frames * bodies))
                                 .arg(static_cast<qulonglong>(frames))
                                 .arg(static_cast<double>(r.firstFrame) / m_fps, 0, 'f', 3)
                                 .arg(static_cast<double>(last) / m_fps, 0, 'f', 3)
                                 .arg(static_cast<qulonglong>(bodies));
        m_summary->setText(rows + QLatin1Char(' ') +
                           (m_hasVelocities ? tr("Centres of mass, rotations and velocities.")
                                            : tr("Centres of mass and rotations; this bake was read from a .bake "
                                                 "file, which holds no velocities, so those fields stay empty.")));
    } else {
        m_summary->setText(tr("Every body and frame (%1 × %2), with the scene as OBJ text, readable by the original "
                              "project's reader.")
                               .arg(static_cast<qulonglong>(m_frameCount))
                               .arg(static_cast<qulonglong>(m_bodyCount)));
    }
}

void ExportDialog::browse() {
    const bool csv = request().format == ExportRequest::Format::Csv;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Bake"), m_path->text(),
                                                      csv ? tr("CSV files (*.csv)") : tr("Bake files (*.bake)"));
    if (!path.isEmpty())
        m_path->setText(path);
}

void ExportDialog::accept() {
    const ExportRequest r = request();
    if (r.path.isEmpty()) {
        QMessageBox::warning(this, windowTitle(), tr("Choose a file to export to."));
        return;
    }
    if (m_frameRange->isChecked() && m_firstFrame->value() > m_lastFrame->value()) {
        QMessageBox::warning(
            this, windowTitle(),
            tr("The first frame (%1) is after the last (%2).").arg(m_firstFrame->value()).arg(m_lastFrame->value()));
        return;
    }
    QDialog::accept();
}

} // namespace rl
