#include "analysis/SceneAccuracy.h"

#include "io/NumberFormat.h"
#include "world/World.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>

namespace rl {

std::vector<SceneAccuracySetting> defaultSceneAccuracySettings() {
    std::vector<SceneAccuracySetting> settings;
    for (Integrator integrator :
         {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4})
        for (int substeps : {1, 2, 4, 8, 16})
            settings.push_back({integrator, substeps});
    return settings;
}

namespace {

// CPU time of the calling thread: the world steps on one thread, and other processes on a loaded machine then do
// not count. Falls back to the wall clock where the thread clock is missing.
Real threadSeconds() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec ts{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) == 0)
        return static_cast<Real>(ts.tv_sec) + static_cast<Real>(ts.tv_nsec) * 1e-9;
#endif
    return std::chrono::duration<Real>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

} // namespace

Result<SceneAccuracyResult> runSceneAccuracy(const Scene& input, const SceneAccuracyOptions& options) {
    if (options.settings.empty())
        return Error{{}, 0, {}, "no settings to compare"};
    if (!(options.seconds > 0.0) || !std::isfinite(options.seconds))
        return Error{{}, 0, {}, "the duration must be a positive number of seconds"};
    for (const SceneAccuracySetting& s : options.settings)
        if (s.substeps < 1)
            return Error{{}, 0, {}, "substeps must be at least 1"};
    if (options.reference.substeps < 1)
        return Error{{}, 0, {}, "the reference needs at least 1 substep"};

    SceneAccuracyResult result;
    Scene scene = input;
    scene.bodies.clear();
    for (const BodyDef& body : input.bodies) {
        if (!body.anchor && ++result.dynamicBodiesInScene > options.maxDynamicBodies)
            continue;
        scene.bodies.push_back(body);
    }
    result.dynamicBodies = std::min(result.dynamicBodiesInScene, options.maxDynamicBodies);
    if (result.dynamicBodies == 0)
        return Error{input.sourcePath, 0, {}, "the scene has no dynamic body to compare"};

    std::vector<size_t> dynamic;
    for (size_t i = 0; i < scene.bodies.size(); ++i)
        if (!scene.bodies[i].anchor)
            dynamic.push_back(i);

    const Real fps = scene.world.fps;
    result.fps = fps;
    result.frames = std::max<size_t>(1, static_cast<size_t>(std::llround(options.seconds * fps)));

    size_t total = options.reference.substeps;
    for (const SceneAccuracySetting& s : options.settings)
        total += static_cast<size_t>(s.substeps);
    total *= result.frames;
    size_t done = 0;

    // Runs one setting; `perFrame` sees the world after each frame. Returns the stepping CPU time.
    auto run = [&](const SceneAccuracySetting& setting, auto&& perFrame) -> Result<Real> {
        WorldOptions worldOptions;
        worldOptions.integrator = setting.integrator;
        worldOptions.substeps = setting.substeps;
        Result<World> created = World::create(scene, worldOptions);
        if (!created)
            return created.error();
        World& world = created.value();
        Real cpu = 0.0;
        for (size_t f = 1; f <= result.frames; ++f) {
            const Real start = threadSeconds();
            world.step();
            cpu += threadSeconds() - start;
            perFrame(world, f);
            done += static_cast<size_t>(setting.substeps);
            if (options.progress && !options.progress(done, total))
                return Error{{}, 0, {}, "cancelled"};
        }
        return cpu;
    };

    {
        // Reference centres of mass, [frame - 1][dynamic body].
        std::vector<Vec3> reference(result.frames * dynamic.size());
        Result<Real> refCpu = run(options.reference, [&](const World& world, size_t f) {
            for (size_t k = 0; k < dynamic.size(); ++k)
                reference[(f - 1) * dynamic.size() + k] = world.centerOfMass(dynamic[k]);
        });
        if (!refCpu)
            return refCpu.error();
        result.referenceCpuSeconds = *refCpu;

        for (const SceneAccuracySetting& setting : options.settings) {
            Real sumSquares = 0.0, maxError = 0.0;
            bool finite = true;
            Result<Real> cpu = run(setting, [&](const World& world, size_t f) {
                for (size_t k = 0; k < dynamic.size(); ++k) {
                    const Real e =
                        glm::length(world.centerOfMass(dynamic[k]) - reference[(f - 1) * dynamic.size() + k]);
                    if (!std::isfinite(e)) {
                        finite = false;
                        continue;
                    }
                    sumSquares += e * e;
                    maxError = std::max(maxError, e);
                }
            });
            if (!cpu)
                return cpu.error();
            SceneAccuracyRow row;
            row.setting = setting;
            row.cpuSeconds = *cpu;
            const Real inf = std::numeric_limits<Real>::infinity();
            row.rmsError = finite ? std::sqrt(sumSquares / static_cast<Real>(result.frames * dynamic.size())) : inf;
            row.maxError = finite ? maxError : inf;
            result.rows.push_back(row);
        }
    }
    return result;
}

std::string sceneAccuracyCsv(const SceneAccuracyResult& result, const SceneAccuracySetting& reference) {
    std::string text = "setting,integrator,substeps,rms_error,max_error,cpu_seconds\n";
    auto row = [&](const char* kind, const SceneAccuracySetting& s, Real rms, Real max, Real cpu) {
        text += std::string(kind) + ',' + std::string(integratorName(s.integrator)) + ',' + std::to_string(s.substeps) +
                ',' + formatDouble(rms) + ',' + formatDouble(max) + ',' + formatDouble(cpu) + '\n';
    };
    row("reference", reference, 0.0, 0.0, result.referenceCpuSeconds);
    for (const SceneAccuracyRow& r : result.rows)
        row("compared", r.setting, r.rmsError, r.maxError, r.cpuSeconds);
    return text;
}

} // namespace rl
