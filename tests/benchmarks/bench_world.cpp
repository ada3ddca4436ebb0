// Whole-world benchmark: steps the same scenes in RigidLab (default settings) and, when built with Bullet, in
// Bullet's btDiscreteDynamicsWorld, and prints ms/step for both and the ratio RigidLab/Bullet from the same run.
#include "BenchMedian.h"
#include "io/SceneImport.h"
#include "scene/BodyProperties.h"
#include "scene/SceneLibrary.h"
#include "world/World.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <time.h>
#include <vector>

#ifdef RL_HAVE_BULLET
#include <btBulletDynamicsCommon.h>
#endif

using namespace rl;

namespace {

// Wall clock (what a user waits for) and thread CPU time (less disturbed by the other jobs on a shared machine).
struct Sample {
    double wallMs = 0.0;
    double cpuMs = 0.0;
};

double threadCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

template <class StepFn>
std::vector<Sample> timeSteps(int frames, StepFn&& step) {
    using Clock = std::chrono::steady_clock;
    std::vector<Sample> samples;
    samples.reserve(static_cast<size_t>(frames));
    for (int f = 0; f < frames; ++f) {
        const double c0 = threadCpuMs();
        const Clock::time_point w0 = Clock::now();
        step();
        const double wall = std::chrono::duration<double, std::milli>(Clock::now() - w0).count();
        samples.push_back({wall, threadCpuMs() - c0});
    }
    return samples;
}

struct Summary {
    double wallMedian = 0.0, wallP95 = 0.0, cpuMedian = 0.0, cpuMean = 0.0;
    int awake = 0, contacts = 0;
    double topY = 0.0; // highest centre of mass of a dynamic body at the end: shows whether a tower still stands
};

double p95Of(std::vector<double> v) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(v.size())));
    return v[std::clamp<size_t>(rank, 1, v.size()) - 1];
}

Summary summarize(const std::vector<Sample>& samples) {
    std::vector<double> wall, cpu;
    for (const Sample& s : samples) {
        wall.push_back(s.wallMs);
        cpu.push_back(s.cpuMs);
    }
    Summary out;
    out.wallMedian = bench::median(wall);
    out.wallP95 = p95Of(wall);
    out.cpuMedian = bench::median(cpu);
    double total = 0.0;
    for (double c : cpu)
        total += c;
    out.cpuMean = cpu.empty() ? 0.0 : total / static_cast<double>(cpu.size());
    return out;
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

std::optional<Summary> runRigidLab(const Scene& scene, int frames, bool noSleep) {
    WorldOptions options;
    if (noSleep)
        options.effects = EffectsSetting::parse("auto,-sleeping");
    Result<World> created = World::create(scene, options);
    if (!created) {
        std::fprintf(stderr, "rigidlab: %s\n", created.error().toString().c_str());
        return std::nullopt;
    }
    World& world = created.value();
    Summary s = summarize(timeSteps(frames, [&] { world.step(); }));
    const FrameDiagnostics d = world.diagnostics();
    s.awake = d.awakeBodies;
    s.contacts = d.contactPoints;
    s.topY = -1e300;
    for (size_t i = 0; i < world.bodyCount(); ++i)
        if (!world.isAnchor(i))
            s.topY = std::max(s.topY, world.centerOfMass(i).y);
    return s;
}

#ifdef RL_HAVE_BULLET

btVector3 toBt(const Vec3& v) {
    return btVector3(static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z));
}

btQuaternion toBt(const Quat& q) {
    return btQuaternion(static_cast<btScalar>(q.x), static_cast<btScalar>(q.y), static_cast<btScalar>(q.z),
                        static_cast<btScalar>(q.w));
}

// Bullet combines with globals; these carry the scene's combine rules to the callbacks.
CombineRule gFrictionRule = CombineRule::GeometricMean;
CombineRule gRestitutionRule = CombineRule::Max;

btScalar combinedFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return static_cast<btScalar>(combine(gFrictionRule, a->getFriction(), b->getFriction()));
}

btScalar combinedRestitution(const btCollisionObject* a, const btCollisionObject* b) {
    return static_cast<btScalar>(combine(gRestitutionRule, a->getRestitution(), b->getRestitution()));
}

// The Bullet side of one scene. Members are destroyed in reverse order: the world goes first, while the bodies,
// shapes, solver, broadphase and dispatcher it refers to are still alive.
struct BulletWorld {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};

    ~BulletWorld() {
        for (auto& body : bodies)
            world.removeRigidBody(body.get());
    }
};

// Builds the scene in Bullet: Box -> btBoxShape, Sphere -> btSphereShape, Hull/Mesh -> btConvexHullShape of the
// RigidLab collision hull relative to the centre of mass; anchors have mass 0; per-body friction and restitution
// from the body's effective material, combined by the scene's rules. Shape margins are Bullet's defaults.
std::unique_ptr<BulletWorld> buildBullet(const Scene& scene, bool noSleep) {
    auto bw = std::make_unique<BulletWorld>();
    bw->world.setGravity(toBt(scene.world.gravity));
    gFrictionRule = scene.world.frictionCombine;
    gRestitutionRule = scene.world.restitutionCombine;
    gCalculateCombinedFrictionCallback = combinedFriction;
    gCalculateCombinedRestitutionCallback = combinedRestitution;

    for (const BodyDef& body : scene.bodies) {
        Result<BodyProperties> props = computeBodyProperties(scene, body);
        if (!props) {
            std::fprintf(stderr, "bullet: %s\n", props.error().toString().c_str());
            return nullptr;
        }
        std::unique_ptr<btCollisionShape> shape;
        Vec3 origin = body.position; // box and sphere: the shape origin is the centre of mass
        switch (body.shape.type) {
        case ShapeType::Box:
            shape = std::make_unique<btBoxShape>(toBt(body.shape.halfExtents));
            break;
        case ShapeType::Sphere:
            shape = std::make_unique<btSphereShape>(static_cast<btScalar>(body.shape.radius));
            break;
        case ShapeType::Hull:
        case ShapeType::Mesh: {
            // The centre of mass in shape coordinates; hull points are made relative to it.
            const Vec3 comShape = glm::inverse(body.orientation) * (props->com - body.position);
            auto hull = std::make_unique<btConvexHullShape>();
            for (const Vec3& v : props->hull.vertices)
                hull->addPoint(toBt(v - comShape), false);
            hull->recalcLocalAabb();
            shape = std::move(hull);
            origin = props->com;
            break;
        }
        }
        const MaterialDef material = scene.effectiveMaterial(body);
        const btScalar mass = body.anchor ? btScalar(0) : static_cast<btScalar>(props->mass);
        btVector3 inertia(0, 0, 0);
        if (!body.anchor)
            shape->calculateLocalInertia(mass, inertia);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), inertia);
        info.m_startWorldTransform = btTransform(toBt(body.orientation), toBt(origin));
        info.m_friction = static_cast<btScalar>(material.friction);
        info.m_restitution = static_cast<btScalar>(material.restitution);
        auto rb = std::make_unique<btRigidBody>(info);
        if (!body.anchor) {
            rb->setLinearVelocity(toBt(body.velocity));
            rb->setAngularVelocity(toBt(body.angularVelocity));
            if (noSleep)
                rb->setActivationState(DISABLE_DEACTIVATION);
        }
        bw->world.addRigidBody(rb.get());
        bw->shapes.push_back(std::move(shape));
        bw->bodies.push_back(std::move(rb));
    }
    return bw;
}

std::optional<Summary> runBullet(const Scene& scene, int frames, bool noSleep) {
    std::unique_ptr<BulletWorld> bw = buildBullet(scene, noSleep);
    if (!bw)
        return std::nullopt;
    const btScalar dt = static_cast<btScalar>(1.0 / scene.world.fps);
    // maxSubSteps 0: exactly one internal step of dt per call (Bullet's default 10 solver iterations).
    Summary s = summarize(timeSteps(frames, [&] { bw->world.stepSimulation(dt, 0); }));
    s.topY = -1e300;
    for (const auto& rb : bw->bodies) {
        if (rb->isStaticObject())
            continue;
        s.awake += rb->isActive() ? 1 : 0;
        s.topY = std::max(s.topY, static_cast<double>(rb->getCenterOfMassPosition().y()));
    }
    for (int m = 0; m < bw->dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = bw->dispatcher.getManifoldByIndexInternal(m);
        for (int k = 0; k < manifold->getNumContacts(); ++k)
            s.contacts += manifold->getContactPoint(k).getDistance() <= 0 ? 1 : 0;
    }
    return s;
}

#endif

void printSide(const char* engine, const std::string& name, size_t bodies, int frames, const Summary& s) {
    std::printf("%-9s %-14s bodies=%-5zu frames=%-4d wall_median_ms=%8.3f wall_p95_ms=%8.3f cpu_median_ms=%8.3f "
                "cpu_mean_ms=%8.3f awake=%-5d contacts=%-5d top_y=%.3f\n",
                engine, name.c_str(), bodies, frames, s.wallMedian, s.wallP95, s.cpuMedian, s.cpuMean, s.awake,
                s.contacts, s.topY);
}

} // namespace

int main(int argc, char** argv) {
    int frames = 300;
    bool noSleep = false;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
            frames = std::atoi(argv[++i]);
            if (frames <= 0) {
                std::fprintf(stderr, "bench_world: --frames takes a positive number\n");
                return 2;
            }
        } else if (std::strcmp(argv[i], "--no-sleep") == 0) {
            noSleep = true;
        } else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::printf("Usage: bench_world [--frames N] [--no-sleep] [NAME|FILE|ramps ...]\n"
                        "Default: stack20 pyramid20 ramps boxes1000, 300 frames each.\n"
                        "--no-sleep keeps every body awake in both engines (RigidLab: effects auto,-sleeping; "
                        "Bullet: DISABLE_DEACTIVATION).\n");
            return 0;
        } else {
            names.push_back(argv[i]);
        }
    }
    if (names.empty())
        names = {"stack20", "pyramid20", "ramps", "boxes1000"};

    std::printf("bench_world: %d frames per scene; RigidLab at scene defaults, threads 1; sleeping %s\n", frames,
                noSleep ? "off in both engines" : "at each engine's defaults");
#ifdef RL_HAVE_BULLET
    std::printf("bullet: version %d, btScalar is %s, btDbvtBroadphase + btSequentialImpulseConstraintSolver, "
                "%d iterations\n",
                btGetVersion(), sizeof(btScalar) == sizeof(double) ? "double" : "float",
                btContactSolverInfo().m_numIterations);
#else
    std::printf("bullet: not built (libbullet-dev not found); RigidLab figures only\n");
#endif
    std::printf("loadavg at start: %s\n", loadAverage().c_str());
    std::fflush(stdout);

    int status = 0;
    for (const std::string& name : names) {
        Scene scene;
        if (std::optional<Scene> named = scenes::byName(name)) {
            scene = std::move(*named);
        } else {
            const std::string path =
                name == "ramps" ? std::string(RL_SOURCE_DIR) + "/resources/scenes/ramps.obj" : name;
            Result<Scene> imported = importScene(path);
            if (!imported) {
                std::fprintf(stderr, "bench_world: %s\n", imported.error().toString().c_str());
                status = 1;
                continue;
            }
            scene = std::move(imported).value();
        }
        std::fprintf(stderr, "bench_world: %s (%zu bodies)\n", name.c_str(), scene.bodies.size());
        const std::optional<Summary> rl = runRigidLab(scene, frames, noSleep);
        if (!rl) {
            status = 1;
            continue;
        }
        printSide("rigidlab", name, scene.bodies.size(), frames, *rl);
#ifdef RL_HAVE_BULLET
        const std::optional<Summary> bt = runBullet(scene, frames, noSleep);
        if (!bt) {
            status = 1;
            continue;
        }
        printSide("bullet", name, scene.bodies.size(), frames, *bt);
        std::printf("ratio     %-14s rigidlab/bullet wall_median=%.2f cpu_median=%.2f cpu_mean=%.2f\n", name.c_str(),
                    bt->wallMedian > 0 ? rl->wallMedian / bt->wallMedian : 0.0,
                    bt->cpuMedian > 0 ? rl->cpuMedian / bt->cpuMedian : 0.0,
                    bt->cpuMean > 0 ? rl->cpuMean / bt->cpuMean : 0.0);
#endif
        std::fflush(stdout);
    }
    std::printf("loadavg at end: %s\n", loadAverage().c_str());
    return status;
}
