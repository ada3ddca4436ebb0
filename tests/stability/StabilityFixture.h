// Shared helpers of the stability suites: build a world from a named scene at default settings, run it, and
// measure what the thresholds of the hard cases are about (drift, speeds, penetration, energy, NaN).
#pragma once

#include "world/World.h"

#include <QtGlobal>

#include <cmath>
#include <cstdlib>
#include <functional>

namespace rl::test {

inline World makeWorld(const Scene& scene, const WorldOptions& given = {}) {
    WorldOptions options = given;
    // Experiments only: RL_TEST_SUBSTEPS / RL_TEST_ITERATIONS / RL_TEST_INTEGRATOR override the defaults the cases
    // are judged at.
    if (const char* s = std::getenv("RL_TEST_SUBSTEPS"); s && !options.substeps)
        options.substeps = std::atoi(s);
    if (const char* s = std::getenv("RL_TEST_ITERATIONS"); s && !options.iterations)
        options.iterations = std::atoi(s);
    if (const char* s = std::getenv("RL_TEST_INTEGRATOR"); s && !options.integrator)
        options.integrator = parseIntegrator(s);
    Result<World> w = World::create(scene, options);
    if (!w)
        qFatal("%s", w.error().toString().c_str());
    return std::move(w).value();
}

inline bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline Real horizontal(const Vec3& a, const Vec3& b) {
    return std::hypot(a.x - b.x, a.z - b.z);
}

// Kinetic plus potential energy of the dynamic bodies (J), as the world reports them.
inline Real totalEnergy(const World& w) {
    const FrameDiagnostics d = w.diagnostics();
    return d.kineticEnergy + d.potentialEnergy;
}

struct RunStats {
    Real maxSpeedLastSecond = 0.0; // linear speed of any dynamic body in the last second
    Real maxPenetration = 0.0;     // deepest contact seen in the run
    bool allFinite = true;
    int firstNonFiniteFrame = -1;
};

// Steps `frames` frames; `each` (optional) is called after every frame with the frame number.
inline RunStats run(World& w, int frames, const std::function<void(int)>& each = {}) {
    RunStats stats;
    const int lastSecond = frames - static_cast<int>(std::lround(w.fps()));
    for (int f = 0; f < frames; ++f) {
        w.step();
        const FrameDiagnostics d = w.diagnostics();
        stats.maxPenetration = std::max(stats.maxPenetration, d.maxPenetration);
        for (size_t i = 0; i < w.bodyCount(); ++i) {
            if (w.isAnchor(i))
                continue;
            if (!finite(w.centerOfMass(i)) || !finite(w.linearVelocity(i))) {
                if (stats.allFinite)
                    stats.firstNonFiniteFrame = f;
                stats.allFinite = false;
            }
            if (f >= lastSecond)
                stats.maxSpeedLastSecond = std::max(stats.maxSpeedLastSecond, glm::length(w.linearVelocity(i)));
        }
        if (each)
            each(f);
    }
    return stats;
}

} // namespace rl::test
