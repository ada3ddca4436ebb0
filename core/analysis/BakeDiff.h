// Re-bake diff: compares two bakes of the same scene frame by frame and body by body, to find where a change of
// settings, code or machine made a run diverge. Used by `rigidlab-cli diff` and the editor's Compare bakes view.
#pragma once

#include "bake/Bake.h"
#include "math/Types.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rl {

struct BakeDiffOptions {
    // A body diverges in a frame when its position moved by more than positionTolerance (m) or its rotation by more
    // than rotationToleranceDegrees between the two bakes. The defaults (10 µm, 0.001°) are far below any motion that
    // matters and above the rounding of frames stored as float (about 1e-7 relative: 1 µm at 10 m from the origin).
    // A bake and the same bake written to a .bake file and read back compare exactly equal (tst_bakediff).
    Real positionTolerance = 1e-5;
    Real rotationToleranceDegrees = 1e-3;
};

// One body's largest differences over the compared frames. Positions are the bodies' vertex means (what a .bake
// stores, so that bakes with and without known centres of mass compare alike); rotations are the angle of the
// relative rotation between the two bakes' rotations since frame 0.
struct BakeBodyDiff {
    size_t body = 0;
    std::string name;
    Real maxPositionDelta = 0.0; // m
    size_t maxPositionFrame = 0;
    Real maxRotationDegrees = 0.0;
    size_t maxRotationFrame = 0;
    std::optional<size_t> firstDivergingFrame; // first frame over a tolerance, if any
};

struct BakeDiffResult {
    // Empty when the bakes can be compared; otherwise why not (different body counts or frame rates), and then
    // nothing else is filled in.
    std::string incompatibility;
    size_t framesA = 0, framesB = 0;
    size_t framesCompared = 0; // the frames both bakes have
    std::optional<size_t> firstDivergingFrame;
    std::optional<size_t> firstDivergingBody; // the body that crossed a tolerance first (lowest index in that frame)
    std::vector<BakeBodyDiff> bodies;         // one per body, in body order

    bool comparable() const { return incompatibility.empty(); }
    // Comparable, the same number of frames, and no frame over a tolerance.
    bool equal() const { return comparable() && framesA == framesB && !firstDivergingFrame; }
};

// Angle of the rotation that takes a to b, in degrees, computed so that equal quaternions give exactly 0.
Real rotationDeltaDegrees(const glm::quat& a, const glm::quat& b);

BakeDiffResult diffBakes(const Bake& a, const Bake& b, const BakeDiffOptions& options = {});

// Plain text for people: a summary line, then the bodies that differ at all, largest position delta first.
std::string formatBakeDiff(const BakeDiffResult& result, const BakeDiffOptions& options);
// body,name,first_diverging_frame,max_position_delta,max_position_frame,max_rotation_deg,max_rotation_frame, one
// row per body in body order; an empty first_diverging_frame means within tolerance throughout.
std::string bakeDiffCsv(const BakeDiffResult& result);

} // namespace rl
