// The toolbars and the status bar as a user sees them: every toolbar button has an icon (no theme is installed on a
// plain Debian desktop, so a themed icon alone left bare text buttons), the toolbar does not change width when the
// undo text does, and the status bar's anchor count follows an anchor toggle.
#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "ui/GuiTestSetup.h"
#include "viewport/Camera.h"
#include "viewport/Viewport.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QTest>
#include <QToolBar>

class TestToolbars : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void everyButtonHasAnIcon_data() {
        QTest::addColumn<QString>("toolbar");
        QTest::newRow("file") << "FileToolBar";
        QTest::newRow("edit") << "EditToolBar";
        QTest::newRow("simulation") << "SimulationToolBar";
        QTest::newRow("tools") << "ToolsToolBar";
    }
    void everyButtonHasAnIcon() {
        QFETCH(QString, toolbar);
        rl::MainWindow window;
        auto* bar = window.findChild<QToolBar*>(toolbar);
        QVERIFY(bar);
        for (QAction* action : bar->actions()) {
            if (action->isSeparator() || !action->isVisible())
                continue;
            QVERIFY2(!action->icon().isNull(), qPrintable(action->text()));
        }
    }

    void editToolbarKeepsItsWidth() {
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        auto* bar = window.findChild<QToolBar*>("EditToolBar");
        QVERIFY(bar);
        const int before = bar->sizeHint().width();
        window.setSelectedBodies({3});
        window.findChild<QAction*>("ToggleAnchorAction")->trigger();
        QVERIFY(window.document()->undoStack()->canUndo());
        QCOMPARE(bar->sizeHint().width(), before);
    }

    // Every dock can be closed and brought back from the Window menu (the outliner, the inspector and the history
    // could not: closed, they were gone until the settings were deleted).
    void windowMenuBringsBackEveryDock() {
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QList<QAction*> listed = window.menu(rl::MainWindow::Menu::Window)->actions();
        const QList<QDockWidget*> docks = window.findChildren<QDockWidget*>();
        QVERIFY(docks.size() >= 6);
        for (QDockWidget* dock : docks) {
            QVERIFY2(listed.contains(dock->toggleViewAction()), qPrintable(dock->objectName()));
            QVERIFY(dock->isVisible() || window.tabifiedDockWidgets(dock).size() > 0);
            dock->close();
            QTRY_VERIFY(!dock->isVisible());
            dock->toggleViewAction()->trigger();
            QTRY_VERIFY2(dock->isVisible(), qPrintable(dock->objectName()));
        }
    }

    // View > Frame Selected and Frame All move the camera like F and Home in the viewport.
    void viewMenuFramesTheCamera() {
        rl::MainWindow window;
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        QTRY_VERIFY_WITH_TIMEOUT(window.viewport()->isRendererReady(), 10000);
        auto* frameSelected = window.findChild<QAction*>("FrameSelectedAction");
        auto* frameAll = window.findChild<QAction*>("FrameAllAction");
        QVERIFY(frameSelected && frameAll);
        QVERIFY(window.menu(rl::MainWindow::Menu::View)->actions().contains(frameSelected));
        window.viewport()->frameAll();
        const float allDistance = window.viewport()->camera().distance();
        window.setSelectedBodies({5});
        frameSelected->trigger();
        QVERIFY2(window.viewport()->camera().distance() < allDistance * 0.9f,
                 qPrintable(QString::number(window.viewport()->camera().distance())));
        frameAll->trigger();
        QCOMPARE(window.viewport()->camera().distance(), allDistance);
    }

    // The status bar's read-outs are filled from the start, with no scene and before any selection.
    void statusReadOutsFilledAtStart() {
        rl::MainWindow window;
        for (const char* name : {"SelectionLabel", "BodyCountLabel"}) {
            auto* label = window.findChild<QLabel*>(name);
            QVERIFY(label);
            QVERIFY2(!label->text().isEmpty(), name);
        }
    }

    void statusCountsAnchorsAfterAToggle() {
        rl::MainWindow window;
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        auto* label = window.findChild<QLabel*>("BodyCountLabel");
        QVERIFY(label);
        const QString before = label->text();
        window.setSelectedBodies({3});
        window.findChild<QAction*>("ToggleAnchorAction")->trigger();
        QVERIFY(window.document()->body(3).anchor);
        QVERIFY2(label->text() != before, qPrintable(label->text()));
        QVERIFY2(label->text().contains(QLatin1String("2")), qPrintable(label->text()));
        window.document()->undoStack()->undo();
        QCOMPARE(label->text(), before);
    }
};

QTEST_MAIN(TestToolbars)
#include "tst_toolbars.moc"
