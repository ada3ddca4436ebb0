// Analysis > Accuracy: what accuracy costs in time, as log-log charts of error against CPU time with the figures in a
// table beside them. The first tab runs the exact-solution study of core/analysis/Accuracy (one series per
// integrator, per problem); the second bakes the current scene under several settings and compares each with a fine
// reference run (core/analysis/SceneAccuracy). Both run on a worker thread.
#pragma once

#include "analysis/Accuracy.h"
#include "analysis/SceneAccuracy.h"

#include <QDialog>

#include <atomic>
#include <functional>
#include <memory>

class QChart;
class QChartView;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QStandardItemModel;
class QTableView;
class QTabWidget;

namespace rl {

class AccuracyPanel : public QDialog {
    Q_OBJECT
public:
    AccuracyPanel(std::function<Scene()> sceneSource, QWidget* parent = nullptr);
    ~AccuracyPanel() override;

    QTabWidget* tabs() const { return m_tabs; }
    QChart* studyChart() const { return m_studyChart; }
    QStandardItemModel* studyTable() const { return m_studyModel; }
    QChart* sceneChart() const { return m_sceneChart; }
    QStandardItemModel* sceneTable() const { return m_sceneModel; }
    QComboBox* problemBox() const { return m_problem; }
    QDoubleSpinBox* durationBox() const { return m_duration; }
    const AccuracyReport* studyReport() const { return m_report.get(); }
    bool isStudyRunning() const { return m_studyRunning; }
    bool isSceneRunning() const { return m_sceneState != nullptr; }

    void runStudy();
    void runSceneComparison();
    void cancelSceneComparison();

signals:
    void studyFinished();
    // ok: the comparison filled the chart and table; false when it failed or was cancelled (the message is shown).
    void sceneComparisonFinished(bool ok);

private:
    struct SceneJob;
    QWidget* createStudyTab();
    QWidget* createSceneTab();
    void showProblem();
    void showSceneResult(const SceneAccuracyResult& result, const SceneAccuracySetting& reference);

    std::function<Scene()> m_sceneSource;
    QTabWidget* m_tabs = nullptr;

    QComboBox* m_problem = nullptr;
    QPushButton* m_runStudy = nullptr;
    QProgressBar* m_studyProgress = nullptr;
    QLabel* m_studyStatus = nullptr;
    QChart* m_studyChart = nullptr;
    QChartView* m_studyView = nullptr;
    QStandardItemModel* m_studyModel = nullptr;
    QTableView* m_studyTableView = nullptr;
    std::shared_ptr<AccuracyReport> m_report;
    bool m_studyRunning = false;

    QDoubleSpinBox* m_duration = nullptr;
    QList<QCheckBox*> m_substepBoxes;
    QList<QCheckBox*> m_integratorBoxes;
    QPushButton* m_runScene = nullptr;
    QPushButton* m_cancelScene = nullptr;
    QProgressBar* m_sceneProgress = nullptr;
    QLabel* m_sceneStatus = nullptr;
    QChart* m_sceneChart = nullptr;
    QChartView* m_sceneView = nullptr;
    QStandardItemModel* m_sceneModel = nullptr;
    QTableView* m_sceneTableView = nullptr;
    std::shared_ptr<SceneJob> m_sceneState;
};

} // namespace rl
