// The editor's main window: opening scenes from disk fills the outliner; bad files give an error, not a crash.
#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "outliner/OutlinerModel.h"
#include "ui/GuiTestSetup.h"
#include "viewport/Viewport.h"

#include <QAbstractItemModel>
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QIcon>
#include <QImage>
#include <QLineEdit>
#include <QLineF>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QTest>
#include <QTimer>
#include <QTreeView>

class TestMainWindow : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void opensSceneIntoOutliner_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("bodies");
        QTest::addColumn<int>("anchors");
        QTest::newRow("stack") << "stack.obj" << 11 << 1;
        QTest::newRow("pyramid") << "pyramid.obj" << 56 << 1;
        QTest::newRow("mixed") << "mixed.obj" << 9 << 2;
        // Formats that go through assimp open the same way.
        QTest::newRow("glTF") << RL_SOURCE_DIR "/tests/data/acceptance/tower20.glb" << 21 << 1;
        QTest::newRow("FBX") << RL_SOURCE_DIR "/tests/data/acceptance/tower20.fbx" << 21 << 1;
    }
    void opensSceneIntoOutliner() {
        QFETCH(QString, file);
        QFETCH(int, bodies);
        QFETCH(int, anchors);
        rl::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QString path = file.startsWith('/') ? file : QStringLiteral(RL_SOURCE_DIR "/resources/scenes/") + file;
        QVERIFY(window.openFile(path));
        QAbstractItemModel* model = window.outlinerView()->model();
        QCOMPARE(model->rowCount(), bodies);
        int anchorRows = 0;
        QImage anchorIcon, dynamicIcon;
        for (int row = 0; row < model->rowCount(); ++row) {
            const bool anchor = model->index(row, 0).data(rl::OutlinerModel::AnchorRole).toBool();
            anchorRows += anchor ? 1 : 0;
            QCOMPARE(anchor, window.document()->body(row).anchor);
            // The material column names the body's material; the name column's icon tells anchors from the rest.
            QCOMPARE(model->index(row, rl::OutlinerModel::MaterialColumn).data().toString(),
                     QString::fromStdString(window.document()->body(row).material));
            const QIcon icon = qvariant_cast<QIcon>(model->index(row, 0).data(Qt::DecorationRole));
            QVERIFY(!icon.isNull());
            const QImage image = icon.pixmap(16, 16).toImage();
            if (anchorIcon.isNull() && anchor)
                anchorIcon = image;
            if (dynamicIcon.isNull() && !anchor)
                dynamicIcon = image;
            QCOMPARE(image, anchor ? anchorIcon : dynamicIcon);
        }
        QCOMPARE(anchorRows, anchors);
        QVERIFY(anchorIcon != dynamicIcon);
        // Names in file order, as the document holds them.
        QCOMPARE(model->index(0, 0).data().toString(), QString::fromStdString(window.document()->body(0).name));
        QVERIFY(window.windowTitle().contains(QFileInfo(file).fileName()));
    }

    void filterNarrowsRows() {
        rl::MainWindow window;
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        auto* filter = window.findChild<QLineEdit*>("OutlinerFilter");
        QVERIFY(filter);
        QTest::keyClicks(filter, "anchor");
        QCOMPARE(window.outlinerView()->model()->rowCount(), 1);
        filter->clear();
        QCOMPARE(window.outlinerView()->model()->rowCount(), 11);
    }

    // Clicking a body in the viewport selects it there and in the outliner; Ctrl-click extends; selecting in the
    // outliner selects in the viewport.
    void selectionStaysInSync() {
        rl::MainWindow window;
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        rl::Viewport* viewport = window.viewport();
        QTRY_VERIFY(viewport->isRendererReady());
        auto pixelOf = [&](int body) {
            const rl::BodyDef& b = window.document()->body(body);
            glm::dvec3 mean(0.0);
            for (const rl::Vec3& p : b.shape.points)
                mean += p;
            mean /= double(b.shape.points.size());
            const glm::vec3 p = viewport->camera().project(glm::vec3(mean));
            return QPoint(int(p.x), int(p.y));
        };
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(10));
        QCOMPARE(window.selectedBodies(), QList<int>{10});
        QCOMPARE(viewport->selection(), QList<int>{10});
        QModelIndexList rows = window.outlinerView()->selectionModel()->selectedRows();
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows.first().data(rl::OutlinerModel::BodyIndexRole).toInt(), 10);

        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier, pixelOf(5));
        QCOMPARE(window.selectedBodies(), (QList<int>{5, 10}));
        QCOMPARE(window.outlinerView()->selectionModel()->selectedRows().size(), 2);

        window.outlinerView()->selectionModel()->select(window.outlinerView()->model()->index(3, 0),
                                                        QItemSelectionModel::ClearAndSelect |
                                                            QItemSelectionModel::Rows);
        QCOMPARE(window.selectedBodies(), QList<int>{3});
        QCOMPARE(viewport->selection(), QList<int>{3});
    }

    // Opening a scene frames its bodies, not a ground that dwarfs them (ViewportScene::contentBounds()): a 0.1 m shot
    // 5 m from a 4 m wall on a 400 m floor. Framed whole (Home), the two are a few pixels apart.
    void openingFramesTheBodiesNotTheGround() {
        rl::MainWindow window;
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/tests/data/acceptance/projectile_wall.rlscene")));
        rl::Viewport* viewport = window.viewport();
        QCOMPARE(QString::fromStdString(window.document()->body(1).name), QStringLiteral("Wall"));
        QCOMPARE(QString::fromStdString(window.document()->body(2).name), QStringLiteral("Bullet"));
        const auto pixelOf = [&](const glm::vec3& p) {
            const glm::vec3 q = viewport->camera().project(p);
            return QPointF(q.x, q.y);
        };
        const glm::vec3 wall(5.0f, 2.0f, 0.0f), shot(0.0f, 1.0f, 0.0f);
        const QRectF screen(0.0, 0.0, viewport->width(), viewport->height());
        QVERIFY(screen.contains(pixelOf(wall)));
        QVERIFY(screen.contains(pixelOf(shot)));
        const qreal apart = QLineF(pixelOf(wall), pixelOf(shot)).length();
        qInfo("wall and shot %.0f px apart on opening", apart);
        QVERIFY(apart > 0.2 * viewport->width());
        viewport->frameAll();
        const qreal apartWhole = QLineF(pixelOf(wall), pixelOf(shot)).length();
        qInfo("and %.0f px apart framed whole", apartWhole);
        QVERIFY(apartWhole < 0.05 * viewport->width());
    }

    // The sample scene renders: the viewport's pixels are not blank and the outliner shows every body.
    void screenshotIsNotBlank() {
        rl::MainWindow window;
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/mixed.obj")));
        QTRY_VERIFY(window.viewport()->isRendererReady());
        const QImage image = window.viewport()->grabFramebuffer();
        QVERIFY(!image.isNull());
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 7)
            for (int x = 0; x < image.width(); x += 7)
                colours.insert(image.pixel(x, y));
        QVERIFY2(colours.size() > 50, qPrintable(QString("only %1 distinct colours").arg(colours.size())));
        image.save(QDir::tempPath() + "/rigidlab_mainwindow.png");
    }

    void badFileShowsErrorAndKeepsScene() {
        rl::MainWindow window;
        QVERIFY(window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")));
        QString shownText;
        // The error box is modal; read it and close it from the event loop.
        QTimer::singleShot(200, [&shownText] {
            for (QWidget* w : QApplication::topLevelWidgets()) {
                if (auto* box = qobject_cast<QMessageBox*>(w)) {
                    shownText = box->text();
                    box->accept();
                }
            }
        });
        QVERIFY(!window.openFile("/nonexistent/missing.obj"));
        QVERIFY(shownText.contains("missing.obj"));
        QCOMPARE(window.document()->bodyCount(), 11); // the open scene is not lost
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
