// Prints what each effect costs: every scene is stepped with its auto effects and with each effect toggled against
// auto, so that the time an effect costs, or that auto saves by skipping it, can be read off in one run.
//
// The two worlds of a comparison are stepped by turns, frame by frame, and each of them --runs times; a frame counts
// at its least time over the runs. The host's speed then changes for both alike (on this project's shared machines
// the same run moved by a third within minutes), and a frame slowed in one run counts at its speed in another.
// `same` says whether the toggled run ended in auto's state, bit for bit: then the effect changed no motion in that
// scene, and the difference is the cost of its stage alone. Where auto skipped the effect, that is what skipping it
// saves. Where the toggle changes the motion (friction off lets a pile slide on), the difference also holds the work
// of the other motion.
#include "io/SceneImport.h"
#include "scene/SceneLibrary.h"
#include "world/World.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace rl;

namespace {

struct Measured {
    double msPerStep = 0.0; // the mean over the frames of each frame's least time over the runs
    uint64_t frictionRows = 0, restitutionRows = 0, integrated = 0, ccdBodies = 0; // of the first run
    uint64_t hash = 0;
};

World makeWorld(const Scene& scene, const EffectsSetting& effects) {
    WorldOptions options;
    options.effects = effects;
    Result<World> created = World::create(scene, options);
    if (!created) {
        std::fprintf(stderr, "%s\n", created.error().toString().c_str());
        std::exit(1);
    }
    return std::move(created).value();
}

// Steps a world with the auto effects and one with `toggled` by turns (see the file comment).
std::pair<Measured, Measured> measurePair(const Scene& scene, const EffectsSetting& toggled, int frames, int runs) {
    using Clock = std::chrono::steady_clock;
    const EffectsSetting settings[2] = {EffectsSetting{}, toggled};
    std::vector<double> best[2];
    for (std::vector<double>& b : best)
        b.assign(static_cast<size_t>(frames), std::numeric_limits<double>::infinity());
    Measured out[2];
    for (int run = 0; run < runs; ++run) {
        World worlds[2] = {makeWorld(scene, settings[0]), makeWorld(scene, settings[1])};
        for (int f = 0; f < frames; ++f)
            for (int k = 0; k < 2; ++k) {
                const Clock::time_point start = Clock::now();
                worlds[k].step();
                const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
                double& least = best[k][static_cast<size_t>(f)];
                least = std::min(least, ms);
            }
        if (run > 0)
            continue;
        for (int k = 0; k < 2; ++k) {
            const Profile& p = worlds[k].profile();
            out[k].frictionRows = p.counter(Counter::FrictionRows);
            out[k].restitutionRows = p.counter(Counter::RestitutionRows);
            out[k].integrated = p.counter(Counter::IntegratedBodies);
            out[k].ccdBodies = p.counter(Counter::CcdBodies);
            out[k].hash = worlds[k].stateHash();
        }
    }
    for (int k = 0; k < 2; ++k) {
        double sum = 0.0;
        for (double ms : best[k])
            sum += ms;
        out[k].msPerStep = sum / frames;
    }
    return {out[0], out[1]};
}

// boxes1000 with every body's friction zero: auto skips the friction rows.
Scene frictionlessBoxes() {
    Scene s = *scenes::byName("boxes1000");
    for (BodyDef& b : s.bodies)
        b.friction = 0.0;
    return s;
}

// boxes1000 as frictionless balls, each as wide as its box's narrowest side: auto skips rotation and friction.
Scene frictionlessBalls() {
    Scene s = frictionlessBoxes();
    for (BodyDef& b : s.bodies) {
        if (b.anchor)
            continue;
        const Vec3 half = b.shape.halfExtents;
        b.shape = ShapeDef{};
        b.shape.type = ShapeType::Sphere;
        b.shape.radius = std::min({half.x, half.y, half.z});
    }
    return s;
}

} // namespace

int main(int argc, char** argv) {
    int frames = 120, runs = 3;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0)
            frames = std::max(1, std::atoi(argv[i + 1]));
        else if (std::strcmp(argv[i], "--runs") == 0)
            runs = std::max(1, std::atoi(argv[i + 1]));
    }
    std::vector<std::pair<std::string, Scene>> scenes;
    scenes.emplace_back("pyramid20", *scenes::byName("pyramid20"));
    scenes.emplace_back("boxes1000", *scenes::byName("boxes1000"));
    scenes.emplace_back("boxes_mu0", frictionlessBoxes());
    scenes.emplace_back("balls_mu0", frictionlessBalls());
    Result<Scene> ramps = importScene(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
    if (ramps)
        scenes.emplace_back("ramps", ramps.value());

    std::printf("bench_effects: %d frames, %d runs of each world by turns; ms = mean over the frames of each frame's "
                "least time\n",
                frames, runs);
    std::printf("%-10s %-12s %-6s %9s %9s %9s %7s %5s %14s %14s %12s %10s\n", "scene", "effect", "toggle", "auto_ms",
                "ms", "delta_ms", "ratio", "same", "friction_rows", "restit_rows", "integrated", "ccd_bodies");
    for (const auto& [name, scene] : scenes) {
        const ActiveEffects autoEffects = makeWorld(scene, EffectsSetting{}).effects();
        std::printf("%-10s auto: %s\n", name.c_str(), autoEffects.toString().c_str());
        for (int e = 0; e < kEffectCount; ++e) {
            const Effect effect = static_cast<Effect>(e);
            const bool autoOn = autoEffects.has(effect);
            EffectsSetting setting;
            setting.set(effect, autoOn ? EffectMode::Off : EffectMode::On);
            const auto [base, m] = measurePair(scene, setting, frames, runs);
            // Positive: the toggled run is slower than auto. For an effect auto skipped, that is what skipping it
            // saves; for an effect auto kept, a negative value is what it costs.
            std::printf("%-10s %-12s %-6s %9.3f %9.3f %+9.3f %7.3f %5s %14llu %14llu %12llu %10llu\n", name.c_str(),
                        std::string(effectName(effect)).c_str(), autoOn ? "off" : "on", base.msPerStep, m.msPerStep,
                        m.msPerStep - base.msPerStep, m.msPerStep / base.msPerStep, m.hash == base.hash ? "yes" : "no",
                        (unsigned long long)m.frictionRows, (unsigned long long)m.restitutionRows,
                        (unsigned long long)m.integrated, (unsigned long long)m.ccdBodies);
            std::fflush(stdout);
        }
    }
    return 0;
}
