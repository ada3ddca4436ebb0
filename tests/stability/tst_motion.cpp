// Hard cases in motion: friction on a slope against the closed form, restitution apex heights, a tumbling T-handle,
// coincident boxes, a busy scene for 10 minutes, and projectiles against thin walls. (1,000 boxes dropped on a floor:
// tst_piles, its own test so that ctest runs it beside this one.)
#include "StabilityFixture.h"
#include "dynamics/ContactSolver.h"
#include "io/SceneImport.h"
#include "scene/SceneLibrary.h"

#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <vector>

using namespace rl;
using namespace rl::test;

namespace {
// `scene` with every body of one material of friction mu (density 1,000, no bounce), body 1 spinning about the
// vertical at w0.
Scene spunAboutTheVertical(Scene scene, Real mu, Real w0) {
    scene.materials.push_back({"Spun", 1000.0, mu, 0.0});
    for (BodyDef& body : scene.bodies)
        body.material = "Spun";
    scene.bodies[1].angularVelocity = Vec3(0.0, w0, 0.0);
    return scene;
}

// A ball of the given radius and mass, its centre at `position`.
BodyDef ball(const std::string& name, Real radius, Real mass, Vec3 position) {
    BodyDef b = scenes::sphere(name, radius, position);
    b.mass = mass;
    return b;
}

// A floor, a row of `masses.size()` balls of radius 0.1 m lying `gap` apart on it along x from the origin, and a cue
// ball of that radius 1 m short of the first, sliding into the row at `speed`; all frictionless, with restitution e.
Scene ballRow(const std::vector<Real>& masses, Real cueMass, Real speed, Real gap, Real e) {
    Scene s;
    s.bodies.push_back(scenes::floorBox());
    s.bodies.back().friction = 0.0;
    s.bodies.back().restitution = e;
    const auto rowBall = [&](const std::string& name, Real mass, Real x) {
        BodyDef b = ball(name, 0.1, mass, Vec3(x, 0.1, 0.0));
        b.friction = 0.0;
        b.restitution = e;
        s.bodies.push_back(b);
    };
    rowBall("Cue", cueMass, -1.0);
    s.bodies.back().velocity = Vec3(speed, 0.0, 0.0);
    for (size_t k = 0; k < masses.size(); ++k)
        rowBall("Ball." + std::to_string(k), masses[k], static_cast<Real>(k) * (0.2 + gap));
    return s;
}

// Linear velocities along x after one-dimensional collisions of the row above taken one after the other, each pair
// leaving at e times its approach speed, until no pair approaches faster than `threshold`.
std::vector<Real> collideInTurn(std::vector<Real> v, const std::vector<Real>& m, Real e, Real threshold) {
    for (bool any = true; any;) {
        any = false;
        for (size_t k = 0; k + 1 < v.size(); ++k) {
            const Real closing = v[k] - v[k + 1];
            if (!(closing > threshold))
                continue;
            const Real j = (1.0 + e) * closing / (1.0 / m[k] + 1.0 / m[k + 1]);
            v[k] -= j / m[k];
            v[k + 1] += j / m[k + 1];
            any = true;
        }
    }
    return v;
}

// The projectile speeds of the tunnelling cases.
void addSpeedRows() {
    QTest::addColumn<double>("speed");
    QTest::newRow("30 m/s") << 30.0;
    QTest::newRow("100 m/s") << 100.0;
    QTest::newRow("300 m/s") << 300.0;
}
// Steps w for `frames` and returns the lowest height body 1's hull points (shape coordinates) reached.
Real lowestPointOver(World& w, const std::vector<Vec3>& points, int frames, RunStats& stats) {
    Real lowest = std::numeric_limits<Real>::max();
    stats = run(w, frames, [&](int) {
        const Transform pose = w.transform(1);
        for (const Vec3& p : points)
            lowest = std::min(lowest, pose.apply(p).y);
    });
    return lowest;
}

// A box of a bouncing pile of 1,000 boxes (e = 0.5), captured in motion.
BodyDef pileBox(const char* name, const Vec3& half, const Vec3& position, const Quat& orientation, const Vec3& velocity,
                const Vec3& angularVelocity) {
    BodyDef b = scenes::box(name, half, position, orientation);
    b.restitution = 0.5;
    b.velocity = velocity;
    b.angularVelocity = angularVelocity;
    return b;
}

// Steps two captured bodies, alone in a world, for 30 frames; prints the deepest contact. The first `uncounted` steps
// do not count (a captured state's own overlap).
RunStats runCapturedPair(const BodyDef& first, const BodyDef& second, int uncounted = 0) {
    Scene s;
    s.bodies = {first, second};
    World w = makeWorld(s);
    for (int k = 0; k < uncounted; ++k)
        w.step();
    const RunStats stats = run(w, 30 - uncounted);
    qInfo("deepest contact %s%.2f mm", uncounted > 0 ? "after the first steps " : "", 1e3 * stats.maxPenetration);
    return stats;
}

// A row of `count` dominoes (2 x 20 x 10 cm, 700 kg/m3) standing `spacing` apart along x on a floor of the default
// material, the dominoes of friction mu and restitution e; the first is turned towards the second at 8 rad/s.
// Steps `frames` frames and prints the highest total energy any frame reached against the start's.
struct EnergyRun {
    Real start = 0.0, highest = 0.0;
    RunStats stats;
};
EnergyRun runForHighestEnergy(World& w, int frames) {
    EnergyRun r;
    r.start = r.highest = totalEnergy(w);
    int highestFrame = 0;
    r.stats = run(w, frames, [&](int f) {
        if (const Real energy = totalEnergy(w); !(energy <= r.highest)) {
            r.highest = energy;
            highestFrame = f;
        }
    });
    qInfo("energy at most %+.4f %% of its start (%.4g J), at frame %d", 100.0 * (r.highest - r.start) / r.start,
          r.start, highestFrame);
    return r;
}

// A state captured for these tests (tests/data/stability/README.md), by its file name there.
Result<Scene> capturedScene(const std::string& file) {
    return importScene(std::string(RL_SOURCE_DIR "/tests/data/stability/") + file);
}

Scene dominoRow(int count, Real spacing, Real mu, Real e) {
    Scene s;
    s.bodies.push_back(scenes::floorBox());
    for (int k = 0; k < count; ++k) {
        BodyDef d = scenes::box("Domino." + std::to_string(k), Vec3(0.01, 0.1, 0.05),
                                Vec3(static_cast<Real>(k) * spacing, 0.1, 0.0));
        d.density = 700.0;
        d.friction = mu;
        d.restitution = e;
        s.bodies.push_back(d);
    }
    s.bodies[1].angularVelocity = Vec3(0.0, 0.0, -8.0);
    return s;
}

} // namespace

class TestMotion : public QObject {
    Q_OBJECT
private slots:
    void slopeSticksWithHighFriction() {
        World w = makeWorld(scenes::slope(30.0, 0.7));
        const Vec3 start = w.centerOfMass(1);
        run(w, 600);
        const Real drift = glm::length(w.centerOfMass(1) - start);
        qInfo("slope 30 deg, mu 0.7: drift %.3g m", drift);
        QVERIFY(drift < 0.001);
    }

    void slopeSlidesAsTheClosedForm() {
        const Real theta = glm::radians(30.0), mu = 0.3, g = 9.81;
        World w = makeWorld(scenes::slope(30.0, mu));
        const Vec3 start = w.centerOfMass(1);
        run(w, 60);
        const Real distance = glm::length(w.centerOfMass(1) - start);
        const Real exact = 0.5 * g * (std::sin(theta) - mu * std::cos(theta)) * 1.0;
        qInfo("slope 30 deg, mu 0.3: slid %.4f m in 1 s, closed form %.4f m (%.2f %%)", distance, exact,
              100.0 * (distance - exact) / exact);
        QVERIFY(std::abs(distance - exact) < 0.02 * exact);
    }

    // A ball let go on a slope rolls without slipping while mu >= 2/7 tan(theta): its centre accelerates at
    // 5/7 g sin(theta) and it spins at v / r. With less friction it slips: g (sin(theta) - mu cos(theta)), and the
    // friction spins it up at 5 mu g cos(theta) / (2 r). Measured 2026-12-05: every row's distance at 1 s within
    // +0.27 to +0.29 % (the symplectic step's lead of h/2), its spin within 0.01 %.
    void ballOnASlopeRollsOrSlipsAsTheClosedForm_data() {
        QTest::addColumn<Real>("degrees");
        QTest::addColumn<Real>("mu");
        QTest::newRow("10 deg, mu 0.7: rolls") << 10.0 << 0.7;
        QTest::newRow("30 deg, mu 0.7: rolls") << 30.0 << 0.7;
        QTest::newRow("45 deg, mu 0.7: rolls") << 45.0 << 0.7;
        QTest::newRow("30 deg, mu 0.1: slips") << 30.0 << 0.1;
        QTest::newRow("45 deg, mu 0.1: slips") << 45.0 << 0.1;
    }
    void ballOnASlopeRollsOrSlipsAsTheClosedForm() {
        QFETCH(Real, degrees);
        QFETCH(Real, mu);
        const Real theta = glm::radians(degrees), g = 9.81, radius = 0.2, t = 1.0;
        Scene scene = scenes::slope(degrees, mu);
        const Vec3 normal = glm::angleAxis(theta, Vec3(0, 0, 1)) * Vec3(0, 1, 0);
        BodyDef& ball = scene.bodies[1]; // the block becomes a ball, of the same material
        ball.shape.type = ShapeType::Sphere;
        ball.shape.radius = radius;
        ball.position = radius * normal;
        ball.orientation = identityQuat();
        World w = makeWorld(scene);
        const Vec3 start = w.centerOfMass(1);
        run(w, static_cast<int>(std::lround(60.0 * t)));
        const bool rolls = mu >= 2.0 / 7.0 * std::tan(theta);
        const Real a = rolls ? 5.0 / 7.0 * g * std::sin(theta) : g * (std::sin(theta) - mu * std::cos(theta));
        const Real distance = glm::length(w.centerOfMass(1) - start), exact = 0.5 * a * t * t;
        const Real spin = glm::length(w.angularVelocity(1));
        const Real exactSpin = rolls ? a * t / radius : 2.5 * mu * g * std::cos(theta) * t / radius;
        qInfo("ball on a %.0f deg slope, mu %.1f (%s): %.4f m in %.0f s against %.4f m (%+.2f %%), spin %.3f rad/s "
              "against %.3f (%+.2f %%)",
              degrees, mu, rolls ? "rolls" : "slips", distance, t, exact, 100.0 * (distance - exact) / exact, spin,
              exactSpin, 100.0 * (spin - exactSpin) / exactSpin);
        QVERIFY(std::abs(distance - exact) < 0.01 * exact);
        QVERIFY(std::abs(spin - exactSpin) < 0.01 * exactSpin);
    }

    // Issue 4 asks for the first three apexes of an e = 0.5 drop within 3 % of e^(2n) h0, at default settings. The
    // restitution pass takes the speed at impact from energy on the flight the integrator follows and launches on
    // it (ContactSolver::applyRestitution()), so the apexes no longer depend on where in a step the ball lands nor
    // on the integrator: every row at 5 m measured within 0.4 % (2026-11-26); before, the third apex was -2.1 % at
    // 8 substeps and +3.3 % at 6. A ball the relax sweep's speculative row stops a few millimetres short of the
    // floor at the end of a step is launched from there with the speed it would have on its way back up
    // (2026-12-05); launched at the floor's speed, the second apex from 1 m was 6.5 % high and the third from 1.25 m
    // 14.8 % (frame maxima of `rigidlab-cli bake`). The heights below are the ones that went wrong, and 5 m. The rows
    // hold the apexes to 1 % (explicit Euler's to 2 %: its third apex from 1.25 m at 4 substeps measured -1.10 %),
    // each taken as the vertex of the parabola through the three frames around it (frame maxima alone are up to
    // g dt^2 / 8 = 0.34 mm low, 2 % of the third apex from 1 m).
    void bounceApexHeights_data() {
        QTest::addColumn<double>("h0");
        QTest::addColumn<int>("substeps");
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("within");
        for (const double h0 : {1.0, 1.25, 2.0, 5.0})
            QTest::addRow("%g m, default settings", h0) << h0 << 0 << QString() << 0.01;
        for (const double h0 : {1.25, 5.0})
            for (const char* integrator : {"symplectic-euler", "explicit-euler", "verlet", "rk4"})
                for (int substeps : {4, 6})
                    QTest::addRow("%g m, %s, %d substeps", h0, integrator, substeps)
                        << h0 << substeps << QString(integrator)
                        << (std::string_view(integrator) == "explicit-euler" ? 0.02 : 0.01);
    }

    void bounceApexHeights() {
        QFETCH(double, h0);
        QFETCH(int, substeps);
        QFETCH(QString, integrator);
        QFETCH(double, within);
        const Real e = 0.5;
        WorldOptions options;
        if (substeps > 0)
            options.substeps = substeps;
        if (!integrator.isEmpty())
            options.integrator = parseIntegrator(integrator.toStdString());
        World w = makeWorld(scenes::drop(h0, e), options);
        std::vector<Real> heights{w.centerOfMass(1).y - 0.1}; // of the bottom of the ball, frame by frame
        run(w, 600, [&](int) { heights.push_back(w.centerOfMass(1).y - 0.1); });
        std::vector<Real> apexes;
        for (size_t f = 1; f + 1 < heights.size(); ++f) {
            const Real before = heights[f - 1], at = heights[f], after = heights[f + 1];
            if (before <= at && at > after) {
                const Real a = 0.5 * (before + after) - at, b = 0.5 * (after - before);
                apexes.push_back(at - b * b / (4.0 * a));
            }
        }
        QVERIFY(apexes.size() >= 3);
        for (int n = 1; n <= 3; ++n) {
            const Real expected = std::pow(e, 2.0 * n) * h0;
            qInfo("bounce %d: apex %.5f m, expected %.5f m (%.2f %%)", n, apexes[n - 1], expected,
                  100.0 * (apexes[n - 1] - expected) / expected);
            QVERIFY(std::abs(apexes[n - 1] - expected) < within * expected);
        }
    }

    // A ball rolled into a row of touching balls (or balls 0.5 mm apart, inside the speculative distance, so that the
    // whole row is in one step's contacts): with e = 1 the last ball leaves at the cue's speed and the others stay,
    // with e < 1 each ball passes on (1 + e) / 2 of what it got. The restitution pass plays a chain's collisions out
    // one after the other (ContactSolver::bounceChains()); each link's bounce from its own approach speed before the
    // step, the rule for a manifold alone, took the row as one lump: five balls with e = 1 sent the last off at 0.66
    // of the cue's speed and kept 48 % of the energy (2026-12-05).
    void rowOfTouchingBallsPassesTheBlowOn_data() {
        QTest::addColumn<int>("balls");
        QTest::addColumn<double>("gap");
        QTest::addColumn<double>("e");
        for (const double e : {1.0, 0.9})
            for (const int balls : {1, 3, 5, 8})
                for (const double gap : {0.0, 0.0005})
                    QTest::addRow("%d balls %g m apart, e = %g", balls, gap, e) << balls << gap << e;
    }
    void rowOfTouchingBallsPassesTheBlowOn() {
        QFETCH(int, balls);
        QFETCH(double, gap);
        QFETCH(double, e);
        const Real speed = 2.0;
        World w = makeWorld(ballRow(std::vector<Real>(static_cast<size_t>(balls), 1.0), 1.0, speed, gap, e));
        const auto energy = [&] { return w.diagnostics().kineticEnergy; };
        const Real start = energy();
        Real highest = start;
        const RunStats stats = run(w, 90, [&](int) { highest = std::max(highest, energy()); });
        const Real last = w.linearVelocity(w.bodyCount() - 1).x;
        const Real expected = std::pow(0.5 * (1.0 + e), balls) * speed;
        Real others = 0.0; // the fastest of the rest, whose expected speeds are (1 - e) / 2 of what each got
        for (size_t i = 1; i + 1 < w.bodyCount(); ++i)
            others = std::max(others, std::abs(w.linearVelocity(i).x));
        qInfo("last ball %.4f m/s (expected %.4f), the others at most %.4f m/s, energy at most %+.3f %% of its start",
              last, expected, others, 100.0 * (highest - start) / start);
        QVERIFY(stats.allFinite);
        QVERIFY(std::abs(last - expected) < 0.01 * speed);
        QVERIFY(others <= 0.5 * (1.0 - e) * speed + 0.01 * speed);
        QVERIFY(highest <= start * 1.001);
    }

    // The same with balls that get lighter along the row: each leaves at a third of its speed and the next at four
    // thirds, so no two meet again and the answer is that of collisions taken in turn (collideInTurn()), to 1 % of
    // the cue's speed.
    void rowOfLighterBallsAsCollisionsInTurn() {
        const std::vector<Real> masses{0.5, 0.25, 0.125, 0.0625};
        const Real speed = 2.0, e = 1.0;
        World w = makeWorld(ballRow(masses, 1.0, speed, 0.0, e));
        run(w, 90);
        std::vector<Real> start{speed}, mass{1.0};
        for (const Real m : masses) {
            start.push_back(0.0);
            mass.push_back(m);
        }
        const std::vector<Real> expected = collideInTurn(start, mass, e, 1.0);
        for (size_t k = 0; k < expected.size(); ++k) {
            const Real v = w.linearVelocity(k + 1).x;
            qInfo("%s: %.4f m/s, expected %.4f", w.name(k + 1).c_str(), v, expected[k]);
            QVERIFY(std::abs(v - expected[k]) < 0.01 * speed);
        }
    }

    // A row of touching cubes hit by one more, e = 1, frictionless: face contacts of four points each pass the blow
    // on as the balls do. (By the rule for a manifold alone, three cubes kept 72 % of the energy and six 45 %.)
    void rowOfTouchingCubesKeepsItsEnergy_data() {
        QTest::addColumn<int>("cubes");
        for (const int cubes : {3, 6})
            QTest::addRow("%d cubes", cubes) << cubes;
    }
    void rowOfTouchingCubesKeepsItsEnergy() {
        QFETCH(int, cubes);
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        const Real speed = 3.0;
        for (int k = 0; k <= cubes; ++k) {
            BodyDef b;
            b.name = k == 0 ? std::string("Hit") : "Cube." + std::to_string(k);
            b.shape.halfExtents = Vec3(0.1);
            b.position = Vec3(k == 0 ? -1.0 : 0.2 * (k - 1), 0.1, 0.0);
            b.velocity = Vec3(k == 0 ? speed : 0.0, 0.0, 0.0);
            b.mass = 1.0;
            s.bodies.push_back(b);
        }
        for (BodyDef& b : s.bodies) {
            b.friction = 0.0;
            b.restitution = 1.0;
        }
        World w = makeWorld(s);
        const Real start = w.diagnostics().kineticEnergy;
        Real highest = start;
        const RunStats stats = run(w, 120, [&](int) { highest = std::max(highest, w.diagnostics().kineticEnergy); });
        const Real end = w.diagnostics().kineticEnergy;
        const Real last = w.linearVelocity(w.bodyCount() - 1).x;
        qInfo("last cube %.4f m/s of %.1f, energy at the end %+.3f %% of its start, at most %+.3f %%", last, speed,
              100.0 * (end - start) / start, 100.0 * (highest - start) / start);
        QVERIFY(stats.allFinite);
        QVERIFY(std::abs(last - speed) < 0.01 * speed);
        QVERIFY(end > 0.99 * start);
        QVERIFY(highest <= start * 1.001);
    }

    // A small ball resting on a big one, both dropped 1 m onto the floor with e = 1: the big one bounces off the floor
    // and meets the small one still falling, which leaves at (3M - m) / (M + m) of their speed (a basketball and a
    // tennis ball). By the rule for a manifold alone it rose 18 % short of that.
    void ballDroppedOnABallGoesUpFast() {
        const Real bigMass = 0.6, bigRadius = 0.12, smallMass = 0.058, smallRadius = 0.033, gap = 0.0005, h = 1.0;
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        s.bodies.push_back(ball("Big", bigRadius, bigMass, Vec3(0.0, h + bigRadius, 0.0)));
        s.bodies.push_back(
            ball("Small", smallRadius, smallMass, Vec3(0.0, h + 2.0 * bigRadius + smallRadius + gap, 0.0)));
        for (BodyDef& b : s.bodies)
            b.restitution = 1.0;
        World w = makeWorld(s);
        Real apex = 0.0;
        run(w, 150, [&](int) { apex = std::max(apex, w.centerOfMass(2).y); });
        const Real g = 9.81, v = std::sqrt(2.0 * g * h);
        const Real leaves = v * (3.0 * bigMass - smallMass) / (bigMass + smallMass);
        const Real expected = 2.0 * bigRadius + smallRadius + gap + leaves * leaves / (2.0 * g);
        qInfo("small ball's apex %.4f m, expected %.4f m (%+.2f %%)", apex, expected,
              100.0 * (apex - expected) / expected);
        QVERIFY(std::abs(apex - expected) < 0.02 * expected);
    }

    // States captured from random scenes of bouncing shapes (tests/data/stability/README.md) that gained energy:
    // a 536 kg cylinder falling onto a 3 kg cone spinning at 52 rad/s and an 83 kg box (bounced off the light bodies
    // held under it as ground, it gained 16 kJ in a step with e = 0.9), and a 79 kg cone landing on its rim while
    // turning fast (+945 J: its four points left at e times four different approach speeds). With e = 0 and 0.5 as
    // well. The first may gain 1 %, the budget for a busy scene: the held cone still drags the cylinder by
    // friction as a conveyor belt would (+0.95, +0.73 and +0.80 % measured, 2026-12-05; see World::contactHold()).
    void capturedBouncesGainNoEnergy_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("e");
        QTest::addColumn<double>("within");
        for (const char* file : {"heavy_onto_spinning_light_bodies.rlscene", "spinning_cone_lands.rlscene"})
            for (const double e : {-1.0, 0.0, 0.5})
                QTest::addRow("%s, %s", file,
                              e < 0.0    ? "its restitution"
                              : e == 0.0 ? "e = 0"
                                         : "e = 0.5")
                    << QString(file) << e << (std::string_view(file).starts_with("heavy") ? 0.01 : 0.001);
    }
    void capturedBouncesGainNoEnergy() {
        QFETCH(QString, file);
        QFETCH(double, e);
        QFETCH(double, within);
        Result<Scene> scene = capturedScene(file.toStdString());
        QVERIFY2(scene, scene ? "" : scene.error().toString().c_str());
        if (e >= 0.0)
            for (BodyDef& b : scene->bodies)
                b.restitution = e;
        World w = makeWorld(*scene);
        const EnergyRun r = runForHighestEnergy(w, 120);
        QVERIFY(r.stats.allFinite);
        QVERIFY(r.highest <= r.start + within * std::abs(r.start));
    }

    // Rods dropped on a floor, turning: 0.5 m long boxes and 16-sided cylinders of 5:1, 20:1 and 100:1, from 0.5 and
    // 3 m, tilted 20 and 60 degrees, spinning at 10 and 30 rad/s about a slanted axis, of Steel (e 0.6) and Rubber (e
    // 0.8). None may gain energy. Before 2026-12-07, 57 of these 96 drops gained more than 1 % (3 and 2 of the 5:1
    // boxes and cylinders, 10 and 11 of the 20:1, 15 and 16 of the 100:1), many of them without bound: a thin body's
    // inverse inertia turned with it within a step while the solver's rows kept the step start's masses
    // (BodyState::solverInverseInertia()), the restitution pass bounded a bounce by energies taken with the inverse
    // inertia of another pose (ContactSolver::applyRestitution()), and pushes out of overlaps turned a spin about a
    // rod's length onto its width (World::keepSpinEnergy()). A sweep of 540 such drops through `rigidlab-cli bake` (4 s
    // each): 208 gained more than 5 % before, none after; of 96 needles of 20 x 0.2 x 0.2 cm (10 s), 75 before, none
    // after.
    void turningRodsGainNoEnergy_data() {
        QTest::addColumn<int>("aspect");
        QTest::addColumn<bool>("cylinder");
        QTest::addColumn<double>("height");
        QTest::addColumn<double>("tilt");
        QTest::addColumn<double>("spin");
        QTest::addColumn<QString>("material");
        QTest::addColumn<int>("row");
        int k = 0;
        for (const int aspect : {5, 20, 100})
            for (const bool cylinder : {false, true})
                for (const double height : {0.5, 3.0})
                    for (const double tilt : {20.0, 60.0})
                        for (const double spin : {10.0, 30.0})
                            for (const char* material : {"Steel", "Rubber"})
                                QTest::addRow("%d:1 %s from %.1f m, %.0f deg, %.0f rad/s, %s", aspect,
                                              cylinder ? "cylinder" : "box", height, tilt, spin, material)
                                    << aspect << cylinder << height << tilt << spin << QString(material) << k++;
    }
    void turningRodsGainNoEnergy() {
        QFETCH(int, aspect);
        QFETCH(bool, cylinder);
        QFETCH(double, height);
        QFETCH(double, tilt);
        QFETCH(double, spin);
        QFETCH(QString, material);
        QFETCH(int, row);
        const Real half = 0.25, radius = half / aspect;
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        // Axes that differ from row to row: the tilt about one, the spin about another.
        const Vec3 tiltAxis = glm::normalize(Vec3(std::sin(1.3 * row), 0.4, std::cos(0.7 * row)));
        const Vec3 spinAxis = glm::normalize(Vec3(std::cos(2.1 * row), std::sin(0.9 * row + 0.5), 0.6));
        const Quat orientation = glm::angleAxis(tilt * kPi / 180.0, tiltAxis);
        if (!cylinder) {
            s.bodies.push_back(scenes::box("Rod", Vec3(half, radius, radius), Vec3(0.0, height, 0.0), orientation));
        } else {
            BodyDef rod;
            rod.name = "Rod";
            rod.shape.type = ShapeType::Hull;
            for (int side = 0; side < 16; ++side)
                for (const Real x : {-half, half})
                    rod.shape.points.push_back(Vec3(x, radius * std::cos(2.0 * kPi * side / 16.0),
                                                    radius * std::sin(2.0 * kPi * side / 16.0)));
            rod.position = Vec3(0.0, height, 0.0);
            rod.orientation = orientation;
            s.bodies.push_back(rod);
        }
        s.bodies.back().material = material.toStdString();
        s.bodies.back().angularVelocity = spin * spinAxis;
        World w = makeWorld(s);
        const EnergyRun r = runForHighestEnergy(w, 240);
        QVERIFY(r.stats.allFinite);
        QVERIFY(r.highest <= r.start * 1.01);
    }

    // Piles of 120 sticks dropped on a floor (tests/data/stability/README.md: sticks_pile_*.rlscene, written by a
    // script as the piles of pileOfSticksGainsNoEnergy, 10:1 to 80:1, five materials, 0.1 to 75 kg). Crossed sticks
    // lie in loops: a light one held under a heavy one (World::contactHold()) bore up a third stick that rested on
    // the heavy one, or the heavy one rested on a third that rested on the light one, and the held stick, pushed by
    // the third, lifted the heavy one as an immovable piston would, a little more at each sweep: before 2026-12-07
    // these three piles gained 24 %, 7 % and 119 % of their energy within one step (from a census of 159 such piles:
    // 3 on the code before, 0 now). The energy may not rise above its start (+1 %) in 2 s.
    void pilesOfCrossedSticksGainNoEnergy_data() {
        QTest::addColumn<QString>("file");
        for (const char* file : {"sticks_pile_10.rlscene", "sticks_pile_17.rlscene", "sticks_pile_117.rlscene"})
            QTest::newRow(file) << QString(file);
    }
    void pilesOfCrossedSticksGainNoEnergy() {
        QFETCH(QString, file);
        Result<Scene> scene = capturedScene(file.toStdString());
        QVERIFY2(scene, scene ? "" : scene.error().toString().c_str());
        World w = makeWorld(*scene);
        const EnergyRun r = runForHighestEnergy(w, 120);
        QVERIFY(r.stats.allFinite);
        QVERIFY(r.highest <= r.start * 1.01);
    }

    // Bullets at thin walls (tests/data/stability/README.md: bullet_*.rlscene): rods of 4-16 cm, cubes of 2-10 cm and
    // a tetrahedron at 50-2,000 m/s (clamped to 1,000), head on or up to 75 degrees off, some spinning at about 130 or
    // 1,300 rad/s, into anchored and free-standing walls of 1-10 mm. A sweep of 400 such shots (`rigidlab-cli bake`,
    // 0.5 s) let 8 through before 2026-12-08, all 8 kept here; none now. CCD bounded a body's approach by its whole
    // sweep, so one sliding fast along a wall while it closed in slowly ran out of iterations and was let through;
    // and a body that began the step near a wall was left to the solver, whose points (found at the step's start) did
    // not hold it once the blow turned it, or once a free wall it had set turning swung away from them: its centre
    // went through. The bullet's centre may never cross the wall's middle plane within the wall
    // (World::continuousCollision()).
    void bulletsStayOnTheirSideOfThinWalls_data() {
        QTest::addColumn<QString>("file");
        for (const char* file : {"bullet_rod_grazing_thin_wall.rlscene", "bullet_box_into_free_wall.rlscene",
                                 "bullet_tetrahedron_grazing_wall.rlscene", "bullet_box_into_free_foil.rlscene",
                                 "bullet_spinning_rod_into_wall.rlscene", "bullet_rod_grazing_falling_wall.rlscene",
                                 "bullet_rod_grazing_free_wall.rlscene", "bullet_cube_into_falling_wall.rlscene"})
            QTest::newRow(file) << QString(file);
    }
    void bulletsStayOnTheirSideOfThinWalls() {
        QFETCH(QString, file);
        Result<Scene> scene = capturedScene(file.toStdString());
        QVERIFY2(scene, scene ? "" : scene.error().toString().c_str());
        size_t wall = 0, bullet = 0;
        for (size_t i = 0; i < scene->bodies.size(); ++i) {
            if (scene->bodies[i].name == "Wall")
                wall = i;
            if (scene->bodies[i].name == "Bullet")
                bullet = i;
        }
        QVERIFY(wall > 0 && bullet > 0);
        const Vec3 half = scene->bodies[wall].shape.halfExtents;
        World w = makeWorld(*scene);
        // The bullet's centre in the wall's frame; it starts on the wall's -x side.
        const auto local = [&] {
            return glm::inverse(w.shapeOrientation(wall)) * (w.centerOfMass(bullet) - w.centerOfMass(wall));
        };
        const auto withinWall = [&](const Vec3& p) { return std::abs(p.y) < half.y && std::abs(p.z) < half.z; };
        Vec3 before = local();
        QVERIFY(before.x < -half.x);
        int crossed = -1;
        Real farthest = before.x;
        const RunStats stats = run(w, 30, [&](int f) {
            const Vec3 now = local();
            if (crossed < 0 && before.x < 0.0 && now.x > 0.0 && withinWall(before) && withinWall(now))
                crossed = f;
            farthest = std::max(farthest, now.x);
            before = now;
        });
        qInfo("%s: the bullet's centre got to %.1f mm from the wall's middle (its face at %.1f mm), %s",
              qPrintable(file), 1e3 * farthest, -1e3 * half.x,
              crossed < 0 ? "never through" : qPrintable(QString("through at frame %1").arg(crossed)));
        QVERIFY(stats.allFinite);
        QCOMPARE(crossed, -1);
    }

    // Bodies landing on a floor while they spin fast, with e 0.95 and 1, with and without friction: a box, a 16-sided
    // cone and a plank, dropped still from 1 m or thrown down at 6 m/s from 2 m, spinning at 10 and 30 rad/s about an
    // axis and from a pose that differ from row to row. Each point of a landing bounces at e times its own approach
    // speed, and the restitution pass bounds the whole bounce by energy (ContactSolver::launch()). Before 2026-12-07
    // that bound was the kinetic energy the bodies would have had after free flight through the step and a substep,
    // more than a body that landed within the step ever has: a sweep of 150 such drops (`rigidlab-cli bake`, 3 s) found
    // 10 gaining 0.1 to 2.1 % of their energy. The bound is now the energy at the step start and gravity's work over
    // the step's actual motion: none of the 150 above +0.09 %.
    void spinningLandingsGainNoEnergy_data() {
        QTest::addColumn<int>("shape");
        QTest::addColumn<double>("e");
        QTest::addColumn<double>("spin");
        QTest::addColumn<bool>("thrown");
        QTest::addColumn<double>("mu");
        QTest::addColumn<int>("row");
        int k = 0;
        for (const int shape : {0, 1, 2})
            for (const double e : {0.95, 1.0})
                for (const double spin : {10.0, 30.0})
                    for (const bool thrown : {false, true})
                        for (const double mu : {0.0, 0.5})
                            QTest::addRow("%s, e %.2f, mu %.1f, %.0f rad/s, %s",
                                          shape == 0   ? "box"
                                          : shape == 1 ? "cone"
                                                       : "plank",
                                          e, mu, spin, thrown ? "thrown at 6 m/s from 2 m" : "dropped from 1 m")
                                << shape << e << spin << thrown << mu << k++;
    }
    void spinningLandingsGainNoEnergy() {
        QFETCH(int, shape);
        QFETCH(double, e);
        QFETCH(double, spin);
        QFETCH(bool, thrown);
        QFETCH(double, mu);
        QFETCH(int, row);
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        const Vec3 tiltAxis = glm::normalize(Vec3(std::sin(1.7 * row + 0.3), 0.5, std::cos(1.1 * row)));
        const Vec3 spinAxis = glm::normalize(Vec3(std::cos(2.3 * row), std::sin(1.3 * row + 0.5), 0.7));
        const Quat orientation = glm::angleAxis(0.4 + 0.37 * row, tiltAxis);
        const Vec3 position(0.0, thrown ? 2.0 : 1.0, 0.0);
        if (shape == 1) {
            BodyDef cone;
            cone.name = "Cone";
            cone.shape.type = ShapeType::Hull;
            for (int side = 0; side < 16; ++side)
                cone.shape.points.push_back(
                    Vec3(0.3 * std::cos(2.0 * kPi * side / 16.0), 0.0, 0.3 * std::sin(2.0 * kPi * side / 16.0)));
            cone.shape.points.push_back(Vec3(0.0, 0.6, 0.0));
            cone.position = position;
            cone.orientation = orientation;
            s.bodies.push_back(cone);
        } else {
            const Vec3 half = shape == 0 ? Vec3(0.3, 0.1, 0.2) : Vec3(0.4, 0.05, 0.2);
            s.bodies.push_back(scenes::box(shape == 0 ? "Box" : "Plank", half, position, orientation));
        }
        s.bodies.back().angularVelocity = spin * spinAxis;
        s.bodies.back().velocity = Vec3(0.0, thrown ? -6.0 : 0.0, 0.0);
        for (BodyDef& b : s.bodies) {
            b.restitution = e;
            b.friction = mu;
        }
        World w = makeWorld(s);
        const EnergyRun r = runForHighestEnergy(w, 180);
        QVERIFY(r.stats.allFinite);
        QVERIFY(r.highest <= r.start * 1.001);
    }

    // Piles of sticks dropped on a floor ("pick-up sticks"): 40 boxes and 8-sided cylinders of 15 cm to 1 m, 10:1 to
    // 80:1, turned at random, of five materials, falling onto each other within 1.2 m square. Their energy may not rise
    // above its start (+1 %) in 10 s. Before 2026-12-07 (see turningRodsGainNoEnergy) seven of eight such piles of 30
    // to 120 sticks (`rigidlab-cli bake`) ended in a non-finite position and the eighth threw a stick at 977 m/s; the
    // four rows here all failed.
    void pileOfSticksGainsNoEnergy_data() {
        QTest::addColumn<unsigned>("seed");
        for (const unsigned seed : {1u, 2u, 3u, 4u})
            QTest::addRow("seed %u", seed) << seed;
    }
    void pileOfSticksGainsNoEnergy() {
        QFETCH(unsigned, seed);
        std::mt19937 random(seed);
        const auto uniform = [&](double lo, double hi) {
            return std::uniform_real_distribution<double>(lo, hi)(random);
        };
        const char* materials[] = {"Wood", "Steel", "Plastic", "Default", "Rubber"};
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        for (int i = 0; i < 40; ++i) {
            const Real length = uniform(0.15, 1.0), aspect = std::array{10.0, 20.0, 40.0, 80.0}[random() % 4];
            const Real radius = 0.5 * length / aspect;
            const Quat turn = glm::angleAxis(
                uniform(0.0, kPi), glm::normalize(Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1) + 1e-3)));
            const Vec3 at(uniform(-0.6, 0.6), 0.3 + 0.05 * i + uniform(0.0, 0.1), uniform(-0.6, 0.6));
            BodyDef stick = scenes::box("Stick", Vec3(0.5 * length, radius, radius), at, turn);
            if (random() % 2 == 1) {
                stick.shape.type = ShapeType::Hull;
                for (int side = 0; side < 8; ++side)
                    for (const Real x : {-0.5 * length, 0.5 * length})
                        stick.shape.points.push_back(Vec3(x, radius * std::cos(2.0 * kPi * side / 8.0),
                                                          radius * std::sin(2.0 * kPi * side / 8.0)));
            }
            stick.material = materials[random() % 5];
            s.bodies.push_back(stick);
        }
        World w = makeWorld(s);
        const Real start = totalEnergy(w);
        Real highest = start;
        const RunStats stats = run(w, 600, [&](int) { highest = std::max(highest, totalEnergy(w)); });
        qInfo("40 sticks: energy at most %+.4f %% of its start (%.1f J), fastest in the last second %.3f m/s",
              100.0 * (highest - start) / start, start, stats.maxSpeedLastSecond);
        QVERIFY(stats.allFinite);
        QVERIFY(highest <= start * 1.01);
    }

    // A state captured from a random scene (tests/data/stability/README.md): a 7,500 kg cylinder falling onto a 17 kg
    // one that tumbles on a ball. The light one's surface slides across the contact at 4-6 m/s; not held under the
    // heavy one for that (tried, 2026-12-05), it was crushed 187 mm into it.
    void capturedHeavyLandingCrushesNothing() {
        Result<Scene> scene = capturedScene("heavy_onto_tumbling_light_body.rlscene");
        QVERIFY2(scene, scene ? "" : scene.error().toString().c_str());
        World w = makeWorld(*scene);
        const RunStats stats = run(w, 120);
        qInfo("deepest contact %.2f mm", 1e3 * stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(stats.maxPenetration < 0.01);
    }

    // A heavy ball meets a light one in mid-air just above the floor and drives it down further in one step than the
    // light ball's own speed would take it: the floor must be in the light ball's contacts at the step's start all
    // the same (World::pushSpeedsOfNewPairs()). The two meet in the first step, new to the world and to each other, or
    // fall for four frames before (the world then holds their pairs from the steps before). (A 314 kg ball at 6 m/s
    // onto a 4.5 kg one 40 mm up, falling at 1.05 m/s, in the first step: 62 mm deep when only the light ball's own
    // speed widened its margin to the floor; 2026-12-05.)
    void heavyBallDrivesALightOneIntoNothing_data() {
        QTest::addColumn<Real>("above");
        QTest::addColumn<Real>("heavySpeed");
        QTest::addColumn<Real>("e");
        QTest::addColumn<int>("framesBefore");
        for (const int framesBefore : {0, 4})
            for (const Real above : {0.01, 0.04, 0.08})
                for (const Real heavySpeed : {3.0, 6.0, 12.0})
                    for (const Real e : {0.0, 0.5})
                        QTest::addRow("%g mm up, heavy at %g m/s, e = %g, %d frames before", 1e3 * above, heavySpeed, e,
                                      framesBefore)
                            << above << heavySpeed << e << framesBefore;
    }
    void heavyBallDrivesALightOneIntoNothing() {
        QFETCH(Real, above);
        QFETCH(Real, heavySpeed);
        QFETCH(Real, e);
        QFETCH(int, framesBefore);
        const Real lightRadius = 0.05, heavyRadius = 0.2, lightSpeed = 1.05, g = 9.81;
        // Where the two meet, `above` the floor; they start on their free flight framesBefore frames earlier.
        const Real t = framesBefore / 60.0;
        const auto back = [&](Real y, Real v) { return std::pair<Real, Real>{y + v * t - 0.5 * g * t * t, v - g * t}; };
        const auto [lightY, lightV] = back(above + lightRadius, lightSpeed);
        const auto [heavyY, heavyV] = back(above + 2.0 * lightRadius + heavyRadius + 0.001, heavySpeed);
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        s.bodies.push_back(ball("Light", lightRadius, 4.5, Vec3(0.0, lightY, 0.0)));
        s.bodies.back().velocity = Vec3(0.0, -lightV, 0.0);
        s.bodies.push_back(ball("Heavy", heavyRadius, 314.0, Vec3(0.0, heavyY, 0.0)));
        s.bodies.back().velocity = Vec3(0.0, -heavyV, 0.0);
        for (BodyDef& b : s.bodies)
            b.restitution = e;
        World w = makeWorld(s);
        Real lowest = std::numeric_limits<Real>::max();
        const RunStats stats = run(w, 60, [&](int) { lowest = std::min(lowest, w.centerOfMass(1).y - lightRadius); });
        qInfo("light ball's lowest point %.2f mm, deepest contact %.2f mm", 1e3 * lowest, 1e3 * stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(lowest > -0.01);
        QVERIFY(stats.maxPenetration < 0.01);
    }

    // Twist friction: a cube set spinning about the vertical on the floor stops as Coulomb friction at its four
    // corner contacts says, and stays where it is. Each corner is d = 0.5 sqrt(2) m from the centre and carries a
    // quarter of the weight, so the friction torque is mu m g d and the cube (I = m / 6) turns through
    // w0^2 / (2 mu g d 6) before it stops.
    void spinningCubeStopsByTwistFriction() {
        const Real mu = 0.1, w0 = 2.0, g = 9.81;
        World w = makeWorld(spunAboutTheVertical(scenes::stack(1), mu, w0));
        const Vec3 start = w.centerOfMass(1);
        run(w, 120);
        const Quat turn = w.rotationSinceStart(1);
        const Real angle = 2.0 * std::atan2(glm::length(Vec3(turn.x, turn.y, turn.z)), std::abs(turn.w));
        const Real expected = w0 * w0 / (2.0 * mu * g * 0.5 * std::sqrt(2.0) * 6.0);
        const Real moved = glm::length(w.centerOfMass(1) - start);
        qInfo("cube spun at %.1f rad/s, mu %.1f: turned %.4f rad, expected %.4f rad (%.2f %%); centre moved %.3g m, "
              "spin at 2 s %.3g rad/s",
              w0, mu, angle, expected, 100.0 * (angle - expected) / expected, moved, glm::length(w.angularVelocity(1)));
        QVERIFY(std::abs(angle - expected) < 0.03 * expected);
        QVERIFY(moved < 1e-3);
        QVERIFY(glm::length(w.angularVelocity(1)) < 1e-3);
    }

    // A point contact stands for a small patch (ContactSolver::kPatchRadius, r): a ball spun about the vertical on the
    // floor feels the twist torque mu r m g and (I = 0.4 m R^2) turns through w0^2 0.4 R^2 / (2 mu r g) before it
    // stops, then stays where it is. With no patch a lone point held no twist at all and the ball spun for ever.
    void spinningBallStopsByPatchFriction_data() {
        QTest::addColumn<Real>("mu");
        QTest::addColumn<Real>("w0");
        QTest::newRow("mu 0.5, 10 rad/s") << 0.5 << 10.0;
        QTest::newRow("mu 0.2, 4 rad/s") << 0.2 << 4.0;
        QTest::newRow("mu 1.0, 20 rad/s") << 1.0 << 20.0;
    }
    void spinningBallStopsByPatchFriction() {
        QFETCH(Real, mu);
        QFETCH(Real, w0);
        const Real g = 9.81, radius = 0.1, r = ContactSolver::kPatchRadius;
        World w = makeWorld(spunAboutTheVertical(scenes::drop(0.0, 0.0), mu, w0));
        const Vec3 start = w.centerOfMass(1);
        const Real expected = w0 * w0 * 0.4 * radius * radius / (2.0 * mu * r * g);
        const Real stopsAt = w0 * 0.4 * radius * radius / (mu * r * g);
        // The angle turned, by the trapezoid rule over the frames (the ball turns more than half a turn).
        Real angle = 0.0, spinLate = 0.0, previous = w0;
        run(w, static_cast<int>(std::ceil((stopsAt + 1.0) * 60.0)), [&](int f) {
            const Real spin = glm::length(w.angularVelocity(1));
            angle += 0.5 * (previous + spin) / 60.0;
            previous = spin;
            if (f / 60.0 > stopsAt + 0.5)
                spinLate = std::max(spinLate, glm::length(w.angularVelocity(1)));
        });
        const Real moved = glm::length(w.centerOfMass(1) - start);
        qInfo("ball spun at %.0f rad/s, mu %.1f: turned %.3f rad, expected %.3f rad (%.2f %%); centre moved %.3g m, "
              "spin after it should have stopped %.3g rad/s",
              w0, mu, angle, expected, 100.0 * (angle - expected) / expected, moved, spinLate);
        QVERIFY(std::abs(angle - expected) < 0.01 * expected);
        QVERIFY(moved < 1e-3);
        QVERIFY(spinLate < 1e-3);
    }

    // A ball thrown along the floor lands and rolls; its surface under the contact stays where its centre puts it, so
    // the ball must not sink however fast it turns. While the solver measured the contact's separation from an anchor
    // that turned with the ball, a rolling ball's anchor rose off the floor within each step and the contact let go:
    // every row below sank 4.5-28.7 mm (a 3 cm ball at 15 m/s bouncing with e 0.5 the most), and 72 such scenes baked
    // for 4 s (radii 3-50 cm, 5-30 m/s, e 0 and 0.5, mu 0.1-1) all sank by more than 1 mm, 21 of them by more than
    // 1 cm (2026-12-05). Now the deepest of the 72 is 0.03 mm.
    void rollingBallStaysOnTheFloor_data() {
        QTest::addColumn<Real>("radius");
        QTest::addColumn<Real>("speed");
        QTest::addColumn<Real>("restitution");
        QTest::newRow("3 cm at 5 m/s") << 0.03 << 5.0 << 0.0;
        QTest::newRow("3 cm at 15 m/s, e 0.5") << 0.03 << 15.0 << 0.5;
        QTest::newRow("10 cm at 5 m/s") << 0.1 << 5.0 << 0.0;
        QTest::newRow("10 cm at 30 m/s") << 0.1 << 30.0 << 0.0;
        QTest::newRow("17 cm at 15 m/s, e 0.5") << 0.17 << 15.0 << 0.5;
        QTest::newRow("50 cm at 15 m/s") << 0.5 << 15.0 << 0.0;
    }
    void rollingBallStaysOnTheFloor() {
        QFETCH(Real, radius);
        QFETCH(Real, speed);
        QFETCH(Real, restitution);
        Scene scene = scenes::drop(0.5, restitution);
        BodyDef& ball = scene.bodies[1];
        ball.shape.radius = radius;
        ball.position = Vec3(-19.0, radius + 0.5, 0.0);
        ball.velocity = Vec3(speed, -3.0, 0.3 * speed);
        World w = makeWorld(scene);
        // Until it would reach the floor's far edge (it rolls a little slower than it was thrown).
        const int frames = std::min(240, static_cast<int>(60.0 * 30.0 / speed));
        Real lowest = 1.0, spin = 0.0;
        const RunStats stats = run(w, frames, [&](int) {
            lowest = std::min(lowest, w.centerOfMass(1).y - radius);
            spin = std::max(spin, glm::length(w.angularVelocity(1)));
        });
        qInfo("ball of %.2f m at %.0f m/s, e %.1f: lowest %.3f mm, spin up to %.0f rad/s, at %.2f m from the start",
              radius, speed, restitution, 1e3 * lowest, spin, glm::length(w.centerOfMass(1) - ball.position));
        QVERIFY(stats.allFinite);
        QVERIFY(spin * radius > 0.25 * speed); // it rolls
        QVERIFY(lowest > -1e-3);
    }

    // The same with balls and cylinders made of faces, as Blender exports a UV sphere (32 segments, 16 rings), an
    // icosphere or a cylinder (32 sides): the anchors of the face it lies on turn with it, and while it turns through
    // more than one face in a step the faces coming down were unseen. It is then held round, about every axis or about
    // its own (WorldTuning::roundHullRoundness), and sinks at most by how much nearer its faces are than its corners,
    // 0.5-1 % of its radius here. Before (2026-12-05), the balls dipped 9.1, 10.2, 4.0 and 12.9 mm, and the
    // cylinders rolled in hops of up to 199 and 116 mm off the floor and dipped 19.5 and 13.5 mm; now the balls dip
    // 0.5-0.9 mm, the cylinders none, and they hop 4.4 and 3.6 mm. In a sweep of 108 balls thrown (UV spheres of 32 and
    // 16 segments, icospheres of 80 and 320 faces; 0.1, 0.3 and 1 m; 5, 10 and 20 m/s; three starts each) the deepest
    // dip went from 25.7 mm to 14.0 mm, and the throws dipping more than 5 mm from 31 to 12.
    void rollingRoundHullStaysOnTheFloor_data() {
        QTest::addColumn<QString>("shape");
        QTest::addColumn<Real>("radius");
        QTest::addColumn<Real>("speed");
        QTest::newRow("UV sphere of 10 cm at 10 m/s") << "UV sphere" << 0.1 << 10.0;
        QTest::newRow("UV sphere of 10 cm at 20 m/s") << "UV sphere" << 0.1 << 20.0;
        QTest::newRow("UV sphere of 30 cm at 20 m/s") << "UV sphere" << 0.3 << 20.0;
        QTest::newRow("icosphere of 10 cm at 20 m/s") << "icosphere" << 0.1 << 20.0;
        QTest::newRow("cylinder of 5 cm at 10 m/s") << "cylinder" << 0.05 << 10.0;
        QTest::newRow("cylinder of 10 cm at 10 m/s") << "cylinder" << 0.1 << 10.0;
    }
    void rollingRoundHullStaysOnTheFloor() {
        QFETCH(QString, shape);
        QFETCH(Real, radius);
        QFETCH(Real, speed);
        std::vector<Vec3> points;
        if (shape == "UV sphere") { // Blender's primitive: poles and 15 rings of 32
            points = {Vec3(0.0, radius, 0.0), Vec3(0.0, -radius, 0.0)};
            for (int ring = 1; ring < 16; ++ring)
                for (int segment = 0; segment < 32; ++segment) {
                    const Real theta = kPi * ring / 16.0, phi = 2.0 * kPi * segment / 32.0;
                    points.push_back(radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                   std::sin(theta) * std::sin(phi)));
                }
        } else if (shape == "icosphere") { // an icosahedron's faces split in four twice, pushed out to the sphere
            const Real t = 0.5 * (1.0 + std::sqrt(5.0));
            std::vector<Vec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
            std::vector<glm::ivec3> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
            for (int split = 0; split < 2; ++split) {
                std::vector<glm::ivec3> finer;
                const auto middle = [&v](int a, int b) {
                    v.push_back(0.5 * (v[a] + v[b]));
                    return static_cast<int>(v.size()) - 1;
                };
                for (const glm::ivec3& f : faces) {
                    const int ab = middle(f.x, f.y), bc = middle(f.y, f.z), ca = middle(f.z, f.x);
                    finer.insert(finer.end(), {{f.x, ab, ca}, {f.y, bc, ab}, {f.z, ca, bc}, {ab, bc, ca}});
                }
                faces = finer;
            }
            for (const Vec3& p : v) // (the midpoints shared by two faces are there twice: the hull takes one)
                points.push_back(radius * glm::normalize(p));
        } else { // a cylinder of 32 sides along z, 3 radii long
            for (int side = 0; side < 32; ++side)
                for (const Real z : {-1.5 * radius, 1.5 * radius})
                    points.push_back(Vec3(radius * std::cos(2.0 * kPi * side / 32.0),
                                          radius * std::sin(2.0 * kPi * side / 32.0), z));
        }
        Scene scene = scenes::drop(0.5, 0.0);
        BodyDef& body = scene.bodies[1];
        body.shape.type = ShapeType::Hull;
        body.shape.points = points;
        if (shape == "cylinder") { // set down rolling along x
            body.position = Vec3(-19.0, radius + 0.002, 0.0);
            body.velocity = Vec3(speed, 0.0, 0.0);
            body.angularVelocity = Vec3(0.0, 0.0, -speed / radius);
        } else { // thrown down and along
            body.position = Vec3(-19.0, radius + 0.5, 0.0);
            body.velocity = Vec3(speed, -3.0, 0.3 * speed);
        }
        World w = makeWorld(scene);
        const int frames = std::min(240, static_cast<int>(60.0 * 30.0 / speed));
        Real lowest = 1.0, hop = 0.0;
        const RunStats stats = run(w, frames, [&](int) {
            const Transform pose = w.transform(1);
            Real low = 1.0;
            for (const Vec3& p : points)
                low = std::min(low, pose.apply(p).y);
            lowest = std::min(lowest, low);
            hop = std::max(hop, low);
        });
        qInfo("%s of %.2f m at %.0f m/s: lowest corner %.3f mm%s, %.2f m from the start", qPrintable(shape), radius,
              speed, 1e3 * lowest,
              shape == "cylinder" ? qPrintable(QString(", most off the floor %1 mm").arg(1e3 * hop, 0, 'f', 1)) : "",
              glm::length(w.centerOfMass(1) - body.position));
        QVERIFY(stats.allFinite);
        QVERIFY(lowest > -3e-3);
        if (shape == "cylinder")
            QVERIFY(hop < 0.01); // it rolls, as a round one does
    }

    // A cone or a cylinder of 32 sides thrown down tumbling: a corner that is not in its manifold at the step's start
    // comes down within the step (the cone's base lands as a 32-gon, of which the manifold holds four corners; the
    // cylinder turns 0.67 rad a step at 40 rad/s). Before the manifold held the corners that the turn brings down
    // (addTurnedSupports()), these went in 11.9, 1.8, 52.1 and 52.8 mm; then 0.1, 0.0, 0.0 and 8.3 mm, and 2.0 mm for
    // the last once bodies were pushed out after the sweeps (pushOutOfContacts(); 2026-12-05).
    void tumblingHullLandsOnItsCorners_data() {
        QTest::addColumn<QString>("shape");
        QTest::addColumn<Real>("radius");
        QTest::addColumn<Real>("spin");
        QTest::addColumn<Real>("fall");
        QTest::addColumn<Real>("deepest");
        QTest::newRow("cone of 10 cm, 10 rad/s, 8 m/s") << "cone" << 0.1 << 10.0 << 8.0 << 3e-3;
        QTest::newRow("cylinder of 40 cm, 25 rad/s, 3 m/s") << "cylinder" << 0.4 << 25.0 << 3.0 << 3e-3;
        QTest::newRow("cylinder of 40 cm, 40 rad/s, 3 m/s") << "cylinder" << 0.4 << 40.0 << 3.0 << 3e-3;
        QTest::newRow("cylinder of 40 cm, 40 rad/s, 8 m/s") << "cylinder" << 0.4 << 40.0 << 8.0 << 1e-2;
    }
    void tumblingHullLandsOnItsCorners() {
        QFETCH(QString, shape);
        QFETCH(Real, radius);
        QFETCH(Real, spin);
        QFETCH(Real, fall);
        QFETCH(Real, deepest);
        std::vector<Vec3> points;
        for (int side = 0; side < 32; ++side) {
            const Real phi = 2.0 * kPi * side / 32.0;
            const Vec3 rim(radius * std::cos(phi), 0.0, radius * std::sin(phi));
            if (shape == "cone") { // 2 radii tall, the base half a radius below the origin
                points.push_back(rim + Vec3(0.0, -0.5 * radius, 0.0));
            } else { // 2 radii long
                points.push_back(rim + Vec3(0.0, -radius, 0.0));
                points.push_back(rim + Vec3(0.0, radius, 0.0));
            }
        }
        if (shape == "cone")
            points.push_back(Vec3(0.0, 1.5 * radius, 0.0));
        Scene scene = scenes::drop(0.5, 0.0);
        BodyDef& body = scene.bodies[1];
        body.shape.type = ShapeType::Hull;
        body.shape.points = points;
        body.density = 1000.0;
        body.position = Vec3(0.0, 0.3 + 2.0 * radius, 0.0);
        body.orientation = glm::angleAxis(0.5, Vec3(1.0, 0.0, 0.0));
        body.velocity = Vec3(1.0, -fall, 0.0);
        body.angularVelocity = spin * Vec3(0.8, 0.0, 0.6);
        World w = makeWorld(scene);
        RunStats stats;
        const Real lowest = lowestPointOver(w, points, 120, stats);
        qInfo("%s of %.2f m tumbling at %.0f rad/s, falling at %.0f m/s: lowest corner %.2f mm", qPrintable(shape),
              radius, spin, fall, 1e3 * lowest);
        QVERIFY(stats.allFinite);
        QVERIFY(lowest > -deepest);
    }

    // Two boxes of a bouncing pile (1,000 boxes, e = 0.5), as they were one step before they met: the upper one
    // (45 kg) falling at 3.1 m/s and turning at 24 rad/s, its bottom edge 6 mm across the lower one's top edge. The
    // contact of two overlapping edges was one point at their witnesses; it held that corner, the upper box turned
    // about it and its bottom face went 80 mm (lower box anchored) or 90 mm (lower box moving) into the other in
    // the next step. With the facing faces clipped as for edges apart when the pair closes or turns fast
    // (CollideOptions::clipOverlappingEdgesFrom), 0.7 mm and none (2026-12-06).
    void boxTurningOntoAnEdgeStaysOut_data() {
        QTest::addColumn<bool>("lowerAnchored");
        QTest::addColumn<bool>("upperFirst"); // the upper box is body A of the pair
        QTest::newRow("lower box anchored") << true << false;
        QTest::newRow("lower box moving") << false << false;
        QTest::newRow("lower box moving, upper box first") << false << true;
    }
    void boxTurningOntoAnEdgeStaysOut() {
        QFETCH(bool, lowerAnchored);
        QFETCH(bool, upperFirst);
        BodyDef lower = pileBox("Lower", Vec3(0.1144114, 0.1798666, 0.2911382), Vec3(-0.1000541, 0.6790972, 1.726555),
                                Quat(0.9991274, -0.03169785, 0.0161626, 0.02187499),
                                Vec3(-1.023161, 0.4156233, 1.733776), Vec3(4.647989, -0.8258891, -6.550461));
        if (lowerAnchored) {
            lower.anchor = true;
            lower.velocity = lower.angularVelocity = Vec3(0.0);
        }
        const BodyDef upper =
            pileBox("Upper", Vec3(0.2664861, 0.1367319, 0.1548344), Vec3(-0.006673311, 1.007107, 1.630036),
                    Quat(0.9989611, 0.02567712, 0.0189, -0.0325596), Vec3(-0.45137, -3.054973, 0.4946377),
                    Vec3(-22.79873, 3.999188, -5.747068));
        const RunStats stats = upperFirst ? runCapturedPair(upper, lower) : runCapturedPair(lower, upper);
        QVERIFY(stats.allFinite);
        // The first step starts 6 mm deep (the edges' overlap).
        QVERIFY(stats.maxPenetration < 0.01);
    }

    // Two more boxes of that pile, both moving, in face contact: the upper one (79 kg) falling at 2.8 m/s and
    // turning at 13.7 rad/s, the lower one (68 kg) turning at 9.4 rad/s. The manifold holds the corners that faced
    // each other at the step's start; the turns brought another round, 67.6 mm into the other box in one step. With
    // the corners a box's turn brings towards its neighbour added once they move more than 5 cm in the step
    // (WorldTuning::boxTurnCorner), 0.7 mm (2026-12-06). With the lower box anchored, the upper one turned so that
    // the anchor's corner went 42.5 mm into its side, nearly at right angles to the manifold's normal; collided again
    // after the step and pushed out (World::separateMovedPairs()), 2.0 mm (2026-12-06). (The first step starts 6.5
    // mm deep.)
    void turningBoxesMeetCornerFirst_data() {
        QTest::addColumn<bool>("lowerAnchored");
        QTest::newRow("both moving") << false;
        QTest::newRow("lower box anchored") << true;
    }
    void turningBoxesMeetCornerFirst() {
        QFETCH(bool, lowerAnchored);
        BodyDef lower = pileBox("Lower", Vec3(0.2035814, 0.2161822, 0.1927282), Vec3(2.860568, 2.223507, -3.971819),
                                Quat(0.9605005, 0.0135724, 0.09993256, -0.2593608),
                                Vec3(1.393733, -0.7981015, 0.2485836), Vec3(-2.058577, 3.688754, -8.356362));
        if (lowerAnchored) {
            lower.anchor = true;
            lower.velocity = lower.angularVelocity = Vec3(0.0);
        }
        const BodyDef upper =
            pileBox("Upper", Vec3(0.1615028, 0.2549494, 0.2387746), Vec3(3.055979, 2.613092, -3.992078),
                    Quat(0.8856193, -0.02701502, 0.1078326, 0.4509111), Vec3(-0.05725528, -2.812669, -0.2922887),
                    Vec3(-4.78871, 1.628526, 12.76246));
        const RunStats stats = runCapturedPair(lower, upper, 1); // the first step starts 6.5 mm deep
        QVERIFY(stats.allFinite);
        QVERIFY(stats.maxPenetration < 0.005);
    }

    // A thrown 2.3 kg box struck from above in mid-air by a 107 kg ball, both falling at 16-18 m/s and the box
    // spinning at 128 rad/s (captured from a random scene of mixed hulls, 2026-12-06). At the step's start the box had
    // only speculative points on the floor; pushed out of the ball after the step, it went 62.8 mm into the floor,
    // which its two pushes out of it, each turning it too, did not undo. Now each pushed body's pairs with still
    // bodies are collided again, the box is pushed out of the floor along the normal, and holds while the ball is
    // pushed off it (World::groundPushedBodies()): 1.0 mm.
    void lightBodyStruckOntoTheFloorStaysOut() {
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        BodyDef box;
        box.name = "Box";
        box.shape.type = ShapeType::Hull;
        const Real r = 0.043781927528870487, h = 0.12497101518595061;
        for (int k = 0; k < 8; ++k)
            box.shape.points.push_back(Vec3(k & 1 ? r : -r, k & 2 ? h : -h, k & 4 ? 0.7 * r : -0.7 * r));
        box.density = 1747.540422555559;
        box.restitution = 0.45733233086036001;
        box.position = Vec3(0.0136071822329232, 0.19006629800677285, -0.024367766375515399);
        box.orientation = Quat(0.52803549534693128, 0.71424458062064045, -0.36099406480708618, 0.28410645871191204);
        box.velocity = Vec3(-4.708582782041737, -17.559331448336241, 1.8539971665479149);
        box.angularVelocity = Vec3(-47.001332559101336, -56.935571863511171, 104.05416066043269);
        BodyDef ball;
        ball.name = "Ball";
        ball.shape.type = ShapeType::Hull; // a UV sphere of 24 segments and 8 rings
        const Real radius = 0.14805376328319922;
        for (int i = 1; i < 8; ++i)
            for (int j = 0; j < 24; ++j) {
                const Real t = kPi * i / 8.0, f = 2.0 * kPi * j / 24.0;
                ball.shape.points.push_back(radius *
                                            Vec3(std::sin(t) * std::cos(f), std::cos(t), std::sin(t) * std::sin(f)));
            }
        ball.shape.points.push_back(Vec3(0.0, radius, 0.0));
        ball.shape.points.push_back(Vec3(0.0, -radius, 0.0));
        ball.density = 8247.9143343080705;
        ball.restitution = 0.58750302693464851;
        ball.position = Vec3(0.015939650920509731, 0.36180068003766902, 0.0093413525857241816);
        ball.orientation = Quat(0.80671740003177694, 0.21070695408386481, 0.21383711624084106, 0.50900226296596307);
        ball.velocity = Vec3(-1.7636658599760711, -16.32140566107773, -0.86551618194501312);
        ball.angularVelocity = Vec3(-0.44034410355222392, 0.0795319483342041, -0.22983100659652753);
        s.bodies.push_back(box);
        s.bodies.push_back(ball);
        World w = makeWorld(s);
        const auto energy = [&] {
            const FrameDiagnostics d = w.diagnostics();
            return d.kineticEnergy + d.potentialEnergy;
        };
        const Real start = energy();
        Real most = start, lowest = std::numeric_limits<Real>::max();
        const RunStats stats = run(w, 30, [&](int) {
            most = std::max(most, energy());
            const Transform pose = w.transform(1);
            for (const Vec3& p : box.shape.points)
                lowest = std::min(lowest, pose.apply(p).y);
        });
        qInfo("box %.2f mm under the floor at most; energy at most %+.4f %% of the start", -1e3 * lowest,
              100.0 * (most - start) / start);
        QVERIFY(stats.allFinite);
        QVERIFY(lowest > -0.005);
        QVERIFY(most <= start * (1.0 + 1e-9));
    }

    // A heavy box falling onto a light one that is falling onto the floor, their pair made frames before the blow
    // (so no push speed widened the light box's margins: World::pushSpeedsOfNewPairs()): struck within the step, the
    // light box went into the floor where its contact there had no points yet, and the pushes after the step, sharing
    // each push by the inverse masses, left it there. Now a body struck faster than its margins allowed has its pairs
    // with still bodies collided again after the step and is pushed out and grounded (World::separateMovedPairs()):
    // 1.0, 1.1 and 1.7 mm; before, 6.7, 26.6 and 11.0 mm (2026-12-06).
    void lightBoxStruckIntoTheFloorStaysOut_data() {
        QTest::addColumn<Real>("speed");
        QTest::addColumn<Real>("density");
        QTest::newRow("216 kg at 10 m/s onto 125 kg") << 10.0 << 1000.0;
        QTest::newRow("2,160 kg at 10 m/s onto 125 kg") << 10.0 << 10000.0;
        QTest::newRow("2,160 kg at 20 m/s onto 125 kg") << 20.0 << 10000.0;
    }
    void lightBoxStruckIntoTheFloorStaysOut() {
        QFETCH(Real, speed);
        QFETCH(Real, density);
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        s.bodies.push_back(scenes::box("Light", Vec3(0.25), Vec3(0.0, 0.31, 0.0))); // 6 cm above the floor
        BodyDef heavy = scenes::box("Heavy", Vec3(0.3), Vec3(0.05, 1.46, 0.02));
        heavy.density = density;
        heavy.velocity = Vec3(0.0, -speed, 0.0);
        s.bodies.push_back(heavy);
        World w = makeWorld(s);
        Real lowest = std::numeric_limits<Real>::max();
        const RunStats stats = run(w, 120, [&](int) {
            lowest = std::min(lowest, w.shape(1).worldBounds(w.transform(1)).min.y); // a box's lowest corner
        });
        qInfo("light box %.2f mm under the floor at most; heavy box on top: %s", -1e3 * lowest,
              w.centerOfMass(2).y > w.centerOfMass(1).y ? "yes" : "no");
        QVERIFY(stats.allFinite);
        QVERIFY(lowest > -0.003);
        QVERIFY(w.centerOfMass(2).y > w.centerOfMass(1).y + 0.5);
    }

    // A box coming down onto a stack resting on the floor (restitution 0) stops on it, and the stack stays down. The
    // sweeps hand a blow on one contact at a time, and the substeps' warm starts gave what the first substeps left of
    // it again: onto one box at 10 and 20 m/s, both went up at 0.84 and 1.78 m/s; onto a stack of four, at 1.50 and
    // 3.02 m/s, 11 and 45 cm high. Now the blow is taken before the substeps (ContactSolver::absorbBlows()): at most
    // 0.001 m/s in every row (2026-12-06).
    void boxStruckOnAStackStaysDown_data() {
        QTest::addColumn<int>("stack");
        QTest::addColumn<Real>("speed");
        for (const int stack : {1, 2, 4})
            for (const Real speed : {10.0, 20.0})
                QTest::addRow("onto %d at %.0f m/s", stack, speed) << stack << speed;
    }
    void boxStruckOnAStackStaysDown() {
        QFETCH(int, stack);
        QFETCH(Real, speed);
        Scene s;
        s.bodies.push_back(scenes::floorBox());
        for (int k = 0; k <= stack; ++k) // the stack, then the box coming down onto it, all touching
            s.bodies.push_back(scenes::box("Box", Vec3(0.25), Vec3(0.0, 0.25 + 0.5 * k, 0.0)));
        s.bodies.back().velocity = Vec3(0.0, -speed, 0.0);
        World w = makeWorld(s);
        Real rising = 0.0, risen = 0.0; // the stack's fastest rise and its highest lift
        const RunStats stats = run(w, 90, [&](int) {
            for (int k = 1; k <= stack; ++k) {
                rising = std::max(rising, w.linearVelocity(static_cast<size_t>(k)).y);
                risen = std::max(risen, w.centerOfMass(static_cast<size_t>(k)).y - (0.25 + 0.5 * (k - 1)));
            }
        });
        const uint64_t rows = w.profile().counters[static_cast<int>(Counter::BlowRows)];
        qInfo("stack rose at %.4f m/s at most, %.2f mm; the top box at %.4f m/s at the end; %llu blow rows", rising,
              1e3 * risen, w.linearVelocity(static_cast<size_t>(stack) + 1).y, static_cast<unsigned long long>(rows));
        QVERIFY(stats.allFinite);
        QVERIFY(rows > 0);
        QVERIFY(rising < 0.05);
        QVERIFY(risen < 0.001);
    }

    // A row of 30 dominoes toppled from one end, as Blender users build them: every domino falls (turned by more
    // than a radian), nothing gains energy, and the row comes to rest. Where a domino's top edge slides down the
    // face of the next while both turn at 5-8 rad/s, and the next is stopped by the one after it, the edge went some
    // millimetres in within a step: 4.3 mm with mu 0.5 and 7.7 mm with mu 0.1 at 60 Hz. It fell as the square of
    // the frame time (1.3 and 1.8 mm at 120 Hz, 0.36 and 0.52 mm at 240 Hz), less with substeps (12: 2.9 and 6.4 mm;
    // 24: 2.3 and 5.5 mm), not at all with iterations (4 or 8: the same): it came from the contact taken once a
    // frame. Collided again after the step and pushed apart where the turns took them in
    // (World::separateMovedPairs()), 2.0-2.1 mm in the five rows (2026-12-06).
    void dominoRowTopples_data() {
        QTest::addColumn<Real>("spacing");
        QTest::addColumn<Real>("mu");
        QTest::addColumn<Real>("e");
        QTest::newRow("0.12 m apart, mu 0.5") << 0.12 << 0.5 << 0.0;
        QTest::newRow("0.06 m apart, mu 0.5") << 0.06 << 0.5 << 0.0;
        QTest::newRow("0.17 m apart, mu 0.5") << 0.17 << 0.5 << 0.0;
        QTest::newRow("0.12 m apart, mu 0.1") << 0.12 << 0.1 << 0.0;
        QTest::newRow("0.12 m apart, mu 0.5, e 0.5") << 0.12 << 0.5 << 0.5;
    }
    void dominoRowTopples() {
        QFETCH(Real, spacing);
        QFETCH(Real, mu);
        QFETCH(Real, e);
        World w = makeWorld(dominoRow(30, spacing, mu, e));
        const auto energy = [&w] { return totalEnergy(w); };
        const Real start = energy();
        Real most = start;
        const RunStats stats = run(w, 600, [&](int) { most = std::max(most, energy()); });
        int lying = 0;
        Real highest = 0.0;
        for (size_t i = 1; i < w.bodyCount(); ++i) {
            const Vec3 up = w.rotationSinceStart(i) * Vec3(0.0, 1.0, 0.0);
            lying += up.y < std::cos(1.0) ? 1 : 0; // turned by more than a radian
            highest = std::max(highest, w.centerOfMass(i).y);
        }
        qInfo("%d of 30 down, highest centre %.4f m, deepest contact %.2f mm, energy at most %+.4f %% of the start, "
              "fastest in the last second %.4f m/s",
              lying, highest, 1e3 * stats.maxPenetration, 100.0 * (most - start) / std::abs(start),
              stats.maxSpeedLastSecond);
        QVERIFY(stats.allFinite);
        QCOMPARE(lying, 30);
        QVERIFY(stats.maxPenetration < 0.003);
        QVERIFY(most <= start + 1e-9 * std::abs(start));
        QVERIFY(stats.maxSpeedLastSecond < 0.01);
    }

    // A top: a cone of 32 sides (10 cm radius, 30 cm to its tip) spinning about its axis on its tip, the axis 0.3 rad
    // from vertical. The rows hold their points' velocities at anchors fixed at the step's start; the tip, off the
    // axis the body turns about while it wobbles, follows an arc while they follow its chord, and it sank about as the
    // spin squared: 8.7, 34 and 65 mm at 40, 80 and 160 rad/s. Pushed out after the sweeps (pushOutOfContacts()), 2.0,
    // 2.3 and 2.0 mm (2026-12-05).
    void spinningTopStaysOnItsTip_data() {
        QTest::addColumn<Real>("spin");
        QTest::newRow("40 rad/s") << 40.0;
        QTest::newRow("80 rad/s") << 80.0;
        QTest::newRow("160 rad/s") << 160.0;
    }
    void spinningTopStaysOnItsTip() {
        QFETCH(Real, spin);
        std::vector<Vec3> points;
        for (int side = 0; side < 32; ++side) {
            const Real phi = 2.0 * kPi * side / 32.0;
            points.push_back(Vec3(0.1 * std::cos(phi), 0.1 * std::sin(phi), 0.0));
        }
        points.push_back(Vec3(0.0, 0.0, 0.3));
        Scene scene = scenes::drop(0.5, 0.0);
        BodyDef& body = scene.bodies[1];
        body.shape.type = ShapeType::Hull;
        body.shape.points = points;
        body.mass = 1.0;
        // Its +z (base to tip) pointing down, 0.3 rad from vertical, the tip 5 mm over the floor.
        body.orientation = glm::angleAxis(0.5 * kPi - 0.3, Vec3(1.0, 0.0, 0.0));
        const Vec3 axis = body.orientation * Vec3(0.0, 0.0, 1.0);
        body.position = Vec3(0.0, 0.005, 0.0) - 0.3 * axis;
        body.angularVelocity = spin * axis;
        World w = makeWorld(scene);
        RunStats stats;
        const Real lowest = lowestPointOver(w, points, 180, stats);
        qInfo("top spinning at %.0f rad/s: lowest point %.2f mm, %lld contacts pushed out", spin, 1e3 * lowest,
              static_cast<long long>(w.profile().counter(Counter::PushedContacts)));
        QVERIFY(stats.allFinite);
        QVERIFY(lowest > -5e-3);
    }

    // A sheared box (a hull whose principal axes are not those of its faces) lying on a frictionless floor, spun about
    // the vertical: the floor keeps it from tilting, so its spin energy can only stay or fall. While the sweeps kept
    // each body's world inverse inertia from the step's start, their impulses turned it in the metric of a pose it
    // had left, and its kinetic energy rose by 1.0 % (2 rad/s) to 7.0 % (5 rad/s) in 19 s.
    void spinningSkewedHullGainsNoEnergy_data() {
        QTest::addColumn<Real>("shear");
        QTest::addColumn<Real>("w0");
        QTest::newRow("shear 0.5, 5 rad/s") << 0.5 << 5.0;
        QTest::newRow("shear 1, 5 rad/s") << 1.0 << 5.0;
        QTest::newRow("shear 1, 2 rad/s") << 1.0 << 2.0;
    }
    void spinningSkewedHullGainsNoEnergy() {
        QFETCH(Real, shear);
        QFETCH(Real, w0);
        Scene scene;
        scene.materials.push_back({"Ice", 1000.0, 0.0, 0.0});
        scene.bodies.push_back(scenes::floorBox());
        BodyDef skewed;
        skewed.name = "Skewed";
        skewed.shape.type = ShapeType::Hull;
        for (int i = 0; i < 8; ++i) {
            const Vec3 corner((i & 1) ? 0.3 : -0.3, (i & 2) ? 0.1 : -0.1, (i & 4) ? 0.15 : -0.15);
            skewed.shape.points.push_back(corner + Vec3(shear, 0.0, 0.5 * shear) * corner.y);
        }
        skewed.position = Vec3(0.0, 0.1, 0.0);
        skewed.angularVelocity = Vec3(0.0, w0, 0.0);
        scene.bodies.push_back(skewed);
        for (BodyDef& body : scene.bodies)
            body.material = "Ice";
        World w = makeWorld(scene);
        // From 1 s on: the first second settles the soft contact.
        Real settled = 0.0, highest = 0.0;
        run(w, 1200, [&](int f) {
            const Real energy = w.diagnostics().kineticEnergy;
            if (f == 59)
                settled = energy;
            if (f >= 59)
                highest = std::max(highest, energy);
        });
        const Real spin = glm::length(w.angularVelocity(1));
        qInfo("sheared box (shear %.1f) spun at %.0f rad/s on ice: kinetic energy at 1 s %.5f J, highest after %.5f J "
              "(%+.4f %%), spin at 20 s %.4f rad/s",
              shear, w0, settled, highest, 100.0 * (highest - settled) / settled, spin);
        QVERIFY(highest <= settled * 1.001);
        QVERIFY(spin > 0.95 * w0); // it keeps spinning: the energy is not simply damped away
    }

    void tumblingIntermediateAxisFlips() {
        // Find the intermediate principal axis of the T-handle from its inertia, then spin it about that axis.
        World probe = makeWorld(scenes::tumbling(0));
        const Mat3 inertia = probe.state().worldInertia(0);
        int order[3] = {0, 1, 2};
        std::sort(order, order + 3, [&](int a, int b) { return inertia[a][a] < inertia[b][b]; });
        World w = makeWorld(scenes::tumbling(order[1]));
        const Real energy0 = w.diagnostics().kineticEnergy;
        const Real momentum0 = glm::length(w.state().angularMomentum(0));
        const Vec3 axis0 = w.shapeOrientation(0) * Vec3(order[1] == 0, order[1] == 1, order[1] == 2);
        int flips = 0;
        Real previous = 1.0, worstL = 0.0, worstE = 0.0;
        run(w, 1200, [&](int) {
            const Vec3 axis = w.shapeOrientation(0) * Vec3(order[1] == 0, order[1] == 1, order[1] == 2);
            const Real c = glm::dot(axis, axis0);
            if ((c < 0.0) != (previous < 0.0))
                ++flips;
            previous = c;
            worstL = std::max(worstL, std::abs(glm::length(w.state().angularMomentum(0)) / momentum0 - 1.0));
            worstE = std::max(worstE, std::abs(w.diagnostics().kineticEnergy / energy0 - 1.0));
        });
        qInfo("T-handle, intermediate axis, 20 s: %d axis reversals, |L| drift %.3g, energy drift %.3g", flips, worstL,
              worstE);
        QVERIFY(flips >= 2);
        QVERIFY(worstL < 0.001);
        QVERIFY(worstE < 0.01);
    }

    void tumblingStableAxesStay_data() {
        QTest::addColumn<int>("rank");
        QTest::newRow("smallest moment") << 0;
        QTest::newRow("largest moment") << 2;
    }
    void tumblingStableAxesStay() {
        QFETCH(int, rank);
        World probe = makeWorld(scenes::tumbling(0));
        const Mat3 inertia = probe.state().worldInertia(0);
        int order[3] = {0, 1, 2};
        std::sort(order, order + 3, [&](int a, int b) { return inertia[a][a] < inertia[b][b]; });
        const int axisIndex = order[rank];
        World w = makeWorld(scenes::tumbling(axisIndex));
        const Vec3 local(axisIndex == 0, axisIndex == 1, axisIndex == 2);
        const Vec3 axis0 = w.shapeOrientation(0) * local;
        Real worst = 0.0;
        run(w, 3600, [&](int) {
            const Real c = std::clamp(glm::dot(w.shapeOrientation(0) * local, axis0), -1.0, 1.0);
            worst = std::max(worst, std::acos(c));
        });
        qInfo("T-handle about a stable axis for 60 s: largest tilt %.3g deg", glm::degrees(worst));
        QVERIFY(glm::degrees(worst) < 5.0);
    }

    // The sample scenes the README opens, made in Blender: nothing goes into the floor by more than resting contact
    // depth, and everything comes to rest. mixed.obj's Cube (rotated, six-decimal coordinates) once had triangle
    // faces, landed on a three-point manifold and sank a corner 37 mm; its Torus 50 mm (measured). Its Torus then
    // never fell asleep: a phantom edge pair (a hull face planar only to the input's rounding against the floor's
    // rim, 5 m away) gave a one-point contact every few frames, it dropped by a frame of gravity and sank up to
    // 3.1 mm each time (measured). Now every body sleeps from frame ~100 on, and the deepest contact is 0.05 mm.
    void sampleScenesStayOutOfTheFloor_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("mixed.obj") << "mixed.obj";
        QTest::newRow("stack.obj") << "stack.obj";
        // Not ramps.obj: rampsCubesMeetEdgeFirst has its own bound.
    }
    void sampleScenesStayOutOfTheFloor() {
        QFETCH(QString, file);
        Result<Scene> scene = importScene(std::string(RL_SOURCE_DIR "/resources/scenes/") + file.toStdString());
        QVERIFY(scene);
        World w = makeWorld(*scene);
        const RunStats stats = run(w, 300);
        qInfo("%s: deepest contact in 5 s %.2f mm", qPrintable(file), 1e3 * stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(stats.maxPenetration < 0.01);
        const RunStats rest = run(w, 300);
        qInfo("%s: from 5 to 10 s deepest contact %.2f mm, fastest in the last second %.2g m/s, awake at 10 s %d",
              qPrintable(file), 1e3 * rest.maxPenetration, rest.maxSpeedLastSecond, w.diagnostics().awakeBodies);
        QCOMPARE(w.diagnostics().awakeBodies, 0);
        QVERIFY(rest.maxSpeedLastSecond < 1e-3);
        QVERIFY(rest.maxPenetration < 0.002);
    }

    // ramps.obj's 0.2 m cubes meet each other edge first at 5-7 m/s. With one point at the edges' witnesses, a cube
    // set spinning at 22 rad/s by the hit turned a corner 71 mm into the other within the next step; speculative
    // edge contacts then clipped the faces that face each other along the axis, and the deepest contact of the
    // first two seconds was 43.1-56.8 mm over the scene and 16 starts with every cube moved by up to 0.1 mm
    // (10942cb): cubes set spinning at 16-25 rad/s within a step, whose separating axis turns in it. Collided again
    // after the step and pushed apart (World::separateMovedPairs()), 3.6-16.0 mm over those 17 starts (3.6 mm from
    // the scene as exported; 2026-12-06). The bound sits between the two; the rows are the scene, the starts of the
    // two deepest contacts (seeds 11 and 1) and one more.
    void rampsCubesMeetEdgeFirst_data() {
        QTest::addColumn<unsigned>("start"); // 0: as exported; else the seed of the cubes' moves
        QTest::newRow("as exported") << 0u;
        QTest::newRow("moved, seed 1") << 1u;
        QTest::newRow("moved, seed 11") << 11u;
        QTest::newRow("moved, seed 15") << 15u;
    }
    void rampsCubesMeetEdgeFirst() {
        QFETCH(unsigned, start);
        Result<Scene> scene = importScene(std::string(RL_SOURCE_DIR "/resources/scenes/ramps.obj"));
        QVERIFY(scene);
        std::mt19937 random(start);
        std::uniform_real_distribution<double> move(-1e-4, 1e-4);
        if (start > 0)
            for (BodyDef& b : scene->bodies)
                if (!b.anchor)
                    for (int axis = 0; axis < 3; ++axis)
                        b.position[axis] += move(random);
        World w = makeWorld(*scene);
        const RunStats stats = run(w, 120);
        qInfo("ramps.obj: deepest contact in the first 2 s %.1f mm", 1e3 * stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(stats.maxPenetration < 0.025);
    }

    // A state captured from ramps.obj (tests/data/stability/README.md): a cube on three corners among anchored
    // neighbours. It rocked at up to 0.8 rad/s without end while the contact reduction dropped a touching corner
    // for speculative ones (measured over 600 frames); now it is asleep within two seconds.
    void cubeOnThreeCornersComesToRest() {
        Result<Scene> scene = capturedScene("cube_on_three_corners.rlscene");
        QVERIFY2(scene, scene ? "" : scene.error().toString().c_str());
        World w = makeWorld(*scene);
        Real fastestSpin = 0.0;
        const RunStats stats = run(w, 300, [&](int frame) {
            if (frame >= 240)
                for (size_t i = 0; i < w.bodyCount(); ++i)
                    fastestSpin = std::max(fastestSpin, glm::length(w.angularVelocity(i)));
        });
        qInfo("cube on three corners: fastest spin in the last second %.3g rad/s, deepest contact %.2f mm, awake %d",
              fastestSpin, 1e3 * stats.maxPenetration, w.diagnostics().awakeBodies);
        QVERIFY(stats.allFinite);
        QCOMPARE(w.diagnostics().awakeBodies, 0);
        QVERIFY(fastestSpin < 0.01);
        QVERIFY(stats.maxPenetration < 0.001);
    }

    void coincidentBoxesSeparateGently() {
        World w = makeWorld(scenes::coincidentBoxes());
        Real fastest = 0.0;
        const RunStats stats = run(w, 120, [&](int) {
            fastest = std::max({fastest, glm::length(w.linearVelocity(0)), glm::length(w.linearVelocity(1))});
        });
        qInfo("coincident boxes: fastest %.3g m/s, apart by %.3g m", fastest,
              glm::length(w.centerOfMass(0) - w.centerOfMass(1)));
        QVERIFY(stats.allFinite);
        QVERIFY(fastest <= 3.0 + 1e-9);
        QVERIFY(glm::length(w.centerOfMass(0) - w.centerOfMass(1)) > 0.9); // separated
    }

    // Bodies created overlapping part at the solver's bounded speed even while they turn: the pass after the step
    // that pushes turned features apart (World::separateMovedPairs()) leaves a contact that began the step deeper
    // than 1 cm at that depth. Pushed to 2 mm at once (tried), these two 1 m boxes, 0.3 m into each other, jumped
    // apart by 0.23 m in one step (measured 2026-12-06).
    void spinningOverlapPartsGently() {
        Scene s = scenes::coincidentBoxes();
        s.bodies[1].position = Vec3(0.7, 0.0, 0.0);
        s.bodies[1].angularVelocity = Vec3(10.0, 0.0, 0.0);
        World w = makeWorld(s);
        Real fastest = 0.0, widest = 0.0, apart = glm::length(w.centerOfMass(1) - w.centerOfMass(0));
        const RunStats stats = run(w, 120, [&](int) {
            const Real now = glm::length(w.centerOfMass(1) - w.centerOfMass(0));
            widest = std::max(widest, now - apart);
            apart = now;
            fastest = std::max({fastest, glm::length(w.linearVelocity(0)), glm::length(w.linearVelocity(1))});
        });
        qInfo("overlapping spinning boxes: fastest %.3g m/s, widest step %.3g m, apart by %.3g m", fastest, widest,
              apart);
        QVERIFY(stats.allFinite);
        QVERIFY(fastest <= 3.0 + 1e-9);
        QVERIFY(widest <= 2.0 * 3.0 / 60.0 + 1e-6); // two bodies at 3 m/s
        QVERIFY(apart > 1.0);                       // parted
    }

    void busySceneTenMinutes() {
        World w = makeWorld(scenes::busy());
        const auto energy = [&w] { return totalEnergy(w); };
        const Real start = energy();
        Real highest = start;
        const RunStats stats = run(w, 36000, [&](int) { highest = std::max(highest, energy()); });
        qInfo("busy scene, 10 min: energy start %.4g J, highest %.4g J (%+.3f %%)", start, highest,
              100.0 * (highest - start) / std::abs(start));
        QVERIFY(stats.allFinite);
        QVERIFY(highest <= start + 0.01 * std::abs(start));
    }

    void bulletNeverTunnels() {
        int stopped = 0;
        for (int k = 0; k < 20; ++k) {
            const Real offset = k * 0.0173; // 20 start offsets spread over more than one step of travel
            World w = makeWorld(scenes::bullet(offset));
            run(w, 60);
            stopped += w.centerOfMass(1).x < 0.0 ? 1 : 0;
        }
        qInfo("0.1 m cube at 300 m/s against a 5 cm wall: stopped in %d of 20 offsets", stopped);
        QCOMPARE(stopped, 20);
    }

    // A free-standing wall is a dynamic body: the shot is swept against it too (World::continuousCollision()).
    void shotNeverTunnelsThroughAStandingWall_data() { addSpeedRows(); }

    void shotNeverTunnelsThroughAStandingWall() {
        QFETCH(double, speed);
        constexpr int kStarts = 10;
        int struck = 0;
        Real leastShare = 1.0;
        for (int k = 0; k < kStarts; ++k) {
            const Real offset = k * speed / 60.0 / kStarts; // start offsets spread over one step of travel
            World w = makeWorld(scenes::shotAtStandingWall(offset, speed));
            const Real shotMomentum = w.mass(2) * speed;
            // Until a quarter of a second after the shot would have reached the wall.
            run(w, static_cast<int>(std::ceil((2.0 + offset) / speed * 60.0)) + 15);
            const Real share = w.mass(1) * w.linearVelocity(1).x / shotMomentum;
            leastShare = std::min(leastShare, share);
            const bool nearSide = w.centerOfMass(2).x < w.centerOfMass(1).x;
            struck += nearSide && share > 0.5 ? 1 : 0;
        }
        qInfo("0.1 m steel cube at %.0f m/s against a free-standing 5 cm wall: struck it in %d of %d starts; the wall "
              "took at least %.1f %% of its momentum",
              speed, struck, kStarts, 100.0 * leastShare);
        QCOMPARE(struck, kStarts);
    }

    // Two fast bodies go back together to the pair's time of impact (World::continuousCollision()).
    void headOnShotsNeverPassThrough_data() { addSpeedRows(); }

    void headOnShotsNeverPassThrough() {
        QFETCH(double, speed);
        constexpr int kStarts = 10;
        int met = 0;
        Real fastestAfter = 0.0;
        for (int k = 0; k < kStarts; ++k) {
            const Real offset = k * 2.0 * speed / 60.0 / kStarts; // spread over one step of their closing travel
            World w = makeWorld(scenes::headOnShots(offset, speed));
            // Until a quarter of a second after they would have met.
            run(w, static_cast<int>(std::ceil((3.0 + offset) / (2.0 * speed) * 60.0)) + 15);
            const Real fastest = std::max(glm::length(w.linearVelocity(0)), glm::length(w.linearVelocity(1)));
            fastestAfter = std::max(fastestAfter, fastest);
            met += w.centerOfMass(0).x < w.centerOfMass(1).x && fastest < 0.5 * speed ? 1 : 0;
        }
        qInfo("two 0.1 m steel cubes head on at %.0f m/s each: met in %d of %d starts, fastest afterwards %.3g m/s",
              speed, met, kStarts, fastestAfter);
        QCOMPARE(met, kStarts);
    }

    // Thin anchored walls (0.1 mm and 1 mm boxes, and a flat quad: a Blender plane) against small fast shots: a ball of
    // 1 cm radius, a 2 cm cube and a 10 x 1 x 1 cm rod, at 300 and 3,000 m/s, head on or 60 and 80 degrees off the
    // normal, still or spinning at 244 rad/s. The shot's centre must never be beyond the wall's face inside the wall's
    // extent (no gravity: a shot that slides along the wall leaves it past its edge). Without CCD
    // (`--effects auto,-ccd`) 240 of a sweep of 384 such cases passed through (2026-12-07).
    void shotsNeverPassThinWalls_data() {
        QTest::addColumn<int>("wall"); // 0: 0.1 mm box, 1: 1 mm box, 2: flat quad
        QTest::addColumn<int>("shot"); // 0: ball, 1: cube, 2: rod
        QTest::addColumn<double>("speed");
        QTest::addColumn<double>("degrees");
        QTest::addColumn<double>("spin");
        const char* walls[] = {"0.1 mm wall", "1 mm wall", "flat wall"};
        const char* shots[] = {"ball", "cube", "rod"};
        for (int wall = 0; wall < 3; ++wall)
            for (int shot = 0; shot < 3; ++shot)
                for (double speed : {300.0, 3000.0})
                    for (double degrees : {0.0, 60.0, 80.0})
                        for (double spin : {0.0, 200.0})
                            QTest::addRow("%s, %s, %.0f m/s, %.0f deg%s", walls[wall], shots[shot], speed, degrees,
                                          spin > 0.0 ? ", spinning" : "")
                                << wall << shot << speed << degrees << spin;
    }

    void shotsNeverPassThinWalls() {
        QFETCH(int, wall);
        QFETCH(int, shot);
        QFETCH(double, speed);
        QFETCH(double, degrees);
        QFETCH(double, spin);
        Scene s;
        s.world.gravity = Vec3(0.0);
        const Vec3 wallAt(5.0, 2.0, 0.0);
        if (wall < 2) {
            s.bodies.push_back(scenes::box("Wall", Vec3(wall == 0 ? 0.00005 : 0.0005, 2.0, 4.0), wallAt));
        } else {
            BodyDef quad;
            quad.name = "Wall";
            quad.shape.type = ShapeType::Hull;
            quad.shape.points = {{0.0, -2.0, -4.0}, {0.0, 2.0, -4.0}, {0.0, 2.0, 4.0}, {0.0, -2.0, 4.0}};
            quad.position = wallAt;
            s.bodies.push_back(quad);
        }
        s.bodies.back().anchor = true;
        const Real a = degrees * kPi / 180.0;
        const Vec3 along(std::cos(a), 0.0, std::sin(a));
        const Vec3 start = Vec3(5.0, 2.0, 0.0) - 3.0 * along;
        if (shot == 0) {
            s.bodies.push_back(scenes::sphere("Shot", 0.01, start));
        } else {
            const Vec3 half = shot == 1 ? Vec3(0.02) : Vec3(0.05, 0.005, 0.005);
            s.bodies.push_back(scenes::box("Shot", half, start));
        }
        s.bodies.back().material = "Steel";
        s.bodies.back().velocity = speed * along;
        s.bodies.back().angularVelocity = Vec3(0.0, spin, 0.7 * spin);
        World w = makeWorld(s);
        bool passed = false, allFinite = true;
        Real deepest = -1e9; // the shot's centre beyond the wall's plane, inside its extent (m)
        run(w, 30, [&](int) {
            const Vec3 c = w.centerOfMass(1);
            allFinite = allFinite && finite(c);
            if (std::abs(c.z) < 4.0 && std::abs(c.y - 2.0) < 2.0) {
                deepest = std::max(deepest, c.x - 5.0);
                passed = passed || c.x > 5.0;
            }
        });
        if (passed)
            qInfo("the shot's centre got %.4f m beyond the wall's plane", deepest);
        QVERIFY(allFinite);
        QVERIFY(!passed);
    }

    void spinningPlankNeverTunnels() {
        World w = makeWorld(scenes::spinningPlank(50.0));
        run(w, 120);
        const Transform xf = w.transform(1);
        Real maxX = -1e9;
        for (int i = 0; i < 8; ++i) {
            const Vec3 corner((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.05 : -0.05, (i & 4) ? 0.1 : -0.1);
            maxX = std::max(maxX, xf.apply(corner).x);
        }
        qInfo("plank spinning at 50 rad/s: furthest corner at x = %.4f (wall face at -0.025)", maxX);
        QVERIFY(maxX < 0.0);
    }
};

QTEST_APPLESS_MAIN(TestMotion)
#include "tst_motion.moc"
