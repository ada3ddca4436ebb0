#include "io/AssimpImporter.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/metadata.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rl {

namespace {

// Node hierarchies are a few levels deep in practice; the bound only stops a hostile file's cycle or chain.
constexpr int kMaxNodeDepth = 256;

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

glm::dmat4 toGlm(const aiMatrix4x4& m) {
    // aiMatrix4x4 is row-major with the translation in the fourth column; glm is column-major (m[column][row]).
    glm::dmat4 out(1.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out[c][r] = static_cast<double>(m[r][c]);
    return out;
}

template <class T>
bool metaNumber(const aiScene* scene, const char* key, double& out) {
    T value{};
    if (scene->mMetaData && scene->mMetaData->Get(std::string(key), value)) {
        out = static_cast<double>(value);
        return true;
    }
    return false;
}

bool metaReal(const aiScene* scene, const char* key, double& out) {
    return metaNumber<double>(scene, key, out) || metaNumber<float>(scene, key, out) ||
           metaNumber<int32_t>(scene, key, out);
}

// FBX declares its axes and unit in GlobalSettings, and assimp 5.2 passes them on as metadata without applying
// them. This is the matrix that takes the file's coordinates to ours: right -> +x, up -> +y, front -> +z,
// centimetres * UnitScaleFactor -> metres. It is the identity for a Y-up file in metres.
Result<glm::dmat4> fbxToWorld(const aiScene* scene, const std::string& path) {
    double up = 1, upSign = 1, front = 2, frontSign = 1, coord = 0, coordSign = 1, unitScale = 1;
    metaReal(scene, "UpAxis", up);
    metaReal(scene, "UpAxisSign", upSign);
    metaReal(scene, "FrontAxis", front);
    metaReal(scene, "FrontAxisSign", frontSign);
    metaReal(scene, "CoordAxis", coord);
    metaReal(scene, "CoordAxisSign", coordSign);
    metaReal(scene, "UnitScaleFactor", unitScale);
    auto axis = [](double index, double sign) {
        glm::dvec3 v(0.0);
        v[int(index)] = sign < 0 ? -1.0 : 1.0;
        return v;
    };
    const auto valid = [](double a) { return a == 0 || a == 1 || a == 2; };
    if (!valid(up) || !valid(front) || !valid(coord) || up == front || up == coord || front == coord)
        return Error{path, 0, {}, "FBX axis settings are inconsistent (up, front and coordinate axes must differ)"};
    if (!std::isfinite(unitScale) || unitScale <= 0)
        return Error{path, 0, {}, "FBX UnitScaleFactor is not a positive number"};
    const glm::dvec3 right = axis(coord, coordSign), upAxis = axis(up, upSign), frontAxis = axis(front, frontSign);
    glm::dmat4 m(0.0);
    // Rows of the rotation are the file's right, up and front axes.
    for (int c = 0; c < 3; ++c) {
        m[c][0] = right[c];
        m[c][1] = upAxis[c];
        m[c][2] = frontAxis[c];
    }
    m[3][3] = 1.0;
    const double toMetres = unitScale / 100.0; // FBX UnitScaleFactor counts centimetres per file unit
    return glm::dmat4(glm::dmat3(toMetres)) * m;
}

// Exact-duplicate key for a float position. -0 and +0 are the same point, so the sign of zero is dropped.
struct PositionKey {
    uint32_t bits[3];
    bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};

struct PositionKeyHash {
    size_t operator()(const PositionKey& k) const {
        uint64_t h = 1469598103934665603ull;
        for (uint32_t b : k.bits)
            h = (h ^ b) * 1099511628211ull;
        return static_cast<size_t>(h);
    }
};

PositionKey keyOf(const aiVector3D& v) {
    PositionKey key{};
    const float xyz[3] = {v.x == 0.0f ? 0.0f : v.x, v.y == 0.0f ? 0.0f : v.y, v.z == 0.0f ? 0.0f : v.z};
    std::memcpy(key.bits, xyz, sizeof key.bits);
    return key;
}

bool isPlaceholderName(const std::string& name) {
    // assimp names nodes it invents "<STL_BINARY>", "<PLY_ROOT>" ... and some formats give no name at all.
    return name.empty() || (name.front() == '<' && name.back() == '>');
}

std::string numberedName(const std::string& stem, size_t n) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, ".%03zu", n);
    return stem + suffix;
}

class Collector {
public:
    Collector(const aiScene* scene, const std::string& path) : m_scene(scene), m_path(path) {}

    std::optional<Error> visit(const aiNode* node, const glm::dmat4& parent, int depth) {
        if (depth > kMaxNodeDepth)
            return Error{m_path, 0, {}, "node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " levels"};
        const glm::dmat4 world = parent * toGlm(node->mTransformation);
        if (node->mNumMeshes > 0)
            if (auto error = addBody(node, world))
                return error;
        for (unsigned i = 0; i < node->mNumChildren; ++i)
            if (node->mChildren && node->mChildren[i])
                if (auto error = visit(node->mChildren[i], world, depth + 1))
                    return error;
        return std::nullopt;
    }

    std::vector<ObjObject>& objects() { return m_objects; }

private:
    std::optional<Error> addBody(const aiNode* node, const glm::dmat4& world) {
        ObjObject object;
        object.name = node->mName.C_Str();
        std::vector<aiVector3D> local;
        std::unordered_map<PositionKey, uint32_t, PositionKeyHash> indexOf;
        uint32_t cornerBase = 0;
        bool haveMaterial = false;
        for (unsigned m = 0; m < node->mNumMeshes; ++m) {
            if (node->mMeshes[m] >= m_scene->mNumMeshes)
                return Error{m_path, 0, object.name, "node refers to a mesh that does not exist"};
            const aiMesh* mesh = m_scene->mMeshes[node->mMeshes[m]];
            if (!mesh || !mesh->mVertices || mesh->mNumVertices == 0)
                continue;
            bool meshHasTriangles = false;
            for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
                const aiFace& face = mesh->mFaces[f];
                // Points and lines carry no volume or area: they are not part of the body.
                if (face.mNumIndices != 3)
                    continue;
                std::array<uint32_t, 3> triangle{};
                for (int c = 0; c < 3; ++c) {
                    const unsigned vi = face.mIndices[c];
                    if (vi >= mesh->mNumVertices)
                        return Error{m_path, 0, object.name, "face index out of range in mesh"};
                    const aiVector3D& p = mesh->mVertices[vi];
                    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                        return Error{m_path, 0, object.name, "vertex is not a finite number"};
                    auto [it, inserted] = indexOf.try_emplace(keyOf(p), uint32_t(local.size()));
                    if (inserted) {
                        local.push_back(p);
                        object.fileVertexIndices.push_back(cornerBase + vi);
                    }
                    triangle[c] = it->second;
                }
                object.triangles.push_back(triangle);
                meshHasTriangles = true;
            }
            cornerBase += mesh->mNumVertices;
            if (meshHasTriangles && !haveMaterial) {
                haveMaterial = true;
                if (mesh->mMaterialIndex < m_scene->mNumMaterials && m_scene->mMaterials[mesh->mMaterialIndex]) {
                    aiString name;
                    if (m_scene->mMaterials[mesh->mMaterialIndex]->Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS)
                        object.material = name.C_Str();
                }
            }
        }
        if (object.triangles.empty())
            return std::nullopt; // a node with only point or line meshes is not a body

        // Duplicates were merged in the mesh's own float coordinates, where equal means bit-equal; only then is
        // the node transform applied, in double.
        object.vertices.reserve(local.size());
        Vec3 sum(0.0);
        for (const aiVector3D& p : local) {
            const glm::dvec4 w = world * glm::dvec4(double(p.x), double(p.y), double(p.z), 1.0);
            const Vec3 v(w.x, w.y, w.z);
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                return Error{m_path, 0, object.name, "node transform makes a vertex non-finite"};
            object.vertices.push_back(v);
            sum += v;
        }
        object.vertexMean = sum / static_cast<Real>(object.vertices.size());
        if (glm::determinant(glm::dmat3(world)) < 0.0)
            for (auto& t : object.triangles)
                std::swap(t[1], t[2]);
        m_objects.push_back(std::move(object));
        return std::nullopt;
    }

    const aiScene* m_scene;
    const std::string& m_path;
    std::vector<ObjObject> m_objects;
};

Result<ObjFile> importUnchecked(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        return Error{path, 0, {}, "file not found"};
    if (fs::is_directory(status))
        return Error{path, 0, {}, "is a directory, not a file"};
    if (fs::file_size(path, ec) == 0 && !ec)
        return Error{path, 0, {}, "file is empty"};

    Assimp::Importer importer;
    // Pivot helper nodes ("$AssimpFbx$") would split one Blender object over several nodes.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);
    // Skeleton-only files must not turn into bodies made of bone stand-in meshes.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    // COLLADA ids are sanitised ("Box.001" becomes id "Box_001"); the name attribute is the object's real name,
    // which the anchor rule needs.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_USE_COLLADA_NAMES, true);
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    if (!scene) {
        std::string reason = importer.GetErrorString();
        return Error{path, 0, {}, reason.empty() ? "assimp could not read the file" : "assimp: " + reason};
    }
    if (!scene->mRootNode || scene->mNumMeshes == 0)
        return Error{path, 0, {}, "the file has no meshes"};

    glm::dmat4 root(1.0);
    const std::string ext = lowerExtension(path);
    if (ext == ".fbx") {
        Result<glm::dmat4> toWorld = fbxToWorld(scene, path);
        if (!toWorld)
            return toWorld.error();
        root = *toWorld;
    }
    Collector collector(scene, path);
    if (auto error = collector.visit(scene->mRootNode, root, 0))
        return std::move(*error);

    ObjFile file;
    file.objects = std::move(collector.objects());
    if (file.objects.empty())
        return Error{path, 0, {}, "the file has no triangle meshes"};
    for (const ObjObject& o : file.objects)
        file.vertexCount += o.vertices.size();

    const bool namelessFormat = ext == ".stl" || ext == ".ply";
    const std::string stem = fileStem(path);
    size_t unnamed = 0;
    for (ObjObject& o : file.objects) {
        if (namelessFormat && file.objects.size() == 1)
            o.name = stem;
        else if (isPlaceholderName(o.name))
            o.name = numberedName(stem, ++unnamed);
    }
    return file;
}

} // namespace

Result<ObjFile> importWithAssimp(const std::string& path) {
    // assimp reports most failures through ReadFile, but some importers throw (std::bad_alloc on absurd sizes,
    // DeadlyImportError escaping a post-process step). None of that may leave this function.
    try {
        return importUnchecked(path);
    } catch (const std::exception& e) {
        return Error{path, 0, {}, std::string("assimp failed: ") + e.what()};
    } catch (...) {
        return Error{path, 0, {}, "assimp failed with an unknown exception"};
    }
}

bool assimpReadsExtension(const std::string& extension) {
    if (extension.empty())
        return false;
    const std::string dotted = extension.front() == '.' ? extension : "." + extension;
    try {
        Assimp::Importer importer;
        return importer.IsExtensionSupported(dotted);
    } catch (...) {
        return false;
    }
}

} // namespace rl
