// The viewport's transform gizmo on a real GL context (xcb under Xvfb, llvmpipe): dragging the move arrows, plane
// squares and rotation rings with the mouse, Ctrl snapping, cancelling with Escape and the right button, hover
// highlight, the pixels it draws, and the 5,000-body frame time with the gizmo shown.
#include "ui/GuiTestSetup.h"
#include "viewport/Viewport.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <optional>
#include <random>

Q_DECLARE_METATYPE(rl::RigidDelta)

namespace {

// A grey floor anchor and two yellow boxes: no body shares the gizmo's red, green or blue.
rl::ViewportScene makeScene() {
    rl::ViewportScene scene;
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(5.0f, 0.25f, 5.0f)));
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.5f)));
    rl::ViewportInstance floor;
    floor.meshIndex = 0;
    floor.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.25f, 0.0f));
    floor.flags = rl::kInstanceAnchor;
    scene.instances.push_back(floor);
    for (int i = 0; i < 2; ++i) {
        rl::ViewportInstance box;
        box.meshIndex = 1;
        box.model = glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f + 2.0f * i, 0.5f, 0.0f));
        box.colour = glm::vec3(0.9f, 0.8f, 0.1f); // yellow: none of the gizmo's colours
        scene.instances.push_back(box);
    }
    return scene;
}

void sendMouse(QWidget* widget, QEvent::Type type, const QPointF& position, Qt::MouseButton button,
               Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QMouseEvent event(type, position, widget->mapToGlobal(position), button, buttons, modifiers);
    QApplication::sendEvent(widget, &event);
}

// A left drag in a few steps, with the given modifiers held throughout.
void drag(QWidget* widget, const QPointF& from, const QPointF& to, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    sendMouse(widget, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton, modifiers);
    for (int step = 1; step <= 4; ++step)
        sendMouse(widget, QEvent::MouseMove, from + (to - from) * (step / 4.0), Qt::NoButton, Qt::LeftButton,
                  modifiers);
    sendMouse(widget, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton, modifiers);
}

// Where the line centre + axis * s comes closest to the ray through a pixel: s (the gizmo's own construction).
double axisParameter(const rl::Camera& camera, const glm::dvec3& centre, const glm::dvec3& axis, const QPointF& at) {
    const rl::ViewRay ray = camera.unproject(static_cast<float>(at.x()), static_cast<float>(at.y()));
    const glm::dvec3 o(ray.origin);
    const glm::dvec3 d = glm::normalize(glm::dvec3(ray.direction));
    const double b = glm::dot(axis, d);
    const glm::dvec3 w = centre - o;
    return (b * glm::dot(d, w) - glm::dot(axis, w)) / (1.0 - b * b);
}

glm::dvec3 planeHit(const rl::Camera& camera, const glm::dvec3& point, const glm::dvec3& normal, const QPointF& at) {
    const rl::ViewRay ray = camera.unproject(static_cast<float>(at.x()), static_cast<float>(at.y()));
    const glm::dvec3 o(ray.origin);
    const glm::dvec3 d = glm::normalize(glm::dvec3(ray.direction));
    return o + d * (glm::dot(point - o, normal) / glm::dot(d, normal));
}

QPointF pixelOf(const rl::Camera& camera, const glm::dvec3& world) {
    const glm::vec3 p = camera.project(glm::vec3(world));
    return {p.x, p.y};
}

int countNear(const QImage& image, const QColor& colour, int tolerance) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += std::abs(c.red() - colour.red()) <= tolerance &&
                     std::abs(c.green() - colour.green()) <= tolerance &&
                     std::abs(c.blue() - colour.blue()) <= tolerance;
        }
    return count;
}

bool isMultipleOf(double value, double step) {
    return std::abs(value / step - std::round(value / step)) < 1e-9;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

} // namespace

class TestGizmo : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void init();
    void cleanup();
    void toolsShowTheGizmoOnlyWithASelection();
    void moveArrowDragsAlongItsAxis_data();
    void moveArrowDragsAlongItsAxis();
    void ctrlSnapsMovesToTenthsOfAMetre();
    void planeSquareMovesInItsPlane();
    void multiSelectionMovesTogether();
    void rotateRingTurnsAboutItsAxis_data();
    void rotateRingTurnsAboutItsAxis();
    void ctrlSnapsRotationsToFifteenDegrees();
    void escapeAndRightButtonCancel();
    void previewIsDrawnWhileDragging();
    void hoverHighlightsTheHandle();
    void gizmoIsDrawnInTheAxisColours();
    void modalGrabFollowsTheMouse();
    void fiveThousandBodiesWithGizmo();

private:
    void show(int width = 800, int height = 600);
    QImage grab() { return m_viewport->grabFramebuffer().convertToFormat(QImage::Format_RGB32); }
    glm::vec3 translationOf(int instance) const { return glm::vec3(m_viewport->scene().instances[instance].model[3]); }

    std::unique_ptr<rl::Viewport> m_viewport;
};

void TestGizmo::init() {
    qRegisterMetaType<rl::RigidDelta>();
    m_viewport = std::make_unique<rl::Viewport>();
    m_viewport->setScene(makeScene());
}

void TestGizmo::cleanup() {
    m_viewport.reset();
}

void TestGizmo::show(int width, int height) {
    m_viewport->resize(width, height);
    m_viewport->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_viewport.get()));
    m_viewport->grabFramebuffer();
    QVERIFY(m_viewport->isRendererReady());
    m_viewport->camera().setYaw(glm::radians(30.0f));
    m_viewport->camera().setPitch(glm::radians(25.0f));
    m_viewport->frameAll();
}

void TestGizmo::toolsShowTheGizmoOnlyWithASelection() {
    show();
    QSignalSpy toolChanged(m_viewport.get(), &rl::Viewport::toolChanged);
    QCOMPARE(m_viewport->tool(), rl::GizmoTool::Select);
    m_viewport->setSelection({1});
    QVERIFY(!m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveX)); // Select tool: no gizmo
    m_viewport->setTool(rl::GizmoTool::Move);
    QCOMPARE(toolChanged.count(), 1);
    QVERIFY(m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveX));
    QVERIFY(!m_viewport->gizmoHandlePosition(rl::GizmoHandle::RotateX));
    m_viewport->setTool(rl::GizmoTool::Rotate);
    QVERIFY(m_viewport->gizmoHandlePosition(rl::GizmoHandle::RotateY));
    QVERIFY(!m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveX));
    m_viewport->setSelection({});
    QVERIFY(!m_viewport->gizmoHandlePosition(rl::GizmoHandle::RotateY));
    // The gizmo sits at the centre of the selection's box.
    m_viewport->setSelection({1, 2});
    QVERIFY(glm::length(*m_viewport->selectionCentre() - glm::vec3(0.0f, 0.5f, 0.0f)) < 1e-5f);
}

void TestGizmo::moveArrowDragsAlongItsAxis_data() {
    QTest::addColumn<int>("axis");
    QTest::addColumn<QPointF>("mouseDelta");
    QTest::newRow("x") << 0 << QPointF(70, 25);
    QTest::newRow("y") << 1 << QPointF(10, -60);
    QTest::newRow("z") << 2 << QPointF(-50, 30);
}

void TestGizmo::moveArrowDragsAlongItsAxis() {
    QFETCH(int, axis);
    QFETCH(QPointF, mouseDelta);
    show();
    m_viewport->setSelection({1});
    m_viewport->setTool(rl::GizmoTool::Move);
    const auto handle = static_cast<rl::GizmoHandle>(static_cast<int>(rl::GizmoHandle::MoveX) + axis);
    const std::optional<QPointF> from = m_viewport->gizmoHandlePosition(handle);
    QVERIFY(from);
    const glm::vec3 before = translationOf(1);
    const glm::dvec3 centre(*m_viewport->selectionCentre());
    glm::dvec3 direction(0.0);
    direction[axis] = 1.0;
    const QPointF to = *from + mouseDelta;
    const double expected = axisParameter(m_viewport->camera(), centre, direction, to) -
                            axisParameter(m_viewport->camera(), centre, direction, *from);
    QVERIFY2(std::abs(expected) > 0.2, qPrintable(QString::number(expected)));

    QSignalSpy started(m_viewport.get(), &rl::Viewport::transformStarted);
    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    drag(m_viewport.get(), *from, to);
    QCOMPARE(started.count(), 1);
    QCOMPARE(finished.count(), 1);
    QCOMPARE(finished.first().at(0).value<QList<int>>(), QList<int>{1});
    const auto delta = finished.first().at(1).value<rl::RigidDelta>();
    // Along the axis only: the other two components are exactly zero, and no rotation.
    for (int k = 0; k < 3; ++k)
        if (k != axis)
            QCOMPARE(delta.translation[k], 0.0);
    QVERIFY(delta.rotation == glm::dquat(1.0, 0.0, 0.0, 0.0));
    QVERIFY2(std::abs(delta.translation[axis] - expected) < 1e-4 * std::max(1.0, std::abs(expected)),
             qPrintable(QStringLiteral("moved %1, expected %2").arg(delta.translation[axis]).arg(expected)));
    // The preview left the box where the drag put it.
    const glm::vec3 after = translationOf(1);
    for (int k = 0; k < 3; ++k)
        QVERIFY(std::abs(after[k] - before[k] - static_cast<float>(delta.translation[k])) < 1e-4f);
    QVERIFY(!m_viewport->isTransforming());
}

void TestGizmo::ctrlSnapsMovesToTenthsOfAMetre() {
    show();
    m_viewport->setSelection({1});
    m_viewport->setTool(rl::GizmoTool::Move);
    const QPointF from = *m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveX);
    const QPointF to = from + QPointF(53, 17);
    const glm::dvec3 centre(*m_viewport->selectionCentre());
    const double free = axisParameter(m_viewport->camera(), centre, {1, 0, 0}, to) -
                        axisParameter(m_viewport->camera(), centre, {1, 0, 0}, from);
    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    drag(m_viewport.get(), from, to, Qt::ControlModifier);
    QCOMPARE(finished.count(), 1);
    const auto delta = finished.first().at(1).value<rl::RigidDelta>();
    QVERIFY2(isMultipleOf(delta.translation.x, 0.1), qPrintable(QString::number(delta.translation.x, 'g', 17)));
    QCOMPARE(std::round(delta.translation.x / 0.1), std::round(free / 0.1));
    QCOMPARE(delta.translation.y, 0.0);
    QCOMPARE(delta.translation.z, 0.0);
}

void TestGizmo::planeSquareMovesInItsPlane() {
    show();
    m_viewport->setSelection({2});
    m_viewport->setTool(rl::GizmoTool::Move);
    const std::optional<QPointF> from = m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveXZ);
    QVERIFY(from);
    const glm::dvec3 centre(*m_viewport->selectionCentre());
    const QPointF to = *from + QPointF(-40, 30);
    const glm::dvec3 expected = planeHit(m_viewport->camera(), centre, {0, 1, 0}, to) -
                                planeHit(m_viewport->camera(), centre, {0, 1, 0}, *from);
    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    drag(m_viewport.get(), *from, to);
    QCOMPARE(finished.count(), 1);
    const auto delta = finished.first().at(1).value<rl::RigidDelta>();
    QCOMPARE(delta.translation.y, 0.0); // the floor plane: height kept exactly
    QVERIFY(std::abs(delta.translation.x - expected.x) < 1e-4);
    QVERIFY(std::abs(delta.translation.z - expected.z) < 1e-4);
    QVERIFY(std::abs(delta.translation.x) > 0.1 || std::abs(delta.translation.z) > 0.1);
}

void TestGizmo::multiSelectionMovesTogether() {
    show();
    m_viewport->setSelection({1, 2});
    m_viewport->setTool(rl::GizmoTool::Move);
    const glm::vec3 a = translationOf(1), b = translationOf(2), floor = translationOf(0);
    const QPointF from = *m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveY);
    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    drag(m_viewport.get(), from, from + QPointF(0, -50));
    QCOMPARE(finished.count(), 1);
    QCOMPARE(finished.first().at(0).value<QList<int>>(), (QList<int>{1, 2}));
    const float dy = static_cast<float>(finished.first().at(1).value<rl::RigidDelta>().translation.y);
    QVERIFY(dy > 0.1f);
    QVERIFY(std::abs(translationOf(1).y - a.y - dy) < 1e-4f);
    QVERIFY(std::abs(translationOf(2).y - b.y - dy) < 1e-4f);
    QCOMPARE(translationOf(0), floor); // not selected, not moved
    // The gizmo followed the selection.
    QVERIFY(std::abs(m_viewport->selectionCentre()->y - (0.5f + dy)) < 1e-4f);
}

void TestGizmo::rotateRingTurnsAboutItsAxis_data() {
    QTest::addColumn<int>("axis");
    QTest::addColumn<double>("degrees");
    QTest::newRow("y +40") << 1 << 40.0;
    QTest::newRow("y -70") << 1 << -70.0;
    QTest::newRow("x +30") << 0 << 30.0;
    QTest::newRow("z -50") << 2 << -50.0;
}

void TestGizmo::rotateRingTurnsAboutItsAxis() {
    QFETCH(int, axis);
    QFETCH(double, degrees);
    show();
    m_viewport->setSelection({1, 2});
    m_viewport->setTool(rl::GizmoTool::Rotate);
    const auto handle = static_cast<rl::GizmoHandle>(static_cast<int>(rl::GizmoHandle::RotateX) + axis);
    const std::optional<QPointF> from = m_viewport->gizmoHandlePosition(handle);
    QVERIFY(from);
    const rl::Camera& camera = m_viewport->camera();
    const glm::dvec3 centre(*m_viewport->selectionCentre());
    glm::dvec3 a(0.0);
    a[axis] = 1.0;
    // The target pixel: the press point turned by `degrees` about the axis, in the ring's plane.
    const glm::dvec3 press = planeHit(camera, centre, a, *from);
    const glm::dvec3 turned = centre + glm::angleAxis(glm::radians(degrees), a) * (press - centre);
    const QPointF to = pixelOf(camera, turned);
    const glm::vec3 boxBefore = translationOf(1);

    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    drag(m_viewport.get(), *from, to);
    QCOMPARE(finished.count(), 1);
    const auto delta = finished.first().at(1).value<rl::RigidDelta>();
    QCOMPARE(delta.translation, glm::dvec3(0.0));
    QVERIFY(glm::length(delta.pivot - centre) < 1e-6);
    // A turn about this axis only: the quaternion's other components vanish, the angle is the one dragged.
    const glm::dquat q = delta.rotation;
    for (int k = 0; k < 3; ++k)
        if (k != axis)
            QVERIFY2(std::abs(q[k]) < 1e-9, qPrintable(QString::number(q[k])));
    const double angle = glm::degrees(2.0 * std::atan2(q[axis], q.w));
    QVERIFY2(std::abs(angle - degrees) < 1.0, qPrintable(QStringLiteral("turned %1 degrees").arg(angle)));
    // The boxes turned about the selection centre: box 1 is where the rotation takes it.
    const glm::dvec3 expected = centre + q * (glm::dvec3(boxBefore) - centre);
    QVERIFY(glm::length(glm::dvec3(translationOf(1)) - expected) < 1e-4);
}

void TestGizmo::ctrlSnapsRotationsToFifteenDegrees() {
    show();
    m_viewport->setSelection({1});
    m_viewport->setTool(rl::GizmoTool::Rotate);
    const QPointF from = *m_viewport->gizmoHandlePosition(rl::GizmoHandle::RotateY);
    const rl::Camera& camera = m_viewport->camera();
    const glm::dvec3 centre(*m_viewport->selectionCentre());
    const glm::dvec3 press = planeHit(camera, centre, {0, 1, 0}, from);
    const QPointF to =
        pixelOf(camera, centre + glm::angleAxis(glm::radians(52.0), glm::dvec3(0, 1, 0)) * (press - centre));
    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    drag(m_viewport.get(), from, to, Qt::ControlModifier);
    QCOMPARE(finished.count(), 1);
    const glm::dquat q = finished.first().at(1).value<rl::RigidDelta>().rotation;
    const double angle = glm::degrees(2.0 * std::atan2(q.y, q.w));
    QVERIFY2(std::abs(angle - 45.0) < 1e-9, qPrintable(QString::number(angle, 'g', 17)));
}

void TestGizmo::escapeAndRightButtonCancel() {
    show();
    m_viewport->setSelection({1});
    m_viewport->setTool(rl::GizmoTool::Move);
    const glm::mat4 before = m_viewport->scene().instances[1].model;
    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    QSignalSpy cancelled(m_viewport.get(), &rl::Viewport::transformCancelled);
    const QPointF from = *m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveX);
    const QPointF to = from + QPointF(60, 0);

    sendMouse(m_viewport.get(), QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    sendMouse(m_viewport.get(), QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    QVERIFY(m_viewport->isTransforming());
    QVERIFY(m_viewport->scene().instances[1].model != before); // previewed live
    QTest::keyClick(m_viewport.get(), Qt::Key_Escape);
    QVERIFY(!m_viewport->isTransforming());
    QCOMPARE(m_viewport->scene().instances[1].model, before);
    sendMouse(m_viewport.get(), QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    QCOMPARE(cancelled.count(), 1);

    sendMouse(m_viewport.get(), QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    sendMouse(m_viewport.get(), QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    sendMouse(m_viewport.get(), QEvent::MouseButtonPress, to, Qt::RightButton, Qt::LeftButton | Qt::RightButton);
    QCOMPARE(m_viewport->scene().instances[1].model, before);
    sendMouse(m_viewport.get(), QEvent::MouseButtonRelease, to, Qt::RightButton, Qt::LeftButton);
    sendMouse(m_viewport.get(), QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
    QCOMPARE(cancelled.count(), 2);
    QCOMPARE(finished.count(), 0);
    // A release on the spot (no motion) is not an edit either.
    sendMouse(m_viewport.get(), QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    sendMouse(m_viewport.get(), QEvent::MouseButtonRelease, from, Qt::LeftButton, Qt::NoButton);
    QCOMPARE(finished.count(), 0);
}

void TestGizmo::previewIsDrawnWhileDragging() {
    show();
    m_viewport->setSelection({1});
    m_viewport->setTool(rl::GizmoTool::Move);
    auto isYellow = [](const QColor& c) { return c.red() > c.blue() + 60 && c.green() > c.blue() + 60; };
    // A point on the box's front face, away from the gizmo's handles (which sit on the box centre's pixel).
    const glm::vec3 face = translationOf(1) + glm::vec3(0.0f, -0.3f, 0.5f);
    const QPointF before = pixelOf(m_viewport->camera(), glm::dvec3(face));
    QVERIFY(isYellow(grab().pixelColor(before.toPoint())));
    const QPointF from = *m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveY);
    sendMouse(m_viewport.get(), QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    sendMouse(m_viewport.get(), QEvent::MouseMove, from + QPointF(0, -120), Qt::NoButton, Qt::LeftButton);
    // Only the moved instance was re-uploaded; the frame shows it at its new place and not at the old one.
    const QImage during = grab();
    during.save(QDir::tempPath() + QStringLiteral("/rl_gizmo_drag.png"));
    const glm::vec3 lifted = translationOf(1) + glm::vec3(0.0f, -0.3f, 0.5f);
    QVERIFY(lifted.y > face.y + 0.5f);
    QVERIFY(!isYellow(during.pixelColor(before.toPoint())));
    QVERIFY(isYellow(during.pixelColor(pixelOf(m_viewport->camera(), glm::dvec3(lifted)).toPoint())));
    QTest::keyClick(m_viewport.get(), Qt::Key_Escape);
    QVERIFY(isYellow(grab().pixelColor(before.toPoint())));
    sendMouse(m_viewport.get(), QEvent::MouseButtonRelease, from, Qt::LeftButton, Qt::NoButton);
}

void TestGizmo::hoverHighlightsTheHandle() {
    show();
    m_viewport->setSelection({1});
    m_viewport->setTool(rl::GizmoTool::Move);
    const QPointF handle = *m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveZ);
    const QImage plain = grab();
    sendMouse(m_viewport.get(), QEvent::MouseMove, handle, Qt::NoButton, Qt::NoButton);
    QCOMPARE(m_viewport->hoveredHandle(), rl::GizmoHandle::MoveZ);
    const QImage hovered = grab();
    hovered.save(QDir::tempPath() + QStringLiteral("/rl_gizmo_hover.png"));
    // The highlighted arrow is lighter and thicker: more pixels of the lighter blue, and the image changed only
    // near the handle.
    const QColor lighter = QColor(64, 128, 240).lighter(135);
    QVERIFY2(
        countNear(hovered, lighter, 25) > countNear(plain, lighter, 25) + 20,
        qPrintable(QStringLiteral("%1 vs %2").arg(countNear(hovered, lighter, 25)).arg(countNear(plain, lighter, 25))));
    sendMouse(m_viewport.get(), QEvent::MouseMove, QPointF(5, 5), Qt::NoButton, Qt::NoButton);
    QCOMPARE(m_viewport->hoveredHandle(), rl::GizmoHandle::None);
}

void TestGizmo::gizmoIsDrawnInTheAxisColours() {
    show();
    m_viewport->setSelection({1});
    const QImage none = grab();
    m_viewport->setTool(rl::GizmoTool::Move);
    const QImage move = grab();
    move.save(QDir::tempPath() + QStringLiteral("/rl_gizmo_move.png"));
    m_viewport->setTool(rl::GizmoTool::Rotate);
    const QImage rotate = grab();
    rotate.save(QDir::tempPath() + QStringLiteral("/rl_gizmo_rotate.png"));
    // The axis indicator in the corner has the same colours, so count what the gizmo adds.
    const QColor colours[] = {QColor(232, 64, 80), QColor(120, 200, 40), QColor(64, 128, 240)};
    for (const QColor& colour : colours) {
        const int base = countNear(none, colour, 30);
        const int withMove = countNear(move, colour, 30);
        const int withRotate = countNear(rotate, colour, 30);
        QVERIFY2(
            withMove > base + 150 && withRotate > base + 300,
            qPrintable(QStringLiteral("%1: %2 / %3 / %4").arg(colour.name()).arg(base).arg(withMove).arg(withRotate)));
    }
    // Drawn over the bodies, not hidden by them: the selected box's centre pixel lies under the view disc's ring
    // or near it, and the arrows' pixels sit around the projected centre.
    const QPointF centre = pixelOf(m_viewport->camera(), glm::dvec3(*m_viewport->selectionCentre()));
    const QRect around(QPoint(int(centre.x()) - 120, int(centre.y()) - 120), QSize(240, 240));
    QVERIFY(countNear(move.copy(around), colours[0], 30) > 100);
}

void TestGizmo::modalGrabFollowsTheMouse() {
    show();
    m_viewport->setSelection({1});
    QSignalSpy finished(m_viewport.get(), &rl::Viewport::transformFinished);
    QCursor::setPos(m_viewport->mapToGlobal(QPoint(400, 300)));
    QVERIFY(m_viewport->startModalTransform(rl::GizmoTool::Move));
    QVERIFY(m_viewport->isTransforming());
    const glm::vec3 before = translationOf(1);
    const QPointF start = m_viewport->mapFromGlobal(QCursor::pos());
    sendMouse(m_viewport.get(), QEvent::MouseMove, start + QPointF(40, 0), Qt::NoButton, Qt::NoButton);
    QVERIFY(translationOf(1) != before);
    sendMouse(m_viewport.get(), QEvent::MouseButtonPress, start + QPointF(40, 0), Qt::LeftButton, Qt::LeftButton);
    sendMouse(m_viewport.get(), QEvent::MouseButtonRelease, start + QPointF(40, 0), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(finished.count(), 1);
    // Moving right on screen moves along the camera's right vector, in the view plane.
    const glm::dvec3 t = finished.first().at(1).value<rl::RigidDelta>().translation;
    QVERIFY(glm::dot(t, glm::dvec3(m_viewport->camera().right())) > 0.1);
    QVERIFY(std::abs(glm::dot(t, glm::dvec3(m_viewport->camera().forward()))) < 1e-6);
    QVERIFY(!m_viewport->isTransforming());
    // R then Escape: nothing happens.
    QVERIFY(m_viewport->startModalTransform(rl::GizmoTool::Rotate));
    const glm::mat4 model = m_viewport->scene().instances[1].model;
    sendMouse(m_viewport.get(), QEvent::MouseMove, start + QPointF(10, 60), Qt::NoButton, Qt::NoButton);
    QTest::keyClick(m_viewport.get(), Qt::Key_Escape);
    QCOMPARE(m_viewport->scene().instances[1].model, model);
    QCOMPARE(finished.count(), 1);
}

void TestGizmo::fiveThousandBodiesWithGizmo() {
    // The scene of tst_viewport's measurement: 5,000 boxes, with three selected and the move gizmo shown.
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
    for (int i = 0; i < 4999; ++i) {
        rl::ViewportInstance box;
        box.meshIndex = 1 + i % 3;
        box.model = rl::instanceTransform(
            glm::dvec3(1.2 * (i % 50 - 24.5), 0.6 + 1.1 * (i / 2500), 1.2 * ((i / 50) % 50 - 24.5)),
            glm::normalize(glm::dquat(1.0, unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5)));
        box.colour = glm::vec3(0.25f + 0.7f * unit(random), 0.25f + 0.7f * unit(random), 0.25f + 0.7f * unit(random));
        scene.instances.push_back(box);
    }
    m_viewport->setScene(std::move(scene));
    m_viewport->setSelection({1275, 1276, 1277});
    m_viewport->setTool(rl::GizmoTool::Move);
    m_viewport->resize(1280, 800);
    m_viewport->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_viewport.get()));
    m_viewport->grabFramebuffer();
    m_viewport->camera().setYaw(glm::radians(35.0f));
    m_viewport->camera().setPitch(glm::radians(30.0f));
    m_viewport->frameAll();
    m_viewport->camera().zoom(0.75f);
    grab().save(QDir::tempPath() + QStringLiteral("/rl_gizmo_5000.png"));

    // Frames as in tst_viewport: paintGL's own time (glFinish included), wall time per frame and process CPU time
    // per frame; once orbiting with the gizmo shown, once dragging the X arrow (live preview every frame).
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
        return std::array<double, 3>{median(paint), static_cast<double>(wall.nsecsElapsed()) * 1e-6 / count,
                                     1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC / count};
    };
    const int kFrames = 12;
    // The same orbit without the gizmo (Select tool) in the same run, so the gizmo's share can be read off.
    m_viewport->setTool(rl::GizmoTool::Select);
    const auto plain = measure(kFrames, [this](int) { m_viewport->camera().orbit(3.0f, 0.0f); });
    m_viewport->setTool(rl::GizmoTool::Move);
    const auto orbiting = measure(kFrames, [this](int) { m_viewport->camera().orbit(3.0f, 0.0f); });
    const std::optional<QPointF> handle = m_viewport->gizmoHandlePosition(rl::GizmoHandle::MoveX);
    QVERIFY(handle);
    sendMouse(m_viewport.get(), QEvent::MouseButtonPress, *handle, Qt::LeftButton, Qt::LeftButton);
    QVERIFY(m_viewport->isTransforming());
    const auto dragging = measure(kFrames, [&](int f) {
        sendMouse(m_viewport.get(), QEvent::MouseMove, *handle + QPointF(2.0 * (f % 10), 0), Qt::NoButton,
                  Qt::LeftButton);
    });
    QVERIFY(m_viewport->isTransforming());
    sendMouse(m_viewport.get(), QEvent::MouseButtonRelease, *handle, Qt::LeftButton, Qt::NoButton);
    QFile loadFile(QStringLiteral("/proc/loadavg"));
    const QByteArray load = loadFile.open(QIODevice::ReadOnly) ? loadFile.readLine().trimmed() : QByteArray("?");
    qInfo("5000 instances at %dx%d with the move gizmo, %d frames each, load average %s", m_viewport->width(),
          m_viewport->height(), kFrames, load.constData());
    qInfo("  orbiting without the gizmo: paintGL median %.1f ms, wall %.1f ms/frame, process CPU %.1f ms/frame",
          plain[0], plain[1], plain[2]);
    qInfo("  orbiting with the gizmo: paintGL median %.1f ms, wall %.1f ms/frame, process CPU %.1f ms/frame",
          orbiting[0], orbiting[1], orbiting[2]);
    qInfo("  dragging the X arrow: paintGL median %.1f ms, wall %.1f ms/frame, process CPU %.1f ms/frame", dragging[0],
          dragging[1], dragging[2]);
    QVERIFY(orbiting[0] > 0.0 && dragging[0] > 0.0);
}

QTEST_MAIN(TestGizmo)
#include "tst_gizmo.moc"
