#include "edit/Primitives.h"

#include "geometry/MeshTools.h"

#include <QCoreApplication>

namespace rl {

namespace {
constexpr double kHalfSize = 0.5; // every primitive fits a 1 m cube
constexpr int kSegments = 32;
} // namespace

BodyDef makePrimitiveBody(Primitive kind) {
    BodyDef body;
    switch (kind) {
    case Primitive::Box:
        body.name = "Cube"; // Blender's name for its box
        body.shape.type = ShapeType::Box;
        body.shape.halfExtents = Vec3(kHalfSize);
        break;
    case Primitive::Sphere:
        body.name = "Sphere";
        body.shape.type = ShapeType::Sphere;
        body.shape.radius = kHalfSize;
        break;
    case Primitive::Cylinder:
        body.name = "Cylinder";
        body.shape.type = ShapeType::Hull;
        body.shape.points = makeCylinderMesh(kHalfSize, kHalfSize, kSegments).vertices;
        break;
    case Primitive::Cone:
        body.name = "Cone";
        body.shape.type = ShapeType::Hull;
        body.shape.points = makeConeMesh(kHalfSize, kHalfSize, kSegments).vertices;
        break;
    }
    return body;
}

QString primitiveLabel(Primitive kind) {
    switch (kind) {
    case Primitive::Box:
        return QCoreApplication::translate("rl::Primitives", "&Cube");
    case Primitive::Sphere:
        return QCoreApplication::translate("rl::Primitives", "&Sphere");
    case Primitive::Cylinder:
        return QCoreApplication::translate("rl::Primitives", "C&ylinder");
    case Primitive::Cone:
        return QCoreApplication::translate("rl::Primitives", "C&one");
    }
    return {};
}

double primitiveHalfHeight(Primitive) {
    return kHalfSize;
}

} // namespace rl
