// View > Overlays: the actions enable their kind and install the viewport painter only when something is drawn, the
// projection puts world points at the right pixels, each overlay paints its colour where it should, sleeping bodies
// are flagged and restored, trails follow consecutive frames (or a bake), and 5,000 bodies paint in bounded time.
#include "MainWindow.h"
#include "bake/Bake.h"
#include "overlays/OverlayController.h"
#include "overlays/OverlayPainter.h"
#include "overlays/OverlayProjection.h"
#include "ui/GuiTestSetup.h"
#include "ui/Screenshot.h"
#include "viewport/Camera.h"
#include "viewport/ScenePresenter.h"
#include "viewport/Viewport.h"

#include <QAction>
#include <QDir>
#include <QElapsedTimer>
#include <QImage>
#include <QMenu>
#include <QPainter>
#include <QSettings>
#include <QTest>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

using rl::OverlayController;

Q_DECLARE_METATYPE(OverlayController::Kind)

namespace {

const QString kStack = QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj");

// A window on the stack sample (an anchor plane and ten unit cubes), shown, with the renderer ready.
struct Window {
    rl::MainWindow window;
    Window() {
        window.resize(1100, 760);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(kStack));
        QTRY_VERIFY_WITH_TIMEOUT(window.viewport()->isRendererReady(), 20000);
    }
    OverlayController* overlays() const { return window.overlays(); }
    rl::Viewport* viewport() const { return window.viewport(); }
    int bodies() const { return static_cast<int>(viewport()->scene().instances.size()); }
    glm::vec3 centre(int body) const { return viewport()->scene().instanceBounds(body).centre(); }

    // A frame of the edit pose: centres and boxes from the viewport's instances, every dynamic body moving +X.
    rl::OverlayFrame editFrame(int number = 0) const {
        rl::OverlayFrame frame;
        frame.frame = number;
        for (int i = 0; i < bodies(); ++i) {
            frame.centres.push_back(centre(i));
            frame.aabbs.push_back(viewport()->scene().instanceBounds(i));
            frame.linearVelocities.push_back(i == 0 ? glm::vec3(0.0f) : glm::vec3(3.0f, 0.0f, 0.0f));
            frame.sleeping.push_back(0);
        }
        return frame;
    }
    QPointF pixelOf(const glm::vec3& world) const {
        const rl::ScreenProjector projector(viewport()->camera(), QSizeF(viewport()->size()));
        const auto p = projector.toPixel(world);
        return p ? *p : QPointF(-1, -1);
    }
};

bool near(const QColor& a, const QColor& b, int tolerance) {
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

int distance(const QColor& a, const QColor& b) {
    return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
}

// Whether a pixel within `radius` logical pixels of `at` has the colour (the image is in device pixels).
bool hasColourNear(const QImage& image, const QPointF& at, const QColor& colour, int radius, int tolerance) {
    const qreal ratio = image.devicePixelRatio();
    const int cx = static_cast<int>(std::lround(at.x() * ratio)), cy = static_cast<int>(std::lround(at.y() * ratio));
    const int r = static_cast<int>(std::ceil(radius * ratio));
    for (int y = cy - r; y <= cy + r; ++y)
        for (int x = cx - r; x <= cx + r; ++x)
            if (image.valid(x, y) && near(image.pixelColor(x, y), colour, tolerance))
                return true;
    return false;
}

// Whether some pixel near `at` moved at least 35% of the way from its colour in `before` to `colour` in `after`:
// an antialiased one-pixel line covers some pixel at least half, however it falls between pixel centres.
bool paintedNear(const QImage& before, const QImage& after, const QPointF& at, const QColor& colour, int radius) {
    const qreal ratio = after.devicePixelRatio();
    const int cx = static_cast<int>(std::lround(at.x() * ratio)), cy = static_cast<int>(std::lround(at.y() * ratio));
    const int r = static_cast<int>(std::ceil(radius * ratio));
    for (int y = cy - r; y <= cy + r; ++y)
        for (int x = cx - r; x <= cx + r; ++x) {
            if (!after.valid(x, y) || !before.valid(x, y))
                continue;
            const int was = distance(before.pixelColor(x, y), colour);
            const int now = distance(after.pixelColor(x, y), colour);
            if (was >= 60 && now <= 0.65 * was)
                return true;
        }
    return false;
}

} // namespace

class TestOverlays : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void init() {
        // Overlay toggles persist; every test starts with all of them off.
        QSettings().remove(QStringLiteral("overlays"));
    }
    void cleanupTestCase() { QSettings().remove(QStringLiteral("overlays")); }

    void toggleInstallsPainter_data() {
        QTest::addColumn<OverlayController::Kind>("kind");
        QTest::addColumn<QString>("actionName");
        QTest::addColumn<bool>("paints");
        QTest::newRow("contacts") << OverlayController::Contacts << "OverlayContactsAction" << true;
        QTest::newRow("velocities") << OverlayController::Velocities << "OverlayVelocitiesAction" << true;
        QTest::newRow("centres") << OverlayController::Centres << "OverlayCentresAction" << true;
        QTest::newRow("aabbs") << OverlayController::Aabbs << "OverlayAabbsAction" << true;
        // Sleeping changes the bodies' look, not the painted layer.
        QTest::newRow("sleeping") << OverlayController::Sleeping << "OverlaySleepingAction" << false;
        QTest::newRow("trails") << OverlayController::Trails << "OverlayTrailsAction" << true;
    }
    void toggleInstallsPainter() {
        QFETCH(OverlayController::Kind, kind);
        QFETCH(QString, actionName);
        QFETCH(bool, paints);
        Window w;
        OverlayController* overlays = w.overlays();
        auto* submenu = w.window.findChild<QMenu*>("OverlaysMenu");
        QVERIFY(submenu);
        QVERIFY(w.window.menu(rl::MainWindow::Menu::View)->actions().contains(submenu->menuAction()));
        auto* action = w.window.findChild<QAction*>(actionName);
        QVERIFY(action);
        QVERIFY(submenu->actions().contains(action));
        QVERIFY(action->isCheckable());
        QVERIFY(!action->isChecked());
        QVERIFY(!overlays->isEnabled(kind));

        // On without a frame (the edit pose): nothing to draw, no painter.
        action->trigger();
        QVERIFY(overlays->isEnabled(kind));
        QVERIFY(!overlays->isPainterInstalled());
        QCOMPARE(QSettings()
                     .value(QStringLiteral("overlays/") + actionName.mid(7, actionName.size() - 13).toLower())
                     .toBool(),
                 true);

        overlays->setFrame(w.editFrame());
        QCOMPARE(overlays->isPainterInstalled(), paints);
        int before = overlays->paintCount();
        w.viewport()->grabFramebuffer(); // renders, so an installed painter runs
        QCOMPARE(overlays->paintCount() > before, paints);

        action->trigger();
        QVERIFY(!overlays->isEnabled(kind));
        QVERIFY(!overlays->isPainterInstalled());
        before = overlays->paintCount();
        w.viewport()->grabFramebuffer();
        QCOMPARE(overlays->paintCount(), before);

        // Back on with a frame, then clear(): the painter goes with the frame.
        overlays->setEnabled(kind, true);
        QVERIFY(action->isChecked());
        QCOMPARE(overlays->isPainterInstalled(), paints);
        overlays->clear();
        QVERIFY(!overlays->isPainterInstalled());
        QVERIFY(overlays->isEnabled(kind));
    }

    void togglesPersist() {
        {
            Window w;
            w.overlays()->action(OverlayController::Aabbs)->trigger();
            w.overlays()->action(OverlayController::Trails)->trigger();
            w.overlays()->legendAction()->trigger(); // on by default, now off
        }
        Window w;
        for (int k = 0; k < OverlayController::KindCount; ++k) {
            const auto kind = static_cast<OverlayController::Kind>(k);
            const bool expected = kind == OverlayController::Aabbs || kind == OverlayController::Trails;
            QCOMPARE(w.overlays()->isEnabled(kind), expected);
            QCOMPARE(w.overlays()->action(kind)->isChecked(), expected);
        }
        QVERIFY(!w.overlays()->legendAction()->isChecked());
    }

    // A camera at distance 10 on +Z looking at the origin (yaw 0, pitch 0), 45° vertical field, 800 x 600 pixels:
    // a point x metres right of the target at its depth lands x / (10 tan 22.5°) * 300 pixels right of the centre.
    void projectionPutsPointsAtExpectedPixels_data() {
        QTest::addColumn<glm::vec3>("world");
        QTest::addColumn<bool>("visible");
        QTest::addColumn<QPointF>("pixel");
        const double unit = 0.1 / std::tan(glm::radians(22.5)) * 300.0; // 72.43 px per metre at the target
        QTest::newRow("target") << glm::vec3(0.0f) << true << QPointF(400, 300);
        QTest::newRow("right") << glm::vec3(1, 0, 0) << true << QPointF(400 + unit, 300);
        QTest::newRow("up") << glm::vec3(0, 1, 0) << true << QPointF(400, 300 - unit);
        QTest::newRow("left-down") << glm::vec3(-2, -1, 0) << true << QPointF(400 - 2 * unit, 300 + unit);
        // 5 m nearer the eye, so twice as far from the centre.
        QTest::newRow("nearer") << glm::vec3(1, 0, 5) << true << QPointF(400 + 2 * unit, 300);
        QTest::newRow("behind eye") << glm::vec3(0, 0, 20) << false << QPointF();
        QTest::newRow("at eye") << glm::vec3(0, 0, 10) << false << QPointF();
    }
    void projectionPutsPointsAtExpectedPixels() {
        QFETCH(glm::vec3, world);
        QFETCH(bool, visible);
        QFETCH(QPointF, pixel);
        rl::Camera camera;
        camera.setViewportSize(800, 600);
        camera.setTarget(glm::vec3(0.0f));
        camera.setDistance(10.0f);
        camera.setYaw(0.0f);
        camera.setPitch(0.0f);
        camera.setFovY(glm::radians(45.0f));
        const rl::ScreenProjector projector(camera, QSizeF(800, 600));
        const std::optional<QPointF> p = projector.toPixel(world);
        QCOMPARE(p.has_value(), visible);
        if (visible) {
            QVERIFY2(std::abs(p->x() - pixel.x()) < 0.01 && std::abs(p->y() - pixel.y()) < 0.01,
                     qPrintable(QString("got (%1, %2)").arg(p->x()).arg(p->y())));
        }
    }

    // The projector agrees with Camera::project for points in front of the eye, from arbitrary views.
    void projectionMatchesCamera() {
        std::mt19937 random(7);
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
        rl::Camera camera;
        camera.setViewportSize(640, 480);
        int compared = 0;
        for (int view = 0; view < 20; ++view) {
            camera.setYaw(3.0f * unit(random));
            camera.setPitch(1.2f * unit(random));
            camera.setDistance(5.0f + 4.0f * unit(random));
            camera.setTarget(glm::vec3(unit(random), unit(random), unit(random)));
            const rl::ScreenProjector projector(camera, QSizeF(640, 480));
            for (int i = 0; i < 50; ++i) {
                const glm::vec3 world(8.0f * unit(random), 8.0f * unit(random), 8.0f * unit(random));
                const glm::vec3 expected = camera.project(world);
                const std::optional<QPointF> p = projector.toPixel(world);
                if (expected.z < -1.0f || expected.z > 1.0f)
                    continue; // outside the depth range: Camera::project flags it differently
                QVERIFY(p.has_value());
                QVERIFY(std::abs(p->x() - expected.x) < 0.05 && std::abs(p->y() - expected.y) < 0.05);
                ++compared;
            }
        }
        QVERIFY(compared > 500);
    }

    // Segments crossing the near plane are cut there; wholly behind or wholly off to one side, they are dropped.
    void segmentsClipAtNearPlane() {
        rl::Camera camera;
        camera.setViewportSize(800, 600);
        camera.setYaw(0.0f);
        camera.setPitch(0.0f);
        camera.setDistance(10.0f);
        const rl::ScreenProjector projector(camera, QSizeF(800, 600));
        QLineF line;
        // From the target through the eye to behind it: kept, cut at the near plane, which is on the view axis.
        QVERIFY(projector.segment(glm::vec3(1, 0, 0), glm::vec3(1, 0, 30), line));
        QVERIFY(std::isfinite(line.p2().x()) && std::isfinite(line.p2().y()));
        QVERIFY(line.p2().x() > line.p1().x()); // towards the eye, x = 1 spreads to the right
        const glm::vec4 cut = camera.viewProjection() * glm::vec4(1, 0, 10 - camera.nearPlane(), 1);
        QVERIFY(std::abs(line.p2().x() - projector.pixel(cut).x()) < 1.0);
        // Wholly behind the eye.
        QVERIFY(!projector.segment(glm::vec3(0, 0, 11), glm::vec3(1, 1, 30), line));
        // Wholly to the left of the view.
        QVERIFY(!projector.segment(glm::vec3(-100, 0, 0), glm::vec3(-100, 5, -3), line));
        // Crossing the view: kept even though both ends are off-screen.
        QVERIFY(projector.segment(glm::vec3(-100, 0, 0), glm::vec3(100, 0, 0), line));
        QVERIFY(line.p1().x() < 0 && line.p2().x() > 800);
    }

    // Each layer paints its colour at the projected place of what it shows.
    void paintsOverlayColours_data() {
        QTest::addColumn<OverlayController::Kind>("kind");
        QTest::addColumn<QColor>("colour");
        QTest::newRow("contacts") << OverlayController::Contacts << rl::overlay_colours::contact();
        QTest::newRow("velocities") << OverlayController::Velocities << rl::overlay_colours::velocity();
        QTest::newRow("centres") << OverlayController::Centres << rl::overlay_colours::centre();
        QTest::newRow("aabbs") << OverlayController::Aabbs << rl::overlay_colours::aabb();
        QTest::newRow("trails") << OverlayController::Trails << rl::overlay_colours::trail();
    }
    void paintsOverlayColours() {
        QFETCH(OverlayController::Kind, kind);
        QFETCH(QColor, colour);
        Window w;
        OverlayController* overlays = w.overlays();
        overlays->legendAction()->setChecked(false); // keep the corner clear of legend glyphs
        rl::OverlayFrame frame = w.editFrame(0);
        const int body = 6;
        const glm::vec3 c = w.centre(body);
        QPointF probe; // where the colour must show, in logical pixels
        const float wpp = w.viewport()->camera().worldPerPixelAtTarget();
        switch (kind) {
        case OverlayController::Contacts:
            frame.contacts.push_back({c, glm::vec3(0, 1, 0), 0.01f});
            probe = w.pixelOf(c);
            break;
        case OverlayController::Velocities:
            // 3 m/s is 36 px at the target's depth; half-way along the shaft.
            probe = w.pixelOf(c + glm::vec3(3.0f * rl::kVelocityPixelsPerMps * 0.5f * wpp, 0, 0));
            break;
        case OverlayController::Centres:
            probe = w.pixelOf(c);
            break;
        case OverlayController::Aabbs: {
            const rl::Bounds box = frame.aabbs[body];
            probe = w.pixelOf(glm::vec3(box.max.x, 0.5f * (box.min.y + box.max.y), box.max.z)); // a vertical edge
            break;
        }
        case OverlayController::Trails: {
            // The body moved 0.5 m along +X over 5 consecutive frames; probe the trail's middle. Trails are drawn
            // for the selection only, so selecting the body is what makes it appear below.
            overlays->setEnabled(kind, true);
            for (int f = 0; f < 5; ++f) {
                frame.frame = f;
                frame.centres[body] = c + glm::vec3(0.125f * f, 0, 0);
                overlays->setFrame(frame);
            }
            probe = w.pixelOf(c + glm::vec3(0.25f, 0, 0));
            break;
        }
        default:
            QFAIL("no probe");
        }
        // Before: not there. After enabling: there. After clear(): gone again.
        overlays->setFrame(frame);
        const QImage before = w.viewport()->grabFramebuffer();
        overlays->setEnabled(kind, true);
        if (kind == OverlayController::Trails)
            w.window.setSelectedBodies({body});
        const QImage image = w.viewport()->grabFramebuffer();
        QVERIFY2(paintedNear(before, image, probe, colour, 2),
                 qPrintable(QString("no %1 near (%2, %3)").arg(colour.name()).arg(probe.x()).arg(probe.y())));
        QVERIFY(overlays->lastPaintStats().lines + overlays->lastPaintStats().points > 0);
        overlays->clear();
        QVERIFY(!paintedNear(before, w.viewport()->grabFramebuffer(), probe, colour, 2));
    }

    // The legend lists the enabled kinds in the top-left corner; its action hides it.
    void legendFollowsItsAction() {
        Window w;
        OverlayController* overlays = w.overlays();
        overlays->setFrame(w.editFrame());
        const QImage plain = w.viewport()->grabFramebuffer();
        auto legendPixels = [&](const QImage& image) {
            int changed = 0;
            const qreal ratio = image.devicePixelRatio();
            for (int y = 14; y < 40; ++y)
                for (int x = 14; x < 120; ++x)
                    changed +=
                        image.pixel(int(x * ratio), int(y * ratio)) != plain.pixel(int(x * ratio), int(y * ratio)) ? 1
                                                                                                                   : 0;
            return changed;
        };
        overlays->setEnabled(OverlayController::Velocities, true);
        QVERIFY(overlays->legendAction()->isChecked()); // on by default
        QVERIFY(legendPixels(w.viewport()->grabFramebuffer()) > 200);
        overlays->legendAction()->trigger();
        QCOMPARE(legendPixels(w.viewport()->grabFramebuffer()), 0);
        QVERIFY(!QSettings().value(QStringLiteral("overlays/legend")).toBool());
    }

    // Sleeping bodies get the renderer's sleeping flag (washed out); other flags and the colour stay; clear() and
    // switching the overlay off restore exactly the previous look.
    void sleepingFlagsAndRestore() {
        Window w;
        OverlayController* overlays = w.overlays();
        w.window.setSelectedBodies({3});
        const std::vector<rl::ViewportInstance> original = w.viewport()->scene().instances;
        rl::OverlayFrame frame = w.editFrame(0);
        frame.sleeping[3] = 1;
        frame.sleeping[7] = 1;
        overlays->setFrame(frame);
        auto flagsOf = [&](int i) { return w.viewport()->scene().instances[i].flags; };
        for (int i = 0; i < w.bodies(); ++i)
            QCOMPARE(flagsOf(i), original[i].flags); // the overlay is off: nothing changes

        const QPointF p7 = w.pixelOf(w.centre(7) + glm::vec3(0, 0, 0.5f)); // the front face of body 7
        const QColor awake = w.viewport()->grabFramebuffer().pixelColor(p7.toPoint());
        overlays->setEnabled(OverlayController::Sleeping, true);
        for (int i = 0; i < w.bodies(); ++i) {
            const bool asleep = i == 3 || i == 7;
            QCOMPARE(flagsOf(i), original[i].flags | (asleep ? rl::kInstanceSleeping : 0u));
            QCOMPARE(w.viewport()->scene().instances[i].colour, original[i].colour);
        }
        QVERIFY(flagsOf(3) & rl::kInstanceSelected);
        const QColor asleep = w.viewport()->grabFramebuffer().pixelColor(p7.toPoint());
        QVERIFY2(asleep != awake, qPrintable(asleep.name() + " == " + awake.name()));
        QVERIFY(asleep.hsvSaturation() < awake.hsvSaturation()); // washed out

        // Body 7 wakes up, body 2 falls asleep.
        frame.frame = 1;
        frame.sleeping[7] = 0;
        frame.sleeping[2] = 1;
        overlays->setFrame(frame);
        QVERIFY(!(flagsOf(7) & rl::kInstanceSleeping));
        QVERIFY(flagsOf(2) & rl::kInstanceSleeping);

        overlays->clear();
        for (int i = 0; i < w.bodies(); ++i)
            QCOMPARE(flagsOf(i), original[i].flags);

        overlays->setFrame(frame);
        QVERIFY(flagsOf(2) & rl::kInstanceSleeping);
        overlays->setEnabled(OverlayController::Sleeping, false);
        for (int i = 0; i < w.bodies(); ++i)
            QCOMPARE(flagsOf(i), original[i].flags);
    }

    // Live trails keep the frames shown; going back, jumping far ahead or an unknown frame starts them again.
    void trailsFollowConsecutiveFrames_data() {
        QTest::addColumn<QList<int>>("frames");
        QTest::addColumn<int>("length");          // trail length in frames
        QTest::addColumn<QList<int>>("expected"); // the frames the trail holds at the end, oldest first
        QTest::newRow("consecutive") << QList<int>{0, 1, 2, 3, 4} << 120 << QList<int>{0, 1, 2, 3, 4};
        QTest::newRow("capped") << QList<int>{0, 1, 2, 3, 4, 5} << 3 << QList<int>{3, 4, 5};
        // A slow live display skips states: the trail keeps what was shown, over the same span of frames.
        QTest::newRow("skipped states") << QList<int>{0, 1, 3, 6, 10} << 120 << QList<int>{0, 1, 3, 6, 10};
        QTest::newRow("capped with skips") << QList<int>{0, 2, 4, 6, 8} << 5 << QList<int>{4, 6, 8};
        QTest::newRow("jump far ahead") << QList<int>{0, 1, 2, 2 + OverlayController::kTrailMaxGapFrames + 1, 34} << 120
                                        << QList<int>{33, 34};
        QTest::newRow("backwards") << QList<int>{5, 6, 7, 3, 4} << 120 << QList<int>{3, 4};
        QTest::newRow("same frame again") << QList<int>{0, 1, 1, 2} << 120 << QList<int>{0, 1, 2};
        QTest::newRow("restart at 0") << QList<int>{0, 1, 2, 0} << 120 << QList<int>{0};
        QTest::newRow("unknown frames") << QList<int>{-1, -1, -1} << 120 << QList<int>{-1};
    }
    void trailsFollowConsecutiveFrames() {
        QFETCH(QList<int>, frames);
        QFETCH(int, length);
        QFETCH(QList<int>, expected);
        Window w;
        OverlayController* overlays = w.overlays();
        overlays->setEnabled(OverlayController::Trails, true);
        overlays->setTrailLength(length);
        const int body = 4;
        rl::OverlayFrame frame = w.editFrame();
        // The body's x is the frame number, so the trail tells which frames it kept.
        for (int f : frames) {
            frame.frame = f;
            frame.centres[body] = glm::vec3(static_cast<float>(f), 1.0f, 0.0f);
            overlays->setFrame(frame);
        }
        const std::vector<glm::vec3> trail = overlays->trail(body);
        QList<int> got;
        for (const glm::vec3& p : trail)
            got.append(static_cast<int>(p.x));
        QCOMPARE(got, expected);
        overlays->clear();
        QVERIFY(overlays->trail(body).empty());
    }

    // With a bake as the trail source, the trail is the bake's path up to the shown frame, also when scrubbing back.
    void trailsFromBakeFollowScrubbing() {
        Window w;
        OverlayController* overlays = w.overlays();
        overlays->setEnabled(OverlayController::Trails, true);
        overlays->setTrailLength(4);
        std::vector<rl::BakeBodyInfo> infos(static_cast<size_t>(w.bodies()));
        auto bake = std::make_shared<rl::Bake>(infos, 60.0);
        for (int f = 0; f < 10; ++f) {
            bake->addFrame();
            for (int b = 0; b < w.bodies(); ++b) {
                rl::BakeBodyState state;
                state.position = glm::vec3(static_cast<float>(f), static_cast<float>(b), 0.0f);
                bake->setState(static_cast<size_t>(f), static_cast<size_t>(b), state);
            }
        }
        overlays->setTrailSource(bake);
        auto framesOf = [&](int body) {
            QList<int> got;
            for (const glm::vec3& p : overlays->trail(body)) {
                got.append(static_cast<int>(p.x));
                if (static_cast<int>(p.y) != body)
                    return QList<int>{-1};
            }
            return got;
        };
        rl::OverlayFrame frame = w.editFrame(7);
        overlays->setFrame(frame);
        QCOMPARE(framesOf(2), (QList<int>{4, 5, 6, 7}));
        frame.frame = 2; // scrubbed back
        overlays->setFrame(frame);
        QCOMPARE(framesOf(2), (QList<int>{0, 1, 2}));
        frame.frame = 50; // past the end of the bake: up to its last frame
        overlays->setFrame(frame);
        QCOMPARE(framesOf(5), (QList<int>{6, 7, 8, 9}));
        QVERIFY(overlays->trail(w.bodies() + 3).empty()); // no such body in the bake

        // Painted only for the selection.
        w.window.setSelectedBodies({});
        w.viewport()->grabFramebuffer();
        QCOMPARE(overlays->lastPaintStats().lines, 0);
        w.window.setSelectedBodies({2, 5});
        w.viewport()->grabFramebuffer();
        QVERIFY(overlays->lastPaintStats().lines > 0);
    }

    // 5,000 bodies with boxes, velocities and centres on: everything is painted in one pass per layer, off-screen
    // bodies are culled, and the paint time is printed (QElapsedTimer around the painter).
    void manyBodiesPaintInBoundedTime() {
        Window w;
        OverlayController* overlays = w.overlays();
        constexpr int kSide = 50, kLayers = 2; // 50 x 50 x 2 = 5,000 boxes
        rl::ViewportScene scene;
        scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.2f)));
        rl::OverlayFrame frame;
        frame.frame = 0;
        std::mt19937 random(3);
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
        for (int layer = 0; layer < kLayers; ++layer)
            for (int i = 0; i < kSide; ++i)
                for (int j = 0; j < kSide; ++j) {
                    const glm::vec3 p(0.6f * (i - kSide / 2), 0.2f + 0.6f * layer, 0.6f * (j - kSide / 2));
                    rl::ViewportInstance instance;
                    instance.model = glm::translate(glm::mat4(1.0f), p);
                    instance.colour = rl::ScenePresenter::bodyColour(scene.instances.size(), false);
                    scene.instances.push_back(instance);
                    frame.centres.push_back(p);
                    rl::Bounds box;
                    box.extend(p - glm::vec3(0.2f));
                    box.extend(p + glm::vec3(0.2f));
                    frame.aabbs.push_back(box);
                    frame.linearVelocities.push_back(glm::vec3(unit(random), unit(random), unit(random)) * 4.0f);
                    frame.sleeping.push_back(0);
                }
        QCOMPARE(frame.centres.size(), size_t(5000));
        w.viewport()->setScene(scene);
        w.viewport()->frameAll();
        overlays->setEnabled(OverlayController::Aabbs, true);
        overlays->setEnabled(OverlayController::Velocities, true);
        overlays->setEnabled(OverlayController::Centres, true);
        overlays->setFrame(frame);

        // Wall and thread CPU time of the painter (the machine may be loaded: CPU time is the steadier figure).
        auto measure = [&](const char* what) {
            QList<double> wall, cpu;
            for (int i = 0; i < 7; ++i) {
                w.viewport()->grabFramebuffer();
                wall.append(overlays->lastPaintMs());
                cpu.append(overlays->lastPaintCpuMs());
            }
            std::sort(wall.begin(), wall.end());
            std::sort(cpu.begin(), cpu.end());
            qInfo("%s: overlay paint median of 7: %.1f ms wall, %.1f ms CPU (CPU min %.1f, max %.1f); %d lines, %d "
                  "culled",
                  what, wall[3], cpu[3], cpu.first(), cpu.last(), overlays->lastPaintStats().lines,
                  overlays->lastPaintStats().culled);
            return cpu[3];
        };
        // Each layer alone, then all three.
        for (auto kind : {OverlayController::Aabbs, OverlayController::Velocities, OverlayController::Centres}) {
            for (auto other : {OverlayController::Aabbs, OverlayController::Velocities, OverlayController::Centres})
                overlays->setEnabled(other, other == kind);
            measure(qPrintable(overlays->action(kind)->text().remove('&') + QStringLiteral(" only")));
        }
        overlays->setEnabled(OverlayController::Aabbs, true);
        overlays->setEnabled(OverlayController::Velocities, true);
        measure("5000 bodies, all in view");
        const rl::OverlayPaintStats all = overlays->lastPaintStats();
        QCOMPARE(all.culled, 0);
        QVERIFY(all.lines > 5000 * 12); // every box's 12 edges, plus crosses and arrows

        // Close up on one corner: most bodies are off-screen and culled.
        rl::Camera& camera = w.viewport()->camera();
        camera.setTarget(frame.centres.front());
        camera.setDistance(3.0f);
        overlays->legendAction()->setChecked(false);
        measure("5000 bodies, close-up, no legend");
        overlays->legendAction()->setChecked(true);
        const double closeMs = measure("5000 bodies, close-up");
        QVERIFY(overlays->lastPaintStats().culled > 4000);
        QVERIFY(overlays->lastPaintStats().lines < all.lines / 4);
        // Generous bound on a loaded 2-core machine: culled geometry must not cost like drawn geometry.
        QVERIFY2(closeMs < 200.0, qPrintable(QString::number(closeMs)));

        // Trails of a selection of 1,000: drawn for the first kMaxTrailBodies only. Frame 0 was on show when trails
        // were switched on, then 3 more: 4 points, 3 segments each.
        for (auto kind : {OverlayController::Aabbs, OverlayController::Velocities, OverlayController::Centres})
            overlays->setEnabled(kind, false);
        overlays->setEnabled(OverlayController::Trails, true);
        w.viewport()->frameAll();
        QList<int> thousand;
        for (int i = 0; i < 1000; ++i)
            thousand.append(i);
        w.window.setSelectedBodies(thousand);
        for (int f = 1; f <= 3; ++f) {
            frame.frame = f;
            for (glm::vec3& centre : frame.centres)
                centre.y += 0.1f;
            overlays->setFrame(frame);
        }
        QCOMPARE(overlays->trail(999).size(), size_t(4));
        measure("trails, 1000 selected");
        QCOMPARE(overlays->lastPaintStats().lines, OverlayController::kMaxTrailBodies * 3);
        overlays->setEnabled(OverlayController::Trails, false);

        // Every body falls asleep in one frame, then wakes: the flag change for 5,000 instances, timed.
        overlays->setEnabled(OverlayController::Sleeping, true);
        std::fill(frame.sleeping.begin(), frame.sleeping.end(), 1);
        QElapsedTimer timer;
        timer.start();
        overlays->setFrame(frame);
        const double sleepMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        int flagged = 0;
        for (const rl::ViewportInstance& instance : w.viewport()->scene().instances)
            flagged += (instance.flags & rl::kInstanceSleeping) ? 1 : 0;
        QCOMPARE(flagged, 5000);
        timer.restart();
        overlays->clear();
        const double wakeMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
        for (const rl::ViewportInstance& instance : w.viewport()->scene().instances)
            QVERIFY(!(instance.flags & rl::kInstanceSleeping));
        qInfo("5000 bodies fall asleep in one frame: setFrame %.1f ms; clear() %.1f ms", sleepMs, wakeMs);
    }

    // Screenshot with every overlay on, for looking at (saved to the temp directory): a stack toppling to +X, the
    // bodies moved with it, contacts under each cube, the two lowest asleep, the top cube selected with its trail.
    void screenshotWithEveryOverlay() {
        Window w;
        w.window.resize(1400, 900);
        OverlayController* overlays = w.overlays();
        for (int k = 0; k < OverlayController::KindCount; ++k)
            overlays->setEnabled(static_cast<OverlayController::Kind>(k), true);
        w.window.setSelectedBodies({10});
        const std::vector<rl::ViewportInstance> original = w.viewport()->scene().instances;
        rl::Bounds cubes;
        for (int b = 1; b < w.bodies(); ++b)
            cubes.extend(w.viewport()->scene().instanceBounds(b));
        cubes.extend(cubes.max + glm::vec3(3.0f, 0.0f, 1.0f));
        rl::Camera& camera = w.viewport()->camera();
        camera.setYaw(glm::radians(35.0f));
        camera.setPitch(glm::radians(18.0f));
        camera.frame(cubes);
        rl::OverlayFrame frame = w.editFrame();
        std::vector<glm::mat4> models(original.size());
        std::vector<glm::vec3> rest; // edit-pose centres (w.centre follows the transforms set below)
        for (int b = 0; b < w.bodies(); ++b)
            rest.push_back(w.centre(b));
        for (int f = 0; f < 40; ++f) {
            frame.frame = f;
            frame.contacts.clear();
            models[0] = original[0].model;
            for (int b = 1; b < w.bodies(); ++b) {
                const float height = static_cast<float>(b) / 10.0f;
                const float lean = 0.0012f * f * f * height * height;
                const glm::vec3 offset(lean, -0.02f * lean * b, 0.25f * lean);
                frame.centres[b] = rest[b] + offset;
                frame.aabbs[b] = rl::Bounds{};
                frame.aabbs[b].extend(frame.centres[b] - glm::vec3(0.5f));
                frame.aabbs[b].extend(frame.centres[b] + glm::vec3(0.5f));
                frame.linearVelocities[b] = glm::vec3(0.0024f * f * height * height * 60.0f, -0.05f * b, 0.3f);
                models[b] = glm::translate(glm::mat4(1.0f), offset) * original[b].model;
                const glm::vec3 below = frame.centres[b] - glm::vec3(0, 0.5f, 0);
                for (float dx : {-0.45f, 0.45f})
                    for (float dz : {-0.45f, 0.45f})
                        frame.contacts.push_back({below + glm::vec3(dx, 0, dz), glm::vec3(0, 1, 0), 0.002f});
            }
            frame.sleeping[1] = frame.sleeping[2] = 1;
            w.viewport()->setTransforms(models);
            overlays->setFrame(frame);
        }
        const QImage image = rl::test::screenshot(w.window);
        QVERIFY(!image.isNull());
        const QString path = QDir::tempPath() + "/rigidlab_overlays.png";
        QVERIFY(image.save(path));
        qInfo("saved %s", qPrintable(path));
        overlays->menu()->adjustSize();
        QVERIFY(overlays->menu()->grab().save(QDir::tempPath() + "/rigidlab_overlays_menu.png"));
        QVERIFY(hasColourNear(w.viewport()->grabFramebuffer(), w.pixelOf(frame.centres[10]),
                              rl::overlay_colours::centre(), 2, 40));
    }
};

QTEST_MAIN(TestOverlays)
#include "tst_overlays.moc"
