// Narrowphase throughput: pairs per second for box-box, hull-hull (32 vertices) and sphere-hull, for the full
// manifold (SAT and GJK/EPA variants) and for the bare signed-distance query; and, when Debian's Bullet is found,
// Bullet's btGjkPairDetector (GJK + btGjkEpaPenetrationDepthSolver) and btGjkEpaSolver2 on the same pairs.
//
// Usage: bench_narrowphase [seconds per measurement, default 0.4]
#include "collision/Collide.h"
#include "collision/Penetration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <time.h>
#include <vector>

#ifdef RL_HAVE_BULLET
// Debian's libbullet-dev ships both builds; find_package(Bullet) picks BulletConfig.cmake, whose libraries
// (LinearMath, BulletCollision, ...) are the single-precision ones and whose BULLET_DEFINITIONS is empty. The
// float64 build (BulletConfig-float64.cmake, BT_USE_DOUBLE_PRECISION) is not what gets linked, so the
// precision macro must stay undefined here or the class layouts would not match the library.
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <memory>
#endif

using namespace rl;

namespace {

struct Pose {
    Transform a;
    Transform b;
};

struct PairSet {
    std::string name;
    Shape a;
    Shape b;
    std::vector<Vec3> pointsA; // hull points, for Bullet
    std::vector<Vec3> pointsB;
    std::vector<Pose> poses;
};

Quat randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<Real> n(0.0, 1.0);
    return glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
}

// A 16-sided prism: 32 vertices, 18 faces, 48 edges.
std::vector<Vec3> prismPoints() {
    std::vector<Vec3> polygon;
    for (int i = 0; i < 16; ++i)
        polygon.push_back({0.5 * std::cos(2 * kPi * i / 16), 0.0, 0.5 * std::sin(2 * kPi * i / 16)});
    return polygon;
}

Shape must(Result<Shape> r) {
    if (!r) {
        std::fprintf(stderr, "bench: %s\n", r.error().toString().c_str());
        std::exit(1);
    }
    return std::move(r.value());
}

// Poses with B's centre uniformly in a ball around A's: most pairs overlap, the rest are near misses, which is
// what a narrowphase sees after a broadphase with fat boxes.
std::vector<Pose> makePoses(Real radius, int count, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    std::vector<Pose> poses;
    while (int(poses.size()) < count) {
        const Vec3 p(u(rng), u(rng), u(rng));
        if (glm::dot(p, p) > 1.0)
            continue;
        poses.push_back({Transform::fromQuat(Vec3(0.0), randomRotation(rng)),
                         Transform::fromQuat(p * radius, randomRotation(rng))});
    }
    return poses;
}

// This thread's CPU time: the machine is shared, and wall time would count the other processes' turns.
double threadSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Runs `body` over all poses until `seconds` of CPU time have passed; returns pairs per CPU second, best of three
// runs, so that cache pollution by the other engineers' compiles disturbs the figure less.
double pairsPerSecond(const std::vector<Pose>& poses, double seconds, const std::function<void(const Pose&)>& body) {
    double best = 0.0;
    for (int run = 0; run < 3; ++run) {
        size_t pairs = 0;
        const double start = threadSeconds();
        double elapsed = 0.0;
        while (elapsed < seconds / 3.0) {
            for (const Pose& p : poses)
                body(p);
            pairs += poses.size();
            elapsed = threadSeconds() - start;
        }
        best = std::max(best, double(pairs) / elapsed);
    }
    return best;
}

#ifdef RL_HAVE_BULLET
btTransform toBullet(const Transform& xf) {
    btMatrix3x3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m[r][c] = btScalar(xf.rotation[c][r]);
    return btTransform(m, btVector3(btScalar(xf.position.x), btScalar(xf.position.y), btScalar(xf.position.z)));
}

// Bullet's shapes for ours, all with zero collision margin so that both libraries solve the same exact problem
// (a sphere is a point with its radius as margin in Bullet, which is the same thing).
std::unique_ptr<btConvexShape> toBullet(const Shape& s, const std::vector<Vec3>& points) {
    std::unique_ptr<btConvexShape> out;
    if (s.kind == ShapeKind::Sphere) {
        out = std::make_unique<btSphereShape>(btScalar(s.radius));
        return out;
    }
    if (s.kind == ShapeKind::Box) {
        out = std::make_unique<btBoxShape>(
            btVector3(btScalar(s.halfExtents.x), btScalar(s.halfExtents.y), btScalar(s.halfExtents.z)));
    } else {
        auto hull = std::make_unique<btConvexHullShape>();
        for (const Vec3& p : points)
            hull->addPoint(btVector3(btScalar(p.x), btScalar(p.y), btScalar(p.z)), false);
        hull->recalcLocalAabb();
        out = std::move(hull);
    }
    out->setMargin(0);
    return out;
}
#endif

} // namespace

int main(int argc, char** argv) {
    const double seconds = argc > 1 ? std::max(0.05, std::atof(argv[1])) : 0.4;
    const int kPairs = 1000;
    std::vector<Vec3> prism = prismPoints();
    const ConvexHull hull = prismHull(prism, 0.4);
    std::vector<PairSet> sets;
    sets.push_back({"box-box",
                    must(makeBox(Vec3(0.5, 0.3, 0.4))),
                    must(makeBox(Vec3(0.4, 0.4, 0.2))),
                    {},
                    {},
                    makePoses(1.0, kPairs, 1)});
    sets.push_back({"hull-hull (32 vertices)", must(makeHull(hull)), must(makeHull(hull)), hull.vertices, hull.vertices,
                    makePoses(1.1, kPairs, 2)});
    sets.push_back({"box-hull (32 vertices)",
                    must(makeBox(Vec3(0.5, 0.3, 0.4))),
                    must(makeHull(hull)),
                    {},
                    hull.vertices,
                    makePoses(1.0, kPairs, 4)});
    sets.push_back({"sphere-hull (32 vertices)",
                    must(makeSphere(0.3)),
                    must(makeHull(hull)),
                    {},
                    hull.vertices,
                    makePoses(0.8, kPairs, 3)});

    std::printf("narrowphase pairs per CPU second (best of 3 runs of %.2f s, %d poses per pair type)\n", seconds / 3.0,
                kPairs);
    for (PairSet& set : sets) {
        int overlapping = 0;
        for (const Pose& p : set.poses)
            overlapping += signedDistance(set.a, p.a, set.b, p.b).separation < 0.0;
        std::printf("\n%s: %d of %d poses overlap\n", set.name.c_str(), overlapping, kPairs);

        volatile int sink = 0;
        const Real spec = 0.02;
        const double manifoldAuto = pairsPerSecond(set.poses, seconds, [&](const Pose& p) {
            Manifold m;
            collide(set.a, p.a, set.b, p.b, spec, m);
            sink = sink + m.pointCount;
        });
        CollideOptions sat;
        sat.method = PolyhedronMethod::Sat;
        CollideOptions epa;
        epa.method = PolyhedronMethod::GjkEpa;
        const double manifoldSat = pairsPerSecond(set.poses, seconds, [&](const Pose& p) {
            Manifold m;
            collide(set.a, p.a, set.b, p.b, spec, m, sat);
            sink = sink + m.pointCount;
        });
        const double manifoldEpa = pairsPerSecond(set.poses, seconds, [&](const Pose& p) {
            Manifold m;
            collide(set.a, p.a, set.b, p.b, spec, m, epa);
            sink = sink + m.pointCount;
        });
        const double query = pairsPerSecond(set.poses, seconds, [&](const Pose& p) {
            sink = sink + (signedDistance(set.a, p.a, set.b, p.b).separation < 0.0);
        });
        std::printf("  rigidlab collide, default (auto)      %12.0f pairs/s\n", manifoldAuto);
        std::printf("  rigidlab collide, SAT manifold        %12.0f pairs/s\n", manifoldSat);
        std::printf("  rigidlab collide, GJK/EPA manifold    %12.0f pairs/s\n", manifoldEpa);
        std::printf("  rigidlab signedDistance (GJK+EPA)     %12.0f pairs/s\n", query);

#ifdef RL_HAVE_BULLET
        auto shapeA = toBullet(set.a, set.pointsA);
        auto shapeB = toBullet(set.b, set.pointsB);
        std::vector<std::pair<btTransform, btTransform>> bt;
        for (const Pose& p : set.poses)
            bt.push_back({toBullet(p.a), toBullet(p.b)});
        size_t idx = 0;
        auto btPose = [&](const Pose& p) -> const std::pair<btTransform, btTransform>& {
            return bt[size_t(&p - set.poses.data())];
        };
        (void)idx;
        btVoronoiSimplexSolver simplex;
        btGjkEpaPenetrationDepthSolver penetration;
        auto detect = [&](const Pose& p) {
            btGjkPairDetector detector(shapeA.get(), shapeB.get(), &simplex, &penetration);
            btDiscreteCollisionDetectorInterface::ClosestPointInput input;
            input.m_transformA = btPose(p).first;
            input.m_transformB = btPose(p).second;
            btPointCollector out;
            detector.getClosestPoints(input, out, nullptr);
            return out;
        };
        const double pairDetector =
            pairsPerSecond(set.poses, seconds, [&](const Pose& p) { sink = sink + detect(p).m_hasResult; });
        const double gjkEpa2 = pairsPerSecond(set.poses, seconds, [&](const Pose& p) {
            btGjkEpaSolver2::sResults r;
            sink = sink + (btGjkEpaSolver2::SignedDistance(shapeA.get(), btPose(p).first, shapeB.get(),
                                                           btPose(p).second, btVector3(1, 0, 0), r)
                               ? 1
                               : 0);
        });
        // Same answers? Compare the signed distances pair by pair.
        double worst = 0.0, sum = 0.0;
        int counted = 0;
        for (const Pose& p : set.poses) {
            const btPointCollector out = detect(p);
            if (!out.m_hasResult)
                continue;
            const double d = std::abs(double(out.m_distance) - signedDistance(set.a, p.a, set.b, p.b).separation);
            worst = std::max(worst, d);
            sum += d;
            ++counted;
        }
        std::printf("  bullet btGjkPairDetector (GJK+EPA)    %12.0f pairs/s\n", pairDetector);
        std::printf("  bullet btGjkEpaSolver2::SignedDistance %11.0f pairs/s\n", gjkEpa2);
        std::printf("  ratio rigidlab signedDistance / btGjkPairDetector          %6.2f\n", query / pairDetector);
        std::printf("  ratio rigidlab default manifold (<=4 points) / btGjkPairDetector (1 point) %6.2f\n",
                    manifoldAuto / pairDetector);
        std::printf("  ratio rigidlab signedDistance / btGjkEpaSolver2            %6.2f\n", query / gjkEpa2);
        std::printf("  signed distance vs btGjkPairDetector: mean |diff| %.2e m, worst %.2e m over %d pairs "
                    "(Bullet in single precision)\n",
                    counted ? sum / counted : 0.0, worst, counted);
#else
        std::printf("  (Bullet not found: no comparison)\n");
#endif
    }
    return 0;
}
