// A census of piles of 1,000 boxes: issue 4's hard case ("none below the floor; max speed in the last second < 1
// cm/s") over many seeds, the figures the log's entries on piles give (tests/benchmarks/LOG.md). Each pile steps
// `frames` frames on one thread from the library's layouts:
//   random  scenes::randomBoxes(1000, seed)           (tst_piles' thousandBoxesSettle)
//   grid12  scenes::boxGrid(seed, 1.2, 1.0)           1.2 m apart from 1 m
//   grid16  scenes::boxGrid(seed, 1.6, 1.0)           1.6 m apart from 1 m, as tests/data/acceptance/boxes1000.obj
//   grid16h scenes::boxGrid(seed, 1.6, 10.0)          1.6 m apart from 10 m
// and prints a line per pile: the lowest point of any box (below the floor's top, y = 0, when negative) and its
// frame, the fastest box's speed over the last second (60 frames at 60 Hz), the deepest contact from frame
// `--depth-from` on (5 by default: randomBoxes() creates some boxes inside each other), the frames from then on with a
// contact deeper than 1 cm, and whether the pile moves in its last second (1 cm/s or more). Then a
// line per layout sums them up. Piles run `--jobs` at a time, each world on one thread: every pile's numbers are the
// same whatever the jobs.
//
//   bench_piles [--layouts random,grid12,grid16,grid16h] [--seeds A-B] [--frames N] [--depth-from F] [--jobs J]
#include "scene/SceneLibrary.h"
#include "world/World.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace rl;

namespace {

struct Layout {
    const char* name;
    Real spacing = 0.0, height = 0.0; // 0: randomBoxes
};
constexpr Layout kLayouts[] = {{"random"}, {"grid12", 1.2, 1.0}, {"grid16", 1.6, 1.0}, {"grid16h", 1.6, 10.0}};

struct PileFigures {
    Real lowest = 1e9; // m
    int lowestFrame = 0;
    Real fastestLastSecond = 0.0; // m/s
    Real deepest = 0.0;           // m, the least separation of any contact point (negative: overlap)
    int framesDeeperThan1cm = 0;
    bool finite = true;
};

PileFigures runPile(const Layout& layout, unsigned seed, int frames, int depthFrom) {
    const Scene scene =
        layout.spacing > 0.0 ? scenes::boxGrid(seed, layout.spacing, layout.height) : scenes::randomBoxes(1000, seed);
    Result<World> made = World::create(scene);
    PileFigures out;
    if (!made) { // counted as not finite
        std::fprintf(stderr, "bench_piles: %s seed %u: %s\n", layout.name, seed, made.error().toString().c_str());
        out.finite = false;
        return out;
    }
    World& w = *made;
    const int lastSecond = frames - static_cast<int>(w.fps() + 0.5);
    for (int f = 1; f <= frames; ++f) {
        w.step();
        for (size_t i = 0; i < w.bodyCount(); ++i) {
            if (w.isAnchor(i))
                continue;
            const Vec3 v = w.linearVelocity(i);
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                out.finite = false;
            if (const Real y = w.shape(i).worldBounds(w.transform(i)).min.y; y < out.lowest) {
                out.lowest = y;
                out.lowestFrame = f;
            }
            if (f > lastSecond)
                out.fastestLastSecond = std::max(out.fastestLastSecond, glm::length(v));
        }
        if (f < depthFrom)
            continue;
        Real deepest = 0.0;
        for (const Manifold& m : w.manifolds())
            for (int k = 0; k < m.pointCount; ++k)
                deepest = std::min(deepest, m.points[k].separation);
        out.deepest = std::min(out.deepest, deepest);
        if (deepest < -0.01)
            ++out.framesDeeperThan1cm;
    }
    return out;
}

[[noreturn]] void usage(int code) {
    std::printf("Usage: bench_piles [--layouts random,grid12,grid16,grid16h] [--seeds A-B] [--frames N] "
                "[--depth-from F] [--jobs J]\n"
                "Defaults: every layout, seeds 1-12, 600 frames, depths from frame 5, 2 jobs.\n");
    std::exit(code);
}

} // namespace

int main(int argc, char** argv) {
    std::vector<Layout> layouts(std::begin(kLayouts), std::end(kLayouts));
    unsigned firstSeed = 1, lastSeed = 12;
    int frames = 600, jobs = 2, depthFrom = 5;
    for (int i = 1; i < argc; ++i) {
        const auto value = [&]() -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "bench_piles: %s takes a value\n", argv[i]);
                usage(2);
            }
            return argv[++i];
        };
        if (std::strcmp(argv[i], "--layouts") == 0) {
            layouts.clear();
            std::stringstream list(value());
            for (std::string name; std::getline(list, name, ',');) {
                const auto at = std::find_if(std::begin(kLayouts), std::end(kLayouts),
                                             [&](const Layout& l) { return name == l.name; });
                if (at == std::end(kLayouts)) {
                    std::fprintf(stderr, "bench_piles: no layout '%s'\n", name.c_str());
                    usage(2);
                }
                layouts.push_back(*at);
            }
        } else if (std::strcmp(argv[i], "--seeds") == 0) {
            const char* text = value();
            if (std::sscanf(text, "%u-%u", &firstSeed, &lastSeed) != 2 || firstSeed > lastSeed) {
                std::fprintf(stderr, "bench_piles: --seeds takes A-B with A <= B (got '%s')\n", text);
                usage(2);
            }
        } else if (std::strcmp(argv[i], "--frames") == 0) {
            if ((frames = std::atoi(value())) <= 60) {
                std::fprintf(stderr, "bench_piles: --frames takes a number above 60\n");
                usage(2);
            }
        } else if (std::strcmp(argv[i], "--depth-from") == 0) {
            if ((depthFrom = std::atoi(value())) < 1) {
                std::fprintf(stderr, "bench_piles: --depth-from takes a frame number from 1 on\n");
                usage(2);
            }
        } else if (std::strcmp(argv[i], "--jobs") == 0) {
            if ((jobs = std::atoi(value())) <= 0) {
                std::fprintf(stderr, "bench_piles: --jobs takes a positive number\n");
                usage(2);
            }
        } else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            usage(0);
        } else {
            std::fprintf(stderr, "bench_piles: unknown argument '%s'\n", argv[i]);
            usage(2);
        }
    }
    const size_t seeds = lastSeed - firstSeed + 1;
    std::vector<PileFigures> figures(layouts.size() * seeds);
    std::atomic<size_t> next{0};
    const auto work = [&] {
        for (size_t k; (k = next.fetch_add(1)) < figures.size();)
            figures[k] = runPile(layouts[k / seeds], firstSeed + static_cast<unsigned>(k % seeds), frames, depthFrom);
    };
    std::vector<std::thread> threads;
    for (int j = 1; j < jobs; ++j)
        threads.emplace_back(work);
    work();
    for (std::thread& t : threads)
        t.join();

    for (size_t l = 0; l < layouts.size(); ++l) {
        int moving = 0, belowFloor6mm = 0, deepFrames = 0, broken = 0;
        Real deepestSum = 0.0;
        for (size_t s = 0; s < seeds; ++s) {
            const PileFigures& p = figures[l * seeds + s];
            const bool moves = !p.finite || p.fastestLastSecond >= 0.01;
            std::printf(
                "pile layout=%s seed=%zu lowest_mm=%.2f lowest_frame=%d fastest_last_second=%.4f deepest_mm=%.2f "
                "frames_deeper_1cm=%d finite=%s moving=%s\n",
                layouts[l].name, firstSeed + s, 1e3 * p.lowest, p.lowestFrame, p.fastestLastSecond, -1e3 * p.deepest,
                p.framesDeeperThan1cm, p.finite ? "yes" : "no", moves ? "yes" : "no");
            moving += moves ? 1 : 0;
            belowFloor6mm += p.lowest < -0.006 ? 1 : 0;
            deepFrames += p.framesDeeperThan1cm;
            deepestSum += -p.deepest;
            broken += p.finite ? 0 : 1;
        }
        std::printf("layout=%s seeds=%u-%u frames=%d piles=%zu moving=%d not_finite=%d below_floor_6mm=%d "
                    "frames_deeper_1cm=%d deepest_mean_mm=%.1f depth_from=%d\n",
                    layouts[l].name, firstSeed, lastSeed, frames, seeds, moving, broken, belowFloor6mm, deepFrames,
                    1e3 * deepestSum / static_cast<Real>(seeds), depthFrom);
    }
    return 0;
}
