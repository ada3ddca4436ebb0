// Unit tests of the viewport's scene data: model matrices, instance bounds, the fallback pick and the mesh helpers.
#include "viewport/ViewportScene.h"

#include <QTest>

#include <glm/gtc/matrix_transform.hpp>

#include <map>

namespace {

// Every directed edge has its twin and the signed volume is positive: closed and wound outwards.
void verifyClosedAndOutward(const rl::ViewportMesh& mesh, float expectedVolume, float tolerance) {
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    float volume = 0.0f;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k)
            ++edges[{t[k], t[(k + 1) % 3]}];
        volume += glm::dot(mesh.vertices[t[0]], glm::cross(mesh.vertices[t[1]], mesh.vertices[t[2]])) / 6.0f;
    }
    for (const auto& [edge, count] : edges) {
        QCOMPARE(count, 1);
        QVERIFY(edges.count({edge.second, edge.first}) == 1);
    }
    QVERIFY2(std::abs(volume - expectedVolume) < tolerance, qPrintable(QString::number(volume)));
}

} // namespace

class TestViewportScene : public QObject {
    Q_OBJECT
private slots:
    void boxMeshIsClosedAndOutward();
    void sphereMeshIsClosedAndOutward();
    void instanceTransformAppliesShapeFrameThenRotationThenPosition();
    void instanceBoundsFollowTheModel();
    void sceneBoundsSkipHiddenAndCanTakeTheSelection();
    void pickBoundsReturnsTheNearestHit();
    void rayBoundsSlabTest();
};

void TestViewportScene::boxMeshIsClosedAndOutward() {
    const rl::ViewportMesh box = rl::makeViewportBoxMesh(glm::vec3(0.5f, 1.0f, 2.0f));
    QCOMPARE(box.vertices.size(), size_t(8));
    QCOMPARE(box.triangles.size(), size_t(12));
    verifyClosedAndOutward(box, 1.0f * 2.0f * 4.0f, 1e-4f);
    const rl::Bounds b = box.bounds();
    QCOMPARE(b.min, glm::vec3(-0.5f, -1.0f, -2.0f));
    QCOMPARE(b.max, glm::vec3(0.5f, 1.0f, 2.0f));
}

void TestViewportScene::sphereMeshIsClosedAndOutward() {
    const rl::ViewportMesh sphere = rl::makeViewportSphereMesh(1.0f, 32, 16);
    // A faceted sphere is a little smaller than the round one (4.18879): within 5% at this resolution.
    verifyClosedAndOutward(sphere, 4.18879f, 0.05f * 4.18879f);
    for (const glm::vec3& v : sphere.vertices)
        QVERIFY(std::abs(glm::length(v) - 1.0f) < 1e-5f);
}

void TestViewportScene::instanceTransformAppliesShapeFrameThenRotationThenPosition() {
    // 90 degrees about +Y maps +X to -Z.
    const glm::dquat rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(0.0, 1.0, 0.0));
    const glm::mat4 frame = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::mat4 model = rl::instanceTransform(glm::dvec3(10.0, 20.0, 30.0), rotation, frame);
    const glm::vec3 p = glm::vec3(model * glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)); // shape point (1,0,0) -> body (2,0,0)
    QVERIFY(glm::length(p - glm::vec3(10.0f, 20.0f, 28.0f)) < 1e-5f);
}

void TestViewportScene::instanceBoundsFollowTheModel() {
    rl::ViewportScene scene;
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(1.0f, 0.5f, 0.25f)));
    rl::ViewportInstance inst;
    inst.model =
        rl::instanceTransform(glm::dvec3(5.0, 0.0, 0.0), glm::angleAxis(glm::radians(90.0), glm::dvec3(0.0, 0.0, 1.0)));
    scene.instances.push_back(inst);
    const rl::Bounds b = scene.instanceBounds(0);
    // Rotated 90 degrees about Z: the X and Y extents swap.
    QVERIFY(glm::length(b.min - glm::vec3(4.5f, -1.0f, -0.25f)) < 1e-5f);
    QVERIFY(glm::length(b.max - glm::vec3(5.5f, 1.0f, 0.25f)) < 1e-5f);
    QVERIFY(scene.instanceBounds(1).isEmpty());
    scene.instances[0].meshIndex = 3; // a bad mesh index gives no box rather than a crash
    QVERIFY(scene.instanceBounds(0).isEmpty());
}

void TestViewportScene::sceneBoundsSkipHiddenAndCanTakeTheSelection() {
    rl::ViewportScene scene;
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.5f)));
    for (int i = 0; i < 3; ++i) {
        rl::ViewportInstance inst;
        inst.model = glm::translate(glm::mat4(1.0f), glm::vec3(10.0f * i, 0.0f, 0.0f));
        scene.instances.push_back(inst);
    }
    scene.instances[2].flags = rl::kInstanceHidden;
    scene.instances[1].flags = rl::kInstanceSelected;
    QCOMPARE(scene.bounds().max.x, 10.5f);
    QCOMPARE(scene.bounds().min.x, -0.5f);
    QCOMPARE(scene.bounds(true).min.x, 9.5f);
    scene.instances[1].flags = 0;
    QVERIFY(scene.bounds(true).isEmpty());
}

void TestViewportScene::pickBoundsReturnsTheNearestHit() {
    rl::ViewportScene scene;
    scene.meshes.push_back(rl::makeViewportBoxMesh(glm::vec3(0.5f)));
    for (float z : {-5.0f, -2.0f, -8.0f}) {
        rl::ViewportInstance inst;
        inst.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, z));
        scene.instances.push_back(inst);
    }
    rl::ViewRay ray;
    ray.origin = glm::vec3(0.0f, 0.2f, 0.0f);
    ray.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    QCOMPARE(scene.pickBounds(ray), 1);
    scene.instances[1].flags = rl::kInstanceHidden;
    QCOMPARE(scene.pickBounds(ray), 0);
    ray.origin.x = 3.0f;
    QCOMPARE(scene.pickBounds(ray), -1);
}

void TestViewportScene::rayBoundsSlabTest() {
    rl::Bounds box;
    box.extend(glm::vec3(-1.0f));
    box.extend(glm::vec3(1.0f));
    rl::ViewRay ray;
    ray.origin = glm::vec3(-5.0f, 0.0f, 0.0f);
    ray.direction = glm::vec3(1.0f, 0.0f, 0.0f);
    QCOMPARE(rl::intersectRayBounds(ray, box), 4.0f);
    ray.direction = glm::vec3(-1.0f, 0.0f, 0.0f); // pointing away
    QVERIFY(rl::intersectRayBounds(ray, box) < 0.0f);
    ray.origin = glm::vec3(0.0f); // starting inside: hit at distance 0
    QCOMPARE(rl::intersectRayBounds(ray, box), 0.0f);
    ray.origin = glm::vec3(-5.0f, 2.0f, 0.0f); // parallel to a slab, outside it
    ray.direction = glm::vec3(1.0f, 0.0f, 0.0f);
    QVERIFY(rl::intersectRayBounds(ray, box) < 0.0f);
}

QTEST_APPLESS_MAIN(TestViewportScene)
#include "tst_viewportscene.moc"
