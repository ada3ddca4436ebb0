// The editor as a new user meets it: no settings yet, started from the command line under an X server with no window
// manager (as in a scripted review), keys pressed before anything was clicked.
#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "ui/GuiTestSetup.h"
#include "viewport/Viewport.h"

#include <QApplication>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QScreen>
#include <QSettings>
#include <QTest>
#include <QTimer>

class TestFirstLaunch : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void init() { QSettings().clear(); }
    void cleanup() { QSettings().clear(); }

    // The window takes the keyboard when it appears and the viewport holds the focus, so that Space, A or the arrows
    // act at once, without a click first. A single-key action (A: select all) only fires when the viewport has the
    // focus, so this checks both.
    void keysWorkBeforeAnyClick() {
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        QTRY_VERIFY_WITH_TIMEOUT(window.isActiveWindow(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(QApplication::focusWidget(), static_cast<QWidget*>(window.viewport()), 10000);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_A);
        QCOMPARE(window.selectedBodies().size(), window.document()->bodyCount());
    }

    // After a modal dialog (a message box, the bake dialog, a file dialog) closes, the window has the keyboard
    // again: with no window manager nobody else gives it back, and every key after Save As or an error box was lost.
    void keysWorkAfterADialogCloses() {
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        QTRY_VERIFY_WITH_TIMEOUT(window.isActiveWindow(), 10000);
        for (int round = 0; round < 2; ++round) {
            QDialog dialog(&window);
            dialog.resize(300, 200);
            bool wasActive = false;
            QTimer::singleShot(0, &dialog, [&] {
                // Close only once the dialog has the keyboard, as when a user answers it.
                auto* poll = new QTimer(&dialog);
                connect(poll, &QTimer::timeout, &dialog, [&] {
                    if (!dialog.isActiveWindow())
                        return;
                    wasActive = true;
                    dialog.accept();
                });
                poll->start(50);
            });
            QTimer::singleShot(10000, &dialog, &QDialog::reject); // never hang
            dialog.exec();
            QVERIFY(wasActive);
            QTRY_VERIFY_WITH_TIMEOUT(window.isActiveWindow(), 10000);
            QTRY_COMPARE_WITH_TIMEOUT(QApplication::focusWidget(), static_cast<QWidget*>(window.viewport()), 10000);
        }
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_A);
        QCOMPARE(window.selectedBodies().size(), window.document()->bodyCount());
    }

    // A path relative to the working directory (as in the README's command) is kept absolute: the title, Save, the
    // export dialogs and the recent files must name the same file when RigidLab next starts elsewhere.
    void relativePathIsKeptAbsolute_data() {
        QTest::addColumn<QString>("relative");
        QTest::newRow("obj") << "resources/scenes/stack.obj";
        QTest::newRow("dot slash") << "./resources/scenes/mixed.obj";
    }
    void relativePathIsKeptAbsolute() {
        QFETCH(QString, relative);
        const QString previous = QDir::currentPath();
        QVERIFY(QDir::setCurrent(QStringLiteral(RL_SOURCE_DIR)));
        rl::MainWindow window;
        const bool opened = window.openFile(relative);
        QDir::setCurrent(previous);
        QVERIFY(opened);
        const QString path = window.document()->filePath();
        QVERIFY2(QFileInfo(path).isAbsolute(), qPrintable(path));
        QCOMPARE(path, QFileInfo(QStringLiteral(RL_SOURCE_DIR "/") + relative).absoluteFilePath());
    }

    // As in Blender, the keys follow the mouse: after picking a body in the outliner, W with the mouse over the
    // viewport switches to the move tool. Text fields keep the keyboard (typing a value must not turn into tools).
    void viewportTakesKeysUnderTheMouse_data() {
        QTest::addColumn<QString>("focused");
        QTest::addColumn<bool>("viewportGetsFocus");
        QTest::newRow("outliner") << "OutlinerView" << true;
        QTest::newRow("filter box") << "OutlinerFilter" << false;
    }
    void viewportTakesKeysUnderTheMouse() {
        QFETCH(QString, focused);
        QFETCH(bool, viewportGetsFocus);
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        QTRY_VERIFY_WITH_TIMEOUT(window.isActiveWindow(), 10000);
        window.setSelectedBodies({4});
        auto* widget = window.findChild<QWidget*>(focused);
        QVERIFY(widget);
        widget->setFocus(Qt::MouseFocusReason);
        QTRY_COMPARE_WITH_TIMEOUT(QApplication::focusWidget(), widget, 10000);
        const QPoint centre = window.viewport()->rect().center();
        QEnterEvent enter(centre, window.viewport()->mapTo(&window, centre), window.viewport()->mapToGlobal(centre));
        QApplication::sendEvent(window.viewport(), &enter);
        QCOMPARE(QApplication::focusWidget() == window.viewport(), viewportGetsFocus);
        if (viewportGetsFocus) {
            QTest::keyClick(QApplication::focusWidget(), Qt::Key_W);
            QCOMPARE(window.viewport()->tool(), rl::GizmoTool::Move);
        }
    }

    // File dialogs open large enough to read: Qt's own dialog (used where no desktop dialog is) opened so narrow that
    // the size, type and date columns were elided ("377...tes", "pla...ent").
    void fileDialogsOpenWideEnough() {
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QFileDialog dialog(&window, QStringLiteral("x"), QStringLiteral(RL_SOURCE_DIR));
        dialog.setOption(QFileDialog::DontUseNativeDialog);
        const QSize before = dialog.sizeHint();
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        const QSize available = window.screen()->availableGeometry().size();
        const QSize want = QSize(900, 560).boundedTo(available);
        QVERIFY2(dialog.width() >= want.width() && dialog.height() >= want.height(),
                 qPrintable(QStringLiteral("%1x%2 (hint %3x%4)")
                                .arg(dialog.width())
                                .arg(dialog.height())
                                .arg(before.width())
                                .arg(before.height())));
        QVERIFY(QRect(QPoint(0, 0), available).contains(dialog.frameGeometry()));
        // Centred over the window, not in the screen's corner.
        QVERIFY2((dialog.geometry().center() - window.geometry().center()).manhattanLength() < 40,
                 qPrintable(QStringLiteral("dialog at %1,%2").arg(dialog.x()).arg(dialog.y())));
        dialog.reject();
    }

    // The first geometry for common screens: a small screen is filled, a large one gets most of it, centred, never
    // less than 1280x800 where that fits.
    void firstGeometry_data() {
        QTest::addColumn<QRect>("available");
        QTest::addColumn<QRect>("expected");
        QTest::newRow("1280x800") << QRect(0, 0, 1280, 800) << QRect(0, 0, 1280, 800);
        QTest::newRow("1366x768 with a panel") << QRect(0, 0, 1366, 740) << QRect(0, 0, 1366, 740);
        QTest::newRow("1920x1080") << QRect(0, 0, 1920, 1080) << QRect(96, 54, 1728, 972);
        QTest::newRow("1920x1080 second screen") << QRect(1920, 0, 1920, 1080) << QRect(2016, 54, 1728, 972);
        QTest::newRow("2560x1440") << QRect(0, 0, 2560, 1440) << QRect(128, 72, 2304, 1296);
        QTest::newRow("1024x600") << QRect(0, 0, 1024, 600) << QRect(0, 0, 1024, 600);
    }
    void firstGeometry() {
        QFETCH(QRect, available);
        QFETCH(QRect, expected);
        QCOMPARE(rl::MainWindow::firstGeometry(available), expected);
    }

    // With no saved geometry the window fills most of the screen (all of a small one), lies on it, and no dock is
    // squashed: the timeline is at the bottom and visible, the outliner and inspector have room, the viewport most.
    void firstLayoutIsSensible() {
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/mixed.obj")));
        const QRect available = window.screen()->availableGeometry();
        const QRect frame = window.frameGeometry();
        QVERIFY2(available.contains(frame), qPrintable(QStringLiteral("window %1,%2 %3x%4 off the screen %5x%6")
                                                           .arg(frame.x())
                                                           .arg(frame.y())
                                                           .arg(frame.width())
                                                           .arg(frame.height())
                                                           .arg(available.width())
                                                           .arg(available.height())));
        QVERIFY2(frame.width() >= std::min(1280, available.width()) && frame.width() >= available.width() * 8 / 10 &&
                     frame.height() >= available.height() * 8 / 10,
                 qPrintable(QStringLiteral("window %1x%2 on a %3x%4 screen")
                                .arg(frame.width())
                                .arg(frame.height())
                                .arg(available.width())
                                .arg(available.height())));
        auto* timeline = window.findChild<QDockWidget*>("TimelineDock");
        QVERIFY(timeline);
        QVERIFY(timeline->isVisible());
        QCOMPARE(window.dockWidgetArea(timeline), Qt::BottomDockWidgetArea);
        QVERIFY(timeline->height() >= 80);
        auto* outliner = window.findChild<QDockWidget*>("OutlinerDock");
        auto* inspector = window.findChild<QDockWidget*>("InspectorDock");
        QVERIFY(outliner && inspector);
        QVERIFY(outliner->isVisible() && inspector->isVisible());
        QVERIFY2(outliner->width() >= 220, qPrintable(QString::number(outliner->width())));
        QVERIFY2(inspector->width() >= 300, qPrintable(QString::number(inspector->width())));
        QVERIFY(window.viewport()->width() > inspector->width());
    }
    // What the user arranged comes back at the next start: the window's size and the dock layout (a closed dock
    // stays closed, a moved dock stays where it was put), saved when the window closes.
    void layoutAndGeometryPersist() {
        QSize arranged;
        {
            rl::MainWindow window;
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            window.resize(1000, 700);
            QTRY_COMPARE(window.size(), QSize(1000, 700));
            arranged = window.size();
            auto* outliner = window.findChild<QDockWidget*>("OutlinerDock");
            auto* timeline = window.findChild<QDockWidget*>("TimelineDock");
            QVERIFY(outliner && timeline);
            outliner->close();
            window.addDockWidget(Qt::TopDockWidgetArea, timeline);
            QVERIFY(window.close());
        }
        QVERIFY(QSettings().contains("mainwindow/geometry"));
        QVERIFY(QSettings().contains("mainwindow/state"));
        rl::MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QCOMPARE(again.size(), arranged);
        auto* outliner = again.findChild<QDockWidget*>("OutlinerDock");
        auto* timeline = again.findChild<QDockWidget*>("TimelineDock");
        QVERIFY(!outliner->isVisible());
        QVERIFY(timeline->isVisible());
        QCOMPARE(again.dockWidgetArea(timeline), Qt::TopDockWidgetArea);
        QVERIFY(again.findChild<QDockWidget*>("InspectorDock")->isVisible());
    }
};

QTEST_MAIN(TestFirstLaunch)
#include "tst_firstlaunch.moc"
