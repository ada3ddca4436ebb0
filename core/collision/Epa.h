// EPA: penetration depth, normal and witness points of two overlapping convex shapes, grown from GJK's simplex.
// The polytope's face and vertex budgets are bounded; running out of them is reported so that callers fall back.
#pragma once

#include "collision/Gjk.h"
#include "collision/Shape.h"

namespace rl {

struct EpaOptions {
    int maxIterations = 128;
    // Face budget of the polytope (dead faces included); it also bounds the memory. In a 200-pair sample of two
    // overlapping 2,000-vertex hulls, one pair (nearly coincident, so almost every direction is as deep) ran out
    // of a 512-face budget; with 1024 it stops at the iteration bound instead and keeps its bracketed answer.
    int maxFaces = 1024;
    // Converged when support distance and face distance agree to this fraction of the problem's size.
    Real relativeTolerance = 1e-12;
};

enum class EpaStatus : uint8_t {
    Converged,
    BudgetExceeded, // iterations or faces ran out; the result is only a lower bound
    Degenerate      // the Minkowski difference is flat here, or the horizon was not a simple loop
};

struct EpaResult {
    EpaStatus status = EpaStatus::Degenerate;
    Real depth = 0.0;           // penetration depth of the full shapes (radii included), >= 0 up to rounding
    Vec3 normal{0.0, 1.0, 0.0}; // unit, from A to B: moving B by depth * normal separates the shapes
    Vec3 pointA{0.0};           // deepest point of A inside B, world
    Vec3 pointB{0.0};           // deepest point of B inside A, world; pointA - pointB == depth * normal
    int iterations = 0;
    int faces = 0;
};

// `gjk` must come from gjkDistance on the same input with cores overlapping (coreDistance == 0).
EpaResult epaPenetration(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                         const GjkResult& gjk, const EpaOptions& options = {});

} // namespace rl
