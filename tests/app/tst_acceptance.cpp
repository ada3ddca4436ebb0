// Issue 4, "How it will be checked", done as the reviewers will do it: scenes made with Blender 3.4's own exporters
// (tests/data/acceptance/make_scenes.py) and JSON scenes over them are baked with `rigidlab-cli bake SCENE
// --seconds 10 --csv OUT.csv` at default settings, and each threshold of the table is checked from the CSV
// alone (plus the OBJ vertices for the lowest point). Re-bakes and 2-thread bakes must hash identically, and the
// accuracy orders are refitted from `rigidlab-cli accuracy --csv`. The 642-cube ramps scene is in
// tst_acceptance_slow.
#include "data/acceptance/AcceptanceCsv.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>

using namespace rl::test::acceptance;

namespace {

constexpr double kG = 9.81;

#define BAKE_OR_FAIL(var, ...)                                                                                         \
    const Bake var = bake(__VA_ARGS__);                                                                                \
    QVERIFY2(var.run.exitCode == 0, qPrintable(var.command + "\n" + QString::fromUtf8(var.run.err)));                  \
    QVERIFY2(var.csv.ok, qPrintable(var.csv.error));                                                                   \
    QCOMPARE(var.csv.frames, 601);                                                                                     \
    QVERIFY2(var.csv.allFinite(), "NaN or inf in the CSV")

// Least-squares slope of log(error) over log(step).
double fitOrder(const std::vector<std::pair<double, double>>& stepError) {
    double mx = 0, my = 0;
    for (const auto& [h, e] : stepError) {
        mx += std::log(h);
        my += std::log(e);
    }
    mx /= stepError.size();
    my /= stepError.size();
    double sxy = 0, sxx = 0;
    for (const auto& [h, e] : stepError) {
        sxy += (std::log(h) - mx) * (std::log(e) - my);
        sxx += (std::log(h) - mx) * (std::log(h) - mx);
    }
    return sxy / sxx;
}

} // namespace

class TestAcceptance : public QObject {
    Q_OBJECT
private slots:
    // Towers, the pyramid, the slab, Jenga, and the 20-cube tower through FBX (Y up and Z up) and glTF.
    // maxDrift: top body's horizontal drift; maxSpeed: any body in the last second (finite differences), < 0 = not
    // part of the case; stand: every body ends within this distance of where it started ("stands").
    void stacks_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("maxDrift");
        QTest::addColumn<double>("maxSpeed");
        QTest::addColumn<double>("stand");
        QTest::newRow("tower20.obj") << "tower20.obj" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20_new_exporter.obj") << "tower20_new_exporter.obj" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20_rot45.obj") << "tower20_rot45.obj" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20.fbx") << "tower20.fbx" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20_zup.fbx") << "tower20_zup.fbx" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20.glb") << "tower20.glb" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20_2m.obj (Blender's default 2 m cubes)") << "tower20_2m.obj" << 0.01 << 0.01 << 0.05;
        // As users build it: 10 cm and 5 cm cubes, 1 cm gaps (each cube falls up to 19 cm before it settles), each
        // cube turned by a random angle and shifted by up to 5 cm, and the tower 500 m from the origin.
        QTest::newRow("tower20_10cm.obj") << "tower20_10cm.obj" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20_5cm.obj") << "tower20_5cm.obj" << 0.01 << 0.01 << 0.05;
        // 2 cm cubes in plain JSON: until 2026-12-05 this tower fell (World::sizeRefinement()).
        QTest::newRow("tower20_2cm.rlscene") << "tower20_2cm.rlscene" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20_gaps.obj") << "tower20_gaps.obj" << 0.01 << 0.01 << 0.25;
        QTest::newRow("tower20_jitter.obj") << "tower20_jitter.obj" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower20_far.obj") << "tower20_far.obj" << 0.01 << 0.01 << 0.05;
        QTest::newRow("tower40.obj") << "tower40.obj" << 0.02 << -1.0 << 0.05;
        QTest::newRow("pyramid20.obj") << "pyramid20.obj" << 0.01 << -1.0 << 0.05;
        QTest::newRow("slab.obj") << "slab.obj" << 0.05 << -1.0 << 0.05;
        QTest::newRow("jenga30.obj") << "jenga30.obj" << 0.05 << -1.0 << 0.05;
        // 40 cards of 2 mm x 0.4 m built in Blender (stands: every card within 2 cm of where it was put), with card
        // stock's mu 0.7 from the JSON scene, and straight from the OBJ (the Default material's mu 0.5).
        QTest::newRow("card_house.rlscene (mu 0.7)") << "card_house.rlscene" << 0.02 << 0.01 << 0.02;
        QTest::newRow("card_house.obj (mu 0.5)") << "card_house.obj" << 0.02 << 0.01 << 0.02;
        // The same house with the cards leaning 20 degrees on mu 0.4 and 24 degrees on mu 0.5. The first fell
        // until 2026-12-07: the two cards of an apex met along one card's face normal, tilted by the lean, which
        // asked friction to hold the apex (turnWedgeNormal() in Collide.cpp).
        QTest::newRow("card_house_20deg_mu04.rlscene") << "card_house_20deg_mu04.rlscene" << 0.02 << 0.01 << 0.02;
        QTest::newRow("card_house_24deg_mu05.rlscene") << "card_house_24deg_mu05.rlscene" << 0.02 << 0.01 << 0.02;
    }
    void stacks() {
        QFETCH(QString, scene);
        QFETCH(double, maxDrift);
        QFETCH(double, maxSpeed);
        QFETCH(double, stand);
        BAKE_OR_FAIL(b, dataPath(scene));
        const int top = b.csv.topBody();
        const double drift = b.csv.horizontalDrift(top);
        const double speed = b.csv.maxSpeedLastSecond();
        const double moved = b.csv.maxDisplacement();
        qInfo("%s: top '%s' drift %.3f mm (< %.0f mm), max speed in the last second %.4f cm/s, largest "
              "displacement %.2f mm (stands: < %.0f mm)",
              qPrintable(scene), qPrintable(b.csv.names[top]), 1e3 * drift, 1e3 * maxDrift, 1e2 * speed, 1e3 * moved,
              1e3 * stand);
        QVERIFY(drift < maxDrift);
        if (maxSpeed > 0)
            QVERIFY(speed < maxSpeed);
        QVERIFY(moved < stand);
        if (scene.endsWith(".obj")) {
            int frame = 0;
            QString body;
            const double low = lowestVertexY(b.csv, dataPath(scene), &frame, &body);
            qInfo("%s: lowest vertex y %.3f mm ('%s', frame %d)", qPrintable(scene), 1e3 * low, qPrintable(body),
                  frame);
            QVERIFY(low > -0.01); // the floor's top is y = 0
        }
    }

    // 1 kg under 1,000 kg (Blender cubes with JSON masses, and JSON boxes), a 1:10:100:1000 ladder, 1,000 kg on two 1
    // kg boxes and 1 kg between two 1,000 kg: the order is kept and no contact is more than 1 cm deep at any frame.
    // half: the boxes' half height.
    void massRatio_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("half");
        QTest::newRow("mass_ratio.rlscene") << "mass_ratio.rlscene" << 0.25;
        QTest::newRow("mass_pair_boxes.rlscene") << "mass_pair_boxes.rlscene" << 0.5;
        QTest::newRow("mass_ladder.rlscene") << "mass_ladder.rlscene" << 0.25;
        QTest::newRow("mass_heavy_on_two_light.rlscene") << "mass_heavy_on_two_light.rlscene" << 0.5;
        QTest::newRow("mass_sandwich.rlscene") << "mass_sandwich.rlscene" << 0.5;
        // The world block of DESIGN.md section 6's example: substeps 4 (the defaults are 6 substeps x 2 iterations).
        QTest::newRow("mass_pair_design_world.rlscene (substeps 4)") << "mass_pair_design_world.rlscene" << 0.25;
    }
    void massRatio() {
        QFETCH(QString, scene);
        QFETCH(double, half);
        BAKE_OR_FAIL(b, dataPath(scene));
        std::vector<int> order; // bottom to top at frame 0
        for (int i = 0; i < b.csv.bodies; ++i)
            if (!b.csv.anchor[i])
                order.push_back(i);
        std::sort(order.begin(), order.end(), [&](int l, int r) { return b.csv.at(0, l)[Y] < b.csv.at(0, r)[Y]; });
        double deepest = 0.0, resting = 0.0, slide = 0.0;
        int deepestFrame = 0;
        for (int f = 0; f < b.csv.frames; ++f) {
            double pen = half - b.csv.at(f, order[0])[Y]; // floor top at y = 0
            for (size_t k = 1; k < order.size(); ++k) {
                const Row &lo = b.csv.at(f, order[k - 1]), &hi = b.csv.at(f, order[k]);
                pen = std::max(pen, 2.0 * half - (hi[Y] - lo[Y]));
                slide = std::max(slide, std::hypot(hi[X] - lo[X], hi[Z] - lo[Z]));
            }
            if (pen > deepest) {
                deepest = pen;
                deepestFrame = f;
            }
            if (f == b.csv.last())
                resting = pen;
        }
        bool ordered = true;
        for (size_t k = 1; k < order.size(); ++k)
            ordered = ordered && b.csv.at(b.csv.last(), order[k])[Y] > b.csv.at(b.csv.last(), order[k - 1])[Y] + half;
        qInfo("%s: order kept %s, deepest contact %.2f mm at frame %d, %.2f mm at rest (< 10 mm), largest sideways "
              "offset between neighbours %.2f mm",
              qPrintable(scene), ordered ? "yes" : "NO", 1e3 * deepest, deepestFrame, 1e3 * resting, 1e3 * slide);
        QVERIFY(ordered);
        QVERIFY(slide < 0.05);
        QVERIFY(deepest < 0.01);
    }

    // A 0.5 m block on a 30 degree ramp. mu 0.7 (Concrete on Concrete straight from the OBJ, and as a JSON
    // override): drift < 1 mm over 10 s. mu 0.3: distance at t = 1 s within 2 % of 1/2 g (sin - mu cos) t^2.
    void slope_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("mu");
        QTest::newRow("slope30.obj (Concrete, mu 0.7)") << "slope30.obj" << 0.7;
        QTest::newRow("slope30_mu07.rlscene") << "slope30_mu07.rlscene" << 0.7;
        QTest::newRow("slope30_mu03.rlscene") << "slope30_mu03.rlscene" << 0.3;
    }
    void slope() {
        QFETCH(QString, scene);
        QFETCH(double, mu);
        BAKE_OR_FAIL(b, dataPath(scene));
        const int block = b.csv.byName("Block");
        QVERIFY(block >= 0);
        auto distance = [&](int frame) {
            const Row &a = b.csv.at(0, block), &c = b.csv.at(frame, block);
            return std::sqrt((c[X] - a[X]) * (c[X] - a[X]) + (c[Y] - a[Y]) * (c[Y] - a[Y]) +
                             (c[Z] - a[Z]) * (c[Z] - a[Z]));
        };
        const double theta = 30.0 * M_PI / 180.0;
        const double accel = kG * (std::sin(theta) - mu * std::cos(theta));
        if (accel <= 0) {
            const double drift = distance(b.csv.last());
            qInfo("%s: mu %.1f, drift over 10 s %.4f mm (< 1 mm)", qPrintable(scene), mu, 1e3 * drift);
            QVERIFY(drift < 0.001);
        } else {
            const double d = distance(60), exact = 0.5 * accel;
            qInfo("%s: mu %.1f, slid %.5f m in 1 s, closed form %.5f m (%+.3f %%, within 2 %%)", qPrintable(scene), mu,
                  d, exact, 100.0 * (d - exact) / exact);
            QVERIFY(std::abs(d - exact) < 0.02 * exact);
        }
    }

    // Drop with e = 0.5 from h0 = 5 m: the first three apex heights (frame maxima of the centre, minus the half
    // height) within 3 % of e^(2n) h0. A Blender UV sphere (r 0.1) and a Blender 0.2 m cube falling face down; and in
    // plain JSON a sphere from 1 m and 1.25 m and a cube from 2 m, whose second or third apexes were 6-15 % high
    // until 2026-12-05 (ContactSolver::applyRestitution()).
    void drop_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("half");
        // Dropped straight, neither should pick up spin: a one-pass restitution left the cube at 15 rad/s and the
        // sphere (landing on its pole, with a ring of vertices 1.9 mm above it) at 28 rad/s. Measured now (2026-12-05):
        // 0.008 and 1.9 rad/s (the sphere once it rolls, after its bounces); the JSON sphere 0, the JSON cube 0.014.
        QTest::addColumn<double>("maxSpin");
        QTest::newRow("drop_e05.rlscene (UV sphere)") << "drop_e05.rlscene" << 0.1 << 2.0;
        QTest::newRow("drop_cube_e05.rlscene (cube)") << "drop_cube_e05.rlscene" << 0.1 << 0.5;
        QTest::newRow("drop_sphere_1m_e05.rlscene") << "drop_sphere_1m_e05.rlscene" << 0.1 << 0.5;
        QTest::newRow("drop_sphere_1.25m_e05.rlscene") << "drop_sphere_1.25m_e05.rlscene" << 0.1 << 0.5;
        QTest::newRow("drop_cube_2m_e05.rlscene") << "drop_cube_2m_e05.rlscene" << 0.1 << 0.5;
    }
    void drop() {
        QFETCH(QString, scene);
        QFETCH(double, half);
        QFETCH(double, maxSpin);
        BAKE_OR_FAIL(b, dataPath(scene));
        const int body = b.csv.topBody();
        const double h0 = b.csv.at(0, body)[Y] - half, e = 0.5;
        std::vector<double> apexes;
        for (int f = 2; f < b.csv.last(); ++f) {
            const double y = b.csv.at(f, body)[Y];
            if (b.csv.at(f - 1, body)[Y] < y && y >= b.csv.at(f + 1, body)[Y])
                apexes.push_back(y - half);
        }
        double spin = 0.0;
        for (int f = 0; f < b.csv.frames; ++f) {
            const Row& r = b.csv.at(f, body);
            spin = std::max(spin, std::sqrt(r[WX] * r[WX] + r[WY] * r[WY] + r[WZ] * r[WZ]));
        }
        QVERIFY2(apexes.size() >= 3, "fewer than three bounces");
        QString line;
        bool pass = true;
        for (int n = 1; n <= 3; ++n) {
            const double expected = std::pow(e, 2.0 * n) * h0, got = apexes[n - 1];
            const double rel = (got - expected) / expected;
            line += QString::asprintf(" apex %d %.5f m vs %.5f m (%+.2f %%)", n, got, expected, 100.0 * rel);
            pass = pass && std::abs(rel) < 0.03;
        }
        qInfo("%s: h0 %.3f m;%s (within 3 %%); largest spin %.3f rad/s", qPrintable(scene), h0, qPrintable(line), spin);
        QVERIFY2(pass, qPrintable(line));
        QVERIFY(spin < maxSpin);
    }

    // Projectiles in JSON scenes: a lob against the exact parabola until just before it lands, a 0.1 m steel cube
    // at 300 m/s into a 5 cm anchor wall (must not pass it), a 1,000 kg ball at 10 m/s into a 1 kg box.
    void projectileLob() {
        BAKE_OR_FAIL(b, dataPath("projectile_lob.rlscene"));
        const int shot = b.csv.byName("Shot");
        const Row& s0 = b.csv.at(0, shot);
        double worst = 0.0;
        for (int f = 0; f <= 96; ++f) { // lands at t = 1.75 s; 96 frames = 1.6 s
            const double t = f / 60.0;
            const Row& r = b.csv.at(f, shot);
            const double ex = s0[X] + s0[VX] * t, ey = s0[Y] + s0[VY] * t - 0.5 * kG * t * t;
            worst = std::max(worst, std::hypot(r[X] - ex, r[Y] - ey));
        }
        // First order in the step: an Euler step of one whole frame would be off by 1/2 g t dt = 0.131 m at 1.6 s.
        const double frameEuler = 0.5 * kG * 1.6 / 60.0;
        qInfo("projectile_lob: largest position error in 1.6 s of flight %.5f m (one-frame Euler bound %.4f m)", worst,
              frameEuler);
        QVERIFY(worst < frameEuler);
    }
    void projectileWall() {
        BAKE_OR_FAIL(b, dataPath("projectile_wall.rlscene"));
        const int bullet = b.csv.byName("Bullet");
        double furthest = -1e300;
        for (int f = 0; f < b.csv.frames; ++f)
            furthest = std::max(furthest, b.csv.at(f, bullet)[X]);
        const Row& after = b.csv.at(2, bullet);
        qInfo("projectile_wall: bullet centre got to x = %.5f m (wall face 4.975 m, centre at contact 4.925 m); "
              "vx two frames later %.3f m/s (Steel e 0.6 would give -180)",
              furthest, after[VX]);
        QVERIFY(furthest < 4.975); // its centre never reaches the wall's face
        QVERIFY(after[VX] <= 0.0);
    }
    // The heavy projectile at the default substeps and at others: until 2026-11-27 the box sank 1.0 mm at the default
    // 6 by luck, and 2.2-4.3 cm at 4, 5, 7, 8, 10 and 12, wedged into the floor by the ball, which it then threw up to
    // 1.1-1.4 m (see WorldTuning::holdMassRatio).
    void projectileHeavy_data() {
        QTest::addColumn<int>("substeps"); // 0: the scene's default
        for (int k : {0, 4, 5, 7, 8, 10, 12})
            QTest::newRow(k == 0 ? "default" : qPrintable(QString("%1 substeps").arg(k))) << k;
    }
    void projectileHeavy() {
        QFETCH(int, substeps);
        const QStringList extra = substeps > 0 ? QStringList{"--substeps", QString::number(substeps)} : QStringList{};
        BAKE_OR_FAIL(b, dataPath("projectile_heavy.rlscene"), extra);
        const int box = b.csv.byName("Box"), ball = b.csv.byName("Ball");
        double boxLow = 1e300, ballLow = 1e300, ballHigh = -1e300, boxFarthest = -1e300;
        for (int f = 0; f < b.csv.frames; ++f) {
            boxLow = std::min(boxLow, b.csv.at(f, box)[Y]);
            ballLow = std::min(ballLow, b.csv.at(f, ball)[Y]);
            ballHigh = std::max(ballHigh, b.csv.at(f, ball)[Y]);
            boxFarthest = std::max(boxFarthest, b.csv.at(f, box)[X]);
        }
        qInfo("projectile_heavy: lowest box centre %.4f m (half 0.1), ball centre from %.4f to %.4f m (radius 0.5; "
              "the box is 0.2 m tall), box pushed as far as x = %.3f m, at x = %.3f m at the end",
              boxLow, ballLow, ballHigh, boxFarthest, b.csv.at(b.csv.last(), box)[X]);
        // Nothing sinks more than 1 cm (issue 4's mass-ratio row).
        QVERIFY(boxLow > 0.1 - 0.01);
        QVERIFY(ballLow > 0.5 - 0.01);
        // The ball rolls over the box, not thrown off it: its centre rises by about what the box can lift it, no more.
        // The box tumbles ahead of the ball and may stand on an edge, 0.2 sqrt(2) m tall, when the ball meets it
        // again: since point contacts resist spin (2026-11-28, ContactSolver::kPatchRadius) the default run strikes it
        // twice and the ball's centre rises to 0.815 m on the second (0.70-0.72 m at the other substep counts). The
        // failure this guards against threw it to 1.1-1.4 m.
        QVERIFY(ballHigh < 0.5 + 0.2 * std::sqrt(2.0) + 0.05);
        // It was hit. (Where it ends is chaotic: squeezed out from under the ball, it may fly off backwards.)
        QVERIFY(boxFarthest > 3.2);
    }

    // Mixed shapes (cubes, a stack, UV spheres, cylinders, cones, an icosphere, a torus, Suzanne): no NaN, nothing
    // under the floor, everything at rest in the last second (< 1 cm/s, the 1,000-boxes criterion).
    void mixedShapes() {
        BAKE_OR_FAIL(b, dataPath("mixed_shapes.obj"));
        int frame = 0;
        QString body;
        const double low = lowestVertexY(b.csv, dataPath("mixed_shapes.obj"), &frame, &body);
        const double speed = b.csv.maxSpeedLastSecond();
        qInfo("mixed_shapes: lowest vertex y %.3f mm ('%s', frame %d), max speed in the last second %.4f cm/s, "
              "largest displacement %.1f mm",
              1e3 * low, qPrintable(body), frame, 1e2 * speed, 1e3 * b.csv.maxDisplacement());
        QVERIFY(low > -0.01);
        QVERIFY(speed < 0.01);
    }

    // 24 rods made with Blender (broomsticks, laths, pencils, knitting needles of 25:1 to 88:1, turned at random)
    // dropped onto a floor box: the total energy, the bodies' masses and inertias taken from `rigidlab-cli info --json`
    // and their motion from the CSV, never above its start (+1 %); none below the floor; all at rest in the last
    // second. Before 2026-12-07 the thin rods spun up and were thrown, at up to 444 km/s, the energy reached 2e9 times
    // its start and the CSV held a non-finite number (tst_motion's turningRodsGainNoEnergy has the causes).
    void droppedRods() {
        BAKE_OR_FAIL(b, dataPath("rods.obj"));
        const rl::test::CliRun info = rl::test::runCli({"info", dataPath("rods.obj"), "--json"});
        QCOMPARE(info.exitCode, 0);
        const QJsonArray bodies = QJsonDocument::fromJson(info.out).object().value("bodies").toArray();
        QCOMPARE(bodies.size(), b.csv.bodies);
        // E = sum of m v^2 / 2 + w' I0 w' / 2 + m g y, w' the angular velocity turned back to the start (the CSV's
        // quaternion is the turn since frame 0) and I0 the inertia at the start, world axes.
        const auto energyAt = [&](int frame) {
            double e = 0.0;
            for (int k = 0; k < b.csv.bodies; ++k) {
                if (b.csv.anchor[k])
                    continue;
                const QJsonObject body = bodies[k].toObject();
                const double m = body.value("mass").toDouble();
                const QJsonArray inertia = body.value("inertia").toArray();
                const Row& r = b.csv.at(frame, k);
                // w' = conjugate(q) w, as glm's q * v with q's vector part negated.
                const double qw = r[QW], ux = -r[QX], uy = -r[QY], uz = -r[QZ];
                const double w[3] = {r[WX], r[WY], r[WZ]};
                const double cx = uy * w[2] - uz * w[1], cy = uz * w[0] - ux * w[2], cz = ux * w[1] - uy * w[0];
                const double wb[3] = {w[0] + 2.0 * (qw * cx + (uy * cz - uz * cy)),
                                      w[1] + 2.0 * (qw * cy + (uz * cx - ux * cz)),
                                      w[2] + 2.0 * (qw * cz + (ux * cy - uy * cx))};
                double spin = 0.0;
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        spin += wb[i] * inertia[i].toArray()[j].toDouble() * wb[j];
                e += 0.5 * m * (r[VX] * r[VX] + r[VY] * r[VY] + r[VZ] * r[VZ]) + 0.5 * spin + m * kG * r[Y];
            }
            return e;
        };
        const double start = energyAt(0);
        double highest = start;
        int highestFrame = 0;
        for (int f = 1; f < b.csv.frames; ++f)
            if (const double e = energyAt(f); e > highest) {
                highest = e;
                highestFrame = f;
            }
        int frame = 0;
        QString body;
        const double low = lowestVertexY(b.csv, dataPath("rods.obj"), &frame, &body);
        const double speed = b.csv.maxSpeedLastSecond();
        qInfo("rods: energy at most %+.4f %% of its start %.2f J (frame %d); lowest vertex y %.3f mm ('%s', frame %d); "
              "max speed in the last second %.4f cm/s",
              100.0 * (highest - start) / start, start, highestFrame, 1e3 * low, qPrintable(body), frame, 1e2 * speed);
        QVERIFY(highest <= 1.01 * start);
        QVERIFY(low > -0.01);
        QVERIFY(speed < 0.01);
    }

    // 1,000 random boxes (0.3-0.8 m a side, turned at random, a 10 x 10 x 10 grid 1.6 m apart) dropped on a floor box:
    // none below the floor, and the largest speed in the last second < 1 cm/s. "Below" allows the contacts' 2 mm slop
    // and rounding: the lowest corner was 4.99 mm under until 2026-12-07, when boxes that landing ones had pushed into
    // the floor stayed there up to 5 mm (World::roundsBeyond()), and 2.00 mm since.
    void randomBoxes() {
        BAKE_OR_FAIL(b, dataPath("boxes1000.obj"));
        QCOMPARE(b.csv.bodies, 1001);
        int frame = 0;
        QString body;
        const double low = lowestVertexY(b.csv, dataPath("boxes1000.obj"), &frame, &body);
        const double speed = b.csv.maxSpeedLastSecond();
        qInfo("boxes1000: lowest vertex y %.3f mm ('%s', frame %d), max speed in the last second %.4f cm/s", 1e3 * low,
              qPrintable(body), frame, 1e2 * speed);
        QVERIFY(low > -0.0025);
        QVERIFY(speed < 0.01);
    }

    // Two identical 1 m boxes in the same place, no gravity: they part (centres more than a box apart) at no more than
    // 3 m/s, with no NaN.
    void coincidentBoxes() {
        BAKE_OR_FAIL(b, dataPath("coincident_boxes.rlscene"));
        double fastest = 0.0;
        for (const Row& r : b.csv.rows)
            fastest = std::max(fastest, std::sqrt(r[VX] * r[VX] + r[VY] * r[VY] + r[VZ] * r[VZ]));
        const Row &a = b.csv.at(b.csv.last(), 0), &c = b.csv.at(b.csv.last(), 1);
        const double apart =
            std::sqrt((a[X] - c[X]) * (a[X] - c[X]) + (a[Y] - c[Y]) * (a[Y] - c[Y]) + (a[Z] - c[Z]) * (a[Z] - c[Z]));
        qInfo("coincident_boxes: fastest %.3f m/s, centres %.3f m apart at 10 s", fastest, apart);
        QVERIFY(fastest <= 3.0 + 1e-6);
        QVERIFY(apart > 1.0);
    }

    // Torque-free T-handle, no gravity: spun about its intermediate axis it flips, with |L| within 0.1 % and the
    // energy within 1 % over 20 s; spun about a stable axis (largest or smallest moment) it stays within 5 degrees
    // of it for 60 s. Inertia from `rigidlab-cli info --json` (world axes at frame 0), carried by the CSV's
    // quaternion (rotation since frame 0); angular velocity from the CSV.
    void tumbling_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("axis");
        QTest::addColumn<bool>("flips");
        QTest::addColumn<QString>("seconds");
        QTest::newRow("t_handle_intermediate.rlscene") << "t_handle_intermediate.rlscene" << 1 << true << "20";
        QTest::newRow("t_handle_max.rlscene") << "t_handle_max.rlscene" << 2 << false << "60";
        QTest::newRow("t_handle_min.rlscene") << "t_handle_min.rlscene" << 0 << false << "60";
    }
    void tumbling() {
        QFETCH(QString, scene);
        QFETCH(int, axis);
        QFETCH(bool, flips);
        QFETCH(QString, seconds);
        const rl::test::CliRun info = rl::test::runCli({"info", dataPath(scene), "--json"});
        QCOMPARE(info.exitCode, 0);
        const QJsonArray rowsI = QJsonDocument::fromJson(info.out)
                                     .object()
                                     .value("bodies")
                                     .toArray()
                                     .at(0)
                                     .toObject()
                                     .value("inertia")
                                     .toArray();
        QCOMPARE(rowsI.size(), 3);
        double I0[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                I0[i][j] = rowsI.at(i).toArray().at(j).toDouble();
        const Bake b = bake(dataPath(scene), {}, true, seconds);
        QVERIFY2(b.run.exitCode == 0, qPrintable(b.command + "\n" + QString::fromUtf8(b.run.err)));
        QVERIFY2(b.csv.ok, qPrintable(b.csv.error));
        QCOMPARE(b.csv.frames, 60 * seconds.toInt() + 1);
        QVERIFY2(b.csv.allFinite(), "NaN or inf in the CSV");
        double L0 = 0, E0 = 0, worstL = 0, worstE = 0, minDot = 1, maxTilt = 0;
        for (int f = 0; f < b.csv.frames; ++f) {
            const Row& r = b.csv.at(f, 0);
            const double w = r[QW], x = r[QX], y = r[QY], z = r[QZ];
            const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                                    {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                                    {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
            const double om[3] = {r[WX], r[WY], r[WZ]};
            double RtW[3] = {0, 0, 0}, IRtW[3] = {0, 0, 0}, L[3] = {0, 0, 0};
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    RtW[i] += R[j][i] * om[j];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    IRtW[i] += I0[i][j] * RtW[j];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    L[i] += R[i][j] * IRtW[j];
            const double Lm = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
            const double E = 0.5 * (om[0] * L[0] + om[1] * L[1] + om[2] * L[2]);
            if (f == 0) {
                L0 = Lm;
                E0 = E;
            }
            worstL = std::max(worstL, std::abs(Lm - L0) / L0);
            worstE = std::max(worstE, std::abs(E - E0) / E0);
            // The body axis `axis` in the world (column of R) against its start.
            minDot = std::min(minDot, R[axis][axis]);
            maxTilt = std::max(
                maxTilt, std::acos(std::clamp(std::abs(R[0][axis] * L[0] + R[1][axis] * L[1] + R[2][axis] * L[2]) / Lm,
                                              -1.0, 1.0)) *
                             180.0 / M_PI);
        }
        qInfo("%s: %s s, |L| drift %.3g %% (< 0.1 %%), energy drift %.3g %% (< 1 %%), spin axis against its start: "
              "lowest cosine %.4f, largest angle to L %.3f deg",
              qPrintable(scene), qPrintable(seconds), 100 * worstL, 100 * worstE, minDot, maxTilt);
        QVERIFY(worstL < 0.001);
        QVERIFY(worstE < 0.01);
        if (flips)
            QVERIFY(minDot < -0.9); // turned over
        else
            QVERIFY(maxTilt < 5.0);
    }

    // Re-bakes hash identically, and so does a bake on 2 threads (CSV and .bake).
    void rebakeHashes_data() {
        QTest::addColumn<QString>("scene");
        for (const char* s : {"tower40.obj", "jenga30.obj", "mixed_shapes.obj", "drop_cube_e05.rlscene",
                              "card_house.rlscene", "boxes1000.obj"})
            QTest::newRow(s) << QString::fromLatin1(s);
    }
    void rebakeHashes() {
        QFETCH(QString, scene);
        const Bake a = bake(dataPath(scene), {}, false);
        const Bake b = bake(dataPath(scene), {}, false);
        const Bake c = bake(dataPath(scene), {"--threads", "2"}, false);
        QCOMPARE(a.run.exitCode, 0);
        QVERIFY(!a.csvHash.isEmpty() && !a.bakeHash.isEmpty());
        qInfo("%s: csv sha256 %s / %s / %s (threads 2)", qPrintable(scene), a.csvHash.left(16).constData(),
              b.csvHash.left(16).constData(), c.csvHash.left(16).constData());
        QCOMPARE(b.csvHash, a.csvHash);
        QCOMPARE(b.bakeHash, a.bakeHash);
        QCOMPARE(c.csvHash, a.csvHash);
        QCOMPARE(c.bakeHash, a.bakeHash);
    }

    // A floor renamed "Anchor" in Blender (mesh still "Plane") is exported by the 3.4 legacy OBJ exporter as
    // "o Anchor_Plane", which the anchor rule (DESIGN.md §3, the original project's) makes dynamic, and a dynamic
    // plane has no volume: the import fails, exit 1, with a message that names the file and the object and says
    // how to make it an anchor.
    void blenderRenamedFloor() {
        const rl::test::CliRun r = rl::test::runCli({"info", dataPath("tower20_legacy_names.obj")});
        qInfo("tower20_legacy_names.obj: exit %d, %s", r.exitCode, r.err.trimmed().constData());
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("tower20_legacy_names.obj"));
        QVERIFY(r.err.contains("Anchor_Plane"));
        QVERIFY(r.err.contains("legacy OBJ exporter"));
        QVERIFY(r.err.contains("give the mesh the object's name"));
    }

    // `rigidlab-cli accuracy --csv`: refit the oscillator's convergence orders from the CSV. Expected 1, 1, 2, 4
    // within 0.15. Rows flagged in an `in_fit` column are used when the CSV has one, else every row.
    void accuracyOrders() {
        QTemporaryDir dir;
        const QString path = dir.filePath("accuracy.csv");
        const rl::test::CliRun r = rl::test::runCli({"accuracy", "--csv", path});
        QCOMPARE(r.exitCode, 0);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList header = QString::fromUtf8(f.readLine()).trimmed().split(',');
        const qsizetype cProblem = header.indexOf("problem"), cIntegrator = header.indexOf("integrator"),
                        cSteps = header.indexOf("steps"), cStep = header.indexOf("step"),
                        cError = header.indexOf("error"), cInFit = header.indexOf("in_fit");
        QVERIFY(cProblem >= 0 && cIntegrator >= 0 && cSteps >= 0 && cStep >= 0 && cError >= 0);
        std::map<QString, std::vector<std::pair<double, double>>> fit, original;
        while (!f.atEnd()) {
            const QStringList c = QString::fromUtf8(f.readLine()).trimmed().split(',');
            if (c.size() != header.size() || c[cProblem] != QLatin1String("oscillator"))
                continue;
            const std::pair<double, double> point{c[cStep].toDouble(), c[cError].toDouble()};
            if (cInFit < 0 || c[cInFit] == QLatin1String("1"))
                fit[c[cIntegrator]].push_back(point);
            const int steps = c[cSteps].toInt();
            if (steps == 10 || steps == 20 || steps == 40)
                original[c[cIntegrator]].push_back(point);
        }
        const std::map<QString, double> expected{
            {"explicit-euler", 1.0}, {"symplectic-euler", 1.0}, {"verlet", 2.0}, {"rk4", 4.0}};
        for (const auto& [integrator, order] : expected) {
            QVERIFY2(fit[integrator].size() >= 3, qPrintable(integrator));
            const double p = fitOrder(fit[integrator]);
            const double p3 = original[integrator].size() == 3 ? fitOrder(original[integrator]) : std::nan("");
            qInfo("accuracy: %s order %.3f from %zu rows (expected %.0f +- 0.15); from 10/20/40 steps only %.3f",
                  qPrintable(integrator), p, fit[integrator].size(), order, p3);
            QVERIFY(std::abs(p - order) < 0.15);
        }
    }
};

QTEST_GUILESS_MAIN(TestAcceptance)
#include "tst_acceptance.moc"
