// Tests of the viewport widget on a real GL context (xcb under Xvfb, Mesa llvmpipe): it draws, highlights the
// selection, picks by click and by box, moves the camera, and renders 5,000 instances (frame time printed).
#include "ui/GuiTestSetup.h"
#include "viewport/Viewport.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTest>
#include <QWheelEvent>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <ctime>
#include <functional>
#include <random>

namespace {

// Test scene: a grey floor anchor with its top at y = 0 and three boxes standing on it, red, green and blue.
rl::ViewportScene makeBoxesScene() {
    rl::ViewportScene scene;
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(5.0f, 0.25f, 5.0f)));
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.5f)));
    rl::ViewportInstance floor;
    floor.meshIndex = 0;
    // Off-centre so that its centre does not project onto the middle box (the box-select test relies on that).
    floor.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.25f, 2.0f));
    floor.colour = glm::vec3(0.9f, 0.1f, 0.9f); // ignored: anchors are grey
    floor.flags = rl::kInstanceAnchor;
    scene.instances.push_back(floor);
    const glm::vec3 colours[] = {{0.85f, 0.15f, 0.12f}, {0.2f, 0.75f, 0.25f}, {0.15f, 0.35f, 0.9f}};
    for (int i = 0; i < 3; ++i) {
        rl::ViewportInstance box;
        box.meshIndex = 1;
        box.model = rl::instanceTransform(glm::dvec3(-2.0 + 2.0 * i, 0.5, 0.0),
                                          glm::angleAxis(0.3 * i, glm::dvec3(0.0, 1.0, 0.0)));
        box.colour = colours[i];
        scene.instances.push_back(box);
    }
    return scene;
}

// The pick function an owner would provide, here a plain ray-vs-world-box test over the scene's instances.
int pickByBoxes(const rl::ViewportScene& scene, const rl::ViewRay& ray) {
    int best = -1;
    float bestT = 1e30f;
    for (int i = 0; i < static_cast<int>(scene.instances.size()); ++i) {
        const float t = rl::intersectRayBounds(ray, scene.instanceBounds(i));
        if (t >= 0.0f && t < bestT) {
            bestT = t;
            best = i;
        }
    }
    return best;
}

int countPixelsNear(const QImage& image, const QColor& colour, int tolerance) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) <= tolerance && std::abs(c.green() - colour.green()) <= tolerance &&
                std::abs(c.blue() - colour.blue()) <= tolerance)
                ++count;
        }
    return count;
}

QPoint projectToPixel(const rl::Camera& camera, const glm::vec3& world) {
    const glm::vec3 p = camera.project(world);
    return QPoint(static_cast<int>(p.x), static_cast<int>(p.y));
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

} // namespace

class TestViewport : public QObject {
    Q_OBJECT
public:
    static void initMain();

private slots:
    void init();
    void cleanup();
    void drawsBodiesGridAndBackground();
    void selectionShowsOrangeOutline();
    void clickSelectsTheBoxUnderTheCursor();
    void boxSelectTakesInstancesWhoseCentreIsInside();
    void inputToTheNativeWindowReachesTheViewport();
    void staticLayerLooksTheSameAndNeverGoesStale();
    void mouseAndKeysMoveTheCamera();
    void setTransformsMovesBodies();
    void batchedMeshesLookLikeInstancedOnes_data();
    void batchedMeshesLookLikeInstancedOnes();
    void fiveThousandInstances();

private:
    void showViewport(int width, int height);
    QImage grab();

    std::unique_ptr<rl::Viewport> m_viewport;
};

void TestViewport::initMain() {
    rl::test::prepareGuiTest();
}

void TestViewport::init() {
    m_viewport = std::make_unique<rl::Viewport>();
}

void TestViewport::cleanup() {
    m_viewport.reset();
}

void TestViewport::showViewport(int width, int height) {
    m_viewport->resize(width, height);
    m_viewport->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_viewport.get()));
    m_viewport->grabFramebuffer(); // makes sure initializeGL has run
    QVERIFY2(m_viewport->isRendererReady(), "shaders failed to build (see the warnings above)");
}

QImage TestViewport::grab() {
    QImage image = m_viewport->grabFramebuffer();
    return image.convertToFormat(QImage::Format_RGB32);
}

void TestViewport::drawsBodiesGridAndBackground() {
    m_viewport->setScene(makeBoxesScene());
    showViewport(640, 480);
    m_viewport->frameAll();
    const QImage raw = m_viewport->grabFramebuffer();
    // The frame is opaque everywhere: the blended grid must not lower the alpha (grabFramebuffer keeps it).
    QCOMPARE(raw.format(), QImage::Format_ARGB32_Premultiplied);
    int translucent = 0;
    for (int y = 0; y < raw.height(); ++y)
        for (int x = 0; x < raw.width(); ++x)
            translucent += qAlpha(raw.pixel(x, y)) != 255;
    QCOMPARE(translucent, 0);
    const QImage image = raw.convertToFormat(QImage::Format_RGB32);
    image.save(QDir::tempPath() + QStringLiteral("/rl_viewport_boxes.png"));
    QCOMPARE(image.size(), QSize(640, 480) * m_viewport->devicePixelRatio());

    // Background: a vertical gradient from lighter at the top to darker at the bottom (the corners are sky).
    const QColor top = image.pixelColor(image.width() - 5, 2);
    const QColor bottom = image.pixelColor(image.width() - 5, image.height() - 3);
    QVERIFY(top.lightness() > 40 && top.lightness() < 110);

    // Each box shows its own colour: a pixel at its projected centre is dominated by that channel.
    const rl::ViewportScene& scene = m_viewport->scene();
    for (int i = 1; i <= 3; ++i) {
        const QPoint p = projectToPixel(m_viewport->camera(), scene.instanceBounds(i).centre());
        const QColor c = image.pixelColor(p);
        const int channel[3] = {c.red(), c.green(), c.blue()};
        const int dominant = i - 1; // red, green, blue
        for (int k = 0; k < 3; ++k)
            if (k != dominant)
                QVERIFY2(
                    channel[dominant] > channel[k] + 30,
                    qPrintable(QStringLiteral("box %1 at (%2, %3) is %4").arg(i).arg(p.x()).arg(p.y()).arg(c.name())));
    }
    // The floor is an anchor: grey (r, g, b close) even though its colour is magenta.
    const QPoint floorPixel = projectToPixel(m_viewport->camera(), glm::vec3(3.5f, 0.0f, 3.5f));
    const QColor floor = image.pixelColor(floorPixel);
    QVERIFY2(std::abs(floor.red() - floor.green()) < 20 && std::abs(floor.red() - floor.blue()) < 20,
             qPrintable(floor.name()));
    QVERIFY(floor != top && floor != bottom);
    // No orange outline without a selection.
    QCOMPARE(countPixelsNear(image, QColor(255, 143, 31), 12), 0);
    QVERIFY(m_viewport->lastFrameMs() > 0.0);
}

void TestViewport::selectionShowsOrangeOutline() {
    m_viewport->setScene(makeBoxesScene());
    showViewport(640, 480);
    m_viewport->frameAll();
    const QImage before = grab();
    m_viewport->setSelection({2});
    QCOMPARE(m_viewport->selection(), QList<int>{2});
    const QImage after = grab();
    after.save(QDir::tempPath() + QStringLiteral("/rl_viewport_selected.png"));
    const int outline = countPixelsNear(after, QColor(255, 143, 31), 12);
    qInfo("outline pixels: %d", outline);
    QCOMPARE(countPixelsNear(before, QColor(255, 143, 31), 12), 0);
    QVERIFY2(outline > 100, qPrintable(QString::number(outline)));
    // The outline hugs the selected box: its pixels lie near the box's projected centre, not around the others.
    const rl::Bounds box = m_viewport->scene().instanceBounds(2);
    QRect nearSelected;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                          (corner & 4) ? box.max.z : box.min.z);
        nearSelected |= QRect(projectToPixel(m_viewport->camera(), p), QSize(1, 1));
    }
    nearSelected.adjust(-4, -4, 4, 4); // the outline is 2 px wide
    QCOMPARE(countPixelsNear(after.copy(nearSelected), QColor(255, 143, 31), 12), outline);
    // Deselecting removes it again.
    m_viewport->setSelection({});
    QCOMPARE(countPixelsNear(grab(), QColor(255, 143, 31), 12), 0);
}

void TestViewport::clickSelectsTheBoxUnderTheCursor() {
    m_viewport->setScene(makeBoxesScene());
    m_viewport->setPickFunction([this](const rl::ViewRay& ray) { return pickByBoxes(m_viewport->scene(), ray); });
    showViewport(640, 480);
    m_viewport->frameAll();
    QSignalSpy spy(m_viewport.get(), &rl::Viewport::selectionChanged);

    const QPoint blueBox = projectToPixel(m_viewport->camera(), m_viewport->scene().instanceBounds(3).centre());
    QTest::mouseClick(m_viewport.get(), Qt::LeftButton, Qt::NoModifier, blueBox);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).value<QList<int>>(), QList<int>{3});
    QCOMPARE(spy.at(0).at(1).toBool(), false);

    const QPoint redBox = projectToPixel(m_viewport->camera(), m_viewport->scene().instanceBounds(1).centre());
    QTest::mouseClick(m_viewport.get(), Qt::LeftButton, Qt::ControlModifier, redBox);
    QCOMPARE(spy.count(), 2);
    QCOMPARE(spy.at(1).at(0).value<QList<int>>(), QList<int>{1});
    QCOMPARE(spy.at(1).at(1).toBool(), true);

    QTest::mouseClick(m_viewport.get(), Qt::LeftButton, Qt::ShiftModifier, redBox);
    QCOMPARE(spy.at(2).at(1).toBool(), true);

    // The top row is sky: a plain click there clears, an extending click does nothing.
    QTest::mouseClick(m_viewport.get(), Qt::LeftButton, Qt::ShiftModifier, QPoint(320, 2));
    QCOMPARE(spy.count(), 3);
    QTest::mouseClick(m_viewport.get(), Qt::LeftButton, Qt::NoModifier, QPoint(320, 2));
    QCOMPARE(spy.count(), 4);
    QVERIFY(spy.at(3).at(0).value<QList<int>>().isEmpty());
    QCOMPARE(spy.at(3).at(1).toBool(), false);
}

void TestViewport::boxSelectTakesInstancesWhoseCentreIsInside() {
    m_viewport->setScene(makeBoxesScene());
    showViewport(640, 480);
    m_viewport->frameAll();
    QSignalSpy spy(m_viewport.get(), &rl::Viewport::selectionChanged);
    const rl::Camera& camera = m_viewport->camera();
    const QPoint green = projectToPixel(camera, m_viewport->scene().instanceBounds(2).centre());
    const QPoint blue = projectToPixel(camera, m_viewport->scene().instanceBounds(3).centre());
    // A rectangle around the green and blue boxes' centres only.
    const QPoint from(green.x() - 15, std::min(green.y(), blue.y()) - 15);
    const QPoint to(blue.x() + 15, std::max(green.y(), blue.y()) + 15);
    QTest::mousePress(m_viewport.get(), Qt::LeftButton, Qt::ShiftModifier, from);
    QTest::mouseMove(m_viewport.get(), (from + to) / 2);
    QTest::mouseMove(m_viewport.get(), to);
    const QImage during = grab();
    during.save(QDir::tempPath() + QStringLiteral("/rl_viewport_boxselect.png"));
    // The rectangle shows while dragging: its top edge is dashed white, at least a third of it.
    auto whiteOnTopEdge = [&](const QImage& image) {
        int white = 0;
        for (int x = from.x() + 2; x < to.x() - 2; ++x)
            white += QColor(image.pixel(x, from.y())).lightness() > 200;
        return white;
    };
    const int edge = to.x() - from.x() - 4;
    QVERIFY2(whiteOnTopEdge(during) > edge / 3, qPrintable(QString::number(whiteOnTopEdge(during))));
    QTest::mouseRelease(m_viewport.get(), Qt::LeftButton, Qt::ShiftModifier, to);
    QCOMPARE(whiteOnTopEdge(grab()), 0);
    QCOMPARE(spy.count(), 1);
    QList<int> selected = spy.at(0).at(0).value<QList<int>>();
    std::sort(selected.begin(), selected.end());
    QCOMPARE(selected, (QList<int>{2, 3}));
    QCOMPARE(spy.at(0).at(1).toBool(), true);

    // Escape abandons a box selection: the release then selects nothing.
    QTest::mousePress(m_viewport.get(), Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(m_viewport.get(), to);
    QTest::keyClick(m_viewport.get(), Qt::Key_Escape);
    QTest::mouseRelease(m_viewport.get(), Qt::LeftButton, Qt::NoModifier, to);
    QCOMPARE(spy.count(), 1);
}

// The frames go to a native child window: a click that the window system delivers to it reaches the viewport widget,
// which takes the keyboard focus. (That the native window itself never takes the focus on a press is xcb's
// behaviour for Qt::WindowDoesNotAcceptFocus, which QTest's events do not go through; checked by hand with xdotool.)
void TestViewport::inputToTheNativeWindowReachesTheViewport() {
    m_viewport->setScene(makeBoxesScene());
    m_viewport->setPickFunction([this](const rl::ViewRay& ray) { return pickByBoxes(m_viewport->scene(), ray); });
    showViewport(640, 480);
    m_viewport->frameAll();
    QWindow* native = m_viewport->nativeWindow();
    QVERIFY(native && native->isExposed());
    QCOMPARE(native->size(), m_viewport->size());
    m_viewport->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_viewport.get()));
    m_viewport->clearFocus();
    QVERIFY(!m_viewport->hasFocus());
    QSignalSpy spy(m_viewport.get(), &rl::Viewport::selectionChanged);
    const QPoint blueBox = projectToPixel(m_viewport->camera(), m_viewport->scene().instanceBounds(3).centre());
    QTest::mouseClick(native, Qt::LeftButton, Qt::NoModifier, blueBox);
    QTRY_COMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).value<QList<int>>(), QList<int>{3});
    QVERIFY(m_viewport->hasFocus());

    // A drag on the native window orbits the camera, as on the widget.
    const float yaw = m_viewport->camera().yaw();
    QTest::mousePress(native, Qt::MiddleButton, Qt::NoModifier, QPoint(300, 200));
    QTest::mouseMove(native, QPoint(360, 220));
    QTest::mouseRelease(native, Qt::MiddleButton, Qt::NoModifier, QPoint(360, 220));
    QTRY_VERIFY(std::abs(m_viewport->camera().yaw() - yaw) > 0.1f);

    // Every frame asked for is swapped to the window, once however often it was asked.
    QSignalSpy swapped(m_viewport.get(), &rl::Viewport::frameSwapped);
    for (int k = 0; k < 5; ++k)
        m_viewport->requestRender();
    QVERIFY(swapped.wait(5000));
    QTest::qWait(100);
    QCOMPARE(swapped.count(), 1);
}

// The static layer (background, anchors, grid) is cached while it does not change. Frames drawn from it must be the
// frames drawn without it, pixel for pixel, and no change to what is in it may show a stale layer: after each
// change, the next two frames (the first draws the layer itself, the second rebuilds and copies it) are compared
// with a frame drawn with the cache off.
void TestViewport::staticLayerLooksTheSameAndNeverGoesStale() {
    m_viewport->setScene(makeBoxesScene());
    showViewport(640, 480);
    m_viewport->frameAll();
    auto differingPixels = [](const QImage& a, const QImage& b) {
        int n = 0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x)
                n += a.pixel(x, y) != b.pixel(x, y);
        return n;
    };
    auto check = [&](const char* what) {
        const QImage first = grab();
        const QImage second = grab();
        QVERIFY2(m_viewport->lastFrameUsedStaticLayer(), what);
        m_viewport->setStaticLayerCaching(false);
        const QImage reference = grab();
        QVERIFY(!m_viewport->lastFrameUsedStaticLayer());
        m_viewport->setStaticLayerCaching(true);
        QVERIFY2(differingPixels(first, reference) == 0, what);
        QVERIFY2(differingPixels(second, reference) == 0, what);
    };
    check("first frames");
    QImage before = grab();

    // Moving bodies do not touch the layer: no rebuild.
    const int builds = m_viewport->staticLayerBuilds();
    std::vector<glm::mat4> models;
    for (const rl::ViewportInstance& inst : m_viewport->scene().instances)
        models.push_back(inst.model);
    models[2] = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 1.5f)) * models[2];
    m_viewport->setTransforms(models);
    check("a box moved");
    QCOMPARE(m_viewport->staticLayerBuilds(), builds);
    QVERIFY(differingPixels(before, grab()) > 100);

    // Each change to the layer's content is seen at once.
    models[0] = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.4f, 0.0f)) * models[0];
    m_viewport->setTransforms(models);
    check("the floor moved");
    m_viewport->setSelection({0});
    check("the floor selected");
    m_viewport->setInstanceAppearance(0, glm::vec3(0.2f), rl::kInstanceAnchor | rl::kInstanceHidden);
    check("the floor hidden");
    m_viewport->setInstanceAppearance(0, glm::vec3(0.2f), rl::kInstanceAnchor);
    m_viewport->setInstanceAppearance(3, glm::vec3(0.2f, 0.3f, 0.9f), rl::kInstanceAnchor);
    check("a box anchored");
    m_viewport->setGridVisible(false);
    check("grid off");
    m_viewport->camera().orbit(25.0f, 10.0f);
    check("camera orbited");
    m_viewport->camera().zoom(0.8f);
    check("camera zoomed");
    QVERIFY(m_viewport->staticLayerBuilds() > builds + 6);
}

void TestViewport::mouseAndKeysMoveTheCamera() {
    m_viewport->setScene(makeBoxesScene());
    showViewport(640, 480);
    m_viewport->frameAll();
    rl::Camera& camera = m_viewport->camera();
    const float yaw = camera.yaw();
    const glm::vec3 target = camera.target();

    // Middle drag orbits.
    QTest::mousePress(m_viewport.get(), Qt::MiddleButton, Qt::NoModifier, QPoint(300, 200));
    QTest::mouseMove(m_viewport.get(), QPoint(360, 220));
    QTest::mouseRelease(m_viewport.get(), Qt::MiddleButton, Qt::NoModifier, QPoint(360, 220));
    QVERIFY(std::abs(camera.yaw() - yaw) > 0.1f);
    QCOMPARE(camera.target(), target);

    // Shift + middle drag pans.
    QTest::mousePress(m_viewport.get(), Qt::MiddleButton, Qt::ShiftModifier, QPoint(300, 200));
    QTest::mouseMove(m_viewport.get(), QPoint(340, 200));
    QTest::mouseRelease(m_viewport.get(), Qt::MiddleButton, Qt::ShiftModifier, QPoint(340, 200));
    QVERIFY(glm::length(camera.target() - target) > 0.01f);

    // Alt + left drag orbits too, and emits no selection.
    QSignalSpy selections(m_viewport.get(), &rl::Viewport::selectionChanged);
    const float yaw2 = camera.yaw();
    QTest::mousePress(m_viewport.get(), Qt::LeftButton, Qt::AltModifier, QPoint(300, 200));
    QTest::mouseMove(m_viewport.get(), QPoint(250, 200));
    QTest::mouseRelease(m_viewport.get(), Qt::LeftButton, Qt::AltModifier, QPoint(250, 200));
    QVERIFY(std::abs(camera.yaw() - yaw2) > 0.1f);
    QCOMPARE(selections.count(), 0);

    // The wheel zooms in.
    const float distance = camera.distance();
    QWheelEvent wheel(QPointF(320, 240), m_viewport->mapToGlobal(QPointF(320, 240)), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(m_viewport.get(), &wheel);
    QVERIFY(camera.distance() < distance);

    // Home frames everything, F frames the selection.
    QTest::keyClick(m_viewport.get(), Qt::Key_Home);
    const glm::vec3 allCentre = m_viewport->scene().bounds().centre();
    QVERIFY(glm::length(camera.target() - allCentre) < 1e-4f);
    const float allDistance = camera.distance();
    m_viewport->setSelection({1});
    QTest::keyClick(m_viewport.get(), Qt::Key_F);
    QVERIFY(glm::length(camera.target() - m_viewport->scene().instanceBounds(1).centre()) < 1e-4f);
    QVERIFY(camera.distance() < allDistance);
    QTest::keyClick(m_viewport.get(), Qt::Key_Home);
    QTest::keyClick(m_viewport.get(), Qt::Key_Period, Qt::KeypadModifier);
    QVERIFY(glm::length(camera.target() - m_viewport->scene().instanceBounds(1).centre()) < 1e-4f);

    // Numpad views: 7 looks down from the top, Ctrl+1 from the back (along +Z), 3 from the right (along -X); with
    // Num Lock off the keypad sends Home/End/PageDown, which must give the same views and not "frame all".
    QTest::keyClick(m_viewport.get(), Qt::Key_7, Qt::KeypadModifier);
    QVERIFY(camera.forward().y < -0.99f);
    QTest::keyClick(m_viewport.get(), Qt::Key_1, Qt::KeypadModifier | Qt::ControlModifier);
    QVERIFY(camera.forward().z > 0.99f);
    QTest::keyClick(m_viewport.get(), Qt::Key_PageDown, Qt::KeypadModifier);
    QVERIFY(camera.forward().x < -0.99f);
    const glm::vec3 beforeHome = camera.target();
    QTest::keyClick(m_viewport.get(), Qt::Key_Home, Qt::KeypadModifier);
    QVERIFY(camera.forward().y < -0.99f);
    QCOMPARE(camera.target(), beforeHome);
}

void TestViewport::setTransformsMovesBodies() {
    m_viewport->setScene(makeBoxesScene());
    showViewport(640, 480);
    m_viewport->frameAll();
    const QPoint red = projectToPixel(m_viewport->camera(), m_viewport->scene().instanceBounds(1).centre());
    QVERIFY(grab().pixelColor(red).red() > 100);
    // Lift the red box 20 m: its old place shows no red any more.
    std::vector<glm::mat4> models;
    for (const rl::ViewportInstance& inst : m_viewport->scene().instances)
        models.push_back(inst.model);
    models[1] = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 20.0f, 0.0f)) * models[1];
    m_viewport->setTransforms(models);
    const QColor now = grab().pixelColor(red);
    QVERIFY2(now.red() < now.green() + 30, qPrintable(now.name()));
    QCOMPARE(m_viewport->scene().instances[1].model, models[1]);
}

void TestViewport::batchedMeshesLookLikeInstancedOnes_data() {
    QTest::addColumn<QList<int>>("selection");
    QTest::addColumn<int>("outlineDraws"); // per outline pass, when every box has its own mesh
    QTest::newRow("nothing selected") << QList<int>{} << 0;
    // A few selected boxes are outlined mesh by mesh, one draw each per pass.
    QTest::newRow("three selected") << QList<int>{3, 17, 40} << 3;
    // Many are outlined by drawing the whole batch once per pass (the shader drops the others).
    QList<int> many;
    for (int i = 1; i <= 48; i += 2)
        many.append(i);
    QTest::newRow("24 selected") << many << 1;
}

void TestViewport::batchedMeshesLookLikeInstancedOnes() {
    // The same 48 boxes on a floor, once sharing one mesh (drawn instanced: 48 instances) and once with a mesh of
    // their own each (one instance per mesh: drawn in the batch, with the instance data read from a buffer
    // texture). Both paths must give the same picture, outline included.
    QFETCH(QList<int>, selection);
    QFETCH(int, outlineDraws);
    auto makeScene = [](bool ownMeshes) {
        rl::ViewportScene scene;
        scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(4.0f, 0.25f, 4.0f)));
        rl::ViewportInstance floor;
        floor.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.25f, 0.0f));
        floor.flags = rl::kInstanceAnchor;
        scene.instances.push_back(floor);
        for (int i = 0; i < 48; ++i) {
            if (ownMeshes || i == 0)
                scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.25f, 0.2f, 0.15f)));
            rl::ViewportInstance box;
            box.meshIndex = ownMeshes ? 1 + i : 1;
            box.model =
                rl::instanceTransform(glm::dvec3(0.7 * (i % 8 - 3.5), 0.3 + 0.5 * (i / 24), 0.7 * (i / 8 % 3 - 1)),
                                      glm::angleAxis(0.2 * i, glm::normalize(glm::dvec3(1.0, 2.0, 0.5))));
            box.colour = glm::vec3(0.2f + 0.015f * i, 0.8f - 0.01f * i, 0.5f);
            box.flags = i % 11 == 5 ? rl::kInstanceSleeping : 0u;
            scene.instances.push_back(box);
        }
        return scene;
    };
    QImage images[2];
    int drawCalls[2] = {};
    for (int ownMeshes = 0; ownMeshes < 2; ++ownMeshes) {
        m_viewport = std::make_unique<rl::Viewport>();
        m_viewport->setScene(makeScene(ownMeshes == 1));
        m_viewport->setSelection(selection);
        showViewport(480, 360);
        m_viewport->camera().setYaw(glm::radians(30.0f));
        m_viewport->camera().setPitch(glm::radians(35.0f));
        m_viewport->frameAll();
        images[ownMeshes] = grab();
        // Draw calls of a steady frame: the static layer (background, floor, grid) is cached by then.
        grab();
        grab();
        QVERIFY(m_viewport->lastFrameUsedStaticLayer());
        drawCalls[ownMeshes] = m_viewport->drawCallsLastFrame();
    }
    images[1].save(QDir::tempPath() + QStringLiteral("/rl_viewport_batched.png"));
    // Over the cached static layer: the boxes (instanced) and the batch (the floor has one instance, so it is in the
    // batch either way; the vertex shader drops it, an anchor, from the moving bodies' pass), the axis indicator;
    // outlines as the data say.
    const int selectedMeshes = selection.isEmpty() ? 0 : 1;
    QCOMPARE(drawCalls[0], 2 + 1 + 2 * selectedMeshes);
    QCOMPARE(drawCalls[1], 1 + 1 + 2 * outlineDraws);
    int differing = 0;
    for (int y = 0; y < images[0].height(); ++y)
        for (int x = 0; x < images[0].width(); ++x) {
            const QColor a = images[0].pixelColor(x, y);
            const QColor b = images[1].pixelColor(x, y);
            if (std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue()) > 6)
                ++differing;
        }
    QVERIFY2(differing <= 20, qPrintable(QString::number(differing)));
    const int outline = countPixelsNear(images[1], QColor(255, 143, 31), 12);
    QCOMPARE(outline > 30, !selection.isEmpty());
}

void TestViewport::fiveThousandInstances() {
    // 5,000 boxes of three sizes on a floor: four meshes, so the bodies take a few instanced draw calls.
    rl::ViewportScene scene;
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(40.0f, 0.5f, 40.0f)));
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.3f)));
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.4f, 0.2f, 0.25f)));
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.15f, 0.5f, 0.15f)));
    rl::ViewportInstance floor;
    floor.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.5f, 0.0f));
    floor.flags = rl::kInstanceAnchor;
    scene.instances.push_back(floor);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const int kBodies = 5000;
    for (int i = 0; i < kBodies - 1; ++i) {
        rl::ViewportInstance box;
        box.meshIndex = 1 + i % 3;
        const int column = i % 50;
        const int row = (i / 50) % 50;
        const int layer = i / 2500;
        box.model = rl::instanceTransform(
            glm::dvec3(1.2 * (column - 24.5), 0.6 + 1.1 * layer, 1.2 * (row - 24.5)),
            glm::normalize(glm::dquat(1.0, unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5)));
        box.colour = glm::vec3(0.25f + 0.7f * unit(random), 0.25f + 0.7f * unit(random), 0.25f + 0.7f * unit(random));
        if (i % 97 == 0)
            box.flags |= rl::kInstanceSleeping;
        scene.instances.push_back(box);
    }
    QCOMPARE(static_cast<int>(scene.instances.size()), kBodies);
    m_viewport->setScene(std::move(scene));
    m_viewport->setSelection({10, 11, 12, 500, 2600});
    showViewport(1280, 800);
    m_viewport->camera().setYaw(glm::radians(35.0f));
    m_viewport->camera().setPitch(glm::radians(30.0f));
    m_viewport->frameAll();
    m_viewport->camera().zoom(0.75f);

    const QImage image = grab();
    image.save(QDir::tempPath() + QStringLiteral("/rl_viewport_5000.png"));
    // Instancing, in a steady frame (the static layer of background, floor and grid is cached by then): the batch
    // (the floor has one instance; dropped from this pass), each box mesh's 1,666 or 1,667 instances in 5 parts of
    // at most 341 (4,096 triangles, each part flushed to llvmpipe's rasteriser) and the axis indicator, plus two
    // outline passes over the 3 meshes that have a selected instance (10 and 500 share one).
    grab(); // builds the layer
    grab();
    QVERIFY(m_viewport->lastFrameUsedStaticLayer());
    QCOMPARE(m_viewport->drawCallsLastFrame(), 1 + 3 * 5 + 1 + 2 * 3);
    QVERIFY(countPixelsNear(image, QColor(255, 143, 31), 12) > 20);
    // Most of the middle of the image is covered by bodies, not background.
    int distinct = 0;
    QSet<QRgb> colours;
    for (int y = 200; y < 600; y += 7)
        for (int x = 300; x < 980; x += 7)
            colours.insert(image.pixel(x, y));
    distinct = colours.size();
    QVERIFY2(distinct > 200, qPrintable(QString::number(distinct)));

    // Frame time: repaint as fast as the widget can; paintGL's own time (glFinish included) and the wall time per
    // frame, which adds Qt's composition of the widget into the window.
    // The process CPU time per frame (llvmpipe's threads and Qt's composition run in this process) says how much
    // work a frame is, independent of how busy the machine is; the load average is printed to read the others.
    struct Timing {
        double paintMedianMs = 0.0;
        double wallMs = 0.0;
        double cpuMs = 0.0;
    };
    auto measure = [this](int frames, const std::function<void(int)>& beforeFrame) {
        std::vector<double> paint;
        QSignalSpy swapped(m_viewport.get(), &rl::Viewport::frameSwapped);
        QElapsedTimer wall;
        wall.start();
        const std::clock_t cpuStart = std::clock();
        for (int f = 0; f < frames; ++f) {
            beforeFrame(f);
            m_viewport->requestRender();
            if (!swapped.wait(5000))
                break;
            paint.push_back(m_viewport->lastFrameMs());
        }
        const double count = static_cast<double>(std::max<size_t>(paint.size(), 1));
        Timing t;
        t.paintMedianMs = median(paint);
        t.wallMs = static_cast<double>(wall.nsecsElapsed()) * 1e-6 / count;
        t.cpuMs = 1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC / count;
        return t;
    };
    const int kFrames = 30;
    const auto still = measure(kFrames, [this](int) { m_viewport->camera().orbit(4.0f, 0.0f); });
    std::vector<glm::mat4> models;
    for (const rl::ViewportInstance& inst : m_viewport->scene().instances)
        models.push_back(inst.model);
    const auto playing = measure(kFrames, [&](int f) {
        for (size_t i = 1; i < models.size(); ++i)
            models[i][3].y += 0.01f * static_cast<float>((f % 2) ? -1 : 1);
        m_viewport->setTransforms(models);
    });
    // The CPU side of playback: copying 5,000 matrices into the viewport (the upload itself happens in paintGL).
    QElapsedTimer copyTimer;
    copyTimer.start();
    const int kCopies = 100;
    for (int i = 0; i < kCopies; ++i)
        m_viewport->setTransforms(models);
    const double copyMs = static_cast<double>(copyTimer.nsecsElapsed()) * 1e-6 / kCopies;
    QFile loadFile(QStringLiteral("/proc/loadavg"));
    const QByteArray load = loadFile.open(QIODevice::ReadOnly) ? loadFile.readLine().trimmed() : QByteArray("?");
    qInfo("5000 instances at %dx%d, %d frames each, load average %s", m_viewport->width(), m_viewport->height(),
          kFrames, load.constData());
    qInfo("  orbiting: paintGL median %.1f ms, wall %.1f ms/frame, process CPU %.1f ms/frame", still.paintMedianMs,
          still.wallMs, still.cpuMs);
    qInfo("  playback (setTransforms every frame): paintGL median %.1f ms, wall %.1f ms/frame, process CPU %.1f "
          "ms/frame",
          playing.paintMedianMs, playing.wallMs, playing.cpuMs);
    qInfo("  setTransforms(5000 matrices) alone: %.3f ms per call", copyMs);
    QVERIFY(still.paintMedianMs > 0.0 && playing.paintMedianMs > 0.0);
}

QTEST_MAIN(TestViewport)
#include "tst_viewport.moc"
