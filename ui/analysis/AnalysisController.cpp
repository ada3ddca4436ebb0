#include "analysis/AnalysisController.h"

#include "MainWindow.h"
#include "analysis/AccuracyPanel.h"
#include "analysis/Background.h"
#include "analysis/CompareBakesDialog.h"
#include "analysis/ExportDialog.h"
#include "analysis/Preflight.h"
#include "analysis/PreflightDialog.h"
#include "bake/Bake.h"
#include "document/SceneDocument.h"
#include "simulation/SimulationController.h"

#include <QAction>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>

#include <atomic>

namespace rl {

namespace {

const char* const kPreflightSkipKey = "analysis/preflightSkip";

} // namespace

AnalysisController::AnalysisController(MainWindow* window) : QObject(window), m_window(window) {
    QMenu* exportMenu = window->menu(MainWindow::Menu::Export);
    m_exportBake =
        exportMenu->addAction(tr("&Bake (.bake)…"), this, [this] { exportCurrentBake(ExportRequest::Format::Bake); });
    m_exportBake->setObjectName("ExportBakeAction");
    m_exportBake->setStatusTip(tr("Write the current bake as a .bake file the original project can read"));
    m_exportCsv = exportMenu->addAction(tr("&CSV…"), this, [this] { exportCurrentBake(ExportRequest::Format::Csv); });
    m_exportCsv->setObjectName("ExportCsvAction");
    m_exportCsv->setStatusTip(tr("Write all or selected bodies and frames of the current bake as CSV"));

    QMenu* analysis = window->menu(MainWindow::Menu::Analysis);
    QAction* accuracy = analysis->addAction(tr("&Accuracy…"), this, [this] {
        AccuracyPanel* panel = accuracyPanel();
        panel->show();
        panel->raise();
        panel->activateWindow();
    });
    accuracy->setObjectName("AccuracyAction");
    accuracy->setStatusTip(tr("Error against CPU time per integrator and substep count"));
    QAction* compare = analysis->addAction(tr("&Compare Bakes…"), this, [this] {
        CompareBakesDialog* dialog = compareBakesDialog();
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });
    compare->setObjectName("CompareBakesAction");
    compare->setStatusTip(tr("Find the first frame where two bakes diverge"));
    QAction* preflight = analysis->addAction(tr("&Pre-flight Check…"), this, &AnalysisController::showPreflight);
    preflight->setObjectName("PreflightAction");
    preflight->setStatusTip(tr("List what in the scene may simulate badly"));

    connect(window->simulation(), &SimulationController::bakeChanged, this, &AnalysisController::updateActions);
    connect(window->document(), &SceneDocument::sceneReset, this, [this] { m_skipUntitledPreflight = false; });
    updateActions();
}

std::shared_ptr<const Bake> AnalysisController::currentBake() const {
    if (m_bakeSource)
        return m_bakeSource();
    return m_window->simulation() ? m_window->simulation()->currentBake() : nullptr;
}

void AnalysisController::setBakeSource(std::function<std::shared_ptr<const Bake>()> source) {
    m_bakeSource = std::move(source);
    updateActions();
}

void AnalysisController::updateActions() {
    const bool haveBake = currentBake() != nullptr;
    m_exportBake->setEnabled(haveBake);
    m_exportCsv->setEnabled(haveBake);
}

QString AnalysisController::preflightKey() const {
    const QString path = m_window->document()->filePath();
    return path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
}

bool AnalysisController::confirmPreflight() {
    const QString key = preflightKey();
    if (key.isEmpty() ? m_skipUntitledPreflight : QSettings().value(kPreflightSkipKey).toStringList().contains(key))
        return true;
    const Scene& scene = m_window->document()->scene();
    std::vector<PreflightFinding> findings = runPreflight(scene);
    if (findings.empty())
        return true;
    PreflightDialog dialog(scene, std::move(findings), PreflightDialog::Mode::ConfirmBake, m_window);
    connect(&dialog, &PreflightDialog::bodyActivated, this, [this](int body) {
        if (body < m_window->document()->bodyCount())
            m_window->setSelectedBodies({body});
    });
    const bool go = dialog.exec() == QDialog::Accepted;
    if (go && dialog.dontShowAgain()) {
        if (key.isEmpty()) {
            m_skipUntitledPreflight = true;
        } else {
            QSettings settings;
            QStringList skipped = settings.value(kPreflightSkipKey).toStringList();
            skipped.append(key);
            settings.setValue(kPreflightSkipKey, skipped);
        }
    }
    return go;
}

void AnalysisController::showPreflight() {
    const Scene& scene = m_window->document()->scene();
    auto* dialog = new PreflightDialog(scene, runPreflight(scene), PreflightDialog::Mode::Show, m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &PreflightDialog::bodyActivated, this, [this](int body) {
        if (body < m_window->document()->bodyCount())
            m_window->setSelectedBodies({body});
    });
    dialog->show();
}

bool AnalysisController::exportCurrentBake(ExportRequest::Format format) {
    std::shared_ptr<const Bake> bake = currentBake();
    if (!bake || bake->frameCount() == 0) {
        QMessageBox::information(m_window, tr("Export Bake"),
                                 tr("There is nothing to export yet: bake the scene "
                                    "first or open a .bake file."));
        return false;
    }
    const QString docPath = m_window->document()->filePath();
    const QString base = docPath.isEmpty()
                             ? QDir::home().filePath(tr("untitled"))
                             : QFileInfo(docPath).path() + QLatin1Char('/') + QFileInfo(docPath).completeBaseName();
    const QString suggested = base + (format == ExportRequest::Format::Bake ? ".bake" : ".csv");
    ExportDialog dialog(format, bake->frameCount(), bake->bodyCount(), bake->fps(), bake->hasVelocities(),
                        m_window->selectedBodies(), suggested, m_window);
    if (dialog.exec() != QDialog::Accepted)
        return false;
    QString error;
    if (!exportBake(bake, dialog.request(), &error)) {
        if (!error.isEmpty())
            QMessageBox::warning(m_window, tr("Export Bake"), error);
        return false;
    }
    return true;
}

bool AnalysisController::exportBake(std::shared_ptr<const Bake> bake, const ExportRequest& request, QString* error) {
    struct Job {
        std::atomic<size_t> done{0}, total{0};
        std::atomic<bool> cancel{false};
        Status status = Ok{};
    };
    auto job = std::make_shared<Job>();
    QProgressDialog progress(tr("Exporting %1…").arg(QFileInfo(request.path).fileName()), tr("Cancel"), 0, 1000,
                             m_window);
    progress.setObjectName("ExportProgress");
    progress.setWindowTitle(tr("Export Bake"));
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(m_exportProgressDelay); // small exports finish before it would show
    progress.setAutoClose(false);
    progress.setAutoReset(false);
    progress.setValue(0);
    connect(&progress, &QProgressDialog::canceled, this, [job] { job->cancel = true; });
    QTimer poll;
    poll.setInterval(100);
    connect(&poll, &QTimer::timeout, &progress, [&] {
        if (const size_t total = job->total; total > 0)
            progress.setValue(static_cast<int>(1000.0 * static_cast<double>(job->done) / total));
    });
    poll.start();
    QEventLoop loop;
    runInBackground(
        &loop,
        [job, bake, request] {
            job->status = runExport(*bake, request, [job](size_t done, size_t total) {
                job->done = done;
                job->total = total;
                return !job->cancel.load();
            });
        },
        [&loop] { loop.quit(); });
    loop.exec();
    poll.stop();
    progress.reset();
    if (job->status) {
        m_window->statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(request.path)), 6000);
        return true;
    }
    if (error)
        *error = job->cancel ? QString() : QString::fromStdString(job->status.error().toString());
    if (job->cancel)
        m_window->statusBar()->showMessage(
            tr("Export cancelled; %1 was not changed.").arg(QDir::toNativeSeparators(request.path)), 6000);
    return false;
}

AccuracyPanel* AnalysisController::accuracyPanel() {
    if (!m_accuracy)
        m_accuracy = new AccuracyPanel([this] { return m_window->document()->scene(); }, m_window);
    return m_accuracy;
}

CompareBakesDialog* AnalysisController::compareBakesDialog() {
    if (!m_compare) {
        m_compare = new CompareBakesDialog([this] { return currentBake(); }, m_window);
        connect(m_compare, &CompareBakesDialog::bodyActivated, this, [this](int body) {
            if (body >= 0 && body < m_window->document()->bodyCount())
                m_window->setSelectedBodies({body});
        });
    }
    return m_compare;
}

} // namespace rl
