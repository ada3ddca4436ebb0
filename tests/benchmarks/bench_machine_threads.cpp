// Prints what a second thread gives on this machine at the moment, beside what it gives RigidLab's step. Each round
// times a fixed piece of arithmetic that shares nothing between threads (one thread, then two at once, each doing
// the same work), then steps a scene on two threads and on one (one run each, the median of its frames). On a
// shared virtual machine each virtual CPU's speed moves from one tenth of a second to the next; the arithmetic's
// speedup shows how far that alone moves a two-thread figure, with no synchronisation and no shared data to blame.
// The last column is the core round trip before the round (world/CoreRoundTrip.h): the step hands data from core to
// core, the arithmetic does not, so when the host places the two virtual CPUs far apart only the step slows.
//
//   bench_machine_threads [--rounds N] [--frames N] [SCENE]     (SCENE: a library name or file; default ramps.obj)
#include "BenchMedian.h"
#include "io/SceneImport.h"
#include "scene/SceneLibrary.h"
#include "world/CoreRoundTrip.h"
#include "world/World.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <thread>
#include <vector>

using namespace rl;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// 32 independent multiply-add chains, in registers: 42-97 ms on one thread of this project's machine (2026-12-01).
double arithmetic(double seed) {
    constexpr int kChains = 32;
    double x[kChains];
    for (int k = 0; k < kChains; ++k)
        x[k] = seed + 1e-3 * k;
    for (long i = 0; i < 14'000'000; ++i)
        for (int k = 0; k < kChains; ++k)
            x[k] = x[k] * 0.9999999 + 1e-7;
    double sum = 0.0;
    for (double v : x)
        sum += v;
    return sum;
}

// Wall time of `threads` threads each doing the arithmetic once, all started together.
double arithmeticMs(int threads) {
    std::vector<double> sinks(static_cast<size_t>(threads));
    const Clock::time_point start = Clock::now();
    std::vector<std::thread> team;
    for (int t = 0; t < threads; ++t)
        team.emplace_back([&sinks, t] { sinks[static_cast<size_t>(t)] = arithmetic(1.0 + t); });
    for (std::thread& t : team)
        t.join();
    const double ms = msSince(start);
    if (sinks.front() == 12345.0) // keeps the work from being dropped
        std::printf("?\n");
    return ms;
}

// Median step time of a fresh world over `frames` steps.
double stepMs(const Scene& scene, int threads, int frames, uint64_t& hash) {
    WorldOptions options;
    options.threads = threads;
    Result<World> created = World::create(scene, options);
    if (!created) {
        std::fprintf(stderr, "%s\n", created.error().toString().c_str());
        std::exit(1);
    }
    World& world = created.value();
    std::vector<double> times;
    for (int f = 0; f < frames; ++f) {
        const Clock::time_point start = Clock::now();
        world.step();
        times.push_back(msSince(start));
    }
    hash = world.stateHash();
    return bench::median(times);
}

} // namespace

int main(int argc, char** argv) {
    int rounds = 10, frames = 120;
    std::string sceneArg = RL_SOURCE_DIR "/resources/scenes/ramps.obj";
    for (int a = 1; a < argc; ++a) {
        if (std::strcmp(argv[a], "--rounds") == 0 && a + 1 < argc)
            rounds = std::max(1, std::atoi(argv[++a]));
        else if (std::strcmp(argv[a], "--frames") == 0 && a + 1 < argc)
            frames = std::max(1, std::atoi(argv[++a]));
        else
            sceneArg = argv[a];
    }
    std::optional<Scene> scene = scenes::byName(sceneArg);
    if (!scene) {
        Result<Scene> imported = importScene(sceneArg);
        if (!imported) {
            std::fprintf(stderr, "%s\n", imported.error().toString().c_str());
            return 1;
        }
        scene = std::move(imported).value();
    }
    std::printf("round arithmetic_1t_ms arithmetic_2t_ms arithmetic_speedup step_1t_ms step_2t_ms step_speedup "
                "core_round_trip_ns\n");
    int arithmeticAbove = 0, stepAbove = 0;
    std::vector<double> arithmeticSpeedups, stepSpeedups;
    for (int r = 0; r < rounds; ++r) {
        const std::optional<double> roundTrip = measureCoreRoundTripNs();
        const double one = arithmeticMs(1), two = arithmeticMs(2);
        uint64_t hash2 = 0, hash1 = 0;
        const double step2 = stepMs(*scene, 2, frames, hash2), step1 = stepMs(*scene, 1, frames, hash1);
        if (hash1 != hash2) {
            std::fprintf(stderr, "the two-thread run ended in another state than the one-thread run\n");
            return 1;
        }
        const double a = 2.0 * one / two, s = step1 / step2;
        arithmeticSpeedups.push_back(a);
        stepSpeedups.push_back(s);
        arithmeticAbove += a >= 1.7 ? 1 : 0;
        stepAbove += s >= 1.7 ? 1 : 0;
        std::printf("%d %.1f %.1f %.2f %.3f %.3f %.2f %s\n", r + 1, one, two, a, step1, step2, s,
                    roundTrip ? std::to_string(static_cast<int>(std::lround(*roundTrip))).c_str() : "n/a");
        std::fflush(stdout);
    }
    const auto [aLow, aHigh] = std::minmax_element(arithmeticSpeedups.begin(), arithmeticSpeedups.end());
    const auto [sLow, sHigh] = std::minmax_element(stepSpeedups.begin(), stepSpeedups.end());
    std::printf("arithmetic: %.2f-%.2fx, at or above 1.7x in %d of %d rounds\n", *aLow, *aHigh, arithmeticAbove,
                rounds);
    std::printf("step:       %.2f-%.2fx, at or above 1.7x in %d of %d rounds\n", *sLow, *sHigh, stepAbove, rounds);
}
