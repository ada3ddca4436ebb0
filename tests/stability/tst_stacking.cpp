// Hard cases that stack: towers, pyramids, a 1:1000 mass ratio, a slab on two cubes, a card house and a Jenga
// tower, each at default settings for 10 s at 60 Hz, against the thresholds of the physics issue.
#include "StabilityFixture.h"
#include "scene/SceneLibrary.h"

#include <QTest>

using namespace rl;
using namespace rl::test;

class TestStacking : public QObject {
    Q_OBJECT
private slots:
    // The towers of unit cubes, and 20-cube towers of small cubes: a contact settles the same fraction of a
    // millimetre whatever the size, so small bodies get finer substeps (World::sizeRefinement()). Without them the
    // tower of 2 cm cubes fell and that of 3 cm cubes stood 14 mm askew (2026-12-05). "Stands": the top sank less
    // than sink x the cube's size.
    void towers_data() {
        QTest::addColumn<int>("cubes");
        QTest::addColumn<double>("size");
        QTest::addColumn<double>("maxDrift");
        QTest::addColumn<double>("sink");
        QTest::addColumn<double>("maxSpeed");
        QTest::newRow("20 cubes") << 20 << 1.0 << 0.01 << 0.05 << 0.01;
        QTest::newRow("40 cubes") << 40 << 1.0 << 0.02 << 0.1 << 0.01;
        for (const double size : {0.1, 0.05, 0.03, 0.02, 0.01})
            QTest::addRow("20 cubes of %g m", size) << 20 << size << 0.005 << 0.25 << 0.01;
    }
    void towers() {
        QFETCH(int, cubes);
        QFETCH(double, size);
        QFETCH(double, maxDrift);
        QFETCH(double, sink);
        QFETCH(double, maxSpeed);
        Scene scene = scenes::stack(cubes);
        for (size_t i = 1; i < scene.bodies.size(); ++i) {
            scene.bodies[i].shape.halfExtents *= size;
            scene.bodies[i].position *= size;
        }
        World w = makeWorld(scene);
        const size_t top = w.bodyCount() - 1;
        const Vec3 start = w.centerOfMass(top);
        const RunStats stats = run(w, 600);
        const Real drift = horizontal(w.centerOfMass(top), start);
        qInfo("%d-cube tower of %g m cubes: top drift %.3g m, sank %.3g m, max speed in last second %.3g m/s, max "
              "penetration %.3g m",
              cubes, size, drift, start.y - w.centerOfMass(top).y, stats.maxSpeedLastSecond, stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(drift < maxDrift);
        QVERIFY(std::abs(start.y - w.centerOfMass(top).y) < sink * size); // it stands: no collapse
        QVERIFY(stats.maxSpeedLastSecond < maxSpeed);
    }

    void pyramid20() {
        World w = makeWorld(scenes::pyramid(20));
        QCOMPARE(w.bodyCount(), size_t(211));
        const size_t top = w.bodyCount() - 1;
        const Vec3 start = w.centerOfMass(top);
        const RunStats stats = run(w, 600);
        const Real drift = horizontal(w.centerOfMass(top), start);
        qInfo("pyramid 20: top drift %.3g m, sank %.3g m, max speed last second %.3g m/s, max penetration %.3g m",
              drift, start.y - w.centerOfMass(top).y, stats.maxSpeedLastSecond, stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(drift < 0.01);
        QVERIFY(std::abs(start.y - w.centerOfMass(top).y) < 0.1);
    }

    void massRatio() {
        World w = makeWorld(scenes::massRatio(1.0, 1000.0));
        const RunStats stats = run(w, 600);
        const Vec3 light = w.centerOfMass(1), heavy = w.centerOfMass(2);
        const Real resting = w.diagnostics().maxPenetration;
        qInfo("1:1000: heavy above light by %.4g m (0.5 expected), resting penetration %.3g m, deepest in the run "
              "%.3g m",
              heavy.y - light.y, resting, stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(heavy.y - light.y > 0.45);        // still on top
        QVERIFY(horizontal(heavy, light) < 0.05); // not slid off
        // Issue 4: penetration < 1 cm. Soft contacts settle F / (m_eff omega^2) deep: 1.8 cm at 8 substeps (measured);
        // the world gives islands with a mass ratio above 250 more substeps (2x here), which measured 0.44 cm, and
        // now holds the light cube still under the heavy one (shock propagation): 0.0043 mm.
        QVERIFY(resting < 0.01);
        QVERIFY(stats.maxPenetration < 0.01);
    }

    // The 1,000 kg cube dropped onto the 1 kg one. Before shock propagation (World::heightsAboveSupport()) the
    // deepest contact was 19.8 mm from 10 cm, 39.9 mm from 0.5 m, 59.0 mm from 1 m and 90.1 mm from 2 m. And lighter
    // heavy cubes from 5 m and 10 m: until 2026-12-05 only islands with a mass ratio above 250 held a lower body, and
    // a 20 kg or 200 kg cube dropped 5 m drove the 1 kg one 42 mm or 185 mm into the floor and ended beside it; a 5 kg
    // one from 5 m and a 3 kg one from 10 m went through it too.
    void heavyDroppedOnLight_data() {
        QTest::addColumn<double>("heavyMass");
        QTest::addColumn<double>("drop");
        QTest::newRow("1,000 kg from 10 cm") << 1000.0 << 0.1;
        QTest::newRow("1,000 kg from 0.5 m") << 1000.0 << 0.5;
        QTest::newRow("1,000 kg from 1 m") << 1000.0 << 1.0;
        QTest::newRow("1,000 kg from 2 m") << 1000.0 << 2.0;
        for (const double mass : {3.0, 5.0, 20.0, 200.0, 1000.0})
            for (const double drop : {5.0, 10.0})
                QTest::addRow("%g kg from %g m", mass, drop) << mass << drop;
    }
    void heavyDroppedOnLight() {
        QFETCH(double, heavyMass);
        QFETCH(double, drop);
        Scene s = scenes::massRatio(1.0, heavyMass);
        s.bodies[2].position.y += drop;
        World w = makeWorld(s);
        const RunStats stats = run(w, 300);
        const Vec3 light = w.centerOfMass(1), heavy = w.centerOfMass(2);
        qInfo("1:%g, heavy dropped %.2f m: deepest contact %.3g m, heavy above light by %.4g m at 5 s", heavyMass, drop,
              stats.maxPenetration, heavy.y - light.y);
        QVERIFY(stats.allFinite);
        QVERIFY(stats.maxPenetration < 0.01);
        QVERIFY(heavy.y - light.y > 0.49);
        QVERIFY(horizontal(heavy, light) < 0.05);
    }

    // A wide heavy box dropped flat and centred onto a smaller cube (1,000:1) or an anchored pedestal lands flat and
    // stays on it. Its face meets the small top on four points at once: swept one point after the other, the first
    // took the whole blow (375/0/0/0 N s for 0.5 m on 0.25 m from 2 m) and the box spun off; a 1 m box falling 5 m
    // onto a 10 cm cube counted as resting on the floor 18 cm below (a speculative contact) and was not held by the
    // cube, crushed it into the floor, and both flew up at 3.4 m/s.
    void wideBoxDroppedFlatOnASmallTop_data() {
        QTest::addColumn<double>("lowerEdge");
        QTest::addColumn<double>("upperEdge");
        QTest::addColumn<double>("drop");
        QTest::addColumn<bool>("anchored");
        QTest::addColumn<int>("substeps"); // 0: the default
        QTest::newRow("0.5 m on 0.25 m from 2 m") << 0.25 << 0.5 << 2.0 << false << 0;
        QTest::newRow("0.5 m on 0.25 m from 5 m") << 0.25 << 0.5 << 5.0 << false << 0;
        QTest::newRow("1 m on 0.5 m from 5 m") << 0.5 << 1.0 << 5.0 << false << 0;
        QTest::newRow("1 m on 0.2 m from 2 m") << 0.2 << 1.0 << 2.0 << false << 0;
        QTest::newRow("1 m on 0.1 m from 2 m") << 0.1 << 1.0 << 2.0 << false << 0;
        QTest::newRow("1 m on 0.1 m from 5 m") << 0.1 << 1.0 << 5.0 << false << 0;
        QTest::newRow("0.5 m on 0.1 m from 0.5 m") << 0.1 << 0.5 << 0.5 << false << 0;
        QTest::newRow("0.5 m on 0.1 m from 5 m") << 0.1 << 0.5 << 5.0 << false << 0;
        QTest::newRow("0.5 m on an anchored 0.25 m pedestal from 2 m, 18 substeps") << 0.25 << 0.5 << 2.0 << true << 18;
        QTest::newRow("0.5 m on an anchored 0.25 m pedestal from 5 m, 24 substeps") << 0.25 << 0.5 << 5.0 << true << 24;
    }
    void wideBoxDroppedFlatOnASmallTop() {
        QFETCH(double, lowerEdge);
        QFETCH(double, upperEdge);
        QFETCH(double, drop);
        QFETCH(bool, anchored);
        QFETCH(int, substeps);
        Scene s = scenes::massRatio(1.0, 1000.0);
        s.bodies[1].shape.halfExtents = Vec3(0.5 * lowerEdge);
        s.bodies[1].position = Vec3(0.0, 0.5 * lowerEdge, 0.0);
        s.bodies[1].anchor = anchored;
        s.bodies[2].shape.halfExtents = Vec3(0.5 * upperEdge);
        s.bodies[2].position = Vec3(0.0, lowerEdge + 0.5 * upperEdge + drop, 0.0);
        WorldOptions options;
        if (substeps > 0)
            options.substeps = substeps;
        World w = makeWorld(s, options);
        Real fastestSpin = 0.0;
        const RunStats stats =
            run(w, 300, [&](int) { fastestSpin = std::max(fastestSpin, glm::length(w.angularVelocity(2))); });
        const Vec3 lower = w.centerOfMass(1), upper = w.centerOfMass(2);
        const Real tilt = glm::degrees(glm::angle(w.rotationSinceStart(2)));
        qInfo("%.2f m box from %.1f m on %.2f m: fastest spin %.3g rad/s, at 5 s %.3g mm off centre, tilted %.3g deg, "
              "%.3g mm low; deepest contact %.3g mm",
              upperEdge, drop, lowerEdge, fastestSpin, 1e3 * horizontal(upper, lower), tilt,
              1e3 * (0.5 * (lowerEdge + upperEdge) - (upper.y - lower.y)), 1e3 * stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(stats.maxPenetration < 0.01);
        QVERIFY(horizontal(upper, lower) < 0.005);
        QVERIFY(tilt < 1.0);
        QVERIFY(upper.y - lower.y > 0.5 * (lowerEdge + upperEdge) - 0.005);
        QVERIFY(lower.y > 0.5 * lowerEdge - 0.005);
    }

    // A light body that rises into a heavy one is not held under it as it moves (World::contactHold()): held so, it
    // pushes the heavy one up as an immovable body would. A 463 kg cube falling 0.8 m onto a 0.128 kg box of 1.2 m
    // that was still bouncing on the floor (e = 0.6), turning at 10 rad/s, was thrown up at up to 35 m/s, the scene's
    // energy rising to 3.4 times its start at 57ad949 and 25 times at 3802b6c (2026-12-05). (It first meets the heavy
    // one, World::meetRisingLowerBody(), and is then held: see aRisingLightBallIsNotCrushed.)
    void aRisingLightBodyGivesTheHeavyOneNoEnergy() {
        Scene s = scenes::massRatio(0.128, 463.572);
        s.bodies[0].restitution = 0.6;
        s.bodies[1].shape.halfExtents = Vec3(0.3807752409455521, 0.48222264844574453, 0.6105456818717845);
        s.bodies[1].position = Vec3(-2.46, 1.13, -0.39);
        s.bodies[1].restitution = 0.6;
        s.bodies[2].shape.halfExtents = Vec3(0.15094279707491157, 0.13673637573708028, 0.14433159315855904);
        s.bodies[2].position = Vec3(-2.49, 2.56, 0.16);
        s.bodies[2].restitution = 0.6;
        World w = makeWorld(s);
        const auto energy = [&w] { return totalEnergy(w); };
        const Real start = energy(), fall = 463.572 * 9.81 * 2.56; // the heavy cube's drop to the floor bounds any loss
        Real highest = start, fastest = 0.0;
        const RunStats stats = run(w, 180, [&](int) {
            highest = std::max(highest, energy());
            fastest = std::max({fastest, glm::length(w.linearVelocity(1)), glm::length(w.linearVelocity(2))});
        });
        qInfo(
            "rising light box under a falling 463 kg cube: energy at most %+.4f %% of the heavy cube's drop above its "
            "start, fastest body %.2f m/s, deepest contact %.3g mm",
            100.0 * (highest - start) / fall, fastest, 1e3 * stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(highest <= start + 0.01 * fall);
        QVERIFY(fastest < 10.0);
    }

    // A 3 kg ball that has just bounced off the floor rises into a 580 kg one falling onto it. Not held while it rose
    // (above), it was crushed into the floor as the sweeps took the heavy ball's momentum out through it a little at
    // a time: 43-83 mm in the last four rows (and 110 mm in a random scene of Blender-like shapes, 2026-12-05). Now
    // the two first meet in an inelastic impulse along the normal (World::meetRisingLowerBody()), and the light ball
    // is then held under the heavy one like the ground: 0.03-3.1 mm deep. Two things had to go with it: the impulses
    // of a held contact warm start no step in which it does not hold (in 12 such throws, 4 gained energy, one 17
    // times its start, the fourth row here 89 %, when a 1,368 N s warm start fell on the 3 kg ball), and a body
    // rests only on contacts that can bear it up (heightsAboveSupport(): the ball's floor contact, farther than the
    // heavy ball's above it, did not count, so its hold came and went; the first row sank 20 mm).
    void aRisingLightBallIsNotCrushed_data() {
        QTest::addColumn<Real>("rise");
        QTest::addColumn<Real>("fall");
        QTest::addColumn<Real>("restitution");
        QTest::newRow("2 m/s up, 6 m/s down, e 0") << 2.0 << 6.0 << 0.0;
        QTest::newRow("4 m/s up, 6 m/s down, e 0") << 4.0 << 6.0 << 0.0;
        QTest::newRow("4 m/s up, 12 m/s down, e 0.3") << 4.0 << 12.0 << 0.3;
        QTest::newRow("8 m/s up, 6 m/s down, e 0.3") << 8.0 << 6.0 << 0.3;
        QTest::newRow("8 m/s up, 12 m/s down, e 0") << 8.0 << 12.0 << 0.0;
    }
    void aRisingLightBallIsNotCrushed() {
        QFETCH(Real, rise);
        QFETCH(Real, fall);
        QFETCH(Real, restitution);
        Scene s = scenes::drop(0.0005, restitution);
        s.bodies[1].mass = 3.0;
        s.bodies[1].velocity = Vec3(0.0, rise, 0.0);
        BodyDef heavy = s.bodies[1];
        heavy.name = "Heavy";
        heavy.shape.radius = 0.45;
        heavy.mass = 580.0;
        heavy.position = Vec3(0.02, 0.8, 0.0);
        heavy.velocity = Vec3(0.0, -fall, 0.0);
        s.bodies.push_back(heavy);
        World w = makeWorld(s);
        const auto energy = [&w] { return totalEnergy(w); };
        const Real start = energy();
        Real lowest = 1.0, highest = start;
        const RunStats stats = run(w, 120, [&](int) {
            lowest = std::min(lowest, w.centerOfMass(1).y - 0.1);
            highest = std::max(highest, energy());
        });
        qInfo("3 kg ball rising at %.0f m/s into a 580 kg one falling at %.0f m/s, e %.1f: lowest %.2f mm, energy at "
              "most %+.4f %% of its start",
              rise, fall, restitution, 1e3 * lowest, 100.0 * (highest - start) / start);
        QVERIFY(stats.allFinite);
        QVERIFY(lowest > -5e-3);
        QVERIFY(highest <= start * 1.0001);
    }

    // A heavy plank landing across a light cube and the floor at once (its underside on the line from the floor to the
    // cube's top, 5 cm above it): both contacts bear it up, so it counted as resting on the floor, the two were at the
    // same height, and the cube was not held. The sweeps took the plank's momentum out through the cube a little at a
    // time: deepest contact 2.6, 9.7 and 9.8 mm in these rows (a 22 kg box under a 199 kg cylinder in a random scene
    // went 19.5 mm into the floor). At the same height the body with the lower centre is now held too, when the other
    // is stackHoldRatio times heavier and the normal within 45 degrees of vertical: 0.04, 0.03 and 0.75 mm
    // (2026-12-05).
    void heavyPlankAcrossALightCubeAndTheFloor_data() {
        QTest::addColumn<double>("cubeHalf");
        QTest::addColumn<double>("speed");
        QTest::addColumn<double>("density");
        QTest::newRow("8 kg cube, 400 kg plank at 3 m/s") << 0.1 << 3.0 << 2000.0;
        QTest::newRow("8 kg cube, 1,600 kg plank at 6 m/s") << 0.1 << 6.0 << 8000.0;
        QTest::newRow("8 kg cube, 1,600 kg plank at 10 m/s") << 0.1 << 10.0 << 8000.0;
    }
    void heavyPlankAcrossALightCubeAndTheFloor() {
        QFETCH(double, cubeHalf);
        QFETCH(double, speed);
        QFETCH(double, density);
        Scene s = scenes::massRatio(1.0, 1.0);
        BodyDef& cube = s.bodies[1];
        cube.shape.type = ShapeType::Box;
        cube.shape.halfExtents = Vec3(cubeHalf);
        cube.position = Vec3(0.6, cubeHalf, 0.0);
        cube.mass.reset();
        cube.density = 1000.0;
        // A plank 2 m long, 0.2 m thick and 0.5 m wide, tilted so that its underside runs from the floor at x = -1
        // to the cube's top at x = 0.6.
        const Real angle = std::atan2(2.0 * cubeHalf, 1.6);
        const Vec3 along(std::cos(angle), std::sin(angle), 0.0), up(-std::sin(angle), std::cos(angle), 0.0);
        BodyDef& plank = s.bodies[2];
        plank.shape.type = ShapeType::Box;
        plank.shape.halfExtents = Vec3(1.0, 0.1, 0.25);
        plank.position = Vec3(-1.0, 0.0, 0.0) + 1.05 * along + 0.1 * up + Vec3(0.0, 0.05, 0.0);
        plank.orientation = glm::angleAxis(angle, Vec3(0.0, 0.0, 1.0));
        plank.mass.reset();
        plank.density = density;
        plank.velocity = Vec3(0.0, -speed, 0.0);
        World w = makeWorld(s);
        const RunStats stats = run(w, 120);
        qInfo("%.0f kg plank at %.0f m/s across a %.0f kg cube and the floor: deepest contact %.3f mm", w.mass(2),
              speed, w.mass(1), 1e3 * stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(stats.maxPenetration < 1e-3);
    }

    // A held body is held only against gravity: a 1,000 kg block sliding on a frictionless plate into a 1 kg cube on
    // the floor beside the plate (the block is one contact farther from the floor than the cube) sends the cube off.
    void heavyBodySidewaysIsNotStoppedByALightOne() {
        Scene s;
        s.materials.push_back({"Ice", 1000.0, 0.0, 0.0});
        BodyDef floor;
        floor.name = "Floor";
        floor.anchor = true;
        floor.shape.type = ShapeType::Box;
        floor.shape.halfExtents = Vec3(50.0, 0.5, 50.0);
        floor.position = Vec3(0.0, -0.5, 0.0);
        floor.material = "Ice";
        s.bodies.push_back(floor);
        const auto block = [&](const char* name, const Vec3& half, const Vec3& at, Real mass) {
            BodyDef b = floor;
            b.name = name;
            b.anchor = false;
            b.shape.halfExtents = half;
            b.position = at;
            b.mass = mass;
            s.bodies.push_back(b);
        };
        block("Plate", Vec3(2.0, 0.1, 1.0), Vec3(-2.0, 0.1, 0.0), 1000.0);
        block("Heavy", Vec3(0.25), Vec3(-1.0, 0.45, 0.0), 1000.0);
        block("Light", Vec3(0.25), Vec3(0.3, 0.25, 0.0), 1.0);
        s.bodies[2].velocity = Vec3(2.0, 0.0, 0.0);
        World w = makeWorld(s);
        run(w, 60);
        qInfo("heavy block sideways into a light cube: light cube at x = %.3f m, %.3f m/s; heavy block %.3f m/s",
              w.centerOfMass(3).x, w.linearVelocity(3).x, w.linearVelocity(2).x);
        QVERIFY(w.linearVelocity(3).x > 1.5); // pushed along at the block's speed or faster
        QVERIFY(w.linearVelocity(2).x > 1.5); // the block barely slowed
    }

    void slabOnTwoCubes() {
        World w = makeWorld(scenes::slabOnTwoCubes());
        const Vec3 start = w.centerOfMass(3);
        const RunStats stats = run(w, 600);
        qInfo("slab: sank %.3g m, drift %.3g m, max penetration %.3g m", start.y - w.centerOfMass(3).y,
              horizontal(w.centerOfMass(3), start), stats.maxPenetration);
        QVERIFY(stats.allFinite);
        QVERIFY(std::abs(start.y - w.centerOfMass(3).y) < 0.02);
        QVERIFY(horizontal(w.centerOfMass(3), start) < 0.02);
    }

    // The house starts with no card inside another (its flat cards lie end to end: while they lay 2 mm deep in each
    // other, it fell at 48 substeps), and stands at the default substeps and at finer ones; at the default substeps
    // also with the cards leaning further on less friction, each row on 0.1 more than a friction on which it fell on
    // 2026-12-07 (20 degrees on mu 0.3, 24 degrees on 0.4; tan(tilt) is 0.36 and 0.45).
    void cardHouse_data() {
        QTest::addColumn<int>("substeps");
        QTest::addColumn<double>("tilt");
        QTest::addColumn<double>("friction");
        QTest::newRow("default substeps") << 0 << 18.0 << 0.7;
        QTest::newRow("24 substeps") << 24 << 18.0 << 0.7;
        QTest::newRow("48 substeps") << 48 << 18.0 << 0.7;
        QTest::newRow("leaning 20 degrees, mu 0.4") << 0 << 20.0 << 0.4;
        QTest::newRow("leaning 24 degrees, mu 0.5") << 0 << 24.0 << 0.5;
    }
    void cardHouse() {
        QFETCH(int, substeps);
        QFETCH(double, tilt);
        QFETCH(double, friction);
        const Scene scene = scenes::cardHouse(5, friction, tilt, 0.4);
        QCOMPARE(scene.bodies.size(), size_t(41));
        WorldOptions options;
        if (substeps > 0)
            options.substeps = substeps;
        World w = makeWorld(scene, options);
        std::vector<Vec3> start(w.bodyCount());
        for (size_t i = 0; i < w.bodyCount(); ++i)
            start[i] = w.centerOfMass(i);
        const RunStats first = run(w, 1);
        const RunStats stats = run(w, 599);
        Real worst = 0.0;
        for (size_t i = 1; i < w.bodyCount(); ++i)
            worst = std::max(worst, glm::length(w.centerOfMass(i) - start[i]));
        qInfo("card house at %d substeps, leaning %.0f degrees, mu %.1f: deepest contact of the first step %.3g mm, "
              "largest card displacement %.3g mm, max speed last second %.3g m/s",
              w.substeps(), tilt, friction, 1e3 * first.maxPenetration, 1e3 * worst, stats.maxSpeedLastSecond);
        QVERIFY(first.maxPenetration < 1e-4);
        QVERIFY(stats.allFinite);
        QVERIFY(worst < 0.02); // every card is where it was put: the house stands
        QVERIFY(stats.maxSpeedLastSecond < 0.01);
    }

    // One A-frame of two 2 mm cards on the floor stands where statics says it does: the cards' tops push on each
    // other level by symmetry, so the feet need a friction of tan(tilt) / 2, and nothing at the apex. 15 % above
    // that it stands (every card within 2 mm), 15 % below it falls flat (a card 5 cm from where it was). Until
    // 2026-12-07 the apex's normal was one card's face normal, tilted by the lean, and friction had to hold that
    // too: the frames stood only from tan(tilt) on (20 degrees: mu 0.35 against 0.18; 40: above 0.7 against 0.42).
    void aFrameStandsFromHalfTheTangent_data() {
        QTest::addColumn<double>("tilt");
        QTest::addColumn<double>("share");
        QTest::addColumn<bool>("stands");
        for (const double tilt : {20.0, 30.0, 40.0}) {
            QTest::addRow("%.0f degrees, 1.15 x tan/2", tilt) << tilt << 1.15 << true;
            QTest::addRow("%.0f degrees, 0.85 x tan/2", tilt) << tilt << 0.85 << false;
        }
    }
    void aFrameStandsFromHalfTheTangent() {
        QFETCH(double, tilt);
        QFETCH(double, share);
        QFETCH(bool, stands);
        const Real friction = share * 0.5 * std::tan(glm::radians(tilt));
        World w = makeWorld(scenes::cardHouse(1, friction, tilt, 0.4));
        QCOMPARE(w.bodyCount(), size_t(3));
        const Vec3 start[2] = {w.centerOfMass(1), w.centerOfMass(2)};
        const RunStats stats = run(w, 180);
        const Real moved =
            std::max(glm::length(w.centerOfMass(1) - start[0]), glm::length(w.centerOfMass(2) - start[1]));
        qInfo("A-frame leaning %.0f degrees, mu %.3f (%.2f x tan/2): a card moved %.3g mm", tilt, friction, share,
              1e3 * moved);
        QVERIFY(stats.allFinite);
        if (stands)
            QVERIFY(moved < 0.002);
        else
            QVERIFY(moved > 0.05);
    }

    void jenga() {
        World w = makeWorld(scenes::jenga(30));
        const size_t top = w.bodyCount() - 2; // the middle block of the top layer
        const Vec3 start = w.centerOfMass(top);
        const RunStats stats = run(w, 600);
        qInfo("jenga 30: top drift %.3g m, sank %.3g m", horizontal(w.centerOfMass(top), start),
              start.y - w.centerOfMass(top).y);
        QVERIFY(stats.allFinite);
        QVERIFY(horizontal(w.centerOfMass(top), start) < 0.02);
        QVERIFY(std::abs(start.y - w.centerOfMass(top).y) < 0.05);
    }
};

QTEST_APPLESS_MAIN(TestStacking)
#include "tst_stacking.moc"
