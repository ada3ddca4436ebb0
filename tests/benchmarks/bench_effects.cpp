// Prints what each effect costs: every scene is stepped with its auto effects and with each effect toggled against
// auto (median ms per step, and the work counters), so the time an effect costs or saves can be read off in one run.
#include "io/SceneImport.h"
#include "scene/SceneLibrary.h"
#include "world/World.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace rl;

namespace {

struct Measured {
    double msPerStep = 0.0; // median wall clock
    uint64_t frictionRows = 0, restitutionRows = 0, integrated = 0, ccdBodies = 0;
    std::string effects;
};

Measured measure(const Scene& scene, const EffectsSetting& effects, int frames) {
    WorldOptions options;
    options.effects = effects;
    Result<World> created = World::create(scene, options);
    if (!created) {
        std::fprintf(stderr, "%s\n", created.error().toString().c_str());
        std::exit(1);
    }
    World& w = created.value();
    std::vector<double> times;
    for (int f = 0; f < frames; ++f) {
        const auto start = std::chrono::steady_clock::now();
        w.step();
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    Measured m;
    m.msPerStep = times[times.size() / 2];
    m.frictionRows = w.profile().counter(Counter::FrictionRows);
    m.restitutionRows = w.profile().counter(Counter::RestitutionRows);
    m.integrated = w.profile().counter(Counter::IntegratedBodies);
    m.ccdBodies = w.profile().counter(Counter::CcdBodies);
    m.effects = w.effects().toString();
    return m;
}

} // namespace

int main(int argc, char** argv) {
    int frames = 120;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--frames") == 0)
            frames = std::max(1, std::atoi(argv[i + 1]));
    std::vector<std::pair<std::string, Scene>> scenes;
    scenes.emplace_back("pyramid20", *scenes::byName("pyramid20"));
    scenes.emplace_back("boxes1000", *scenes::byName("boxes1000"));
    Result<Scene> ramps = importScene(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
    if (ramps)
        scenes.emplace_back("ramps", ramps.value());

    std::printf("%-10s %-12s %-8s %10s %10s %14s %14s %14s %14s\n", "scene", "effect", "toggle", "ms/step", "auto ms",
                "delta ms", "friction_rows", "integrated", "ccd_bodies");
    for (const auto& [name, scene] : scenes) {
        const Measured base = measure(scene, EffectsSetting{}, frames);
        std::printf("%-10s %-12s %-8s %10.3f %10.3f %14s %14llu %14llu %14llu   (auto: %s)\n", name.c_str(), "-", "-",
                    base.msPerStep, base.msPerStep, "-", (unsigned long long)base.frictionRows,
                    (unsigned long long)base.integrated, (unsigned long long)base.ccdBodies, base.effects.c_str());
        for (int e = 0; e < kEffectCount; ++e) {
            const Effect effect = static_cast<Effect>(e);
            const bool autoOn = base.effects.find(std::string(effectName(effect))) != std::string::npos;
            EffectsSetting setting;
            setting.set(effect, autoOn ? EffectMode::Off : EffectMode::On);
            const Measured m = measure(scene, setting, frames);
            // Positive: the toggled run is slower than auto. For an effect auto skipped, that is what skipping it
            // saves; for an effect auto kept, a negative value is what it costs (its results differ when it is off).
            char savedText[32];
            std::snprintf(savedText, sizeof savedText, "%+.3f", m.msPerStep - base.msPerStep);
            std::printf("%-10s %-12s %-8s %10.3f %10.3f %14s %14llu %14llu %14llu\n", name.c_str(),
                        std::string(effectName(effect)).c_str(), autoOn ? "off" : "on", m.msPerStep, base.msPerStep,
                        savedText, (unsigned long long)m.frictionRows, (unsigned long long)m.integrated,
                        (unsigned long long)m.ccdBodies);
        }
    }
    return 0;
}
