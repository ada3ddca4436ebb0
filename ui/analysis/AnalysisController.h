// Analysis menu: accuracy panel, re-bake diff, pre-flight check; the UI's exporters (File > Export).
#pragma once

#include "analysis/ExportJob.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>

class QAction;

namespace rl {

class AccuracyPanel;
class Bake;
class CompareBakesDialog;
class MainWindow;

class AnalysisController : public QObject {
    Q_OBJECT
public:
    explicit AnalysisController(MainWindow* window);

    // Runs the pre-flight check on the document's scene before a bake. Returns true when the bake should go on
    // (no findings, "don't show again" chosen earlier for this scene, or the user chose to bake anyway).
    bool confirmPreflight();
    // Analysis > Pre-flight check: the findings, any time.
    void showPreflight();

    // The bake that exports and comparisons use: the simulation's current bake unless a source was set (tests).
    std::shared_ptr<const Bake> currentBake() const;
    void setBakeSource(std::function<std::shared_ptr<const Bake>()> source);

    // File > Export: asks what and where (ExportDialog), then exports the current bake. False when there is nothing
    // to export, the user cancelled, or the export failed (the error is shown).
    bool exportCurrentBake(ExportRequest::Format format);
    // Writes on a worker thread with a progress dialog that can cancel; returns when done. On failure or cancel the
    // target is untouched and *error says why.
    bool exportBake(std::shared_ptr<const Bake> bake, const ExportRequest& request, QString* error = nullptr);
    // How long an export runs before its progress dialog shows (ms; 400 by default, so small exports show none).
    void setExportProgressDelay(int ms) { m_exportProgressDelay = ms; }

    // The panels, created on first use.
    AccuracyPanel* accuracyPanel();
    CompareBakesDialog* compareBakesDialog();

private:
    void updateActions();
    QString preflightKey() const;

    MainWindow* m_window;
    std::function<std::shared_ptr<const Bake>()> m_bakeSource;
    QAction* m_exportBake = nullptr;
    QAction* m_exportCsv = nullptr;
    QPointer<AccuracyPanel> m_accuracy;
    QPointer<CompareBakesDialog> m_compare;
    int m_exportProgressDelay = 400;
    bool m_skipUntitledPreflight = false; // "don't show again" for a scene that has no file yet
};

} // namespace rl
