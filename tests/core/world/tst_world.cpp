// The world's step on small scenes: free flight, resting contact, stacking, effects and their counters,
// sleeping, and determinism across runs and thread counts.
#include "dynamics/ContactSolver.h"
#include "io/SceneImport.h"
#include "scene/BodyProperties.h"
#include "scene/SceneLibrary.h"
#include "world/Baker.h"
#include "world/World.h"

#include <QTest>

#include <cmath>

using namespace rl;

Q_DECLARE_METATYPE(rl::Vec3)

namespace {

BodyDef box(const std::string& name, const Vec3& half, const Vec3& pos, bool anchor = false) {
    BodyDef b;
    b.name = name;
    b.anchor = anchor;
    b.shape.type = ShapeType::Box;
    b.shape.halfExtents = half;
    b.position = pos;
    return b;
}

Scene floorScene() {
    Scene s;
    s.bodies.push_back(box("Floor", Vec3(20, 0.5, 20), Vec3(0, -0.5, 0), true));
    return s;
}

World makeWorld(const Scene& scene, const WorldOptions& options = {}) {
    Result<World> w = World::create(scene, options);
    if (!w)
        qFatal("%s", w.error().toString().c_str());
    return std::move(w).value();
}

// A scene by name: a file under resources/scenes (ending in .obj), "pyramid30", or a library scene.
std::optional<Scene> namedScene(const QString& scene) {
    if (scene.endsWith(".obj")) {
        Result<Scene> imported = importScene(RL_SOURCE_DIR "/resources/scenes/" + scene.toStdString());
        if (!imported.ok())
            return std::nullopt;
        return std::move(imported).value();
    }
    if (scene == "pyramid30")
        return scenes::pyramid(30);
    return scenes::byName(scene.toStdString());
}

// A scene stepped with every body kept awake on `threads` threads: its state hash and the counters of the cuts.
struct CutRun {
    uint64_t hash = 0, cuts = 0, inParts = 0, imbalance = 0;
    int awake = 0;
};
CutRun runAwake(const Scene& scene, int threads, int steps) {
    WorldOptions options;
    options.threads = threads;
    options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
    options.effects = EffectsSetting::parse("auto,-sleeping").value();
    World w = makeWorld(scene, options);
    for (int i = 0; i < steps; ++i)
        w.step();
    CutRun run;
    run.hash = w.stateHash();
    run.cuts = w.profile().counter(Counter::IslandsCut);
    run.inParts = w.profile().counter(Counter::SolvedInParts);
    run.imbalance = w.profile().counter(Counter::PartImbalance);
    run.awake = w.diagnostics().awakeBodies;
    return run;
}

} // namespace

class TestWorld : public QObject {
    Q_OBJECT
private slots:
    void freeFallIsExactPerIntegrator_data() {
        QTest::addColumn<int>("integrator");
        QTest::newRow("symplectic-euler") << int(Integrator::SymplecticEuler);
        QTest::newRow("verlet") << int(Integrator::Verlet);
        QTest::newRow("rk4") << int(Integrator::Rk4);
    }
    void freeFallIsExactPerIntegrator() {
        QFETCH(int, integrator);
        Scene s;
        s.world.integrator = static_cast<Integrator>(integrator);
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 100, 0)));
        World w = makeWorld(s);
        for (int i = 0; i < 60; ++i)
            w.step();
        const Real t = 1.0;
        const Real exact = 100.0 - 0.5 * 9.81 * t * t;
        // Verlet and RK4 are exact for constant gravity; symplectic Euler is first order: error g h t / 2.
        const Real tolerance =
            integrator == int(Integrator::SymplecticEuler) ? 0.5 * 9.81 * (1.0 / 240.0) * t + 1e-9 : 1e-9;
        QVERIFY2(std::abs(w.centerOfMass(0).y - exact) <= tolerance,
                 qPrintable(QString("y = %1, exact %2").arg(w.centerOfMass(0).y, 0, 'g', 12).arg(exact)));
        QCOMPARE(w.effects().has(Effect::Friction), false); // nothing to rub against
    }

    void boxComesToRestOnFloor() {
        Scene s = floorScene();
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 2, 0)));
        World w = makeWorld(s);
        for (int i = 0; i < 180; ++i)
            w.step();
        const Real y = w.centerOfMass(1).y;
        QVERIFY2(std::abs(y - 0.5) < 0.01, qPrintable(QString("rest height %1").arg(y)));
        QVERIFY(glm::length(w.linearVelocity(1)) < 0.01);
        QCOMPARE(w.manifolds().size(), size_t(1));
        QCOMPARE(w.manifolds()[0].pointCount, 4);
    }

    // A hull whose principal moments agree to World::kIsotropicSpread (a cube written with six decimals) is
    // simulated as isotropic, with the mean moment; a box 0.1 % longer one way keeps its three moments.
    void nearlyEqualMomentsAreTakenAsEqual_data() {
        QTest::addColumn<Vec3>("half");
        QTest::addColumn<bool>("turned");
        QTest::addColumn<bool>("isotropic");
        QTest::newRow("cube") << Vec3(0.1) << false << true;
        QTest::newRow("turned cube, six decimals") << Vec3(0.1) << true << true;
        QTest::newRow("box 0.1 % longer") << Vec3(0.1001, 0.1, 0.1) << false << false;
        QTest::newRow("turned box 0.1 % longer, six decimals") << Vec3(0.1001, 0.1, 0.1) << true << false;
    }
    void nearlyEqualMomentsAreTakenAsEqual() {
        QFETCH(Vec3, half);
        QFETCH(bool, turned);
        QFETCH(bool, isotropic);
        Scene s = floorScene();
        BodyDef body;
        body.name = "Cube";
        body.shape.type = ShapeType::Hull;
        const Mat3 turn = glm::mat3_cast(glm::angleAxis(0.7, glm::normalize(Vec3(1.0, 2.0, 3.0))));
        for (int i = 0; i < 8; ++i) {
            Vec3 c = Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1) * half;
            if (turned)
                c = glm::round((turn * c + Vec3(1.5, 2.25, -2.0)) * 1e6) * 1e-6;
            body.shape.points.push_back(c);
        }
        s.bodies.push_back(body);
        const Result<BodyProperties> props = computeBodyProperties(s, s.bodies[1]);
        QVERIFY(props.ok());
        const Vec3 m = props->principalMoments;
        World w = makeWorld(s);
        const Vec3 simulated = w.state().info[1].principalMoments;
        qInfo("moments spread by %.3g of the largest; simulated (%.9g, %.9g, %.9g)", (m.z - m.x) / m.z, simulated.x,
              simulated.y, simulated.z);
        QCOMPARE(simulated.x == simulated.y && simulated.y == simulated.z, isotropic);
        const Real mean = (m.x + m.y + m.z) / 3.0;
        for (int k = 0; k < 3; ++k)
            QVERIFY(std::abs(simulated[k] - mean) <= (isotropic ? 1e-15 : 2e-3) * mean);
        if (turned)
            QVERIFY(m.z - m.x > 0.0); // the rounding made the moments differ
    }

    // Hulls round about every axis (a UV sphere) or about one (prisms and cones of eight sides or more) are found by
    // their shape, and are round to the solver in a step in which they turn through more than one face: 100 rad/s is
    // 1.7 rad a step, 5 rad/s 0.08 (a face of 32 spans 0.20 rad, of 8 0.79). A hexagonal prism (faces 0.87 of its
    // corners' distance from the axis) and a square one are not round.
    void roundHullsAreFoundByTheirShape_data() {
        QTest::addColumn<QString>("shape");
        QTest::addColumn<bool>("aboutAxis"); // spun about the shape's axis, or across it
        QTest::addColumn<Real>("spin");
        QTest::addColumn<bool>("round");
        QTest::newRow("32-sided cylinder, 100 rad/s about its axis") << "prism 32" << true << 100.0 << true;
        QTest::newRow("32-sided cylinder, 100 rad/s across") << "prism 32" << false << 100.0 << false;
        QTest::newRow("32-sided cylinder, 5 rad/s about its axis") << "prism 32" << true << 5.0 << false;
        QTest::newRow("8-sided prism, 100 rad/s about its axis") << "prism 8" << true << 100.0 << true;
        QTest::newRow("6-sided prism, 100 rad/s about its axis") << "prism 6" << true << 100.0 << false;
        QTest::newRow("32-sided cone, 100 rad/s about its axis") << "cone 32" << true << 100.0 << true;
        QTest::newRow("square prism, 100 rad/s") << "prism 4" << true << 100.0 << false;
        QTest::newRow("UV sphere, 100 rad/s") << "sphere" << false << 100.0 << true;
        QTest::newRow("UV sphere, 5 rad/s") << "sphere" << false << 5.0 << false;
    }
    void roundHullsAreFoundByTheirShape() {
        QFETCH(QString, shape);
        QFETCH(bool, aboutAxis);
        QFETCH(Real, spin);
        QFETCH(bool, round);
        const Mat3 turn = glm::mat3_cast(glm::angleAxis(0.7, glm::normalize(Vec3(1.0, 2.0, 3.0))));
        const Vec3 axis = turn * Vec3(0.0, 0.0, 1.0);
        const int sides = shape.section(' ', 1).toInt();
        std::vector<Vec3> points;
        if (shape == "sphere") { // 16 segments, 8 rings
            for (int ring = 0; ring <= 8; ++ring)
                for (int segment = 0; segment < (ring % 8 == 0 ? 1 : 16); ++segment) {
                    const Real theta = kPi * ring / 8.0, phi = 2.0 * kPi * segment / 16.0;
                    points.push_back(
                        0.3 * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
                }
        } else {
            for (int side = 0; side < sides; ++side) {
                const Vec3 rim(0.3 * std::cos(2.0 * kPi * side / sides), 0.3 * std::sin(2.0 * kPi * side / sides), 0.0);
                points.push_back(rim + Vec3(0.0, 0.0, -0.2));
                if (shape.startsWith("prism"))
                    points.push_back(rim + Vec3(0.0, 0.0, 0.2));
            }
            if (shape.startsWith("cone"))
                points.push_back(Vec3(0.0, 0.0, 0.5));
        }
        Scene s;
        s.world.gravity = Vec3(0.0);
        BodyDef body;
        body.name = "Round";
        body.shape.type = ShapeType::Hull;
        for (const Vec3& p : points)
            body.shape.points.push_back(turn * p);
        body.angularVelocity = spin * (aboutAxis ? axis : glm::normalize(glm::cross(axis, Vec3(1.0, 0.0, 0.0))));
        s.bodies.push_back(body);
        World w = makeWorld(s);
        w.step();
        const BodyState& state = w.state();
        const Vec3 rollAxis = state.orientation[0] * state.info[0].rollAxis;
        qInfo("%s: round %d, roll axis (%.3f, %.3f, %.3f), shape axis (%.3f, %.3f, %.3f)", qPrintable(shape),
              state.isRound(0), rollAxis.x, rollAxis.y, rollAxis.z, axis.x, axis.y, axis.z);
        QCOMPARE(state.isRound(0), round);
        if (shape == "sphere")
            QVERIFY(state.info[0].rollAxis == Vec3(0.0));
        else if (round)
            QVERIFY(std::abs(glm::dot(rollAxis, axis)) > 1.0 - 1e-9);
    }

    void stackOfTenStands() {
        Result<Scene> s = importScene(RL_SOURCE_DIR "/resources/scenes/stack.obj");
        QVERIFY(s.ok());
        World w = makeWorld(*s);
        const Vec3 top0 = w.centerOfMass(10);
        Real maxSpeedLastSecond = 0.0;
        for (int i = 0; i < 600; ++i) {
            w.step();
            if (i >= 540)
                for (size_t b = 1; b < w.bodyCount(); ++b)
                    maxSpeedLastSecond = std::max(maxSpeedLastSecond, glm::length(w.linearVelocity(b)));
        }
        const Vec3 top = w.centerOfMass(10);
        const Real drift = glm::length(Vec3(top.x - top0.x, 0.0, top.z - top0.z));
        QVERIFY2(drift < 0.01, qPrintable(QString("drift %1").arg(drift)));
        QVERIFY2(std::abs(top.y - top0.y) < 0.05, qPrintable(QString("sank %1").arg(top0.y - top.y)));
        QVERIFY2(maxSpeedLastSecond < 0.01, qPrintable(QString("speed %1").arg(maxSpeedLastSecond)));
    }

    // The broadphase pairs bodies whose fat boxes overlap; the narrowphase tests the shapes only where the tight
    // boxes come within the pair's speculative margin, and a pair that moved apart loses its points.
    void pairsApartByTheirBoxesAreNotTestedAndLoseTheirPoints() {
        Scene s = floorScene();
        s.materials.push_back({"Slick", 1000.0, 0.0, 0.0});
        s.bodies[0].material = "Slick";
        // Two 0.2 m cubes side by side, touching, pushed apart at 0.6 m/s each.
        s.bodies.push_back(box("Left", Vec3(0.1), Vec3(-0.1, 0.1, 0)));
        s.bodies.push_back(box("Right", Vec3(0.1), Vec3(0.1, 0.1, 0)));
        s.bodies[1].material = s.bodies[2].material = "Slick";
        s.bodies[1].velocity = Vec3(-0.6, 0, 0);
        s.bodies[2].velocity = Vec3(0.6, 0, 0);
        World w = makeWorld(s);
        const auto touchingPairs = [&] {
            int cubes = 0;
            for (const Manifold& m : w.manifolds())
                cubes += (m.bodyA == 1 && m.bodyB == 2) || (m.bodyA == 2 && m.bodyB == 1) ? 1 : 0;
            return cubes;
        };
        w.step();
        QCOMPARE(touchingPairs(), 1); // they start face to face
        QCOMPARE(w.profile().counter(Counter::PairsTested), uint64_t(3));
        // After 5 steps the faces are 10 cm apart: more than the margin (2 cm + 1.2 m/s / 60), within the fat
        // boxes' 2 x 5 cm. The broadphase still pairs the cubes, the narrowphase no longer tests them.
        for (int i = 0; i < 5; ++i)
            w.step();
        QVERIFY(w.centerOfMass(2).x - w.centerOfMass(1).x > 0.2 + 0.08);
        w.resetProfile();
        w.step();
        QCOMPARE(w.profile().counter(Counter::Pairs), uint64_t(3));
        QCOMPARE(w.profile().counter(Counter::PairsTested), uint64_t(2)); // each cube with the floor
        QCOMPARE(touchingPairs(), 0);
        QCOMPARE(w.manifolds().size(), size_t(2));
    }

    void frictionlessSceneSolvesNoFrictionRows() {
        Scene s = floorScene();
        s.materials.push_back({"Slick", 1000.0, 0.0, 0.0});
        s.bodies[0].material = "Slick";
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 0.6, 0)));
        s.bodies.back().material = "Slick";
        World w = makeWorld(s);
        QCOMPARE(w.effects().has(Effect::Friction), false);
        QCOMPARE(w.effects().has(Effect::Restitution), false);
        for (int i = 0; i < 60; ++i)
            w.step();
        QVERIFY(w.profile().counter(Counter::NormalRows) > 0);
        QCOMPARE(w.profile().counter(Counter::FrictionRows), uint64_t(0));
        QCOMPARE(w.profile().calls[int(Stage::Restitution)], uint64_t(0));
    }

    // The solver keeps friction coefficients as floats. With one at or past a float's range, a cube pushed sideways
    // at 1 m/s on the floor still stops at once, with finite numbers.
    void hugeFrictionCoefficientStaysFinite_data() {
        QTest::addColumn<double>("friction");
        QTest::newRow("1e30") << 1e30;
        QTest::newRow("1e39") << 1e39;
        QTest::newRow("1e300") << 1e300;
    }
    void hugeFrictionCoefficientStaysFinite() {
        QFETCH(double, friction);
        Scene s = floorScene();
        s.materials.push_back({"Grip", 1000.0, friction, 0.0});
        s.bodies[0].material = "Grip";
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 0.5, 0)));
        s.bodies.back().material = "Grip";
        s.bodies.back().velocity = Vec3(1.0, 0.0, 0.0);
        World w = makeWorld(s);
        for (int i = 0; i < 120; ++i)
            w.step();
        const Vec3 p = w.centerOfMass(1), v = w.linearVelocity(1), om = w.angularVelocity(1);
        for (int k = 0; k < 3; ++k) {
            QVERIFY(std::isfinite(p[k]) && std::isfinite(v[k]) && std::isfinite(om[k]));
        }
        QVERIFY2(glm::length(v) < 0.01, qPrintable(QString("speed %1 m/s after 2 s").arg(glm::length(v))));
        QVERIFY2(p.x < 0.1, qPrintable(QString("slid to x = %1").arg(p.x)));
    }

    void restingSceneFallsAsleepAndIntegratesNothing() {
        Scene s = floorScene();
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 0.5, 0)));
        World w = makeWorld(s);
        QVERIFY(w.effects().has(Effect::Sleeping));
        for (int i = 0; i < 120; ++i)
            w.step();
        QVERIFY(!w.isAwake(1));
        w.resetProfile();
        for (int i = 0; i < 60; ++i)
            w.step();
        QCOMPARE(w.profile().counter(Counter::IntegratedBodies), uint64_t(0));
        QCOMPARE(w.profile().counter(Counter::AwakeBodies), uint64_t(0));
    }

    // The sleep test goes by how far a body gets in timeToSleep (0.5 s), not by its speed at one instant: a box
    // sliding or turning on a frictionless floor with its fastest point at 4 cm/s covers 2 cm in 0.5 s and sleeps;
    // at 6 cm/s it covers 3 cm, beyond the 2.5 cm of sleepSpeed x timeToSleep, and stays awake.
    void sleepGoesByTheDistanceCoveredInTheWindow_data() {
        QTest::addColumn<Vec3>("velocity");
        QTest::addColumn<Vec3>("spin");
        QTest::addColumn<bool>("sleeps");
        const Real corner = std::sqrt(3.0) * 0.5; // the cube's radius: centre to corner
        QTest::newRow("slides at 4 cm/s") << Vec3(0.04, 0.0, 0.0) << Vec3(0.0) << true;
        QTest::newRow("slides at 6 cm/s") << Vec3(0.06, 0.0, 0.0) << Vec3(0.0) << false;
        QTest::newRow("corners turn at 4 cm/s") << Vec3(0.0) << Vec3(0.0, 0.04 / corner, 0.0) << true;
        QTest::newRow("corners turn at 6 cm/s") << Vec3(0.0) << Vec3(0.0, 0.06 / corner, 0.0) << false;
    }
    void sleepGoesByTheDistanceCoveredInTheWindow() {
        QFETCH(Vec3, velocity);
        QFETCH(Vec3, spin);
        QFETCH(bool, sleeps);
        Scene s = floorScene();
        s.bodies[0].friction = 0.0;
        BodyDef cube = box("Cube", Vec3(0.5), Vec3(0, 0.5, 0));
        cube.friction = 0.0;
        cube.velocity = velocity;
        cube.angularVelocity = spin;
        s.bodies.push_back(cube);
        World w = makeWorld(s);
        QVERIFY(w.effects().has(Effect::Sleeping));
        int asleepAt = -1;
        for (int i = 1; i <= 180 && asleepAt < 0; ++i) {
            w.step();
            if (!w.isAwake(1))
                asleepAt = i;
        }
        qInfo("asleep at frame %d (-1: awake after 3 s)", asleepAt);
        if (sleeps) {
            QVERIFY(asleepAt >= 30); // not before the 0.5 s window is full
            QVERIFY(asleepAt <= 40);
        } else {
            QCOMPARE(asleepAt, -1);
        }
    }

    // The determinism tests compare runs by their hashes, so a hash that told states apart poorly would let them pass
    // for nothing: two worlds of one scene agree, one step apart they differ, and so do two states that differ in one
    // body's position by its last bit or in its orientation alone.
    void stateHashTellsStatesApart() {
        Scene s = floorScene();
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 2, 0)));
        s.bodies.push_back(box("Tilted", Vec3(0.5), Vec3(3, 2, 0)));
        s.bodies[2].orientation = glm::angleAxis(0.3, Vec3(0, 0, 1));
        Scene shifted = s, turned = s;
        shifted.bodies[1].position.x = std::nextafter(0.0, 1.0);
        turned.bodies[2].orientation = glm::angleAxis(0.3 + 1e-9, Vec3(0, 0, 1));
        World a = makeWorld(s), b = makeWorld(s);
        QCOMPARE(a.stateHash(), b.stateHash());
        QVERIFY(a.stateHash() != makeWorld(shifted).stateHash());
        QVERIFY(a.stateHash() != makeWorld(turned).stateHash());
        a.step();
        QVERIFY(a.stateHash() != b.stateHash());
        b.step();
        QCOMPARE(a.stateHash(), b.stateHash());
    }

    void deterministicAcrossRunsAndThreads() {
        Result<Scene> s = importScene(RL_SOURCE_DIR "/resources/scenes/pyramid.obj");
        QVERIFY(s.ok());
        uint64_t hashes[3];
        for (int run = 0; run < 3; ++run) {
            WorldOptions options;
            options.threads = run == 2 ? 2 : 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(*s, options);
            for (int i = 0; i < 120; ++i)
                w.step();
            hashes[run] = w.stateHash();
        }
        QCOMPARE(hashes[0], hashes[1]);
        QCOMPARE(hashes[0], hashes[2]);
    }

    // A world with a team may take any step alone (TeamPacer, when the machine's other cores are busy): ramps.obj's
    // 642 cubes on two threads, the team and alone by turns, and as the pacer chose, end where one thread does.
    void teamAndAloneByTurnsGiveIdenticalResults_data() {
        QTest::addColumn<int>("pacing");
        QTest::addColumn<int>("alone"); // steps alone of 120, or -1: any
        QTest::newRow("every other step alone") << int(TeamPacing::EveryOtherStep) << 60;
        QTest::newRow("always the team") << int(TeamPacing::Always) << 0;
        QTest::newRow("adaptive") << int(TeamPacing::Adaptive) << -1;
    }
    void teamAndAloneByTurnsGiveIdenticalResults() {
        QFETCH(int, pacing);
        QFETCH(int, alone);
        Result<Scene> s = importScene(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
        QVERIFY(s.ok());
        World one = makeWorld(*s);
        WorldOptions options;
        options.threads = 2;
        options.teamPacing = static_cast<TeamPacing>(pacing);
        World two = makeWorld(*s, options);
        for (int i = 0; i < 120; ++i) {
            one.step();
            two.step();
            if (i % 20 == 19)
                QCOMPARE(two.stateHash(), one.stateHash());
        }
        QCOMPARE(one.profile().counter(Counter::StepsAlone), uint64_t(0));
        const uint64_t stepsAlone = two.profile().counter(Counter::StepsAlone);
        qInfo("steps alone: %llu of 120", static_cast<unsigned long long>(stepsAlone));
        if (alone >= 0)
            QCOMPARE(stepsAlone, uint64_t(alone));
        if (pacing == int(TeamPacing::EveryOtherStep))
            QVERIFY(two.profile().counter(Counter::IslandsSharedOut) > 0); // the team did solve
    }

    // The steps in which the team ran a job (Counter::TeamSteps): none for a world of one thread, none for a scene
    // under the team's thresholds (20 cubes), every step for ramps.obj's 642 cubes while they fall.
    void teamStepsAreCounted_data() {
        QTest::addColumn<QString>("scene"); // a library name or a file under resources/scenes
        QTest::addColumn<int>("threads");
        QTest::addColumn<int>("teamSteps"); // of 30
        QTest::newRow("ramps, one thread") << "ramps.obj" << 1 << 0;
        QTest::newRow("ramps, two threads") << "ramps.obj" << 2 << 30;
        QTest::newRow("stack20, two threads") << "stack20" << 2 << 0;
    }
    void teamStepsAreCounted() {
        QFETCH(QString, scene);
        QFETCH(int, threads);
        QFETCH(int, teamSteps);
        const std::optional<Scene> s = namedScene(scene);
        QVERIFY(s.has_value());
        WorldOptions options;
        options.threads = threads;
        options.teamPacing = TeamPacing::Always;
        World w = makeWorld(*s, options);
        for (int i = 0; i < 30; ++i)
            w.step();
        QCOMPARE(w.profile().counter(Counter::TeamSteps), uint64_t(teamSteps));
    }

    // ramps.obj's cubes fall and slide in many small islands, which a team of two shares out in runs of body order
    // (IslandShare.h) in some solves and largest first in others, with the frames of one thread either way.
    void islandsSharedOutInBodyOrder() {
        const std::optional<Scene> s = namedScene("ramps.obj");
        QVERIFY(s.has_value());
        WorldOptions options;
        World one = makeWorld(*s, options);
        options.threads = 2;
        options.teamPacing = TeamPacing::Always;
        World two = makeWorld(*s, options);
        for (int i = 0; i < 90; ++i) {
            one.step();
            two.step();
        }
        QCOMPARE(two.stateHash(), one.stateHash());
        const uint64_t shared = two.profile().counter(Counter::IslandsSharedOut);
        const uint64_t inOrder = two.profile().counter(Counter::IslandsInBodyOrder);
        qInfo("islands shared out in %llu solves, in body order in %llu", static_cast<unsigned long long>(shared),
              static_cast<unsigned long long>(inOrder));
        QVERIFY(inOrder > 0);
        QVERIFY(inOrder <= shared);
        QCOMPARE(one.profile().counter(Counter::IslandsInBodyOrder), uint64_t(0));
    }

    // Where a thread sweeps a part (or a whole group, or its islands) alone, the solver packs the part's levels into
    // full batches (ContactSolver::packPartLevels()): the same updates per body in the same order, so the same frames
    // bit for bit as the levels unpacked (ContactSolver::setPackLevels(false)), in fewer batches: on one thread, with
    // the islands shared out on two, and with a pyramid cut in two parts, each swept by one thread.
    void packedLevelsGiveIdenticalResults_data() {
        QTest::addColumn<QString>("scene"); // a library name or a file under resources/scenes
        QTest::addColumn<int>("threads");
        QTest::addColumn<int>("frames");
        QTest::addColumn<bool>("inParts"); // some solves swept by parts
        QTest::newRow("pyramid20, one thread") << "pyramid20" << 1 << 60 << false;
        QTest::newRow("boxes1000, one thread") << "boxes1000" << 1 << 60 << false;
        QTest::newRow("ramps.obj, two threads") << "ramps.obj" << 2 << 120 << false;
        QTest::newRow("pyramid of 465 cubes, two threads") << "pyramid30" << 2 << 30 << true;
    }
    void packedLevelsGiveIdenticalResults() {
        QFETCH(QString, scene);
        QFETCH(int, threads);
        QFETCH(int, frames);
        QFETCH(bool, inParts);
        const std::optional<Scene> s = namedScene(scene);
        QVERIFY(s.has_value());
        WorldOptions options;
        options.threads = threads;
        options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
        World levels = makeWorld(*s, options), packed = makeWorld(*s, options);
        for (int i = 0; i < frames; ++i) {
            ContactSolver::setPackLevels(false);
            levels.step();
            ContactSolver::setPackLevels(true);
            packed.step();
            if (i % 20 == 19 || i == frames - 1)
                QCOMPARE(packed.stateHash(), levels.stateHash());
        }
        const uint64_t before = levels.profile().counter(Counter::SweptBatches),
                       after = packed.profile().counter(Counter::SweptBatches);
        qInfo("swept batches: %llu in levels, %llu packed", static_cast<unsigned long long>(before),
              static_cast<unsigned long long>(after));
        QVERIFY(after > 0);
        QVERIFY(100 * after < 97 * before);
        QCOMPARE(packed.profile().counter(Counter::SolvedInParts) > 0, inParts);
        if (threads > 1 && !inParts)
            QVERIFY(packed.profile().counter(Counter::IslandsSharedOut) > 0);
    }

    // ramps.obj's 642 cubes on two threads: the team also shares the sleep clocks out (World::updateSleep()), and
    // the cubes that come to rest fall asleep on the same frames as on one thread.
    void sleepOnTwoThreadsGivesIdenticalResults() {
        Result<Scene> s = importScene(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
        QVERIFY(s.ok());
        uint64_t hashes[2];
        int awake[2] = {};
        int64_t awakeFrames[2] = {}; // awake bodies summed over the frames
        for (int run = 0; run < 2; ++run) {
            WorldOptions options;
            options.threads = run + 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(*s, options);
            for (int i = 0; i < 120; ++i) {
                w.step();
                awakeFrames[run] += w.diagnostics().awakeBodies;
            }
            hashes[run] = w.stateHash();
            awake[run] = w.diagnostics().awakeBodies;
        }
        qInfo("awake after 120 frames: %d of 642", awake[0]);
        QCOMPARE(hashes[0], hashes[1]);
        QCOMPARE(awake[0], awake[1]);
        QCOMPARE(awakeFrames[0], awakeFrames[1]);
        QVERIFY(awake[0] < 642); // some of the 642 sleep (25 at frame 120 since 2026-12-05's blocks, 49 before)
    }

    // The solver's sweeps after the first since a position phase reuse each point's separation
    // (ContactSolver::Motion): ramps.obj's cubes landing give the frames of sweeps that take every separation again,
    // on one thread and on two. (Its first 90 frames: since 2026-12-05 the first 60 hold at most 872 contact points.)
    void keptSeparationsGiveTheFramesOfTakenOnes() {
        Result<Scene> s = importScene(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
        QVERIFY(s.ok());
        uint64_t hashes[3];
        int contacts = 0;
        for (int run = 0; run < 3; ++run) { // kept on one thread, kept on two, taken every sweep on one
            ContactSolver::setKeepSeparations(run < 2);
            WorldOptions options;
            options.threads = run == 1 ? 2 : 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(*s, options);
            for (int i = 0; i < 90; ++i) {
                w.step();
                contacts = std::max(contacts, w.diagnostics().contactPoints);
            }
            hashes[run] = w.stateHash();
        }
        ContactSolver::setKeepSeparations(true);
        qInfo("most contact points in a frame: %d", contacts);
        QVERIFY(contacts > 1000);
        QCOMPARE(hashes[1], hashes[0]);
        QCOMPARE(hashes[2], hashes[0]);
    }

    // A thread solves its islands in runs of whole islands (World::solveInRuns()), one run after the other through
    // the substeps: scale1k's 1,000 cubes (471 stacked in pairs, 58 alone) give the frames of one solve of them all
    // in runs of 100 bodies, on one thread and on two.
    void islandsSolvedInRunsGiveTheFramesOfOneSolve() {
        const Scene scene = *scenes::byName("scale1k");
        uint64_t hashes[3];
        uint64_t prepares[3];
        for (int run = 0; run < 3; ++run) { // all at once on one thread; runs of 100 on one, on two
            World::setIslandRunBodies(run == 0 ? 0 : 100);
            WorldOptions options;
            options.threads = run == 2 ? 2 : 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(scene, options);
            for (int i = 0; i < 25; ++i)
                w.step();
            hashes[run] = w.stateHash();
            prepares[run] = w.profile().calls[static_cast<int>(Stage::PrepareContacts)];
            QVERIFY(w.diagnostics().contactPoints > 1000);
        }
        World::setIslandRunBodies(1024);
        qInfo("solver set-ups on one thread over 25 steps: %llu at once, %llu in runs of 100 bodies",
              static_cast<unsigned long long>(prepares[0]), static_cast<unsigned long long>(prepares[1]));
        QCOMPARE(hashes[1], hashes[0]);
        QCOMPARE(hashes[2], hashes[0]);
        QCOMPARE(prepares[0], uint64_t(25));
        QVERIFY(prepares[1] >= 25 * 9); // 1,000 bodies in runs of at least 100
    }

    // One pile of 400 boxes is one island. It is cut in two parts for the solver on one thread and on two
    // (World::cutIslands()), and the two threads each sweep a part; while the falling boxes are in smaller islands,
    // the threads split each level of the solver's schedule or share the islands out.
    void oneBigIslandOnTwoThreadsGivesIdenticalResults() {
        uint64_t hashes[2], cut[2], inParts[2];
        for (int run = 0; run < 2; ++run) {
            WorldOptions options;
            options.threads = run + 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(scenes::randomBoxes(400, 3), options);
            for (int i = 0; i < 150; ++i)
                w.step();
            QVERIFY(w.diagnostics().awakeBodies > 256); // still one big awake pile
            hashes[run] = w.stateHash();
            cut[run] = w.profile().counter(Counter::IslandsCut);
            inParts[run] = w.profile().counter(Counter::SolvedInParts);
        }
        QCOMPARE(hashes[1], hashes[0]);
        QVERIFY(cut[0] > 0);
        QCOMPARE(cut[1], cut[0]);
        QCOMPARE(inParts[0], uint64_t(0));
        QVERIFY(inParts[1] > 0);
        qInfo("400 boxes, 150 steps: an island cut in %llu steps, solved a part per thread in %llu",
              static_cast<unsigned long long>(cut[0]), static_cast<unsigned long long>(inParts[1]));
    }

    // A pyramid of 153 cubes beside 40 lone cubes: the pyramid is under 256 bodies but holds most of the group, so it
    // is cut in two parts all the same (WorldTuning::cutDominantIslandBodies), on one thread as on two; no share of
    // whole islands could keep two threads equally busy. The two threads then each sweep a part.
    void dominantIslandIsCutOnAnyThreadCount_data() {
        QTest::addColumn<int>("loneCubes");
        QTest::addColumn<bool>("cut");
        QTest::addRow("40 lone cubes: the pyramid holds most of the bodies") << 40 << true;
        QTest::addRow("160 lone cubes: it does not") << 160 << false;
    }
    void dominantIslandIsCutOnAnyThreadCount() {
        QFETCH(int, loneCubes);
        QFETCH(bool, cut);
        Scene s = scenes::pyramid(17);
        s.bodies[0].shape.halfExtents = Vec3(40.0, 0.5, 40.0);
        for (int i = 0; i < loneCubes; ++i)
            s.bodies.push_back(box("Lone", Vec3(0.2), Vec3((i % 20) * 1.5 - 15.0, 0.2, 5.0 + (i / 20) * 1.5)));
        const CutRun one = runAwake(s, 1, 30), two = runAwake(s, 2, 30);
        QCOMPARE(two.hash, one.hash);
        QCOMPARE(two.cuts, one.cuts);
        QCOMPARE(one.inParts, uint64_t(0));
        if (cut) {
            QCOMPARE(one.cuts, uint64_t(30)); // every step
            QCOMPARE(two.inParts, uint64_t(30));
        } else {
            QCOMPARE(one.cuts, uint64_t(0));
        }
    }

    // A pile of 400 boxes (one island, cut) beside a pyramid of 78 cubes (an island too small to cut): the pyramid
    // goes whole to one part and the pile is cut where the parts come out even (World::planCuts()), the same way on
    // one thread and on two. (Cut in halves, the pile left the parts 3,836 bodies apart over its 83 cuts.)
    void cutIslandEvensOutTheParts() {
        Scene s = scenes::randomBoxes(400, 3);
        s.bodies[0].shape.halfExtents = Vec3(40.0, 0.5, 40.0);
        const Scene pyramid = scenes::pyramid(12);
        for (size_t i = 1; i < pyramid.bodies.size(); ++i) {
            BodyDef cube = pyramid.bodies[i];
            cube.name = "Pyramid" + cube.name;
            cube.position += Vec3(0.0, 0.0, 15.0);
            s.bodies.push_back(cube);
        }
        const CutRun one = runAwake(s, 1, 120), two = runAwake(s, 2, 120);
        qInfo("120 steps: an island cut in %llu, bodies the larger part had over the other %llu in all",
              static_cast<unsigned long long>(one.cuts), static_cast<unsigned long long>(one.imbalance));
        QCOMPARE(one.awake, 478);
        QCOMPARE(two.hash, one.hash);
        QVERIFY(one.cuts >= 60); // the pile is one island from the time it lands
        QCOMPARE(two.cuts, one.cuts);
        QCOMPARE(two.imbalance, one.imbalance);
        QVERIFY(one.imbalance <= one.cuts); // a body at most apart, on average
        QVERIFY(two.inParts > 0);
    }

    // A big island on teams of two and three: the solver's bodies, contact lists and constraints are set up by the
    // team, the impulses go back to the manifolds shared out, and the narrowphase takes its batches from both ends
    // (a team of two) or in claim order (three). With restitution the solver also keeps its constraint records for
    // the bounce pass; without, it sets the constraints up straight into its batches. Same frames as one thread.
    void bigIslandOnTeamsGivesIdenticalResults_data() {
        QTest::addColumn<int>("threads");
        QTest::addColumn<double>("restitution");
        for (int threads : {2, 3})
            for (double restitution : {0.0, 0.4})
                QTest::addRow("%d threads, restitution %.1f", threads, restitution) << threads << restitution;
    }
    void bigIslandOnTeamsGivesIdenticalResults() {
        QFETCH(int, threads);
        QFETCH(double, restitution);
        Scene s = scenes::randomBoxes(300, 5);
        for (BodyDef& b : s.bodies)
            b.restitution = restitution;
        uint64_t hashes[2], bounces[2];
        for (int run = 0; run < 2; ++run) {
            WorldOptions options;
            options.threads = run == 0 ? 1 : threads;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(s, options);
            for (int i = 0; i < 100; ++i)
                w.step();
            QVERIFY(w.diagnostics().awakeBodies > 128); // big enough for the team
            QCOMPARE(w.effects().has(Effect::Restitution), restitution > 0.0);
            hashes[run] = w.stateHash();
            bounces[run] = w.profile().counter(Counter::RestitutionRows);
            if (run == 1) {
                // Some steps solve one big island on the whole team (the set-up shared out), others share smaller
                // islands out.
                const uint64_t inParts = w.profile().counter(Counter::SolvedInParts);
                const uint64_t sharedOut = w.profile().counter(Counter::IslandsSharedOut);
                qInfo("100 steps: a big island solved by the team in %llu, islands shared out in %llu",
                      static_cast<unsigned long long>(inParts), static_cast<unsigned long long>(sharedOut));
                QVERIFY(inParts > 0);
                QVERIFY(sharedOut > 0);
            }
        }
        QCOMPARE(hashes[1], hashes[0]);
        QCOMPARE(bounces[1], bounces[0]);
        if (restitution > 0.0)
            QVERIFY(bounces[0] > 0);
    }

    void islandsSolvedOnTwoThreadsGiveIdenticalResults() {
        // 200 two-box stacks are 200 islands, enough for the solve to run on two threads (from 128 moving bodies
        // on); a 1:1000 pair adds an island with refined substeps (a group of its own, too small for the team).
        Scene s = floorScene();
        for (int i = 0; i < 200; ++i) {
            const Vec3 at((i % 20) * 1.0 - 10.0, 0.0, (i / 20) * 1.0 - 5.0);
            s.bodies.push_back(box("Low", Vec3(0.2), at + Vec3(0.0, 0.21, 0.0)));
            s.bodies.push_back(box("High", Vec3(0.15), at + Vec3(0.03 * (i % 3), 0.6, 0.0)));
        }
        BodyDef light = box("Light", Vec3(0.25), Vec3(12.0, 0.25, 0.0));
        light.mass = 1.0;
        BodyDef heavy = box("Heavy", Vec3(0.25), Vec3(12.0, 0.75, 0.0));
        heavy.mass = 1000.0;
        s.bodies.push_back(light);
        s.bodies.push_back(heavy);
        uint64_t hashes[2];
        uint64_t rows[2], integrated[2], shared[2];
        for (int run = 0; run < 2; ++run) {
            WorldOptions options;
            options.threads = run + 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            options.effects = EffectsSetting::parse("auto,-sleeping").value();
            World w = makeWorld(s, options);
            for (int i = 0; i < 90; ++i)
                w.step();
            hashes[run] = w.stateHash();
            rows[run] = w.profile().counter(Counter::NormalRows);
            integrated[run] = w.profile().counter(Counter::IntegratedBodies);
            shared[run] = w.profile().counter(Counter::IslandsSharedOut);
        }
        QVERIFY(rows[0] > 0);
        // Two threads shared the 200 islands out, each solving its own with no synchronisation (World::
        // splitByIslands()), in every step; one thread has no one to share with.
        QCOMPARE(shared[0], uint64_t(0));
        QCOMPARE(shared[1], uint64_t(90));
        QCOMPARE(hashes[1], hashes[0]);
        QCOMPARE(rows[1], rows[0]);
        QCOMPARE(integrated[1], integrated[0]);
    }

    void ccdAndBroadphaseOnTwoThreadsGiveIdenticalResults() {
        // 160 small cubes shot down at 40 m/s onto a 5 cm plate: each moves 0.67 m a step against a 0.1 m size, so
        // CCD sweeps them (388 sweeps, 137 hits), shared out to two threads (World::continuousCollision()), and the
        // broadphase queries its 160 moved proxies in chunks on both threads (BroadPhase::updatePairs()). Same frames
        // and counters.
        Scene s;
        s.bodies.push_back(box("Plate", Vec3(20, 0.025, 20), Vec3(0, -0.025, 0), true));
        for (int i = 0; i < 160; ++i) {
            BodyDef b = box("Shot", Vec3(0.05), Vec3((i % 16) * 0.5 - 4.0, 1.0 + 0.13 * (i % 7), (i / 16) * 0.5 - 2.5));
            b.velocity = Vec3(0.1 * (i % 5), -40.0, 0.0);
            s.bodies.push_back(b);
        }
        uint64_t hashes[2], swept[2], hits[2], pairs[2];
        for (int run = 0; run < 2; ++run) {
            WorldOptions options;
            options.threads = run + 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(s, options);
            for (int i = 0; i < 20; ++i)
                w.step();
            hashes[run] = w.stateHash();
            swept[run] = w.profile().counter(Counter::CcdBodies);
            hits[run] = w.profile().counter(Counter::CcdHits);
            pairs[run] = w.profile().counter(Counter::Pairs);
            for (size_t i = 1; i < w.bodyCount(); ++i)
                QVERIFY2(w.centerOfMass(i).y > 0.0, qPrintable(QString("shot %1 went through the plate").arg(i)));
        }
        qInfo("160 shots at 40 m/s, 20 steps: CCD swept %llu times, hit %llu",
              static_cast<unsigned long long>(swept[0]), static_cast<unsigned long long>(hits[0]));
        QVERIFY(swept[0] >= 160);
        QVERIFY(hits[0] > 100); // the rest are stopped by their speculative contacts first
        QCOMPARE(hashes[1], hashes[0]);
        QCOMPARE(swept[1], swept[0]);
        QCOMPARE(hits[1], hits[0]);
        QCOMPARE(pairs[1], pairs[0]);
    }

    void separationOnTwoThreadsGivesIdenticalResults() {
        // boxes1000.obj's 1,000 boxes landing in layers: the collisions after the step (World::separateMovedPairs())
        // test more than 128 turned contacts on the team in 54 of its first 90 steps, and the contacts of the bodies
        // their pushes moved in 11 (counted 2026-12-06), then push in order, taking a test again where a push
        // moved its bodies since. Same frames and pushes.
        Result<Scene> s = importScene(RL_SOURCE_DIR "/tests/data/acceptance/boxes1000.obj");
        QVERIFY(s.ok());
        uint64_t hashes[2], pushes[2];
        for (int run = 0; run < 2; ++run) {
            WorldOptions options;
            options.threads = run + 1;
            options.teamPacing = TeamPacing::Always; // every step on the team, even on a busy machine
            World w = makeWorld(*s, options);
            for (int i = 0; i < 90; ++i)
                w.step();
            hashes[run] = w.stateHash();
            pushes[run] = w.profile().counter(Counter::SeparatedPairs);
        }
        qInfo("boxes1000.obj, 90 steps: %llu pushes apart", static_cast<unsigned long long>(pushes[0]));
        QVERIFY(pushes[0] > 1000);
        QCOMPARE(hashes[1], hashes[0]);
        QCOMPARE(pushes[1], pushes[0]);
    }

    void bakeRecordsFrameZeroAndEveryStep() {
        Scene s = floorScene();
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 3, 0)));
        World w = makeWorld(s);
        Bake bake = startBake(w);
        BakeRequest request;
        request.frames = 30;
        QVERIFY(bakeRun(w, bake, request));
        QCOMPARE(bake.frameCount(), size_t(31));
        QCOMPARE(bake.position(0, 1).y, 3.0f);
        QVERIFY(bake.position(30, 1).y < 3.0f);
        QVERIFY(bake.hasDiagnostics());
    }

    // A bake on a world with a team records each frame's bodies on the team too (World::betweenStepsParallelFor()):
    // ramps.obj's 646 bodies give the same frames, velocities and diagnostics on two threads as on one. Only a world
    // with a team, and enough bodies to pay for a team job, shares the record out.
    void bakeOnTwoThreadsRecordsTheSameFrames() {
        Result<Scene> s = importScene(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
        QVERIFY(s.ok());
        World one = makeWorld(*s);
        WorldOptions options;
        options.threads = 2;
        options.teamPacing = TeamPacing::Always;
        World two = makeWorld(*s, options);
        QVERIFY(!one.betweenStepsParallelFor(two.bodyCount()));
        QVERIFY(two.betweenStepsParallelFor(two.bodyCount()));
        QVERIFY(!two.betweenStepsParallelFor(20)); // too few for a team job

        // The team's record covers every body once.
        std::vector<int> seen(two.bodyCount(), 0);
        two.betweenStepsParallelFor(seen.size())(seen.size(), [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i)
                ++seen[i];
        });
        QCOMPARE(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(seen.size()));

        Bake a = startBake(one), b = startBake(two);
        BakeRequest request;
        request.frames = 40;
        QVERIFY(bakeRun(one, a, request));
        QVERIFY(bakeRun(two, b, request));
        QCOMPARE(b.frameCount(), a.frameCount());
        for (size_t f = 0; f < a.frameCount(); ++f) {
            for (size_t i = 0; i < a.bodyCount(); ++i) {
                QCOMPARE(b.position(f, i), a.position(f, i));
                QCOMPARE(b.rotation(f, i), a.rotation(f, i));
                QCOMPARE(b.linearVelocity(f, i), a.linearVelocity(f, i));
                QCOMPARE(b.angularVelocity(f, i), a.angularVelocity(f, i));
            }
            for (int d = 0; d < kBakeDiagnosticCount; ++d)
                QCOMPARE(b.diagnostic(f, static_cast<BakeDiagnostic>(d)),
                         a.diagnostic(f, static_cast<BakeDiagnostic>(d)));
        }
        QVERIFY(a.position(40, 100) != a.position(0, 100)); // the cubes fell
    }

    // A bake whose simulation starts at frame 10 holds the initial state up to frame 10, then runs exactly as a
    // bake started at frame 0 (bit for bit, shifted by 10 frames).
    void bakeStartingLaterHoldsTheInitialStateThenRunsTheSame() {
        Scene s = floorScene();
        s.bodies.push_back(box("Cube", Vec3(0.5), Vec3(0, 3, 0)));
        s.bodies.back().velocity = Vec3(1, 0, 0);
        World plainWorld = makeWorld(s), laterWorld = makeWorld(s);
        Bake plain = startBake(plainWorld), later = startBake(laterWorld);
        BakeRequest request;
        request.frames = 30;
        QVERIFY(bakeRun(plainWorld, plain, request));
        request.frames = 40;
        request.startFrame = 10;
        QVERIFY(bakeRun(laterWorld, later, request));
        QCOMPARE(later.frameCount(), size_t(41));
        QCOMPARE(later.simulationStart(), size_t(10));
        QCOMPARE(plain.simulationStart(), size_t(0));
        for (size_t f = 0; f <= 10; ++f) {
            QCOMPARE(later.position(f, 1), plain.position(0, 1));
            QCOMPARE(later.rotation(f, 1), plain.rotation(0, 1));
        }
        for (size_t f = 0; f <= 30; ++f) {
            QCOMPARE(later.position(f + 10, 1), plain.position(f, 1));
            QCOMPARE(later.rotation(f + 10, 1), plain.rotation(f, 1));
            QCOMPARE(later.linearVelocity(f + 10, 1), plain.linearVelocity(f, 1));
        }
        QVERIFY(later.position(11, 1) != later.position(10, 1));
    }
};

QTEST_APPLESS_MAIN(TestWorld)
#include "tst_world.moc"
