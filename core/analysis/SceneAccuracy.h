// Accuracy of the current scene under several settings: the scene is run under each (integrator, substeps) pair and
// compared frame by frame with a fine reference run, giving the position error against the CPU time each run took.
// It answers "what do more substeps or another integrator buy on this scene", which the exact-solution study in
// Accuracy.h answers only for single bodies.
#pragma once

#include "common/Result.h"
#include "math/Types.h"
#include "scene/Scene.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace rl {

struct SceneAccuracySetting {
    Integrator integrator = Integrator::SymplecticEuler;
    int substeps = 8;
    bool operator==(const SceneAccuracySetting&) const = default;
};

// The grid the editor offers: substeps 1, 2, 4, 8, 16 under each of the four integrators.
std::vector<SceneAccuracySetting> defaultSceneAccuracySettings();

struct SceneAccuracyOptions {
    Real seconds = 2.0; // simulated duration
    std::vector<SceneAccuracySetting> settings = defaultSceneAccuracySettings();
    // The reference: RK4 at 64 substeps, four times finer than the finest compared setting. Wherever contacts act
    // every integrator is first order (README, Simulation), so only more substeps make the reference better there;
    // in free flight RK4 is fourth order, so it is also the best reference for bodies in the air. At equal substeps
    // it is never less accurate than the other three, which is what a reference needs.
    SceneAccuracySetting reference{Integrator::Rk4, 64};
    // At most this many dynamic bodies are simulated (every anchor is kept, then the first dynamic bodies in scene
    // order): the scene is run once per setting plus the reference, so large scenes are cut down to keep the
    // comparison interactive.
    size_t maxDynamicBodies = 200;
    // Called with (work done, total work) in substep-frames; returning false cancels (the result is then an Error).
    std::function<bool(size_t, size_t)> progress;
};

struct SceneAccuracyRow {
    SceneAccuracySetting setting;
    // Centre-of-mass position error against the reference over every simulated dynamic body and every frame after
    // frame 0: the root mean square, and the largest single value (m). Infinite when the run produced NaN.
    Real rmsError = 0.0;
    Real maxError = 0.0;
    Real cpuSeconds = 0.0; // the run's stepping time on its thread (World creation and the comparison excluded)
};

struct SceneAccuracyResult {
    std::vector<SceneAccuracyRow> rows; // in the order of the settings
    Real referenceCpuSeconds = 0.0;
    size_t frames = 0; // frames after frame 0
    Real fps = 0.0;
    size_t dynamicBodies = 0;        // simulated
    size_t dynamicBodiesInScene = 0; // in the scene; more than dynamicBodies when it was cut down
};

// Errors: the scene cannot be simulated (the World's error), it has no dynamic body, the options are empty or
// invalid, or the run was cancelled.
Result<SceneAccuracyResult> runSceneAccuracy(const Scene& scene, const SceneAccuracyOptions& options = {});

// setting,integrator,substeps,rms_error,max_error,cpu_seconds with the reference as the first row (error 0).
std::string sceneAccuracyCsv(const SceneAccuracyResult& result, const SceneAccuracySetting& reference);

} // namespace rl
