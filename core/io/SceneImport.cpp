#include "io/SceneImport.h"

#include "geometry/ConvexHull.h"
#include "io/AssimpImporter.h"
#include "io/NumberFormat.h"
#include "io/SceneJson.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

namespace rl {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

using Triangles = std::vector<std::array<uint32_t, 3>>;

struct MeshData {
    std::vector<Vec3> vertices;
    Triangles triangles;
};

MeshData boxMesh(const Vec3& h) {
    MeshData mesh;
    // Corner i has x = +h.x when bit 0 is set, y when bit 1, z when bit 2.
    for (int i = 0; i < 8; ++i)
        mesh.vertices.emplace_back(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z);
    // Counter-clockwise seen from outside, two triangles per face: -z, +z, -x, +x, -y, +y.
    mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 4, 6}, {0, 6, 2},
                      {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}};
    return mesh;
}

MeshData icosphereMesh(Real radius, int subdivisions) {
    MeshData mesh;
    const Real t = (1.0 + std::sqrt(5.0)) / 2.0; // the golden ratio places the icosahedron's 12 corners
    const Vec3 corners[12] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (const Vec3& c : corners)
        mesh.vertices.push_back(glm::normalize(c));
    mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpointOf;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [it, inserted] = midpointOf.try_emplace(key, uint32_t(mesh.vertices.size()));
            if (inserted)
                mesh.vertices.push_back(glm::normalize(mesh.vertices[a] + mesh.vertices[b]));
            return it->second;
        };
        Triangles finer;
        finer.reserve(mesh.triangles.size() * 4);
        for (const auto& tri : mesh.triangles) {
            const uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
            finer.push_back({tri[0], ab, ca});
            finer.push_back({tri[1], bc, ab});
            finer.push_back({tri[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    for (Vec3& v : mesh.vertices)
        v *= radius;
    return mesh;
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// OBJ names and material names run to the end of their line: a line break or other control byte in a name
// (possible in .rlscene JSON) would break the statement, so it is written as '_'.
std::string objName(const std::string& name, const std::string& fallback) {
    std::string out = name.empty() ? fallback : name;
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
            c = '_';
    return out;
}

Result<MeshData> bodyMesh(const Scene& scene, const BodyDef& body) {
    const Error error{{}, 0, body.name, {}};
    auto fail = [&](std::string message) {
        Error e = error;
        e.message = std::move(message);
        return e;
    };
    switch (body.shape.type) {
    case ShapeType::Box:
        if (!finite(body.shape.halfExtents))
            return fail("box half extents are not finite");
        return boxMesh(body.shape.halfExtents);
    case ShapeType::Sphere:
        if (!std::isfinite(body.shape.radius))
            return fail("sphere radius is not finite");
        return icosphereMesh(body.shape.radius, kSphereObjSubdivisions);
    case ShapeType::Hull: {
        for (const Vec3& p : body.shape.points)
            if (!finite(p))
                return fail("hull point is not finite");
        const ConvexHull hull = computeConvexHull(body.shape.points);
        if (hull.dimension != HullDimension::Solid && hull.dimension != HullDimension::Flat)
            return fail("hull needs at least 3 points that are not on one line");
        MeshData mesh;
        mesh.vertices = hull.vertices;
        for (const HullFace& face : hull.faces)
            for (size_t i = 2; i < face.vertices.size(); ++i)
                mesh.triangles.push_back({face.vertices[0], face.vertices[i - 1], face.vertices[i]});
        return mesh;
    }
    case ShapeType::Mesh: {
        MeshData mesh{body.shape.points, body.shape.triangles};
        if (mesh.vertices.empty() && !body.shape.objFile.empty()) {
            // A .rlscene body that names an object of an OBJ file, not loaded yet: read it here.
            std::filesystem::path file(body.shape.objFile);
            if (file.is_relative() && !scene.sourcePath.empty())
                file = std::filesystem::path(scene.sourcePath).parent_path() / file;
            Result<ObjFile> obj = readObjFile(file.string());
            if (!obj)
                return obj.error();
            auto it = std::find_if(obj->objects.begin(), obj->objects.end(),
                                   [&](const ObjObject& o) { return o.name == body.shape.objObject; });
            if (it == obj->objects.end())
                return fail("object '" + body.shape.objObject + "' not found in " + file.string());
            mesh.vertices = std::move(it->vertices);
            mesh.triangles = std::move(it->triangles);
        }
        if (mesh.vertices.empty() || mesh.triangles.empty())
            return fail("mesh has no vertices or no triangles");
        for (const Vec3& p : mesh.vertices)
            if (!finite(p))
                return fail("mesh vertex is not finite");
        for (const auto& tri : mesh.triangles)
            for (uint32_t i : tri)
                if (i >= mesh.vertices.size())
                    return fail("mesh triangle index " + std::to_string(i) + " out of range (0.." +
                                std::to_string(mesh.vertices.size() - 1) + ")");
        return mesh;
    }
    }
    return fail("unknown shape type");
}

} // namespace

Scene sceneFromObjects(const ObjFile& file) {
    Scene scene;
    scene.bodies.reserve(file.objects.size());
    for (const ObjObject& object : file.objects) {
        BodyDef body;
        body.name = object.name;
        body.anchor = isAnchorName(object.name);
        const std::optional<MaterialDef> preset = findPreset(object.material);
        body.material = preset ? preset->name : "Default";
        body.shape.type = ShapeType::Mesh;
        body.shape.points = object.vertices;
        body.shape.triangles = object.triangles;
        scene.bodies.push_back(std::move(body));
    }
    return scene;
}

Result<Scene> importScene(const std::string& path) {
    const std::string ext = lowerExtension(path);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return Error{path, 0, {}, "file not found"};
    if (ext == ".rlscene") {
        Result<Scene> scene = readSceneFile(path);
        if (scene && scene->sourcePath.empty())
            scene->sourcePath = path;
        return scene;
    }

    Scene scene;
    if (ext == ".obj") {
        std::string text;
        Result<ObjFile> file = readObjFile(path, &text);
        if (!file)
            return file.error();
        scene = sceneFromObjects(*file);
        scene.sourceObjText = std::move(text);
    } else {
        if (ext.empty() || !assimpReadsExtension(ext))
            return Error{path,
                         0,
                         {},
                         ext.empty() ? "file has no extension, so its format is unknown"
                                     : "unsupported file format '" + ext + "'"};
        Result<ObjFile> file = importWithAssimp(path);
        if (!file)
            return file.error();
        scene = sceneFromObjects(*file);
    }
    scene.sourcePath = path;
    return scene;
}

Result<std::string> sceneToObjText(const Scene& scene) {
    std::string out = "# RigidLab scene as OBJ: one o block per body, in body order, Y-up, metres\n";
    size_t vertexBase = 1; // OBJ indices are 1-based and count over the whole file
    for (size_t b = 0; b < scene.bodies.size(); ++b) {
        const BodyDef& body = scene.bodies[b];
        Result<MeshData> mesh = bodyMesh(scene, body);
        if (!mesh) {
            Error e = mesh.error();
            if (e.object.empty())
                e.object = body.name;
            return e;
        }
        const Quat q = body.orientation;
        const Real qLength = glm::length(glm::dvec4(q.w, q.x, q.y, q.z));
        if (!finite(body.position) || !std::isfinite(qLength) || qLength < 1e-12)
            return Error{{}, 0, body.name, "position or orientation is not a finite placement"};
        const Quat rotation = q / qLength;

        out += "o " + objName(body.name, "Body" + std::to_string(b)) + "\n";
        out += "usemtl " + objName(body.material, "Default") + "\n";
        for (const Vec3& local : mesh->vertices) {
            const Vec3 world = body.position + rotation * local;
            out += "v ";
            appendDouble(out, world.x);
            out += ' ';
            appendDouble(out, world.y);
            out += ' ';
            appendDouble(out, world.z);
            out += '\n';
        }
        for (const auto& tri : mesh->triangles) {
            out += "f " + std::to_string(vertexBase + tri[0]) + ' ' + std::to_string(vertexBase + tri[1]) + ' ' +
                   std::to_string(vertexBase + tri[2]) + '\n';
        }
        vertexBase += mesh->vertices.size();
    }
    return out;
}

} // namespace rl
