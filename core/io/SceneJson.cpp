#include "io/SceneJson.h"

#include "io/AtomicFile.h"
#include "io/ObjReader.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <filesystem>
#include <map>

namespace rl {

namespace {

// Orientation must be a unit quaternion. Hand-written files round to four or five digits (0.7071), so the check only
// catches real mistakes such as Euler angles or degrees; the world normalises what it is given.
constexpr double kUnitQuaternionTolerance = 1e-3;

std::string quotedName(std::string_view s) {
    return "'" + std::string(s) + "'";
}

// Material lookups are case-insensitive (Scene::findMaterial), so two names that differ only in case collide.
bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::string parentDirectory(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return {};
    return path.substr(0, slash + 1);
}

class SceneReader {
public:
    explicit SceneReader(const std::string& path) : m_path(path) {}

    Result<Scene> read(std::string_view text) {
        Result<JsonValue> doc = parseJson(text, m_path);
        if (!doc)
            return doc.error();
        Scene scene;
        scene.sourcePath = m_path;
        if (!readRoot(*doc, scene))
            return m_error;
        return scene;
    }

private:
    bool fail(const JsonValue& at, const std::string& context, const std::string& message) {
        m_error = Error{m_path, at.line(), {}, context.empty() ? message : context + ": " + message, at.column()};
        return false;
    }

    bool wrongType(const JsonValue& v, const std::string& context, std::string_view key, std::string_view expected) {
        return fail(v, context,
                    "'" + std::string(key) + "' must be " + std::string(expected) + ", not " +
                        (v.isNull() ? std::string("null")
                                    : "a" + std::string(v.isArray() || v.isObject() ? "n " : " ") +
                                          std::string(jsonTypeName(v.type()))));
    }

    bool unknownKey(const JsonMember& m, const std::string& context, std::string_view expected) {
        m_error =
            Error{m_path, m.line, {}, "unknown key '" + m.key + "' (expected " + std::string(expected) + ")", m.column};
        if (!context.empty())
            m_error.message = context + ": " + m_error.message;
        return false;
    }

    bool readNumber(const JsonValue& v, const std::string& context, std::string_view key, double& out) {
        if (!v.isNumber())
            return wrongType(v, context, key, "a number");
        out = v.asNumber(); // the JSON reader refuses anything non-finite
        return true;
    }

    enum class Bound { Any, NonNegative, Positive };

    bool readBounded(const JsonValue& v, const std::string& context, std::string_view key, Bound bound, double& out) {
        if (!readNumber(v, context, key, out))
            return false;
        if (bound == Bound::Positive && !(out > 0.0))
            return fail(v, context, "'" + std::string(key) + "' must be greater than 0");
        if (bound == Bound::NonNegative && out < 0.0)
            return fail(v, context, "'" + std::string(key) + "' must not be negative");
        return true;
    }

    bool readOptional(const JsonValue& v, const std::string& context, std::string_view key, Bound bound,
                      std::optional<Real>& out) {
        double d = 0.0;
        if (!readBounded(v, context, key, bound, d))
            return false;
        out = d;
        return true;
    }

    bool readInt(const JsonValue& v, const std::string& context, std::string_view key, int minimum, int& out) {
        double d = 0.0;
        if (!readNumber(v, context, key, d))
            return false;
        if (d != std::floor(d) || d > INT_MAX || d < INT_MIN)
            return fail(v, context, "'" + std::string(key) + "' must be a whole number");
        if (d < minimum)
            return fail(v, context, "'" + std::string(key) + "' must be at least " + std::to_string(minimum));
        out = static_cast<int>(d);
        return true;
    }

    bool readString(const JsonValue& v, const std::string& context, std::string_view key, std::string& out) {
        if (!v.isString())
            return wrongType(v, context, key, "a string");
        out = v.asString();
        return true;
    }

    bool readBool(const JsonValue& v, const std::string& context, std::string_view key, bool& out) {
        if (!v.isBool())
            return wrongType(v, context, key, "true or false");
        out = v.asBool();
        return true;
    }

    template <int N>
    bool readNumbers(const JsonValue& v, const std::string& context, std::string_view key, double (&out)[N]) {
        static const std::string expected = "an array of " + std::to_string(N) + " numbers";
        if (!v.isArray() || v.asArray().size() != N)
            return v.isArray() ? fail(v, context,
                                      "'" + std::string(key) + "' must be " + expected + "; it has " +
                                          std::to_string(v.asArray().size()) + " items")
                               : wrongType(v, context, key, expected);
        for (int i = 0; i < N; ++i) {
            const JsonValue& item = v.asArray()[static_cast<size_t>(i)];
            if (!item.isNumber())
                return fail(item, context,
                            "'" + std::string(key) + "' must be " + expected + ": item " + std::to_string(i) + " is " +
                                std::string(jsonTypeName(item.type())));
            out[i] = item.asNumber();
        }
        return true;
    }

    bool readVec3(const JsonValue& v, const std::string& context, std::string_view key, Vec3& out) {
        double d[3];
        if (!readNumbers(v, context, key, d))
            return false;
        out = Vec3(d[0], d[1], d[2]);
        return true;
    }

    bool readRoot(const JsonValue& root, Scene& scene) {
        if (!root.isObject())
            return fail(root, {}, "a scene must be a JSON object, not " + std::string(jsonTypeName(root.type())));
        for (const JsonMember& m : root.asObject())
            if (m.key != "format" && m.key != "version" && m.key != "world" && m.key != "materials" &&
                m.key != "bodies")
                return unknownKey(m, {}, "format, version, world, materials or bodies");

        const JsonValue* format = root.find("format");
        if (!format || !format->isString() || format->asString() != kSceneFormatName)
            return fail(format ? *format : root, {},
                        "not a RigidLab scene: \"format\" must be \"" + std::string(kSceneFormatName) + "\"");
        const JsonValue* version = root.find("version");
        if (!version)
            return fail(root, {}, "missing key 'version'");
        int v = 0;
        if (!readInt(*version, {}, "version", 1, v))
            return false;
        if (v > kSceneFormatVersion)
            return fail(*version, {},
                        "written by a newer RigidLab: scene version " + std::to_string(v) +
                            ", this build reads up to " + std::to_string(kSceneFormatVersion));

        if (const JsonValue* world = root.find("world"); world && !readWorld(*world, scene.world))
            return false;
        // Materials before bodies, whatever the key order, so that bodies can be checked against them.
        if (const JsonValue* materials = root.find("materials"); materials && !readMaterials(*materials, scene))
            return false;
        if (const JsonValue* bodies = root.find("bodies")) {
            if (!bodies->isArray())
                return wrongType(*bodies, {}, "bodies", "an array");
            scene.bodies.resize(bodies->asArray().size());
            for (size_t i = 0; i < scene.bodies.size(); ++i)
                if (!readBody(bodies->asArray()[i], i, scene, scene.bodies[i]))
                    return false;
        }
        return true;
    }

    bool readWorld(const JsonValue& world, WorldSettings& out) {
        const std::string context = "world";
        if (!world.isObject())
            return wrongType(world, {}, "world", "an object");
        for (const JsonMember& m : world.asObject()) {
            const JsonValue& v = m.value;
            bool ok = true;
            std::string text;
            if (m.key == "gravity") {
                ok = readVec3(v, context, m.key, out.gravity);
            } else if (m.key == "fps") {
                ok = readBounded(v, context, m.key, Bound::Positive, out.fps);
            } else if (m.key == "substeps") {
                ok = readInt(v, context, m.key, 1, out.substeps);
            } else if (m.key == "iterations") {
                ok = readInt(v, context, m.key, 1, out.iterations);
            } else if (m.key == "linear_damping") {
                ok = readBounded(v, context, m.key, Bound::NonNegative, out.linearDamping);
            } else if (m.key == "angular_damping") {
                ok = readBounded(v, context, m.key, Bound::NonNegative, out.angularDamping);
            } else if (m.key == "integrator") {
                ok = readString(v, context, m.key, text);
                if (ok) {
                    const std::optional<Integrator> integrator = parseIntegrator(text);
                    if (!integrator)
                        return fail(v, context,
                                    "unknown integrator " + quotedName(text) +
                                        " (expected explicit-euler, symplectic-euler, verlet or rk4)");
                    out.integrator = *integrator;
                }
            } else if (m.key == "effects") {
                ok = readString(v, context, m.key, text);
                if (ok) {
                    std::string why;
                    const std::optional<EffectsSetting> effects = EffectsSetting::parse(text, &why);
                    if (!effects)
                        return fail(v, context, "'effects': " + why);
                    out.effects = *effects;
                }
            } else if (m.key == "friction_combine" || m.key == "restitution_combine") {
                ok = readString(v, context, m.key, text);
                if (ok) {
                    const std::optional<CombineRule> rule = parseCombineRule(text);
                    if (!rule)
                        return fail(v, context,
                                    "unknown combine rule " + quotedName(text) +
                                        " (expected geometric-mean, average, min, max or multiply)");
                    (m.key == "friction_combine" ? out.frictionCombine : out.restitutionCombine) = *rule;
                }
            } else {
                return unknownKey(m, context,
                                  "gravity, fps, substeps, iterations, integrator, effects, linear_damping, "
                                  "angular_damping, friction_combine or restitution_combine");
            }
            if (!ok)
                return false;
        }
        return true;
    }

    bool readMaterials(const JsonValue& materials, Scene& scene) {
        if (!materials.isObject())
            return wrongType(materials, {}, "materials", "an object of name: {density, friction, restitution}");
        for (const JsonMember& entry : materials.asObject()) {
            const std::string context = "material " + quotedName(entry.key);
            if (entry.key.empty())
                return fail(entry.value, "materials", "a material needs a name");
            for (const MaterialDef& existing : scene.materials)
                if (equalsIgnoreCase(existing.name, entry.key))
                    return fail(entry.value, context,
                                "defined twice (names are case-insensitive: " + quotedName(existing.name) + ")");
            if (!entry.value.isObject())
                return wrongType(entry.value, "materials", entry.key, "an object");
            MaterialDef material;
            material.name = entry.key;
            for (const JsonMember& m : entry.value.asObject()) {
                bool ok = true;
                if (m.key == "density")
                    ok = readBounded(m.value, context, m.key, Bound::Positive, material.density);
                else if (m.key == "friction")
                    ok = readBounded(m.value, context, m.key, Bound::NonNegative, material.friction);
                else if (m.key == "restitution")
                    ok = readRestitution(m.value, context, material.restitution);
                else
                    return unknownKey(m, context, "density, friction or restitution");
                if (!ok)
                    return false;
            }
            scene.materials.push_back(std::move(material));
        }
        return true;
    }

    bool readRestitution(const JsonValue& v, const std::string& context, double& out) {
        if (!readBounded(v, context, "restitution", Bound::NonNegative, out))
            return false;
        if (out > 1.0)
            return fail(v, context, "'restitution' must be between 0 and 1");
        return true;
    }

    bool readBody(const JsonValue& body, size_t index, const Scene& scene, BodyDef& out) {
        std::string context = "body (index " + std::to_string(index) + ")";
        if (!body.isObject())
            return fail(body, context, "must be an object, not " + std::string(jsonTypeName(body.type())));
        if (const JsonValue* name = body.find("name"); name && name->isString())
            context = "body " + quotedName(name->asString()) + " (index " + std::to_string(index) + ")";
        bool hasShape = false;
        for (const JsonMember& m : body.asObject()) {
            const JsonValue& v = m.value;
            bool ok = true;
            if (m.key == "name") {
                ok = readString(v, context, m.key, out.name);
            } else if (m.key == "anchor") {
                ok = readBool(v, context, m.key, out.anchor);
            } else if (m.key == "material") {
                ok = readString(v, context, m.key, out.material);
                if (ok && !scene.findMaterial(out.material))
                    return fail(v, context,
                                "unknown material " + quotedName(out.material) +
                                    " (not a preset and not in \"materials\")");
            } else if (m.key == "density") {
                ok = readOptional(v, context, m.key, Bound::Positive, out.density);
            } else if (m.key == "mass") {
                ok = readOptional(v, context, m.key, Bound::Positive, out.mass);
            } else if (m.key == "friction") {
                ok = readOptional(v, context, m.key, Bound::NonNegative, out.friction);
            } else if (m.key == "restitution") {
                double e = 0.0;
                ok = readRestitution(v, context, e);
                out.restitution = e;
            } else if (m.key == "position") {
                ok = readVec3(v, context, m.key, out.position);
            } else if (m.key == "orientation") {
                double q[4];
                ok = readNumbers(v, context, m.key, q);
                if (ok) {
                    out.orientation = Quat(q[0], q[1], q[2], q[3]);
                    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
                    if (!(std::abs(length - 1.0) <= kUnitQuaternionTolerance))
                        return fail(v, context,
                                    "'orientation' must be a unit quaternion [w, x, y, z]; its length is " +
                                        std::to_string(length));
                }
            } else if (m.key == "velocity") {
                ok = readVec3(v, context, m.key, out.velocity);
            } else if (m.key == "angular_velocity") {
                ok = readVec3(v, context, m.key, out.angularVelocity);
            } else if (m.key == "shape") {
                ok = readShape(v, context, out.shape);
                hasShape = true;
            } else {
                return unknownKey(m, context,
                                  "name, anchor, shape, material, density, mass, friction, restitution, position, "
                                  "orientation, velocity or angular_velocity");
            }
            if (!ok)
                return false;
        }
        if (!hasShape)
            return fail(body, context, "missing key 'shape'");
        return true;
    }

    bool readPoints(const JsonValue& v, const std::string& context, std::string_view key, size_t minimum,
                    std::vector<Vec3>& out) {
        if (!v.isArray())
            return wrongType(v, context, key, "an array of [x, y, z] points");
        const JsonValue::Array& items = v.asArray();
        if (items.size() < minimum)
            return fail(v, context,
                        "'" + std::string(key) + "' needs at least " + std::to_string(minimum) + " points, it has " +
                            std::to_string(items.size()));
        out.resize(items.size());
        for (size_t i = 0; i < items.size(); ++i)
            if (!readVec3(items[i], context, std::string(key) + "[" + std::to_string(i) + "]", out[i]))
                return false;
        return true;
    }

    bool readShape(const JsonValue& shape, const std::string& bodyContext, ShapeDef& out) {
        const std::string context = bodyContext + ": shape";
        constexpr std::string_view kKinds = "box, sphere, hull, mesh or obj (with object)";
        if (!shape.isObject())
            return wrongType(shape, bodyContext, "shape", "an object");
        const JsonValue* kind = nullptr;
        std::string kindName;
        for (const JsonMember& m : shape.asObject()) {
            if (m.key == "object")
                continue;
            if (m.key != "box" && m.key != "sphere" && m.key != "hull" && m.key != "mesh" && m.key != "obj")
                return unknownKey(m, context, kKinds);
            if (kind)
                return fail(m.value, context,
                            "has both '" + kindName + "' and '" + m.key + "'; a shape is one of them");
            kind = &m.value;
            kindName = m.key;
        }
        if (!kind)
            return fail(shape, context, "needs one of " + std::string(kKinds));
        const JsonValue* object = shape.find("object");
        if (object && kindName != "obj")
            return fail(*object, context, "'object' belongs to an 'obj' shape");

        out = ShapeDef{};
        if (kindName == "box") {
            out.type = ShapeType::Box;
            if (!readVec3(*kind, context, "box", out.halfExtents))
                return false;
            if (!(out.halfExtents.x > 0.0 && out.halfExtents.y > 0.0 && out.halfExtents.z > 0.0))
                return fail(*kind, context, "'box' half extents must all be greater than 0");
        } else if (kindName == "sphere") {
            out.type = ShapeType::Sphere;
            if (!readBounded(*kind, context, "sphere", Bound::Positive, out.radius))
                return false;
        } else if (kindName == "hull") {
            out.type = ShapeType::Hull;
            if (!readPoints(*kind, context, "hull", 3, out.points))
                return false;
        } else if (kindName == "mesh") {
            out.type = ShapeType::Mesh;
            if (!readMesh(*kind, context, out))
                return false;
        } else {
            out.type = ShapeType::Mesh;
            if (!readString(*kind, context, "obj", out.objFile))
                return false;
            if (object && !readString(*object, context, "object", out.objObject))
                return false;
            if (!loadObjObject(*kind, context, out))
                return false;
        }
        return true;
    }

    bool readMesh(const JsonValue& mesh, const std::string& context, ShapeDef& out) {
        if (!mesh.isObject())
            return wrongType(mesh, context, "mesh", "an object with vertices and triangles");
        const JsonValue* vertices = mesh.find("vertices");
        const JsonValue* triangles = mesh.find("triangles");
        for (const JsonMember& m : mesh.asObject())
            if (m.key != "vertices" && m.key != "triangles")
                return unknownKey(m, context + ": mesh", "vertices or triangles");
        if (!vertices || !triangles)
            return fail(mesh, context, "'mesh' needs 'vertices' and 'triangles'");
        if (!readPoints(*vertices, context, "vertices", 3, out.points))
            return false;
        if (!triangles->isArray() || triangles->asArray().empty())
            return wrongType(*triangles, context, "triangles", "a non-empty array of [i, j, k] vertex indices");
        const JsonValue::Array& items = triangles->asArray();
        out.triangles.resize(items.size());
        for (size_t t = 0; t < items.size(); ++t) {
            double idx[3];
            const std::string key = "triangles[" + std::to_string(t) + "]";
            if (!readNumbers(items[t], context, key, idx))
                return false;
            for (int c = 0; c < 3; ++c) {
                if (idx[c] != std::floor(idx[c]) || idx[c] < 0 || idx[c] >= static_cast<double>(out.points.size()))
                    return fail(items[t], context,
                                "'" + key + "' has index " + formatIndex(idx[c]) + ", which is not one of the " +
                                    std::to_string(out.points.size()) + " vertices");
                out.triangles[t][static_cast<size_t>(c)] = static_cast<uint32_t>(idx[c]);
            }
        }
        return true;
    }

    static std::string formatIndex(double d) {
        return d == std::floor(d) && std::abs(d) < 1e15 ? std::to_string(static_cast<long long>(d)) : std::to_string(d);
    }

    bool loadObjObject(const JsonValue& at, const std::string& context, ShapeDef& out) {
        const std::string resolved =
            !out.objFile.empty() && out.objFile.front() == '/' ? out.objFile : parentDirectory(m_path) + out.objFile;
        auto cached = m_objCache.find(resolved);
        if (cached == m_objCache.end()) {
            // A scene names files; "/dev/zero" or a FIFO would make the read endless or block.
            std::error_code ec;
            if (std::filesystem::exists(resolved, ec) && !std::filesystem::is_regular_file(resolved, ec))
                return fail(at, context, "cannot load " + quotedName(out.objFile) + ": not a regular file");
            Result<ObjFile> file = readObjFile(resolved);
            if (!file)
                return fail(at, context, "cannot load " + quotedName(out.objFile) + ": " + file.error().toString());
            cached = m_objCache.emplace(resolved, std::move(*file)).first;
        }
        const std::vector<ObjObject>& objects = cached->second.objects;
        const ObjObject* found = nullptr;
        if (out.objObject.empty()) {
            if (objects.size() != 1)
                return fail(at, context,
                            quotedName(out.objFile) + " has " + std::to_string(objects.size()) +
                                " objects; say which one with \"object\"");
            found = &objects.front();
        } else {
            for (const ObjObject& o : objects)
                if (o.name == out.objObject) {
                    found = &o;
                    break;
                }
            if (!found) {
                std::string names;
                constexpr size_t kNamesShown = 8;
                for (size_t i = 0; i < objects.size() && i < kNamesShown; ++i)
                    names += (i ? ", " : "") + objects[i].name;
                if (objects.size() > kNamesShown)
                    names += ", ...";
                return fail(at, context,
                            "no object " + quotedName(out.objObject) + " in " + quotedName(out.objFile) +
                                (names.empty() ? std::string() : " (it has " + names + ")"));
            }
        }
        out.points = found->vertices;
        out.triangles = found->triangles;
        return true;
    }

    const std::string& m_path;
    Error m_error;
    std::map<std::string, ObjFile> m_objCache; // one parse per OBJ file however many bodies use it
};

JsonValue vec3(const Vec3& v) {
    return JsonValue(JsonValue::Array{v.x, v.y, v.z});
}

JsonValue points(const std::vector<Vec3>& pts) {
    JsonValue::Array items;
    items.reserve(pts.size());
    for (const Vec3& p : pts)
        items.push_back(vec3(p));
    return JsonValue(std::move(items));
}

JsonValue shapeToJson(const ShapeDef& shape) {
    JsonValue out = JsonValue::object();
    switch (shape.type) {
    case ShapeType::Box:
        out.set("box", vec3(shape.halfExtents));
        break;
    case ShapeType::Sphere:
        out.set("sphere", shape.radius);
        break;
    case ShapeType::Hull:
        out.set("hull", points(shape.points));
        break;
    case ShapeType::Mesh:
        if (!shape.objFile.empty()) {
            out.set("obj", shape.objFile);
            if (!shape.objObject.empty())
                out.set("object", shape.objObject);
        } else {
            JsonValue mesh = JsonValue::object();
            mesh.set("vertices", points(shape.points));
            JsonValue::Array triangles;
            triangles.reserve(shape.triangles.size());
            for (const auto& t : shape.triangles)
                triangles.push_back(JsonValue(JsonValue::Array{double(t[0]), double(t[1]), double(t[2])}));
            mesh.set("triangles", JsonValue(std::move(triangles)));
            out.set("mesh", std::move(mesh));
        }
        break;
    }
    return out;
}

// JSON has no spelling for NaN or infinity; finds the first such number and says where it is.
bool findNonFinite(const JsonValue& v, std::string& where) {
    if (v.isNumber())
        return !std::isfinite(v.asNumber());
    if (v.isArray()) {
        for (size_t i = 0; i < v.asArray().size(); ++i)
            if (findNonFinite(v.asArray()[i], where)) {
                where = "[" + std::to_string(i) + "]" + where;
                return true;
            }
    } else if (v.isObject()) {
        for (const JsonMember& m : v.asObject())
            if (findNonFinite(m.value, where)) {
                where = "." + m.key + where;
                return true;
            }
    }
    return false;
}

} // namespace

Result<Scene> readSceneJson(std::string_view text, const std::string& path) {
    return SceneReader(path).read(text);
}

Result<Scene> readSceneFile(const std::string& path) {
    Result<std::string> text = readFileBytes(path);
    if (!text)
        return text.error();
    return readSceneJson(*text, path);
}

JsonValue sceneToJson(const Scene& scene) {
    JsonValue root = JsonValue::object();
    root.set("format", std::string(kSceneFormatName));
    root.set("version", kSceneFormatVersion);

    const WorldSettings& w = scene.world;
    JsonValue& world = root.set("world", JsonValue::object());
    world.set("gravity", vec3(w.gravity));
    world.set("fps", w.fps);
    world.set("substeps", w.substeps);
    world.set("iterations", w.iterations);
    world.set("integrator", integratorName(w.integrator));
    world.set("effects", w.effects.toString());
    world.set("linear_damping", w.linearDamping);
    world.set("angular_damping", w.angularDamping);
    world.set("friction_combine", combineRuleName(w.frictionCombine));
    world.set("restitution_combine", combineRuleName(w.restitutionCombine));

    if (!scene.materials.empty()) {
        JsonValue& materials = root.set("materials", JsonValue::object());
        for (const MaterialDef& m : scene.materials) {
            JsonValue& entry = materials.set(m.name, JsonValue::object());
            entry.set("density", m.density);
            entry.set("friction", m.friction);
            entry.set("restitution", m.restitution);
        }
    }

    JsonValue& bodies = root.set("bodies", JsonValue::array());
    const BodyDef defaults;
    for (const BodyDef& b : scene.bodies) {
        JsonValue body = JsonValue::object();
        body.set("name", b.name);
        if (b.anchor)
            body.set("anchor", true);
        body.set("shape", shapeToJson(b.shape));
        if (b.material != defaults.material)
            body.set("material", b.material);
        const std::pair<const char*, const std::optional<Real>*> overrides[] = {
            {"density", &b.density}, {"mass", &b.mass}, {"friction", &b.friction}, {"restitution", &b.restitution}};
        for (const auto& [key, value] : overrides)
            if (value->has_value())
                body.set(key, **value);
        body.set("position", vec3(b.position));
        body.set("orientation",
                 JsonValue(JsonValue::Array{b.orientation.w, b.orientation.x, b.orientation.y, b.orientation.z}));
        if (b.velocity != defaults.velocity)
            body.set("velocity", vec3(b.velocity));
        if (b.angularVelocity != defaults.angularVelocity)
            body.set("angular_velocity", vec3(b.angularVelocity));
        bodies.push(std::move(body));
    }
    return root;
}

std::string writeSceneJson(const Scene& scene) {
    return writeJson(sceneToJson(scene));
}

Status writeSceneFile(const Scene& scene, const std::string& path) {
    const JsonValue doc = sceneToJson(scene);
    std::string where;
    if (findNonFinite(doc, where)) {
        // where is like ".bodies[3].position[1]": name the body when it is one.
        std::string context;
        constexpr std::string_view kBodies = ".bodies[";
        if (where.rfind(kBodies, 0) == 0) {
            const size_t index = std::stoul(where.substr(kBodies.size()));
            context = "body " + quotedName(scene.bodies[index].name) + " (index " + std::to_string(index) + "): ";
        }
        return Error{path, 0, {}, context + "not a finite number at " + where.substr(1)};
    }
    return writeFileAtomically(path, std::string_view(writeJson(doc)));
}

} // namespace rl
