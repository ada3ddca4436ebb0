// The bodies the Add menu creates: a 1 m cube, a sphere, a cylinder and a cone of 1 m diameter and height.
// Cylinders and cones are convex hulls of the core's primitive meshes (32 segments), so they collide as drawn.
#pragma once

#include "scene/BodyDef.h"

#include <QString>

namespace rl {

enum class Primitive { Box, Sphere, Cylinder, Cone };

// A dynamic body centred on the origin (shape coordinates), named "Cube", "Sphere", "Cylinder" or "Cone".
BodyDef makePrimitiveBody(Primitive kind);
// The menu text of each primitive, translated.
QString primitiveLabel(Primitive kind);
// Half its height: the Add action rests a new body on the ground or on top of the selection.
double primitiveHalfHeight(Primitive kind);

} // namespace rl
