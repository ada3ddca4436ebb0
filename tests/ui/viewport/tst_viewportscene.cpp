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

Q_DECLARE_METATYPE(rl::ViewportMesh)

class TestViewportScene : public QObject {
    Q_OBJECT
private slots:
    void boxMeshIsClosedAndOutward();
    void sphereMeshIsClosedAndOutward();
    void flatShadingEndsEveryTriangleOnItsNormal_data();
    void flatShadingEndsEveryTriangleOnItsNormal();
    void instanceTransformAppliesShapeFrameThenRotationThenPosition();
    void instanceBoundsFollowTheModel();
    void sceneBoundsSkipHiddenAndCanTakeTheSelection();
    void contentLeavesOutAGroundThatDwarfsTheRest_data();
    void contentLeavesOutAGroundThatDwarfsTheRest();
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

void TestViewportScene::flatShadingEndsEveryTriangleOnItsNormal_data() {
    QTest::addColumn<rl::ViewportMesh>("mesh");
    QTest::addColumn<int>("expectedVertices"); // -1: not checked
    QTest::newRow("box") << rl::makeViewportBoxMesh(glm::vec3(0.5f, 1.0f, 2.0f)) << 8;
    // 16 x 8 sphere: 114 vertices for 224 triangles in 128 faces (the quads' halves are coplanar), so copies.
    QTest::newRow("sphere") << rl::makeViewportSphereMesh(1.0f, 16, 8) << -1;
    rl::ViewportMesh bad = rl::makeViewportBoxMesh(glm::vec3(1.0f));
    bad.triangles.push_back({0, 1, 99}); // an index out of range is dropped, not read
    QTest::newRow("bad index") << bad << 8;
}

// flatShaded(): the same triangles (same corners, same winding), each ending on a vertex whose normal is the
// triangle's own, with as few copies as the greedy assignment needs.
void TestViewportScene::flatShadingEndsEveryTriangleOnItsNormal() {
    QFETCH(rl::ViewportMesh, mesh);
    QFETCH(int, expectedVertices);
    const rl::FlatShadedMesh flat = rl::flatShaded(mesh);
    size_t valid = 0;
    for (const auto& t : mesh.triangles)
        valid += t[0] < mesh.vertices.size() && t[1] < mesh.vertices.size() && t[2] < mesh.vertices.size();
    QCOMPARE(flat.triangles.size(), valid);
    for (size_t i = 0; i < flat.triangles.size(); ++i) {
        const auto& in = mesh.triangles[i];
        const auto& out = flat.triangles[i];
        const glm::vec3 a = flat.vertices[out[0]].position, b = flat.vertices[out[1]].position,
                        c = flat.vertices[out[2]].position;
        const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
        // The last vertex carries the normal of this triangle, wound as the input was (a rotation of it).
        QVERIFY2(glm::dot(flat.vertices[out[2]].normal, normal) > 0.9999f, qPrintable(QString::number(i)));
        const glm::vec3 inNormal = glm::normalize(
            glm::cross(mesh.vertices[in[1]] - mesh.vertices[in[0]], mesh.vertices[in[2]] - mesh.vertices[in[0]]));
        QVERIFY(glm::dot(inNormal, normal) > 0.9999f);
        bool sameCorners = false;
        for (int r = 0; r < 3; ++r)
            sameCorners = sameCorners || (flat.vertices[out[0]].position == mesh.vertices[in[r]] &&
                                          flat.vertices[out[1]].position == mesh.vertices[in[(r + 1) % 3]] &&
                                          flat.vertices[out[2]].position == mesh.vertices[in[(r + 2) % 3]]);
        QVERIFY(sameCorners);
    }
    QVERIFY(flat.vertices.size() >= mesh.vertices.size());
    if (expectedVertices >= 0)
        QCOMPARE(flat.vertices.size(), size_t(expectedVertices));
    else
        QVERIFY(flat.vertices.size() > mesh.vertices.size());
    qInfo("%zu vertices for %zu triangles (the mesh has %zu vertices)", flat.vertices.size(), flat.triangles.size(),
          mesh.vertices.size());
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

void TestViewportScene::contentLeavesOutAGroundThatDwarfsTheRest_data() {
    QTest::addColumn<float>("groundHalfWidth");
    QTest::addColumn<bool>("withWall");
    QTest::addColumn<float>("expectedMaxX"); // of the content's bounds
    // A 0.1 m cube on an anchored ground slab 2 cm thick, and (optionally) a 4 m anchored wall 5 m away on it.
    QTest::newRow("a 40 m ground under a cube: the cube") << 20.0f << false << 0.05f;
    QTest::newRow("a 400 m ground under a cube and a wall: both, the wall too") << 200.0f << true << 5.025f;
    QTest::newRow("a 20 m ground under the cube and the wall: all") << 10.0f << true << 10.0f;
    QTest::newRow("a 0.3 m ground under the cube: all") << 0.15f << false << 0.15f;
}

void TestViewportScene::contentLeavesOutAGroundThatDwarfsTheRest() {
    QFETCH(float, groundHalfWidth);
    QFETCH(bool, withWall);
    QFETCH(float, expectedMaxX);
    rl::ViewportScene scene;
    const auto add = [&scene](const glm::vec3& half, const glm::vec3& centre, uint32_t flags) {
        scene.meshes.push_back(rl::makeViewportBoxMesh(half));
        rl::ViewportInstance inst;
        inst.meshIndex = static_cast<int>(scene.meshes.size()) - 1;
        inst.model = glm::translate(glm::mat4(1.0f), centre);
        inst.flags = flags;
        scene.instances.push_back(inst);
    };
    QVERIFY(scene.contentBounds().isEmpty());
    add(glm::vec3(groundHalfWidth, 0.01f, groundHalfWidth), glm::vec3(0.0f, -0.01f, 0.0f), rl::kInstanceAnchor);
    QCOMPARE(scene.contentBounds().max.x, groundHalfWidth); // the ground alone is what there is
    add(glm::vec3(0.05f), glm::vec3(0.0f, 0.05f, 0.0f), 0);
    if (withWall)
        add(glm::vec3(0.025f, 2.0f, 2.0f), glm::vec3(5.0f, 2.0f, 0.0f), rl::kInstanceAnchor);
    const rl::Bounds content = scene.contentBounds();
    QCOMPARE(content.max.x, expectedMaxX);
    // A hidden ground counts for nothing, as in bounds(); the wall, beside the cube and not under it, stays.
    scene.instances[0].flags |= rl::kInstanceHidden;
    QCOMPARE(scene.contentBounds().max.x, withWall ? 5.025f : 0.05f);
    // A ground that is not under the rest is not a ground: raised above the cube, it is kept.
    scene.instances[0].flags = rl::kInstanceAnchor;
    scene.instances[0].model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 10.0f, 0.0f));
    QCOMPARE(scene.contentBounds().max.x, groundHalfWidth);
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
