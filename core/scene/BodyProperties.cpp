#include "scene/BodyProperties.h"

#include "geometry/MassProperties.h"
#include "geometry/MeshTools.h"

#include <cmath>

namespace rl {

namespace {

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const Quat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

Error bodyError(const BodyDef& body, std::string message) {
    Error e;
    e.object = body.name;
    e.message = std::move(message);
    return e;
}

// Blender's legacy OBJ exporter (3.4's bpy.ops.export_scene.obj) writes an object whose mesh has another name as
// "o <object>_<mesh>": a floor renamed "Anchor" in the outliner, its mesh still "Plane", comes out as "Anchor_Plane",
// which the anchor rule (DESIGN.md §3, the original project's) makes dynamic. Such a dynamic body is told what to do.
// (One phrase, without the names, so that the editor can translate it: ui/document/CoreText.cpp.)
constexpr const char* kLegacyAnchorHint =
    "named as Blender's legacy OBJ exporter names an object Anchor whose mesh has another name (object_mesh), which "
    "the anchor rule makes dynamic: for an anchor, give the mesh the object's name or export with File > Export > "
    "Wavefront (.obj)";

bool hasLegacyAnchorName(const BodyDef& body) {
    const size_t cut = body.name.find('_');
    return !body.anchor && cut != std::string::npos && cut + 1 < body.name.size() &&
           isAnchorName(std::string_view(body.name).substr(0, cut));
}

} // namespace

std::vector<Vec3> shapePoints(const ShapeDef& shape) {
    switch (shape.type) {
    case ShapeType::Box: {
        std::vector<Vec3> corners;
        corners.reserve(8);
        for (int i = 0; i < 8; ++i)
            corners.emplace_back((i & 1 ? 1.0 : -1.0) * shape.halfExtents.x, (i & 2 ? 1.0 : -1.0) * shape.halfExtents.y,
                                 (i & 4 ? 1.0 : -1.0) * shape.halfExtents.z);
        return corners;
    }
    case ShapeType::Sphere:
        return {Vec3(0.0)};
    case ShapeType::Hull:
    case ShapeType::Mesh:
        return shape.points;
    }
    return {};
}

Result<BodyProperties> computeBodyProperties(const Scene& scene, const BodyDef& body) {
    if (!finite(body.position) || !finite(body.orientation) || !finite(body.velocity) || !finite(body.angularVelocity))
        return bodyError(body, "position, orientation or velocity is not a finite number");
    const Real qn = glm::length(body.orientation);
    if (qn < 1e-12)
        return bodyError(body, "orientation quaternion has zero length");
    BodyDef def = body;
    def.orientation = body.orientation / qn;
    const Mat3 rotation = glm::mat3_cast(def.orientation);

    const MaterialDef material = scene.effectiveMaterial(body);
    if (!(material.density > 0.0) || !std::isfinite(material.density))
        return bodyError(body, "density must be a positive number (is " + std::to_string(material.density) + ")");
    if (body.mass && (!(*body.mass > 0.0) || !std::isfinite(*body.mass)))
        return bodyError(body, "mass must be a positive number (is " + std::to_string(*body.mass) + ")");

    BodyProperties props;
    const std::vector<Vec3> points = shapePoints(body.shape);
    for (const Vec3& p : points)
        if (!finite(p))
            return bodyError(body, "shape has a vertex that is not a finite number");

    MassProperties unit; // per unit density, shape coordinates
    Vec3 localMean(0.0);
    if (body.shape.type == ShapeType::Sphere) {
        const Real r = body.shape.radius;
        if (!(r > 0.0) || !std::isfinite(r))
            return bodyError(body, "sphere radius must be positive");
        unit.volume = 4.0 / 3.0 * kPi * r * r * r;
        unit.area = 4.0 * kPi * r * r;
        const Real moment = 0.4 * unit.volume * r * r;
        unit.inertia = Mat3(moment);
    } else {
        if (body.shape.type == ShapeType::Box &&
            !(body.shape.halfExtents.x > 0.0 && body.shape.halfExtents.y > 0.0 && body.shape.halfExtents.z > 0.0))
            return bodyError(body, "box half extents must be positive");
        if (points.empty())
            return bodyError(body, "shape has no vertices");
        props.hull = computeConvexHull(points);
        props.hullVertexCount = static_cast<int>(props.hull.vertices.size());
        for (const Vec3& p : points)
            localMean += p;
        localMean /= static_cast<Real>(points.size());
        if (props.hull.dimension == HullDimension::Flat) {
            if (!body.anchor)
                return bodyError(body, std::string("a dynamic body needs volume, but all its points lie in one plane "
                                                   "(fewer than 4 non-coplanar points); ") +
                                           (hasLegacyAnchorName(body) ? std::string("it is ") + kLegacyAnchorHint
                                                                      : "make it an anchor or give it thickness"));
            props.flat = true;
        } else if (props.hull.dimension != HullDimension::Solid) {
            return bodyError(body, "shape is degenerate (its points lie on a line or at one point): "
                                   "it needs at least 3 points that span a plane (anchors) or 4 that span a volume");
        }
        unit = hullMassProperties(props.hull);
        if (body.shape.type == ShapeType::Mesh && !props.flat && !body.shape.triangles.empty()) {
            props.concave = isConcave(body.shape.points, body.shape.triangles, props.hull);
            if (props.concave)
                props.warnings.push_back("concave: simulated as its convex hull");
        }
    }

    props.volume = unit.volume;
    if (props.flat) {
        props.density = material.density;
        props.mass = 0.0;
    } else if (body.mass) {
        props.mass = *body.mass;
        props.density = props.mass / props.volume;
    } else {
        props.density = material.density;
        props.mass = material.density * props.volume;
    }
    props.com = shapeToWorld(def, unit.centroid);
    props.inertia = rotateInertia(unit.inertia * props.density, rotation);
    Mat3 axes;
    principalAxes(props.inertia, props.principalMoments, axes);
    props.vertexMean = shapeToWorld(def, localMean);

    if (hasLegacyAnchorName(body))
        props.warnings.push_back(kLegacyAnchorHint);
    if (!body.anchor && props.volume > 0.0) {
        // Bodies under 2 cm are hard to keep stable at 60 Hz; say so early (the pre-flight check repeats it).
        const Real size = std::cbrt(props.volume);
        if (size < 0.02)
            props.warnings.push_back("smaller than 2 cm: may need more substeps");
    }
    return props;
}

} // namespace rl
