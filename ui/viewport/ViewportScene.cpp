#include "viewport/ViewportScene.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace rl {

Bounds ViewportMesh::bounds() const {
    Bounds b;
    for (const glm::vec3& v : vertices)
        b.extend(v);
    return b;
}

namespace {

// The eight corners of a local box, transformed: exact for the box, conservative for the mesh in it. Empty for an
// empty box.
Bounds transformedBox(const Bounds& local, const glm::mat4& model) {
    Bounds world;
    if (local.isEmpty())
        return world;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                          (corner & 4) ? local.max.z : local.min.z);
        world.extend(glm::vec3(model * glm::vec4(p, 1.0f)));
    }
    return world;
}

// Each mesh's box, once: 5,000 instances often share one mesh.
std::vector<Bounds> meshBoxes(const std::vector<ViewportMesh>& meshes) {
    std::vector<Bounds> boxes(meshes.size());
    for (size_t m = 0; m < meshes.size(); ++m)
        boxes[m] = meshes[m].bounds();
    return boxes;
}

} // namespace

Bounds ViewportScene::instanceBounds(int instance) const {
    if (instance < 0 || instance >= static_cast<int>(instances.size()))
        return Bounds{};
    const ViewportInstance& inst = instances[instance];
    if (inst.meshIndex < 0 || inst.meshIndex >= static_cast<int>(meshes.size()))
        return Bounds{};
    return transformedBox(meshes[inst.meshIndex].bounds(), inst.model);
}

Bounds ViewportScene::bounds(bool selectedOnly) const {
    const std::vector<Bounds> boxes = meshBoxes(meshes);
    Bounds all;
    for (const ViewportInstance& inst : instances) {
        if ((inst.flags & kInstanceHidden) || (selectedOnly && !(inst.flags & kInstanceSelected)))
            continue;
        if (inst.meshIndex < 0 || inst.meshIndex >= static_cast<int>(meshes.size()))
            continue;
        all.extend(transformedBox(boxes[inst.meshIndex], inst.model));
    }
    return all;
}

Bounds ViewportScene::contentBounds() const {
    const std::vector<Bounds> boxes = meshBoxes(meshes);
    const auto diagonal = [](const Bounds& b) { return glm::length(b.size()); };
    std::vector<Bounds> each;
    each.reserve(instances.size());
    size_t ground = instances.size(); // the largest anchor's place in `each`, if any
    for (const ViewportInstance& inst : instances) {
        if ((inst.flags & kInstanceHidden) || inst.meshIndex < 0 || inst.meshIndex >= static_cast<int>(meshes.size()))
            continue;
        const Bounds b = transformedBox(boxes[inst.meshIndex], inst.model);
        if (b.isEmpty())
            continue;
        if ((inst.flags & kInstanceAnchor) && (ground == instances.size() || diagonal(b) > diagonal(each[ground])))
            ground = each.size();
        each.push_back(b);
    }
    Bounds rest, all;
    for (size_t k = 0; k < each.size(); ++k) {
        all.extend(each[k]);
        if (k != ground)
            rest.extend(each[k]);
    }
    if (ground == instances.size() || rest.isEmpty() || !(diagonal(each[ground]) > kGroundRatio * diagonal(rest)) ||
        each[ground].max.y > rest.min.y + 1e-3f * diagonal(rest))
        return all;
    return rest;
}

int ViewportScene::pickBounds(const ViewRay& ray) const {
    int best = -1;
    float bestT = std::numeric_limits<float>::max();
    for (int i = 0; i < static_cast<int>(instances.size()); ++i) {
        if (instances[i].flags & kInstanceHidden)
            continue;
        const float t = intersectRayBounds(ray, instanceBounds(i));
        if (t >= 0.0f && t < bestT) {
            bestT = t;
            best = i;
        }
    }
    return best;
}

glm::mat4 instanceTransform(const glm::dvec3& position, const glm::dquat& orientation, const glm::mat4& shapeFrame) {
    glm::mat4 m = glm::mat4_cast(glm::quat(glm::normalize(orientation)));
    m[3] = glm::vec4(glm::vec3(position), 1.0f);
    return m * shapeFrame;
}

FlatShadedMesh flatShaded(const ViewportMesh& mesh) {
    // Normals closer than this (about 0.8 degrees) count as one face: the halves of a quad that Blender wrote
    // planar to six decimals share their vertex.
    constexpr float kSameFace = 0.9999f;
    FlatShadedMesh out;
    out.vertices.reserve(mesh.vertices.size());
    for (const glm::vec3& v : mesh.vertices)
        out.vertices.push_back({v, glm::vec3(0.0f)});
    std::vector<char> carries(mesh.vertices.size(), 0);
    out.triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        if (t[0] >= mesh.vertices.size() || t[1] >= mesh.vertices.size() || t[2] >= mesh.vertices.size())
            continue;
        const glm::vec3& a = mesh.vertices[t[0]];
        glm::vec3 n = glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a);
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
        std::array<uint32_t, 3> tri = t;
        int last = -1;
        for (int k = 0; k < 3 && last < 0; ++k)
            if (carries[tri[k]] && glm::dot(out.vertices[tri[k]].normal, n) > kSameFace)
                last = k;
        for (int k = 0; k < 3 && last < 0; ++k)
            if (!carries[tri[k]]) {
                carries[tri[k]] = 1;
                out.vertices[tri[k]].normal = n;
                last = k;
            }
        if (last < 0) {
            out.vertices.push_back({mesh.vertices[tri[2]], n});
            carries.push_back(1);
            tri[2] = static_cast<uint32_t>(out.vertices.size() - 1);
            last = 2;
        }
        // A rotation keeps the winding.
        out.triangles.push_back({tri[(last + 1) % 3], tri[(last + 2) % 3], tri[last]});
    }
    return out;
}

ViewportMesh makeViewportBoxMesh(const glm::vec3& h) {
    ViewportMesh mesh;
    for (int corner = 0; corner < 8; ++corner)
        mesh.vertices.emplace_back((corner & 1) ? h.x : -h.x, (corner & 2) ? h.y : -h.y, (corner & 4) ? h.z : -h.z);
    // Corner index bits are (x, y, z); each face is two counter-clockwise triangles seen from outside.
    mesh.triangles = {{0, 4, 6}, {0, 6, 2},  // -x
                      {1, 3, 7}, {1, 7, 5},  // +x
                      {0, 1, 5}, {0, 5, 4},  // -y
                      {2, 6, 7}, {2, 7, 3},  // +y
                      {0, 2, 3}, {0, 3, 1},  // -z
                      {4, 5, 7}, {4, 7, 6}}; // +z
    return mesh;
}

ViewportMesh makeViewportSphereMesh(float radius, int segments, int rings) {
    segments = std::max(segments, 3);
    rings = std::max(rings, 2);
    ViewportMesh mesh;
    mesh.vertices.emplace_back(0.0f, radius, 0.0f); // north pole
    for (int r = 1; r < rings; ++r) {
        const float theta = glm::pi<float>() * static_cast<float>(r) / static_cast<float>(rings);
        for (int s = 0; s < segments; ++s) {
            const float phi = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
            mesh.vertices.emplace_back(radius * std::sin(theta) * std::cos(phi), radius * std::cos(theta),
                                       -radius * std::sin(theta) * std::sin(phi));
        }
    }
    const uint32_t south = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.emplace_back(0.0f, -radius, 0.0f);
    auto ringVertex = [&](int r, int s) { return static_cast<uint32_t>(1 + (r - 1) * segments + (s % segments)); };
    for (int s = 0; s < segments; ++s) {
        mesh.triangles.push_back({0, ringVertex(1, s), ringVertex(1, s + 1)});
        for (int r = 1; r < rings - 1; ++r) {
            mesh.triangles.push_back({ringVertex(r, s), ringVertex(r + 1, s), ringVertex(r + 1, s + 1)});
            mesh.triangles.push_back({ringVertex(r, s), ringVertex(r + 1, s + 1), ringVertex(r, s + 1)});
        }
        mesh.triangles.push_back({ringVertex(rings - 1, s), south, ringVertex(rings - 1, s + 1)});
    }
    return mesh;
}

} // namespace rl
