// Continuous collision: time of impact by conservative advancement on GJK distance, for bodies moving with linear
// and angular velocity over a step, and the criterion that says which bodies need it.
#pragma once

#include "collision/Shape.h"

namespace rl {

// A body's motion over one step: the pose at the start and constant velocities (angular about the shape origin,
// which is the centre of mass; world axes).
struct Motion {
    Transform start;
    Vec3 linearVelocity{0.0};
    Vec3 angularVelocity{0.0};

    // The pose after `time` seconds: translation plus rotation by the exact exponential of omega * time.
    Transform at(Real time) const;
};

struct ToiOptions {
    // Advancement stops this far from contact (m), so that the solver sees a speculative contact, not an overlap.
    Real targetSeparation = 0.001;
    // Accept any distance in [target - tolerance, target + tolerance] as the contact.
    Real tolerance = 0.00025;
    // Each advancement is conservative, so stopping early is safe: the result is then a time the bodies do reach
    // without touching. The spinning-plank test needed at most 12 (tst_ccd), so 64 leaves a wide margin.
    int maxIterations = 64;
};

enum class ToiStatus : uint8_t {
    Hit,         // fraction is when the distance reaches targetSeparation
    Miss,        // no contact during the step (fraction = 1)
    Overlapping, // already closer than the target at the start (fraction = 0)
    NotConverged // iterations ran out; fraction is a safe time before contact
};

struct ToiResult {
    ToiStatus status = ToiStatus::Miss;
    Real fraction = 1.0;        // of the step, in [0, 1]
    Vec3 normal{0.0, 1.0, 0.0}; // from A to B at the time of impact
    Real distance = 0.0;        // between the shapes at `fraction`
    int iterations = 0;
};

ToiResult timeOfImpact(const Shape& a, const Motion& motionA, const Shape& b, const Motion& motionB, Real dt,
                       const ToiOptions& options = {});

// A body needs CCD when one step can carry any of its points further than kCcdExtentFraction of its smallest
// extent: then a contact can be missed entirely (tunnelling) rather than found late. The bound on a point's
// travel is (|v| + |omega| * boundingRadius) * dt. A quarter of the extent keeps at least four steps inside any
// wall as thick as the body, which the speculative margin then covers; it keeps CCD off for resting and slow
// bodies.
inline constexpr Real kCcdExtentFraction = 0.25;
bool needsCcd(const Shape& shape, const Vec3& linearVelocity, const Vec3& angularVelocity, Real dt,
              Real extentFraction = kCcdExtentFraction);

} // namespace rl
