// Broadphase benchmark: boxes on a random walk at constant density, 1k, 4k and 16k of them. Prints the median time
// per update (move every proxy + updatePairs), the pair count, and the time over n log2 n so the growth can be seen.
#include "collision/BroadPhase.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <time.h>
#include <vector>

#ifdef RL_HAVE_BULLET
#include <btBulletCollisionCommon.h>
#endif

using namespace rl;

namespace {

// Thread CPU time, not wall time: the benchmark shares two cores with compilers and other runs, and CPU time is
// what is least disturbed by that (cache effects remain, hence the median).
struct Clock {
    static double now() {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
    }
};

double msSince(double t0) {
    return Clock::now() - t0;
}

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

// The walk: 60 Hz steps, velocities kicked by noise and capped at 3 m/s, boxes bounced back into the volume.
// 5% of the boxes are anchors. The volume grows with n so each box keeps about the same number of neighbours.
struct Walk {
    static constexpr Real kDt = 1.0 / 60.0;
    static constexpr Real kMaxSpeed = 3.0;
    static constexpr Real kSpacing = 2.0; // metres of cube edge per body, so density is 1 body per 8 m^3

    std::mt19937 rng;
    Real size;
    std::vector<Vec3> centers;
    std::vector<Vec3> halfExtents;
    std::vector<Vec3> velocities;
    std::vector<bool> anchor;

    Walk(int n, uint32_t seed) : rng(seed), size(std::cbrt(static_cast<Real>(n)) * kSpacing) {
        std::uniform_real_distribution<Real> u(0.0, 1.0);
        for (int i = 0; i < n; ++i) {
            centers.push_back(Vec3(u(rng), u(rng), u(rng)) * size);
            halfExtents.push_back(Vec3(0.25 + 0.25 * u(rng), 0.25 + 0.25 * u(rng), 0.25 + 0.25 * u(rng)));
            velocities.push_back((Vec3(u(rng), u(rng), u(rng)) - 0.5) * kMaxSpeed);
            anchor.push_back(u(rng) < 0.05);
        }
    }
    Aabb box(int i) const { return Aabb::fromCenterHalfExtents(centers[i], halfExtents[i]); }

    void advance() {
        std::normal_distribution<Real> kick(0.0, 4.0); // m/s^2
        for (size_t i = 0; i < centers.size(); ++i) {
            if (anchor[i])
                continue;
            Vec3& v = velocities[i];
            v += Vec3(kick(rng), kick(rng), kick(rng)) * kDt;
            const Real speed = glm::length(v);
            if (speed > kMaxSpeed)
                v *= kMaxSpeed / speed;
            centers[i] += v * kDt;
            for (int k = 0; k < 3; ++k) {
                if ((centers[i][k] < 0.0 && v[k] < 0.0) || (centers[i][k] > size && v[k] > 0.0))
                    v[k] = -v[k];
            }
        }
    }
};

struct Figures {
    double msMedian = 0.0;
    double msMoveMedian = 0.0;
    double pairs = 0.0;
    double reinsertedPerStep = 0.0;
    int height = 0;
    double areaRatio = 0.0;
};

Figures runRigidLab(int n, int steps, const BroadPhaseSettings& settings) {
    Walk walk(n, 1234);
    BroadPhase bp(settings);
    std::vector<ProxyKey> keys;
    for (int i = 0; i < n; ++i)
        keys.push_back(bp.createProxy(walk.box(i), static_cast<uint32_t>(i),
                                      walk.anchor[i] ? ProxyKind::Static : ProxyKind::Dynamic)
                           .value());
    bp.updatePairs();
    const int warmup = 20;
    std::vector<double> total, move;
    double pairs = 0.0, reinserted = 0.0;
    for (int s = 0; s < warmup + steps; ++s) {
        walk.advance();
        const auto t0 = Clock::now();
        for (int i = 0; i < n; ++i) {
            if (!walk.anchor[i])
                bp.moveProxy(keys[i], walk.box(i), walk.velocities[i] * Walk::kDt);
        }
        const double tMove = msSince(t0);
        bp.updatePairs();
        const double tAll = msSince(t0);
        if (s >= warmup) {
            total.push_back(tAll);
            move.push_back(tMove);
            pairs += static_cast<double>(bp.pairs().size());
            reinserted += bp.stats().movedProxies;
        }
    }
    Figures f;
    f.msMedian = median(total);
    f.msMoveMedian = median(move);
    f.pairs = pairs / steps;
    f.reinsertedPerStep = reinserted / steps;
    f.height = bp.tree(ProxyKind::Dynamic).height();
    f.areaRatio = bp.tree(ProxyKind::Dynamic).areaRatio();
    return f;
}

#ifdef RL_HAVE_BULLET
// Bullet's btDbvtBroadphase on the same walk, for reference: it keeps its own fat boxes and pair cache.
Figures runBullet(int n, int steps) {
    Walk walk(n, 1234);
    btDbvtBroadphase bp;
    std::vector<btBroadphaseProxy*> proxies;
    auto toBt = [](const Vec3& v) { return btVector3(btScalar(v.x), btScalar(v.y), btScalar(v.z)); };
    for (int i = 0; i < n; ++i) {
        const Aabb b = walk.box(i);
        const int group = walk.anchor[i] ? btBroadphaseProxy::StaticFilter : btBroadphaseProxy::DefaultFilter;
        const int mask = walk.anchor[i] ? btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter
                                        : btBroadphaseProxy::AllFilter;
        proxies.push_back(bp.createProxy(toBt(b.min), toBt(b.max), 0, nullptr, group, mask, nullptr));
    }
    bp.calculateOverlappingPairs(nullptr);
    const int warmup = 20;
    std::vector<double> total;
    double pairs = 0.0;
    for (int s = 0; s < warmup + steps; ++s) {
        walk.advance();
        const auto t0 = Clock::now();
        for (int i = 0; i < n; ++i) {
            if (!walk.anchor[i]) {
                const Aabb b = walk.box(i);
                bp.setAabb(proxies[i], toBt(b.min), toBt(b.max), nullptr);
            }
        }
        bp.calculateOverlappingPairs(nullptr);
        const double tAll = msSince(t0);
        if (s >= warmup) {
            total.push_back(tAll);
            pairs += bp.getOverlappingPairCache()->getNumOverlappingPairs();
        }
    }
    Figures f;
    f.msMedian = median(total);
    f.pairs = pairs / steps;
    for (btBroadphaseProxy* p : proxies)
        bp.destroyProxy(p, nullptr);
    return f;
}
#endif

} // namespace

int main(int argc, char** argv) {
    // --quick runs fewer steps once, for a smoke run.
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const int steps = quick ? 20 : 200;
    const int repeats = quick ? 1 : 3;
    // The same deterministic run is repeated and the fastest median kept: on a shared machine the slower repeats
    // measure the neighbours, not the code.
    auto best = [&](auto run) {
        Figures f = run();
        for (int r = 1; r < repeats; ++r) {
            const Figures g = run();
            if (g.msMedian < f.msMedian)
                f = g;
        }
        return f;
    };
    std::printf("# bench_broadphase: random walk at 60 Hz, 1 body per 8 m^3, 5%% anchors\n");
    std::printf("# median of %d updates in thread CPU time, best of %d runs\n", steps, repeats);
    std::printf("# update = moveProxy for every dynamic body + updatePairs; ns/nlogn = update time / (n log2 n)\n");
    std::printf("%-10s %7s %10s %10s %10s %10s %8s %8s %10s\n", "impl", "n", "ms/update", "ms/move", "pairs",
                "reinserts", "height", "area", "ns/nlogn");
    for (int n : {1000, 4000, 16000}) {
        const Figures f = best([&] { return runRigidLab(n, steps, BroadPhaseSettings{}); });
        const double nlogn = n * std::log2(static_cast<double>(n));
        std::printf("%-10s %7d %10.3f %10.3f %10.0f %10.0f %8d %8.1f %10.2f\n", "rigidlab", n, f.msMedian,
                    f.msMoveMedian, f.pairs, f.reinsertedPerStep, f.height, f.areaRatio, f.msMedian * 1e6 / nlogn);
#ifdef RL_HAVE_BULLET
        const Figures b = best([&] { return runBullet(n, steps); });
        std::printf("%-10s %7d %10.3f %10s %10.0f %10s %8s %8s %10.2f\n", "bullet", n, b.msMedian, "-", b.pairs, "-",
                    "-", "-", b.msMedian * 1e6 / nlogn);
#endif
    }

    // The fat-box trade-off: a larger margin means fewer reinsertions but more pairs for the narrowphase.
    std::printf("\n# margin sweep at n = 4000 (pairs are what the narrowphase would have to test)\n");
    std::printf("%8s %8s %10s %10s %10s\n", "margin", "predict", "ms/update", "pairs", "reinserts");
    for (Real margin : {0.0, 0.05, 0.1, 0.2}) {
        for (Real multiplier : {0.0, 2.0}) {
            BroadPhaseSettings s;
            s.dynamicTree.margin = margin;
            s.dynamicTree.displacementMultiplier = multiplier;
            const Figures f = best([&] { return runRigidLab(4000, steps / 2, s); });
            std::printf("%8.2f %8.1f %10.3f %10.0f %10.0f\n", margin, multiplier, f.msMedian, f.pairs,
                        f.reinsertedPerStep);
        }
    }
    return EXIT_SUCCESS;
}
