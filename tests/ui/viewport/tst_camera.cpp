// Unit tests of the viewport's orbit camera: framing, unprojection and the mouse moves, without any window or GL.
#include "viewport/Camera.h"

#include <QTest>

#include <glm/gtc/constants.hpp>

Q_DECLARE_METATYPE(glm::vec3)

namespace {

bool insideFrustum(const rl::Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.viewProjection() * glm::vec4(p, 1.0f);
    if (clip.w <= 0.0f)
        return false;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f && std::abs(ndc.z) <= 1.0f;
}

float angleBetween(const glm::vec3& a, const glm::vec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

} // namespace

class TestCamera : public QObject {
    Q_OBJECT
private slots:
    void framingPutsTheBoxInsideTheFrustum_data();
    void framingPutsTheBoxInsideTheFrustum();
    void framingIsTight();
    void unprojectCentreGivesViewDirection_data();
    void unprojectCentreGivesViewDirection();
    void unprojectAndProjectAgree();
    void orbitKeepsTargetAndDistance();
    void pitchIsClampedShortOfThePoles();
    void panMovesThePointUnderTheCursorWithIt();
    void zoomScalesTheDistance();
};

void TestCamera::framingPutsTheBoxInsideTheFrustum_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<float>("yawDegrees");
    QTest::addColumn<float>("pitchDegrees");
    QTest::addColumn<glm::vec3>("min");
    QTest::addColumn<glm::vec3>("max");
    QTest::newRow("unit box, landscape") << 1280 << 800 << 30.0f << 25.0f << glm::vec3(-0.5f) << glm::vec3(0.5f);
    QTest::newRow("long thin box, portrait")
        << 300 << 900 << 80.0f << 10.0f << glm::vec3(-20.0f, 0.0f, -0.1f) << glm::vec3(20.0f, 0.2f, 0.1f);
    QTest::newRow("tall box, from below")
        << 640 << 480 << -135.0f << -60.0f << glm::vec3(3.0f, -1.0f, 7.0f) << glm::vec3(4.0f, 30.0f, 8.0f);
    QTest::newRow("tiny part, top view") << 1280 << 800 << 0.0f << 89.0f << glm::vec3(0.001f)
                                         << glm::vec3(0.011f, 0.004f, 0.02f);
    QTest::newRow("field far from origin")
        << 1000 << 1000 << 170.0f << 45.0f << glm::vec3(1000.0f, 0.0f, -500.0f) << glm::vec3(1300.0f, 5.0f, -100.0f);
}

void TestCamera::framingPutsTheBoxInsideTheFrustum() {
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(float, yawDegrees);
    QFETCH(float, pitchDegrees);
    QFETCH(glm::vec3, min);
    QFETCH(glm::vec3, max);
    rl::Camera camera;
    camera.setViewportSize(width, height);
    camera.setYaw(glm::radians(yawDegrees));
    camera.setPitch(glm::radians(pitchDegrees));
    rl::Bounds box;
    box.extend(min);
    box.extend(max);
    camera.frame(box);
    QVERIFY(glm::length(camera.target() - box.centre()) < 1e-4f * (1.0f + glm::length(box.centre())));
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? max.x : min.x, (corner & 2) ? max.y : min.y, (corner & 4) ? max.z : min.z);
        QVERIFY2(insideFrustum(camera, p), qPrintable(QStringLiteral("corner %1 is outside").arg(corner)));
    }
}

void TestCamera::framingIsTight() {
    // Framing must not simply back off very far: the box's bounding sphere fills most of the narrower field of view.
    rl::Camera camera;
    camera.setViewportSize(1280, 800);
    rl::Bounds box;
    box.extend(glm::vec3(-1.0f));
    box.extend(glm::vec3(1.0f));
    camera.frame(box);
    const float radius = std::sqrt(3.0f);
    const float halfAngle = std::asin(radius / camera.distance());
    QVERIFY(halfAngle > 0.9f * 0.5f * camera.fovY());
    QVERIFY(halfAngle <= 0.5f * camera.fovY());
}

void TestCamera::unprojectCentreGivesViewDirection_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<float>("yawDegrees");
    QTest::addColumn<float>("pitchDegrees");
    QTest::newRow("default") << 1280 << 800 << 30.0f << 25.0f;
    QTest::newRow("odd size, looking up") << 333 << 777 << -100.0f << -40.0f;
    QTest::newRow("front") << 640 << 480 << 0.0f << 0.0f;
}

void TestCamera::unprojectCentreGivesViewDirection() {
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(float, yawDegrees);
    QFETCH(float, pitchDegrees);
    rl::Camera camera;
    camera.setViewportSize(width, height);
    camera.setTarget(glm::vec3(2.0f, 1.0f, -3.0f));
    camera.setDistance(7.5f);
    camera.setYaw(glm::radians(yawDegrees));
    camera.setPitch(glm::radians(pitchDegrees));
    const rl::ViewRay ray = camera.unproject(0.5f * width, 0.5f * height);
    QVERIFY(glm::length(ray.origin - camera.eye()) < 1e-4f);
    QVERIFY(std::abs(glm::length(ray.direction) - 1.0f) < 1e-5f);
    QVERIFY2(angleBetween(ray.direction, camera.forward()) < 1e-3f, "centre ray is not the view direction");
    QVERIFY(angleBetween(ray.direction, camera.target() - camera.eye()) < 1e-3f);
}

void TestCamera::unprojectAndProjectAgree() {
    rl::Camera camera;
    camera.setViewportSize(1280, 800);
    camera.setTarget(glm::vec3(0.0f, 0.5f, 0.0f));
    const float pixels[][2] = {{0.0f, 0.0f}, {1279.0f, 799.0f}, {100.0f, 700.0f}, {640.0f, 10.0f}};
    for (const auto& px : pixels) {
        const rl::ViewRay ray = camera.unproject(px[0], px[1]);
        const glm::vec3 point = ray.origin + 5.0f * ray.direction;
        const glm::vec3 back = camera.project(point);
        QVERIFY2(
            std::abs(back.x - px[0]) < 0.05f && std::abs(back.y - px[1]) < 0.05f,
            qPrintable(QStringLiteral("(%1, %2) came back as (%3, %4)").arg(px[0]).arg(px[1]).arg(back.x).arg(back.y)));
        QVERIFY(back.z > -1.0f && back.z < 1.0f);
    }
    // A pixel right of centre gives a ray leaning to the camera's right.
    const rl::ViewRay right = camera.unproject(1000.0f, 400.0f);
    QVERIFY(glm::dot(right.direction, camera.right()) > 0.1f);
    const rl::ViewRay high = camera.unproject(640.0f, 50.0f);
    QVERIFY(glm::dot(high.direction, camera.up()) > 0.1f);
}

void TestCamera::orbitKeepsTargetAndDistance() {
    rl::Camera camera;
    camera.setTarget(glm::vec3(1.0f, 2.0f, 3.0f));
    camera.setDistance(4.0f);
    const float yaw = camera.yaw();
    camera.orbit(120.0f, -35.0f);
    QCOMPARE(camera.target(), glm::vec3(1.0f, 2.0f, 3.0f));
    QVERIFY(std::abs(glm::length(camera.eye() - camera.target()) - 4.0f) < 1e-4f);
    QVERIFY(camera.yaw() < yaw); // dragging right swings the camera to the left
}

void TestCamera::pitchIsClampedShortOfThePoles() {
    rl::Camera camera;
    camera.orbit(0.0f, 1e5f);
    QVERIFY(camera.pitch() < glm::half_pi<float>());
    QVERIFY(camera.pitch() > glm::radians(89.0f));
    // The view stays well defined at the clamp: right and up remain orthonormal.
    QVERIFY(std::abs(glm::length(camera.right()) - 1.0f) < 1e-4f);
    QVERIFY(std::abs(glm::dot(camera.right(), camera.forward())) < 1e-4f);
    camera.orbit(0.0f, -2e5f);
    QVERIFY(camera.pitch() > -glm::half_pi<float>());
}

void TestCamera::panMovesThePointUnderTheCursorWithIt() {
    rl::Camera camera;
    camera.setViewportSize(800, 600);
    camera.setDistance(12.0f);
    const glm::vec3 point = camera.target(); // projects to the centre pixel
    camera.pan(50.0f, -30.0f);
    const glm::vec3 after = camera.project(point);
    QVERIFY2(std::abs(after.x - 450.0f) < 0.5f && std::abs(after.y - 270.0f) < 0.5f,
             qPrintable(QStringLiteral("target went to (%1, %2)").arg(after.x).arg(after.y)));
}

void TestCamera::zoomScalesTheDistance() {
    rl::Camera camera;
    camera.setDistance(10.0f);
    camera.zoom(0.5f);
    QCOMPARE(camera.distance(), 5.0f);
    camera.zoom(0.0f); // ignored, never a zero or negative distance
    QCOMPARE(camera.distance(), 5.0f);
    camera.zoom(1e-12f);
    QVERIFY(camera.distance() > 0.0f);
    QVERIFY(camera.nearPlane() > 0.0f && camera.nearPlane() < camera.distance());
}

QTEST_APPLESS_MAIN(TestCamera)
#include "tst_camera.moc"
