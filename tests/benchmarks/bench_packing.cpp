// The solver's levels packed into full batches (ContactSolver::packPartLevels()) against the levels of the sequential
// order: two worlds of the same scene step by turns, frame by frame, one with packing off (ContactSolver::
// setPackLevels(false)) and one with it on, so that the host's slow spells fall on both. Each frame counts at its
// least time over the rounds; the rounds alternate which world steps first. Prints, per scene, the median and mean
// ms a step of each, the batches their sweeps took (counter swept_batches) and whether both ended in the same state.
//
//   bench_packing [--frames N] [--threads T] [--rounds R] [NAME|FILE ...]   (default: large_pyramid, boxes1000, ramps)
#include "BenchMedian.h"
#include "dynamics/ContactSolver.h"
#include "io/SceneImport.h"
#include "scene/SceneLibrary.h"
#include "world/World.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

using namespace rl;

namespace {

std::optional<Scene> load(const std::string& name) {
    if (name == "ramps")
        return load(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
    if (std::optional<Scene> s = scenes::byName(name))
        return s;
    Result<Scene> imported = importScene(name);
    if (!imported) {
        std::fprintf(stderr, "bench_packing: %s\n", imported.error().toString().c_str());
        return std::nullopt;
    }
    return std::move(imported).value();
}

} // namespace

int main(int argc, char** argv) {
    int frames = 0, threads = 1, rounds = 3;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        const auto number = [&](int& out) {
            if (i + 1 >= argc || (out = std::atoi(argv[++i])) <= 0) {
                std::fprintf(stderr, "bench_packing: %s takes a positive number\n", argv[i - 1]);
                std::exit(2);
            }
        };
        if (std::strcmp(argv[i], "--frames") == 0) {
            number(frames);
        } else if (std::strcmp(argv[i], "--threads") == 0) {
            number(threads);
        } else if (std::strcmp(argv[i], "--rounds") == 0) {
            number(rounds);
        } else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::printf("Usage: bench_packing [--frames N] [--threads T] [--rounds R] [NAME|FILE|ramps ...]\n"
                        "Default scenes large_pyramid (45 frames), boxes1000 and ramps (120 frames).\n");
            return 0;
        } else {
            names.push_back(argv[i]);
        }
    }
    if (names.empty())
        names = {"large_pyramid", "boxes1000", "ramps"};
    std::printf("scene threads frames levels_median_ms packed_median_ms ratio levels_mean_ms packed_mean_ms "
                "levels_batches packed_batches same_state\n");
    for (const std::string& name : names) {
        const std::optional<Scene> scene = load(name);
        if (!scene)
            return 1;
        const int steps = frames > 0 ? frames : name == "large_pyramid" ? 45 : 120;
        std::vector<double> least[2];
        uint64_t batches[2] = {0, 0};
        bool same = true;
        for (int round = 0; round < rounds; ++round) {
            WorldOptions options;
            options.threads = threads;
            options.teamPacing = TeamPacing::Always; // the team on every step, in both worlds
            Result<World> made[2] = {World::create(*scene, options), World::create(*scene, options)};
            if (!made[0] || !made[1]) {
                std::fprintf(stderr, "bench_packing: %s\n", (made[0] ? made[1] : made[0]).error().toString().c_str());
                return 1;
            }
            std::vector<double> ms[2];
            for (int f = 0; f < steps; ++f)
                for (int turn = 0; turn < 2; ++turn) {
                    const int w = (f + round) % 2 == 0 ? turn : 1 - turn; // 0: levels, 1: packed
                    ContactSolver::setPackLevels(w == 1);
                    const auto start = std::chrono::steady_clock::now();
                    made[w].value().step();
                    ms[w].push_back(
                        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
                }
            for (int w = 0; w < 2; ++w) {
                if (least[w].empty())
                    least[w] = ms[w];
                for (size_t f = 0; f < ms[w].size(); ++f)
                    least[w][f] = std::min(least[w][f], ms[w][f]);
                batches[w] = made[w].value().profile().counter(Counter::SweptBatches);
            }
            same = same && made[0].value().stateHash() == made[1].value().stateHash();
        }
        ContactSolver::setPackLevels(true);
        double median[2], mean[2];
        for (int w = 0; w < 2; ++w) {
            median[w] = bench::median(least[w]);
            double total = 0.0;
            for (double v : least[w])
                total += v;
            mean[w] = total / static_cast<double>(least[w].size());
        }
        std::printf("%s %d %d %.3f %.3f %.3f %.3f %.3f %llu %llu %s\n", name.c_str(), threads, steps, median[0],
                    median[1], median[0] > 0.0 ? median[1] / median[0] : 0.0, mean[0], mean[1],
                    static_cast<unsigned long long>(batches[0]), static_cast<unsigned long long>(batches[1]),
                    same ? "yes" : "no");
        std::fflush(stdout);
    }
    return 0;
}
