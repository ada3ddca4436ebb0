// The Analysis menu: the accuracy panel runs the exact-solution study and the scene comparison on worker threads and
// fills the log-log charts and the tables; Compare bakes finds the first diverging frame, sorts, and selects the body
// of a clicked row; the pre-flight dialog lists the expected findings and answers confirmPreflight().
#include "MainWindow.h"
#include "analysis/AccuracyPanel.h"
#include "analysis/AnalysisController.h"
#include "analysis/CompareBakesDialog.h"
#include "analysis/PreflightDialog.h"
#include "bake/Bake.h"
#include "document/SceneDocument.h"
#include "io/BakeFile.h"
#include "io/SceneImport.h"
#include "ui/GuiTestSetup.h"
#include "world/Baker.h"

#include <QAction>
#include <QApplication>
#include <QChart>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>

#include <functional>

using namespace rl;

namespace {

void onModal(const QString& name, std::function<void(QWidget*)> act) {
    auto* timer = new QTimer;
    timer->setInterval(30);
    QObject::connect(timer, &QTimer::timeout, [timer, name, act] {
        QWidget* modal = QApplication::activeModalWidget();
        if (modal && modal->objectName() == name) {
            timer->stop();
            timer->deleteLater();
            act(modal);
        }
    });
    timer->start();
}

BodyDef box(const std::string& name, Vec3 halfExtents, Vec3 position, bool anchor = false) {
    BodyDef b;
    b.name = name;
    b.anchor = anchor;
    b.shape.halfExtents = halfExtents;
    b.position = position;
    return b;
}

// A floor and a spinning box thrown onto it: small enough for the scene comparison to take a few seconds.
Scene throwScene() {
    Scene scene;
    scene.bodies.push_back(box("Floor", {10, 0.5, 10}, {0, -0.5, 0}, true));
    BodyDef cube = box("Cube", {0.3, 0.2, 0.1}, {0, 1.5, 0});
    cube.velocity = {2, 1, 0};
    cube.angularVelocity = {1, 4, 0.5};
    scene.bodies.push_back(cube);
    scene.bodies.push_back(box("Crate", {0.4, 0.4, 0.4}, {3, 0.4, 0}));
    return scene;
}

// Findings: a 1 cm grain (tiny, and it falls 1 m: tunnelling), and a 1 kg cube under a 1,000 kg one.
Scene riskyScene() {
    Scene scene;
    scene.bodies.push_back(box("Floor", {10, 0.5, 10}, {0, -0.5, 0}, true));
    scene.bodies.push_back(box("Grain", {0.005, 0.005, 0.005}, {4, 1, 0}));
    BodyDef light = box("Light", {0.5, 0.5, 0.5}, {0, 0.5, 0});
    light.mass = 1.0;
    BodyDef heavy = box("Heavy", {0.5, 0.5, 0.5}, {0, 1.5, 0});
    heavy.mass = 1000.0;
    scene.bodies.push_back(light);
    scene.bodies.push_back(heavy);
    BodyDef bracket; // an L of two 0.5 m cubes: concave
    bracket.name = "Bracket";
    bracket.position = {-4, 1, 0};
    bracket.shape.type = ShapeType::Mesh;
    bracket.shape.points = {{0, 0, 0},   {1, 0, 0},   {1, 0.5, 0},   {0.5, 0.5, 0},   {0.5, 1, 0},   {0, 1, 0},
                            {0, 0, 0.5}, {1, 0, 0.5}, {1, 0.5, 0.5}, {0.5, 0.5, 0.5}, {0.5, 1, 0.5}, {0, 1, 0.5}};
    bracket.shape.triangles = {{0, 2, 1},   {0, 3, 2},  {0, 5, 3},  {3, 5, 4},   {6, 7, 8}, {6, 8, 9}, {6, 9, 11},
                               {9, 10, 11}, {0, 1, 7},  {0, 7, 6},  {1, 2, 8},   {1, 8, 7}, {2, 3, 9}, {2, 9, 8},
                               {3, 4, 10},  {3, 10, 9}, {4, 5, 11}, {4, 11, 10}, {5, 0, 6}, {5, 6, 11}};
    scene.bodies.push_back(bracket);
    return scene;
}

Bake bakeOf(const Scene& scene, size_t frames, int substeps = 8) {
    WorldOptions options;
    options.substeps = substeps;
    Result<World> world = World::create(scene, options);
    Bake bake = startBake(*world);
    // The OBJ part carries the names into .bake files.
    Result<std::string> obj = sceneToObjText(scene);
    if (obj)
        bake.setSceneObjText(*obj);
    BakeRequest request;
    request.frames = frames;
    bakeRun(*world, bake, request);
    return bake;
}

// Saves a screenshot when RL_SCREENSHOT_DIR is set (for looking at the panels, not for asserting).
void screenshot(QWidget* widget, const char* name) {
    const QString dir = qEnvironmentVariable("RL_SCREENSHOT_DIR");
    if (!dir.isEmpty())
        widget->grab().save(dir + QLatin1Char('/') + QLatin1String(name) + ".png");
}

} // namespace

class TestAnalysis : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void initTestCase() { QSettings().remove("analysis/preflightSkip"); }

    void accuracyStudy() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.findChild<QAction*>("AccuracyAction")->trigger();
        AccuracyPanel* panel = window.analysis()->accuracyPanel();
        QVERIFY(panel->isVisible());
        QSignalSpy finished(panel, &AccuracyPanel::studyFinished);
        panel->findChild<QPushButton*>("AccuracyRunStudy")->click();
        QVERIFY(panel->isStudyRunning());
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 180000);
        QVERIFY(panel->studyReport());
        QVERIFY(panel->problemBox()->count() >= 2);

        // Every problem: one series per integrator with as many points as its table rows of non-zero error, log
        // axes, and table rows that are that problem's rows of the report.
        for (int p = 0; p < panel->problemBox()->count(); ++p) {
            panel->problemBox()->setCurrentIndex(p);
            const std::string problem = panel->problemBox()->currentText().toStdString();
            QMap<QString, int> drawable;
            int rows = 0;
            for (const AccuracyRow& row : panel->studyReport()->rows)
                if (row.problem == problem) {
                    ++rows;
                    if (row.error > 0.0 && std::isfinite(row.error))
                        drawable[QString::fromUtf8(integratorName(row.integrator).data())] += 1;
                }
            QCOMPARE(panel->studyTable()->rowCount(), rows);
            const QList<QAbstractSeries*> series = panel->studyChart()->series();
            QCOMPARE(series.size(), drawable.size());
            for (QAbstractSeries* s : series) {
                auto* line = qobject_cast<QLineSeries*>(s);
                QVERIFY(line);
                QCOMPARE(line->count(), drawable.value(line->name()));
                for (const QPointF& point : line->points())
                    QVERIFY(point.x() > 0.0 && point.y() > 0.0);
            }
            QCOMPARE(panel->studyChart()->axes(Qt::Horizontal).size(), 1);
            QVERIFY(qobject_cast<QLogValueAxis*>(panel->studyChart()->axes(Qt::Horizontal).first()));
            QVERIFY(qobject_cast<QLogValueAxis*>(panel->studyChart()->axes(Qt::Vertical).first()));
        }
        // The oscillator: every integrator has an error, so there are four series.
        panel->problemBox()->setCurrentText("oscillator");
        QCOMPARE(panel->studyChart()->series().size(), 4);
        QCOMPARE(panel->studyTable()->item(0, 0)->text().isEmpty(), false);
        panel->resize(1180, 640);
        QTest::qWait(200);
        screenshot(panel, "accuracy_study");
    }

    void accuracySceneComparison() {
        MainWindow window;
        window.document()->reset(throwScene(), QString());
        AccuracyPanel* panel = window.analysis()->accuracyPanel();
        panel->show();
        panel->tabs()->setCurrentIndex(1);
        panel->durationBox()->setValue(0.5);
        QSignalSpy finished(panel, &AccuracyPanel::sceneComparisonFinished);
        panel->findChild<QPushButton*>("AccuracyRunScene")->click();
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 120000);
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QCOMPARE(panel->sceneTable()->rowCount(), 20); // 4 integrators x 5 substep counts
        const QList<QAbstractSeries*> series = panel->sceneChart()->series();
        QCOMPARE(series.size(), 4);
        for (QAbstractSeries* s : series)
            QCOMPARE(qobject_cast<QLineSeries*>(s)->count(), 5);
        // Symplectic Euler's rows, in substep order: the RMS error falls from 1 to 16 substeps.
        QList<double> errors;
        for (int r = 0; r < panel->sceneTable()->rowCount(); ++r)
            if (panel->sceneTable()->item(r, 0)->text() == "symplectic-euler")
                errors.append(panel->sceneTable()->item(r, 2)->data(Qt::UserRole).toDouble());
        QCOMPARE(errors.size(), 5);
        QVERIFY(errors.last() < errors.first());
        QVERIFY(panel->findChild<QLabel*>("AccuracySceneStatus")->text().contains("2 dynamic bodies"));
        QTest::qWait(200);
        screenshot(panel, "accuracy_scene");

        // Fewer settings: only rk4 at 1 and 2 substeps.
        for (const char* name :
             {"AccuracySubsteps4", "AccuracySubsteps8", "AccuracySubsteps16", "AccuracyIntegrator_explicit-euler",
              "AccuracyIntegrator_symplectic-euler", "AccuracyIntegrator_verlet"})
            panel->findChild<QCheckBox*>(name)->setChecked(false);
        panel->runSceneComparison();
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 2, 120000);
        QCOMPARE(panel->sceneTable()->rowCount(), 2);
        QCOMPARE(panel->sceneChart()->series().size(), 1);

        // Cancel right away: reported as cancelled, and the previous table stays.
        panel->durationBox()->setValue(10.0);
        panel->runSceneComparison();
        QVERIFY(panel->isSceneRunning());
        panel->findChild<QPushButton*>("AccuracyCancelScene")->click();
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 3, 120000);
        QCOMPARE(finished.at(2).at(0).toBool(), false);
        QCOMPARE(panel->findChild<QLabel*>("AccuracySceneStatus")->text(), QString("Cancelled."));
        QCOMPARE(panel->sceneTable()->rowCount(), 2);
    }

    void compareBakes() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const Scene scene = throwScene();
        window.document()->reset(scene, QString());
        auto current = std::make_shared<const Bake>(bakeOf(scene, 60));
        window.analysis()->setBakeSource([current] { return current; });

        QTemporaryDir dir;
        const QString same = dir.filePath("same.bake"), perturbed = dir.filePath("perturbed.bake"),
                      coarse = dir.filePath("coarse.bake");
        QVERIFY(writeBakeFile(*current, same.toStdString()));
        // The crate (body 2) is pushed 5 cm along z from frame 25 on.
        Bake moved = *current;
        for (size_t f = 25; f < moved.frameCount(); ++f) {
            BakeBodyState s = moved.state(f, 2);
            s.position.z += 0.05f;
            moved.setState(f, 2, s);
        }
        QVERIFY(writeBakeFile(moved, perturbed.toStdString()));
        QVERIFY(writeBakeFile(bakeOf(scene, 60, 1), coarse.toStdString()));

        window.findChild<QAction*>("CompareBakesAction")->trigger();
        CompareBakesDialog* dialog = window.analysis()->compareBakesDialog();
        QVERIFY(dialog->isVisible());

        // Current bake against the same run in a file: equal.
        dialog->setUseCurrentBake(true);
        dialog->setFileB(same);
        QVERIFY(dialog->compare());
        QVERIFY2(dialog->summary().contains("Equal within the tolerance"), qPrintable(dialog->summary()));
        QCOMPARE(dialog->model()->rowCount(), 3);

        // Two files: the crate diverges at frame 25 by 50 mm.
        dialog->setFileA(same);
        dialog->setFileB(perturbed);
        QVERIFY(dialog->compare());
        QVERIFY2(dialog->summary().contains("diverge at frame 25"), qPrintable(dialog->summary()));
        QVERIFY(dialog->summary().contains("Crate"));
        QTableView* table = dialog->table();
        // Sorted by the largest position delta, descending: the crate comes first.
        table->sortByColumn(BakeDiffModel::PositionColumn, Qt::DescendingOrder);
        const QModelIndex top = table->model()->index(0, BakeDiffModel::NameColumn);
        QCOMPARE(top.data().toString(), QString("Crate"));
        QVERIFY(std::abs(table->model()->index(0, BakeDiffModel::PositionColumn).data().toString().toDouble() - 50.0) <
                0.01);
        QCOMPARE(table->model()->index(0, BakeDiffModel::FirstFrameColumn).data().toString(), QString("25"));
        // Sorting by name puts Crate, Cube, Floor in order.
        table->sortByColumn(BakeDiffModel::NameColumn, Qt::AscendingOrder);
        QCOMPARE(table->model()->index(2, BakeDiffModel::NameColumn).data().toString(), QString("Floor"));
        // Clicking a row selects its body in the editor.
        table->sortByColumn(BakeDiffModel::NameColumn, Qt::AscendingOrder);
        const QRect rect = table->visualRect(table->model()->index(1, BakeDiffModel::NameColumn));
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, rect.center());
        QCOMPARE(window.selectedBodies(), QList<int>{1}); // Cube

        // Current bake against a re-bake at 1 substep: diverges, the tolerance spin box decides.
        dialog->setUseCurrentBake(true);
        dialog->setFileB(coarse);
        QVERIFY(dialog->compare());
        QVERIFY(dialog->summary().contains("diverge at frame"));
        dialog->findChild<QDoubleSpinBox*>("ComparePositionTolerance")->setValue(1000.0);
        dialog->findChild<QDoubleSpinBox*>("CompareRotationTolerance")->setValue(180.0);
        QVERIFY(dialog->compare());
        QVERIFY(dialog->summary().contains("Equal within the tolerance"));
        dialog->findChild<QDoubleSpinBox*>("ComparePositionTolerance")->setValue(0.01);
        dialog->findChild<QDoubleSpinBox*>("CompareRotationTolerance")->setValue(0.001);
        dialog->setFileA(same);
        dialog->setFileB(perturbed);
        QVERIFY(dialog->compare());
        table->sortByColumn(BakeDiffModel::PositionColumn, Qt::DescendingOrder);
        table->selectRow(0);
        QTest::qWait(200);
        screenshot(dialog, "compare_bakes");

        // A missing file: a message naming it, an empty table.
        dialog->setFileB(dir.filePath("missing.bake"));
        QVERIFY(!dialog->compare());
        QVERIFY(dialog->summary().contains("missing.bake"));
        QCOMPARE(dialog->model()->rowCount(), 0);
    }

    void preflightFindings() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.document()->reset(riskyScene(), QString());
        QStringList seen;
        onModal("PreflightDialog", [&seen](QWidget* dialog) {
            auto* list = dialog->findChild<QTreeWidget*>("PreflightList");
            for (int i = 0; i < list->topLevelItemCount(); ++i)
                seen << list->topLevelItem(i)->text(0) + "|" + list->topLevelItem(i)->text(1);
            // The first finding's fix shows below the list; choosing another shows its fix.
            auto* fix = dialog->findChild<QLabel*>("PreflightFix");
            if (!fix->text().contains("scale it up by 100"))
                seen << "wrong fix: " + fix->text();
            list->setCurrentItem(list->topLevelItem(2));
            if (!fix->text().contains("Light") || !fix->text().contains("100:1"))
                seen << "wrong fix: " + fix->text();
            list->setCurrentItem(list->topLevelItem(3));
            if (!fix->text().contains("Bracket") || !fix->text().contains("convex parts"))
                seen << "wrong fix: " + fix->text();
            screenshot(dialog, "preflight");
            dialog->findChild<QPushButton*>("PreflightCancel")->click();
        });
        QVERIFY(!window.analysis()->confirmPreflight());
        QCOMPARE(seen, (QStringList{"Very small body|Grain", "May pass through|Grain", "Extreme mass ratio|Light",
                                    "Concave body|Bracket"}));

        // Bake anyway.
        onModal("PreflightDialog",
                [](QWidget* dialog) { dialog->findChild<QPushButton*>("PreflightBakeAnyway")->click(); });
        QVERIFY(window.analysis()->confirmPreflight());

        // Bake anyway and don't ask again: the next call does not show the dialog.
        onModal("PreflightDialog", [](QWidget* dialog) {
            dialog->findChild<QCheckBox*>("PreflightDontShow")->setChecked(true);
            dialog->findChild<QPushButton*>("PreflightBakeAnyway")->click();
        });
        QVERIFY(window.analysis()->confirmPreflight());
        int shown = 0;
        QTimer guard;
        connect(&guard, &QTimer::timeout, [&shown] {
            if (auto* d = qobject_cast<QDialog*>(QApplication::activeModalWidget())) {
                ++shown;
                d->reject();
            }
        });
        guard.start(30);
        QVERIFY(window.analysis()->confirmPreflight());
        // A new scene is asked about again.
        window.document()->reset(riskyScene(), QString());
        QVERIFY(!window.analysis()->confirmPreflight()); // the guard rejects the dialog
        QCOMPARE(shown, 1);
        guard.stop();

        // A clean scene: no dialog at all.
        window.document()->reset(throwScene(), QString());
        guard.start(30);
        QVERIFY(window.analysis()->confirmPreflight());
        QCOMPARE(shown, 1);
        guard.stop();
    }

    void preflightDontShowIsPerFile() {
        QTemporaryDir dir;
        MainWindow window;
        window.document()->reset(riskyScene(), dir.filePath("a.rlscene"));
        onModal("PreflightDialog", [](QWidget* dialog) {
            dialog->findChild<QCheckBox*>("PreflightDontShow")->setChecked(true);
            dialog->findChild<QPushButton*>("PreflightBakeAnyway")->click();
        });
        QVERIFY(window.analysis()->confirmPreflight());
        QVERIFY(QSettings().value("analysis/preflightSkip").toStringList().contains(dir.filePath("a.rlscene")));
        QVERIFY(window.analysis()->confirmPreflight()); // would block on the dialog otherwise
        // "Cancel" with the box ticked does not remember anything.
        window.document()->reset(riskyScene(), dir.filePath("b.rlscene"));
        onModal("PreflightDialog", [](QWidget* dialog) {
            dialog->findChild<QCheckBox*>("PreflightDontShow")->setChecked(true);
            dialog->findChild<QPushButton*>("PreflightCancel")->click();
        });
        QVERIFY(!window.analysis()->confirmPreflight());
        QVERIFY(!QSettings().value("analysis/preflightSkip").toStringList().contains(dir.filePath("b.rlscene")));
        QSettings().remove("analysis/preflightSkip");
    }

    void preflightMenuShowsFindings() {
        MainWindow window;
        window.show();
        window.document()->reset(riskyScene(), QString());
        window.findChild<QAction*>("PreflightAction")->trigger();
        auto* dialog = window.findChild<PreflightDialog*>("PreflightDialog");
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->isVisible());
        QCOMPARE(dialog->findings().size(), size_t(4));
        QVERIFY(!dialog->findChild<QCheckBox*>("PreflightDontShow"));
        // Clicking a finding selects its body.
        auto* list = dialog->findChild<QTreeWidget*>("PreflightList");
        const QRect rect = list->visualItemRect(list->topLevelItem(2));
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, rect.center());
        QCOMPARE(window.selectedBodies(), QList<int>{2});
        dialog->close();
    }
};

QTEST_MAIN(TestAnalysis)
#include "tst_analysis.moc"
