// Core numeric types and the conventions every RigidLab module follows.
// Y-up, right-handed, SI units (m, kg, s, rad); quaternions are written and read w-first.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>

namespace rl {

// The core computes in double: mass properties must match closed forms to 1e-9, and long runs must not drift.
// Baked frames are stored as float (see bake/Bake.h) because that is what playback and exports need.
using Real = double;
using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4;
using Mat3 = glm::dmat3; // column-major, as glm: m[c][r]
using Quat = glm::dquat; // glm's constructor order is (w, x, y, z)

inline constexpr Real kPi = 3.14159265358979323846;

inline Quat identityQuat() { return Quat(1.0, 0.0, 0.0, 0.0); }

} // namespace rl
