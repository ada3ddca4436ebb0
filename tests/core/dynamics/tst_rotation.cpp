// Torque-free rotation: the T-handle (Dzhanibekov) flip about the intermediate axis, stability about the other two,
// conservation of |L| and energy per integrator, and the body state's principal-frame bookkeeping.
#include "dynamics/BodyState.h"
#include "dynamics/Gyroscopic.h"
#include "dynamics/Integrator.h"
#include "geometry/ConvexHull.h"
#include "geometry/MassProperties.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace rl;

Q_DECLARE_METATYPE(rl::Integrator)
Q_DECLARE_METATYPE(rl::Vec3)

namespace {

// A steel T-handle made of two boxes: a stem along y and a crossbar along x on top of it. The inertia is built by hand
// with the parallel axis theorem, which is exactly what the hull's divergence-theorem integral must agree with.
struct BoxPart {
    Vec3 halfExtents;
    Vec3 center;
};

constexpr Real kSteel = 7850.0; // kg/m^3
constexpr Real kFrameDt = 1.0 / 60.0;
constexpr int kSubsteps = 4; // the default, WorldSettings::substeps
constexpr Real kDt = kFrameDt / kSubsteps;

struct RigidData {
    Real mass = 0.0;
    Vec3 com{0.0};
    Mat3 inertia{0.0}; // about com
};

RigidData tHandle() {
    const BoxPart parts[] = {{{0.01, 0.05, 0.01}, {0.0, 0.0, 0.0}}, {{0.04, 0.01, 0.01}, {0.0, 0.06, 0.0}}};
    RigidData out;
    for (const BoxPart& p : parts) {
        const Vec3 size = 2.0 * p.halfExtents;
        out.mass += kSteel * size.x * size.y * size.z;
    }
    for (const BoxPart& p : parts) {
        const Vec3 size = 2.0 * p.halfExtents;
        out.com += (kSteel * size.x * size.y * size.z / out.mass) * p.center;
    }
    for (const BoxPart& p : parts) {
        const Vec3 size = 2.0 * p.halfExtents;
        const Real m = kSteel * size.x * size.y * size.z;
        const Vec3 s2 = size * size;
        Mat3 own(0.0);
        own[0][0] = m / 12.0 * (s2.y + s2.z);
        own[1][1] = m / 12.0 * (s2.x + s2.z);
        own[2][2] = m / 12.0 * (s2.x + s2.y);
        const Vec3 d = p.center - out.com;
        // Parallel axis: I + m (|d|^2 E - d d^T)
        const Mat3 shift = m * (glm::dot(d, d) * Mat3(1.0) - glm::outerProduct(d, d));
        out.inertia += own + shift;
    }
    return out;
}

struct RunStats {
    int flips = 0;
    Real maxMomentumDrift = 0.0; // max | |L| - |L0| | / |L0|
    Real maxEnergyDrift = 0.0;   // max | E - E0 | / E0
    Real finalEnergyRatio = 1.0; // E_end / E0
    Real maxAxisAngle = 0.0;     // largest angle (rad) between the spin axis and its initial world direction
};

// Spins the T-handle about shape axis `axis` (0 x, 1 y, 2 z) at `spin` rad/s with a small perturbation about the
// other two, and integrates the free motion for `seconds`.
RunStats spinTHandle(Integrator integrator, int axis, Real spin, Real seconds) {
    const RigidData body = tHandle();
    Vec3 omega(0.01); // rad/s about the other axes: the perturbation that lets the instability show
    omega[axis] = spin;
    BodyState state;
    BodyInit init;
    init.centerOfMass = body.com;
    init.comInShape = body.com;
    init.mass = body.mass;
    init.inertia = body.inertia;
    init.angularVelocity = omega;
    const auto added = state.addBody(init);
    if (!added.ok())
        qFatal("T-handle rejected: %s", added.error().toString().c_str());

    Vec3 shapeAxis(0.0);
    shapeAxis[axis] = 1.0;
    const Vec3 startDirection = state.shapeOrientation(0) * shapeAxis;
    const Real l0 = glm::length(state.angularMomentum(0));
    const Real e0 = state.kineticEnergy(0);
    RunStats stats;
    int side = 1; // which way the axis points along its start direction, with hysteresis so jitter is not a flip
    const int steps = static_cast<int>(std::lround(seconds / kDt));
    for (int k = 0; k < steps; ++k) {
        integrateSmooth(state, allBodies(state), kDt, Vec3(0.0), Damping{}, integrator, true);
        const Vec3 direction = state.shapeOrientation(0) * shapeAxis;
        const Real along = glm::dot(direction, startDirection);
        if (side > 0 && along < -0.5) {
            side = -1;
            ++stats.flips;
        } else if (side < 0 && along > 0.5) {
            side = 1;
            ++stats.flips;
        }
        stats.maxAxisAngle = std::max(stats.maxAxisAngle, std::acos(std::clamp(along, -1.0, 1.0)));
        const Real l = glm::length(state.angularMomentum(0));
        const Real e = state.kineticEnergy(0);
        stats.maxMomentumDrift = std::max(stats.maxMomentumDrift, std::abs(l - l0) / l0);
        stats.maxEnergyDrift = std::max(stats.maxEnergyDrift, std::abs(e - e0) / e0);
        stats.finalEnergyRatio = e / e0;
    }
    return stats;
}

// Shape axes sorted by principal moment: the T-handle's inertia is diagonal in its shape axes (two mirror planes).
int axisWithRank(int rank) {
    const Mat3 inertia = tHandle().inertia;
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int a, int b) { return inertia[a][a] < inertia[b][b]; });
    return order[rank];
}

constexpr Real kSpin = 6.0; // rad/s, about one turn a second: a hand-spun handle

} // namespace

class TestRotation : public QObject {
    Q_OBJECT

private slots:
    void tHandleInertiaMatchesGeometry();
    void bodyFromHull();
    void principalFrameRoundTrip();
    void worldInverseInertiaInAnyPose_data();
    void worldInverseInertiaInAnyPose();
    void rejectsImpossibleInertia_data();
    void rejectsImpossibleInertia();
    void intermediateAxisFlips_data();
    void intermediateAxisFlips();
    void explicitEulerGainsEnergy();
    void stableAxesStayStable_data();
    void stableAxesStayStable();
    void implicitGyroscopicIsStableAtLargeSteps();
    void gyroscopicStepInvariants_data();
    void gyroscopicStepInvariants();
    void newtonStepMatchesTheFullJacobian_data();
    void newtonStepMatchesTheFullJacobian();
    void midpointSolvesItsEquation_data();
    void midpointSolvesItsEquation();
    void gatheredBodiesIntegrateAsInPlace_data();
    void gatheredBodiesIntegrateAsInPlace();
    void listedSymplecticBodiesIntegrateAsRanges_data();
    void listedSymplecticBodiesIntegrateAsRanges();
    void anchorTurnLeavesOutTheRoundPart();
    void symplecticPositionsForSolverAreTheStepsNumbers_data();
    void symplecticPositionsForSolverAreTheStepsNumbers();
    void symplecticVelocitiesForSolverAreTheStepsNumbers_data() {
        symplecticPositionsForSolverAreTheStepsNumbers_data();
    }
    void symplecticVelocitiesForSolverAreTheStepsNumbers();
};

std::vector<Vec3> boxCorners(const Vec3& halfExtents, const Vec3& center) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.push_back(center + Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1) * halfExtents);
    return corners;
}

void TestRotation::tHandleInertiaMatchesGeometry() {
    // The hand-built tensor must agree with the geometry module's divergence-theorem integrals of the two boxes,
    // combined with its parallel-axis shift.
    const RigidData hand = tHandle();
    const std::pair<Vec3, Vec3> parts[] = {{{0.01, 0.05, 0.01}, {0.0, 0.0, 0.0}},
                                           {{0.04, 0.01, 0.01}, {0.0, 0.06, 0.0}}};
    Mat3 total(0.0);
    Real mass = 0.0;
    for (const auto& [halfExtents, center] : parts) {
        const std::vector<Vec3> corners = boxCorners(halfExtents, center);
        const MassProperties box = hullMassProperties(computeConvexHull(corners));
        const Real m = kSteel * box.volume;
        mass += m;
        total += shiftInertia(kSteel * box.inertia, m, hand.com - box.centroid);
    }
    QVERIFY(std::abs(mass - hand.mass) < 1e-12 * hand.mass);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            QVERIFY2(std::abs(total[c][r] - hand.inertia[c][r]) < 1e-9 * hand.inertia[0][0],
                     qPrintable(QString("%1 vs %2").arg(total[c][r]).arg(hand.inertia[c][r])));
}

void TestRotation::bodyFromHull() {
    // A rotated, displaced box hull: mass, centre of mass and world inertia must be the box's closed forms.
    const Vec3 half(0.3, 0.1, 0.2), offset(0.5, -0.2, 0.1);
    const Quat q = glm::normalize(Quat(0.8, 0.1, 0.5, -0.3));
    const Vec3 where(1.0, 2.0, -3.0);
    const auto init = bodyInitFromHull(computeConvexHull(boxCorners(half, offset)), 700.0, where, q);
    QVERIFY(init.ok());
    const Real mass = 700.0 * 8.0 * half.x * half.y * half.z;
    QVERIFY(std::abs(init->mass - mass) < 1e-12 * mass);
    QVERIFY(glm::length(init->centerOfMass - (where + q * offset)) < 1e-12);
    Mat3 boxInertia(0.0);
    boxInertia[0][0] = mass / 3.0 * (half.y * half.y + half.z * half.z);
    boxInertia[1][1] = mass / 3.0 * (half.x * half.x + half.z * half.z);
    boxInertia[2][2] = mass / 3.0 * (half.x * half.x + half.y * half.y);
    const Mat3 r = glm::mat3_cast(q);
    const Mat3 expected = r * boxInertia * glm::transpose(r);
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            QVERIFY(std::abs(init->inertia[c][k] - expected[c][k]) < 1e-12 * boxInertia[0][0]);
    BodyState state;
    QVERIFY(state.addBody(*init).ok());
    QVERIFY(std::abs(std::abs(glm::dot(state.shapeOrientation(0), q)) - 1.0) < 1e-12);
    QVERIFY(glm::length(state.shapeOrigin(0) - where) < 1e-12);
    // Bad input is an Error, not a crash: a flat hull, a bad density.
    const std::vector<Vec3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}};
    QVERIFY(!bodyInitFromHull(computeConvexHull(flat), 700.0, where, q).ok());
    QVERIFY(!bodyInitFromHull(computeConvexHull(boxCorners(half, offset)), -1.0, where, q).ok());
    QVERIFY(!bodyInitFromHull(computeConvexHull(boxCorners(half, offset)), std::nan(""), where, q).ok());
}

void TestRotation::principalFrameRoundTrip() {
    // A rotated, non-diagonal tensor: addBody must diagonalise it, keep the user's orientation, and give back the
    // same world tensor, energy and momentum.
    const RigidData body = tHandle();
    const Quat userOrientation = glm::normalize(Quat(0.9, 0.2, -0.3, 0.25));
    const Mat3 r = glm::mat3_cast(userOrientation);
    BodyInit init;
    init.centerOfMass = Vec3(1.0, 2.0, 3.0);
    init.orientation = userOrientation;
    init.comInShape = body.com;
    init.mass = body.mass;
    init.inertia = r * body.inertia * glm::transpose(r);
    init.angularVelocity = Vec3(0.3, -2.0, 1.1);
    init.linearVelocity = Vec3(1.0, 0.0, -2.0);
    BodyState state;
    QVERIFY(state.addBody(init).ok());

    const Mat3 world = state.worldInertia(0);
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            QVERIFY(std::abs(world[c][k] - init.inertia[c][k]) < 1e-12 * body.inertia[0][0]);
    const Mat3 product = state.worldInverseInertia(0) * world;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            QVERIFY(std::abs(product[c][k] - (c == k ? 1.0 : 0.0)) < 1e-9);
    const Quat back = state.shapeOrientation(0);
    QVERIFY(std::abs(std::abs(glm::dot(back, userOrientation)) - 1.0) < 1e-12);
    QVERIFY(glm::length(state.shapeOrigin(0) - (init.centerOfMass - userOrientation * body.com)) < 1e-12);
    const Vec3 expectedL = init.inertia * init.angularVelocity;
    QVERIFY(glm::length(state.angularMomentum(0) - expectedL) < 1e-12 * glm::length(expectedL));
    const Real expectedE = 0.5 * body.mass * glm::dot(init.linearVelocity, init.linearVelocity) +
                           0.5 * glm::dot(init.angularVelocity, init.inertia * init.angularVelocity);
    QVERIFY(std::abs(state.kineticEnergy(0) - expectedE) < 1e-12 * expectedE);
}

// The world inverse inertia, taken by the solver for every body on every substep (BodyState::worldInverseInertia()):
// R D R^T in any pose, symmetric to the bit; for three moments equal to 1e-12 exactly d times the identity.
void TestRotation::worldInverseInertiaInAnyPose_data() {
    QTest::addColumn<Vec3>("moments");
    QTest::addColumn<bool>("isotropic");
    QTest::newRow("cube") << Vec3(0.25, 0.25, 0.25) << true;
    QTest::newRow("cube, moments 1e-15 apart") << Vec3(18.75, 18.75 * (1.0 + 1e-15), 18.75 * (1.0 - 2e-15)) << true;
    QTest::newRow("moments 1e-9 apart") << Vec3(2.0, 2.0 * (1.0 + 1e-9), 2.0) << false;
    QTest::newRow("T-handle") << Vec3(1.7e-5, 2.9e-5, 4.4e-5) << false;
    QTest::newRow("plank") << Vec3(1.0, 100.0, 100.5) << false;
}

void TestRotation::worldInverseInertiaInAnyPose() {
    QFETCH(Vec3, moments);
    QFETCH(bool, isotropic);
    uint32_t seed = 12345;
    const auto uniform = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<Real>(seed >> 8) / static_cast<Real>(1u << 24) * 2.0 - 1.0;
    };
    Real worst = 0.0;
    for (int pose = 0; pose < 50; ++pose) {
        const Quat q = glm::normalize(Quat(uniform(), uniform(), uniform(), uniform()));
        const Mat3 r = glm::mat3_cast(q);
        BodyInit init;
        init.orientation = q;
        init.mass = 1.0;
        Mat3 d(0.0);
        for (int k = 0; k < 3; ++k)
            d[k][k] = moments[k];
        init.inertia = r * d * glm::transpose(r);
        BodyState state;
        QVERIFY(state.addBody(init).ok());
        const Mat3 m = state.worldInverseInertia(0);
        const Mat3 expected = glm::inverse(init.inertia);
        const Real scale = 1.0 / std::min({moments.x, moments.y, moments.z});
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) {
                QCOMPARE(std::memcmp(&m[c][k], &m[k][c], sizeof(Real)), 0); // symmetric to the bit
                worst = std::max(worst, std::abs(m[c][k] - expected[c][k]) / scale);
                if (isotropic && c != k)
                    QCOMPARE(m[c][k], 0.0);
            }
        if (isotropic)
            QVERIFY(m[0][0] == m[1][1] && m[1][1] == m[2][2]);
    }
    qInfo("largest error against the inverse of the world tensor: %.3g of the largest inverse moment", worst);
    QVERIFY(worst < 1e-12);
}

void TestRotation::rejectsImpossibleInertia_data() {
    QTest::addColumn<Real>("mass");
    QTest::addColumn<Vec3>("moments");
    QTest::newRow("zero mass") << 0.0 << Vec3(1.0, 1.0, 1.0);
    QTest::newRow("negative mass") << -1.0 << Vec3(1.0, 1.0, 1.0);
    QTest::newRow("nan mass") << std::nan("") << Vec3(1.0, 1.0, 1.0);
    QTest::newRow("zero moment") << 1.0 << Vec3(0.0, 1.0, 1.0);
    QTest::newRow("negative moment") << 1.0 << Vec3(-1.0, 1.0, 1.0);
    QTest::newRow("triangle inequality") << 1.0 << Vec3(1.0, 1.0, 3.0);
    QTest::newRow("infinite moment") << 1.0 << Vec3(1.0, INFINITY, 1.0);
}

void TestRotation::rejectsImpossibleInertia() {
    QFETCH(Real, mass);
    QFETCH(Vec3, moments);
    BodyInit init;
    init.mass = mass;
    init.inertia = Mat3(0.0);
    for (int i = 0; i < 3; ++i)
        init.inertia[i][i] = moments[i];
    BodyState state;
    const auto result = state.addBody(init);
    QVERIFY(!result.ok());
    QVERIFY(!result.error().message.empty());
    QCOMPARE(state.size(), 0u);
}

void TestRotation::intermediateAxisFlips_data() {
    QTest::addColumn<Integrator>("integrator");
    QTest::newRow("symplectic-euler") << Integrator::SymplecticEuler;
    QTest::newRow("verlet") << Integrator::Verlet;
    QTest::newRow("rk4") << Integrator::Rk4;
}

void TestRotation::intermediateAxisFlips() {
    QFETCH(Integrator, integrator);
    const RunStats stats = spinTHandle(integrator, axisWithRank(1), kSpin, 20.0);
    qInfo("%s: %d flips in 20 s, max |L| drift %.3e, max energy drift %.3e", integratorName(integrator).data(),
          stats.flips, stats.maxMomentumDrift, stats.maxEnergyDrift);
    QVERIFY2(stats.flips >= 2, "the intermediate axis must flip");
    QVERIFY(stats.maxMomentumDrift < 1e-3);
    QVERIFY(stats.maxEnergyDrift < 1e-2);
}

void TestRotation::explicitEulerGainsEnergy() {
    // Documented behaviour (Gyroscopic.h): explicit Euler adds dt^2 |w x L|^2 to |L|^2 every step, so the tumbling
    // handle gains energy. The original project used it; this pins down why we do not by default.
    const RunStats stats = spinTHandle(Integrator::ExplicitEuler, axisWithRank(1), kSpin, 20.0);
    qInfo("explicit-euler: %d flips in 20 s, max |L| drift %.3e, final energy ratio %.4f", stats.flips,
          stats.maxMomentumDrift, stats.finalEnergyRatio);
    QVERIFY(stats.finalEnergyRatio > 1.01);
}

void TestRotation::stableAxesStayStable_data() {
    QTest::addColumn<Integrator>("integrator");
    QTest::addColumn<int>("rank");
    for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4}) {
        const std::string name(integratorName(integrator));
        QTest::newRow((name + " minor axis").c_str()) << integrator << 0;
        QTest::newRow((name + " major axis").c_str()) << integrator << 2;
    }
}

void TestRotation::stableAxesStayStable() {
    QFETCH(Integrator, integrator);
    QFETCH(int, rank);
    const RunStats stats = spinTHandle(integrator, axisWithRank(rank), kSpin, 60.0);
    qInfo("%s rank %d: max axis angle %.3f deg over 60 s, |L| drift %.3e, energy drift %.3e",
          integratorName(integrator).data(), rank, stats.maxAxisAngle * 180.0 / kPi, stats.maxMomentumDrift,
          stats.maxEnergyDrift);
    QCOMPARE(stats.flips, 0);
    QVERIFY(stats.maxAxisAngle < 5.0 * kPi / 180.0);
}

void TestRotation::implicitGyroscopicIsStableAtLargeSteps() {
    // At a step where w dt is far beyond what explicit Euler survives, the implicit step must still lose, not gain.
    const Vec3 inertia(1.0, 2.0, 3.0);
    Vec3 w(0.1, 10.0, 0.1);
    const Real e0 = 0.5 * glm::dot(w, inertia * w);
    for (int k = 0; k < 1000; ++k)
        w = gyroscopicImplicit(w, inertia, 0.1);
    const Real e = 0.5 * glm::dot(w, inertia * w);
    QVERIFY(std::isfinite(e));
    QVERIFY(e <= e0 * (1.0 + 1e-12));
    // Implicit midpoint at the largest step the clamp allows (|w| dt = pi/4): its Newton iteration must still converge,
    // which shows as |L| and energy kept to rounding.
    Vec3 m(0.1, 10.0, 0.1);
    const Real dt = 0.25 * kPi / glm::length(m);
    const Real l0 = glm::length(inertia * m);
    for (int k = 0; k < 1000; ++k)
        m = gyroscopicMidpoint(m, inertia, dt);
    QVERIFY(std::abs(glm::length(inertia * m) / l0 - 1.0) < 1e-12);
    QVERIFY(std::abs(0.5 * glm::dot(m, inertia * m) / e0 - 1.0) < 1e-12);
}

enum class GyroStep { Explicit, CattoImplicit, Midpoint };
Q_DECLARE_METATYPE(GyroStep)

void TestRotation::gyroscopicStepInvariants_data() {
    // The body-frame steps alone, on the T-handle's moments, 20 s at the default substep: what each does to |L| and E.
    QTest::addColumn<GyroStep>("step");
    QTest::newRow("explicit") << GyroStep::Explicit;
    QTest::newRow("catto implicit") << GyroStep::CattoImplicit;
    QTest::newRow("implicit midpoint") << GyroStep::Midpoint;
}

void TestRotation::gyroscopicStepInvariants() {
    QFETCH(GyroStep, step);
    const Mat3 tensor = tHandle().inertia;
    const Vec3 inertia(tensor[0][0], tensor[1][1], tensor[2][2]);
    Vec3 w(0.01);
    w[axisWithRank(1)] = kSpin;
    auto momentum = [&](const Vec3& x) { return glm::length(inertia * x); };
    auto energy = [&](const Vec3& x) { return 0.5 * glm::dot(x, inertia * x); };
    const Real l0 = momentum(w), e0 = energy(w);
    bool monotone = true;
    Real previous = e0;
    for (int k = 0; k < static_cast<int>(20.0 / kDt); ++k) {
        switch (step) {
        case GyroStep::Explicit:
            w = gyroscopicExplicit(w, inertia, kDt);
            break;
        case GyroStep::CattoImplicit:
            w = gyroscopicImplicit(w, inertia, kDt);
            break;
        case GyroStep::Midpoint:
            w = gyroscopicMidpoint(w, inertia, kDt);
            break;
        }
        const Real e = energy(w);
        if (step == GyroStep::Explicit ? e < previous : e > previous * (1.0 + 1e-15))
            monotone = false;
        previous = e;
    }
    const Real dl = momentum(w) / l0 - 1.0, de = energy(w) / e0 - 1.0;
    qInfo("|L| change %+.3e, energy change %+.3e after 20 s", dl, de);
    switch (step) {
    case GyroStep::Explicit: // gains every step, by dt^2 |w x L|^2 in |L|^2
        QVERIFY(monotone);
        QVERIFY(dl > 1e-2 && de > 1e-2);
        break;
    case GyroStep::CattoImplicit: // loses every step: stable, but too dissipative to be the default (Gyroscopic.h)
        QVERIFY(monotone);
        QVERIFY(dl < -1e-2 && de < -1e-2);
        break;
    case GyroStep::Midpoint: // keeps both up to the Newton tolerance
        QVERIFY(std::abs(dl) < 1e-10 && std::abs(de) < 1e-10);
        break;
    }
}

// Spins and principal moments for the two tests below: a nearly isotropic body, a T-handle-like one, a thin rod, a
// flat plate and a tumbling brick, each at the default substep (1/360 s) and at the largest substep the clamp allows
// (|w| dt = pi/4).
static void addGyroRows() {
    QTest::addColumn<Vec3>("omega");
    QTest::addColumn<Vec3>("inertia");
    QTest::addColumn<Real>("dt");
    const struct {
        const char* name;
        Vec3 omega, inertia;
    } bodies[] = {
        {"near cube", Vec3(0.3, -2.0, 1.1), Vec3(1.0, 1.001, 0.999)},
        {"t-handle", Vec3(0.01, 6.0, -0.02), Vec3(0.0042, 0.0013, 0.0051)},
        {"rod", Vec3(4.0, -0.5, 9.0), Vec3(0.01, 1.0, 1.0)},
        {"plate", Vec3(-7.0, 2.0, 0.4), Vec3(1.0, 1.0, 2.0)},
        {"tumbling brick", Vec3(12.0, -15.0, 20.0), Vec3(0.2, 0.5, 0.6)},
    };
    for (const auto& b : bodies) {
        QTest::addRow("%s, 1/360 s", b.name) << b.omega << b.inertia << Real(1.0 / 360.0);
        QTest::addRow("%s, clamp", b.name) << b.omega << b.inertia << Real(0.25 * kPi / glm::length(b.omega));
    }
}

void TestRotation::newtonStepMatchesTheFullJacobian_data() {
    addGyroRows();
}

void TestRotation::newtonStepMatchesTheFullJacobian() {
    // gyroscopicImplicit() is one Newton step on f(w) = I (w - w0) + h w x (I w) from w0, with its Jacobian written out
    // entry by entry. Here the textbook form: J = I + h (skew(w) I - skew(I w)) as matrices, inverted by glm.
    QFETCH(Vec3, omega);
    QFETCH(Vec3, inertia);
    QFETCH(Real, dt);
    const auto skew = [](const Vec3& v) {
        return Mat3(Vec3(0.0, v.z, -v.y), Vec3(-v.z, 0.0, v.x), Vec3(v.y, -v.x, 0.0));
    };
    Mat3 diagonal(0.0);
    for (int k = 0; k < 3; ++k)
        diagonal[k][k] = inertia[k];
    const Vec3 momentum = inertia * omega;
    const Vec3 residual = dt * glm::cross(omega, momentum); // f(w0)
    const Mat3 jacobian = diagonal + dt * (skew(omega) * diagonal - skew(momentum));
    const Vec3 expected = omega - glm::inverse(jacobian) * residual;
    const Vec3 got = gyroscopicImplicit(omega, inertia, dt);
    QVERIFY2(glm::length(got - expected) <= 1e-13 * glm::length(omega),
             qPrintable(QString("off by %1 of |w|").arg(glm::length(got - expected) / glm::length(omega))));
}

void TestRotation::midpointSolvesItsEquation_data() {
    addGyroRows();
}

void TestRotation::midpointSolvesItsEquation() {
    // The midpoint step stops its Newton iteration once the next update is predicted below 1e-15 of |w|: the result
    // must satisfy I (w1 - w0) = -dt wm x (I wm), wm = (w0 + w1) / 2, to that tolerance, even at the clamp's step and
    // for a thin rod's moments. The residuals come out at 2e-17 to 2e-16 of |I| |w|. (With one Jacobian entry of the
    // wrong sign, Newton converges only linearly and the prediction stops it early: the plate's and the tumbling
    // brick's 'clamp' rows then fail, at 7e-13 and 4e-10.)
    QFETCH(Vec3, omega);
    QFETCH(Vec3, inertia);
    QFETCH(Real, dt);
    const Vec3 next = gyroscopicMidpoint(omega, inertia, dt);
    const Vec3 mid = 0.5 * (omega + next);
    const Vec3 residual = inertia * (next - omega) + dt * glm::cross(mid, inertia * mid);
    const Real scale = std::max({inertia.x, inertia.y, inertia.z}) * glm::length(omega);
    QVERIFY2(glm::length(residual) <= 1e-13 * scale,
             qPrintable(QString("residual %1 of |I| |w|").arg(glm::length(residual) / scale)));
}

// Body b of a set shaped like the T-handle, each placed, moving and spinning its own way, and damped more the higher b.
BodyInit movingHandle(const RigidData& handle, int b) {
    BodyInit init;
    init.centerOfMass = Vec3(0.3 * b, 1.0 + b, -0.2 * b);
    init.orientation = glm::normalize(Quat(1.0, 0.1 * b, -0.2, 0.05 * b));
    init.mass = handle.mass;
    init.inertia = handle.inertia;
    init.linearVelocity = Vec3(0.5 * b, -1.0, 0.25);
    init.angularVelocity = Vec3(kSpin, 0.3 * b, -0.1);
    init.linearDamping = 0.1 * b;
    init.angularDamping = 0.05 * b;
    return init;
}

void TestRotation::gatheredBodiesIntegrateAsInPlace_data() {
    QTest::addColumn<Integrator>("integrator");
    QTest::newRow("explicit-euler") << Integrator::ExplicitEuler;
    QTest::newRow("symplectic-euler") << Integrator::SymplecticEuler;
    QTest::newRow("verlet") << Integrator::Verlet;
    QTest::newRow("rk4") << Integrator::Rk4;
}

void TestRotation::gatheredBodiesIntegrateAsInPlace() {
    // The world's substeps integrate a gathered copy of a group's bodies (BodyState::gather()) and write the motion
    // back (scatterMotion()). That must give the same bits as integrating the bodies where they are, and leave the
    // bodies outside the group alone.
    QFETCH(Integrator, integrator);
    const RigidData handle = tHandle();
    BodyState state;
    for (int b = 0; b < 4; ++b)
        QVERIFY(state.addBody(movingHandle(handle, b)).ok());
    const std::vector<uint32_t> group = {3, 0, 2}; // body 1 is not in it
    BodyState inPlace = state;
    BodyState local;
    local.gather(state, group);
    const std::vector<uint32_t> localIds = {0, 1, 2};
    const Vec3 gravity(0.0, -9.81, 0.0);
    const Damping damping{0.02, 0.03};
    ClampCounters a, b;
    for (int s = 0; s < 16; ++s) {
        integrateVelocities(inPlace, group, kDt / 4.0, gravity, damping, integrator, true, a);
        integratePositions(inPlace, group, kDt / 4.0, gravity, damping, integrator, true);
        integrateVelocities(local, localIds, kDt / 4.0, gravity, damping, integrator, true, b);
        integratePositions(local, localIds, kDt / 4.0, gravity, damping, integrator, true);
    }
    BodyState written = state;
    local.scatterMotion(written, group);
    for (uint32_t i = 0; i < state.size(); ++i) {
        QCOMPARE(written.position[i], inPlace.position[i]);
        QCOMPARE(written.orientation[i], inPlace.orientation[i]);
        QCOMPARE(written.linearVelocity[i], inPlace.linearVelocity[i]);
        QCOMPARE(written.angularVelocity[i], inPlace.angularVelocity[i]);
    }
    QCOMPARE(written.position[1], state.position[1]);
    QVERIFY(written.position[3] != state.position[3]); // the group did move
}

void TestRotation::listedSymplecticBodiesIntegrateAsRanges_data() {
    QTest::addColumn<bool>("rotation");
    QTest::newRow("with rotation") << true;
    QTest::newRow("linear only") << false;
}

void TestRotation::listedSymplecticBodiesIntegrateAsRanges() {
    // The overloads for a list of bodies, which the world's substeps use, take symplectic Euler's phases without the
    // smooth motion (Integrator.cpp); the range overloads keep the general path. Between the phases a solver changes
    // some velocities. Both must give the same bits: a T-handle (gyroscopic term), a cube, damped bodies, one flying
    // past the speed limit and one spinning past the rotation limit (both clamped).
    QFETCH(bool, rotation);
    const RigidData handle = tHandle();
    BodyState state;
    for (int b = 0; b < 6; ++b) {
        BodyInit init = movingHandle(handle, b);
        if (b % 2 == 1) { // a 2 kg cube
            init.mass = 2.0;
            init.inertia = Mat3(0.1);
        }
        if (b == 4)
            init.linearVelocity = Vec3(2000.0, 0.0, 0.0);
        if (b == 5)
            init.angularVelocity = Vec3(0.0, 500.0, 0.0);
        QVERIFY(state.addBody(init).ok());
    }
    BodyState ranged = state, listed = state;
    const std::vector<uint32_t> all = {0, 1, 2, 3, 4, 5};
    const Vec3 gravity(0.0, -9.81, 0.0);
    const Damping damping{0.02, 0.03};
    ClampCounters counters;
    for (int s = 0; s < 24; ++s) {
        integrateVelocities(ranged, BodyRange{0, 6}, kDt, gravity, damping, Integrator::SymplecticEuler, rotation);
        integrateVelocities(listed, all, kDt, gravity, damping, Integrator::SymplecticEuler, rotation, counters);
        for (BodyState* st : {&ranged, &listed}) {
            st->linearVelocity[1] += Vec3(0.0, 0.01 * s, 0.0); // what a contact might do
            if (rotation)
                st->angularVelocity[2] *= 0.9;
        }
        integratePositions(ranged, BodyRange{0, 6}, kDt, gravity, damping, Integrator::SymplecticEuler, rotation);
        integratePositions(listed, all, kDt, gravity, damping, Integrator::SymplecticEuler, rotation);
    }
    for (uint32_t i = 0; i < state.size(); ++i) {
        QCOMPARE(std::memcmp(&listed.position[i], &ranged.position[i], sizeof(Vec3)), 0);
        QCOMPARE(std::memcmp(&listed.orientation[i], &ranged.orientation[i], sizeof(Quat)), 0);
        QCOMPARE(std::memcmp(&listed.linearVelocity[i], &ranged.linearVelocity[i], sizeof(Vec3)), 0);
        QCOMPARE(std::memcmp(&listed.angularVelocity[i], &ranged.angularVelocity[i], sizeof(Vec3)), 0);
    }
    QCOMPARE(counters.linear, ranged.clampCounters.linear);
    QCOMPARE(counters.angular, ranged.clampCounters.angular);
    QVERIFY(counters.linear > 0 && (counters.angular > 0) == rotation);
    QVERIFY(listed.orientation[0] != state.orientation[0] || !rotation);
}

void TestRotation::symplecticPositionsForSolverAreTheStepsNumbers_data() {
    QTest::addColumn<int>("lanes");
    QTest::addColumn<bool>("rotation");
    for (int lanes : {1, 4, 8}) {
        QTest::addRow("%d lanes, with rotation", lanes) << lanes << true;
        QTest::addRow("%d lanes, linear only", lanes) << lanes << false;
    }
}

void TestRotation::symplecticPositionsForSolverAreTheStepsNumbers() {
    // The world's substeps take symplectic Euler's position phase and the solver's view of each body in one pass,
    // several bodies at a time (IntegratorWide.cpp). It must give the bits of the steps it stands for, taken one after
    // the other through the public calls: the solver's velocities into the bodies, integratePositions(), then the
    // motion since the step began and the inverse inertia at the new pose. 21 bodies in an order of their own (two
    // vectors of eight and a tail): T-handles (full inverse inertia), cubes (isotropic), balls (round: dR stays the
    // identity while they turn), a sleeper, bodies at rest, and some turning more than 0.02 rad in the substep (the
    // sine and cosine instead of the series). The start poses
    // are turned well away from the bodies' poses, so that the quaternion products' terms are of one size and any
    // change in their order shows in the roundings (a reordered product failed here, tried).
    QFETCH(int, lanes);
    QFETCH(bool, rotation);
    const RigidData handle = tHandle();
    BodyState state;
    std::vector<SolverBody> solver(1);
    std::vector<Vec3> startPosition;
    std::vector<Quat> startOrientation;
    for (int b = 0; b < 21; ++b) {
        BodyInit init = movingHandle(handle, b);
        const bool cube = b % 3 != 0;
        if (cube) {
            init.mass = 2.0;
            init.inertia = Mat3(0.1);
            init.round = b % 7 == 2; // a ball
        }
        init.round = init.round || b == 3 || b == 12; // T-handles round about their principal z axis (below)
        QVERIFY(state.addBody(init).ok());
        if (b == 3 || b == 12)
            state.info.back().rollAxis = Vec3(0.0, 0.0, 1.0);
        SolverBody s;
        s.isotropic = cube; // as the world marks them
        s.v = b % 5 == 4 ? Vec3(0.0) : Vec3(0.1 * b, -2.0 + 0.05 * b, 0.3);
        s.w = b % 5 == 4 ? Vec3(0.0) : Vec3(0.5 - 0.04 * b, b % 4 == 0 ? 40.0 : 0.2 * b, -0.3);
        solver.push_back(s);
        startPosition.push_back(init.centerOfMass - Vec3(0.01 * b, 0.02, 0.0));
        startOrientation.push_back(glm::normalize(init.orientation * Quat(1.0, 0.1 * b, 0.3, -0.02 * b)));
    }
    state.flags[7] &= static_cast<uint8_t>(~kBodyAwake); // asleep: keeps its pose, still gets the rest
    std::vector<uint32_t> order(21);
    for (uint32_t k = 0; k < 21; ++k)
        order[k] = (k * 8) % 21; // every body once
    const Real dt = 1.0 / 360.0;
    BodyState stepped = state, fused = state;
    std::vector<SolverBody> expected = solver, got = solver;
    for (const uint32_t k : order) {
        stepped.linearVelocity[k] = expected[k + 1].v;
        if (rotation)
            stepped.angularVelocity[k] = expected[k + 1].w;
    }
    integratePositions(stepped, order, dt, Vec3(0.0, -9.81, 0.0), Damping{0.02, 0.03}, Integrator::SymplecticEuler,
                       rotation);
    for (const uint32_t k : order) {
        expected[k + 1].dp = stepped.position[k] - startPosition[k];
        expected[k + 1].dR = stepped.anchorTurn(k, startOrientation[k]);
        if (rotation)
            expected[k + 1].invInertia = stepped.solverInverseInertia(k, startOrientation[k]);
    }
    symplecticPositionsForSolver(fused, order, dt, rotation, startPosition, startOrientation, got, lanes);
    const auto same = [](const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    int turnedFar = 0, drifted = 0;
    for (uint32_t k = 0; k < 21; ++k) {
        drifted += stepped.solverInertiaDrifted(k, startOrientation[k]) ? 1 : 0;
        QVERIFY2(same(fused.position[k], stepped.position[k]), qPrintable(QString("body %1").arg(k)));
        QVERIFY2(same(fused.orientation[k], stepped.orientation[k]), qPrintable(QString("body %1").arg(k)));
        QVERIFY(same(fused.linearVelocity[k], stepped.linearVelocity[k]));
        QVERIFY(same(fused.angularVelocity[k], stepped.angularVelocity[k]));
        QVERIFY(same(got[k + 1].dp, expected[k + 1].dp));
        QVERIFY2(same(got[k + 1].dR, expected[k + 1].dR), qPrintable(QString("body %1").arg(k)));
        QVERIFY(same(got[k + 1].invInertia, expected[k + 1].invInertia));
        turnedFar += glm::length(got[k + 1].w) * dt > 0.02 ? 1 : 0;
    }
    // Both kinds of inverse inertia: the world's at the pose, and the least moment's where it drifted (the T-handles'
    // starts are turned far from their poses; the cubes' and balls' inverse inertias cannot drift).
    QVERIFY2(drifted > 0 && drifted < 21, qPrintable(QString::number(drifted)));
    QVERIFY(fused.position[7] == state.position[7] && fused.orientation[7] == state.orientation[7]);
    QVERIFY(fused.position[0] != state.position[0]);
    QVERIFY(rotation == (fused.orientation[0] != state.orientation[0]));
    QVERIFY(turnedFar > 0);
    for (const uint32_t k : {2u, 16u}) { // the balls turned, and their contacts' anchors did not
        QVERIFY(fused.isRound(k) && !fused.isRound(k - 1));
        QVERIFY(rotation == (fused.orientation[k] != state.orientation[k]));
        QVERIFY(got[k + 1].dR == Mat3(1.0));
    }
    for (const uint32_t k : {3u, 12u}) { // round about an axis: the anchors turned, by less than the body
        const Mat3 full = glm::mat3_cast(glm::normalize(fused.orientation[k] * glm::conjugate(startOrientation[k])));
        QVERIFY(fused.isRound(k) && got[k + 1].dR != Mat3(1.0) && got[k + 1].dR != full);
    }
}

void TestRotation::anchorTurnLeavesOutTheRoundPart() {
    // A body turned by a swing (about an axis across its roll axis) after a twist (about the roll axis, as it was at
    // the start): the anchors of a body round about that axis turn by the swing alone, those of a ball not at all,
    // those of any other body by the whole turn.
    const RigidData handle = tHandle();
    BodyState state;
    for (int b = 0; b < 3; ++b) {
        BodyInit init = movingHandle(handle, b);
        init.round = b > 0;
        QVERIFY(state.addBody(init).ok());
    }
    state.info[1].rollAxis = Vec3(0.0, 1.0, 0.0); // round about its principal y axis; body 2 about every axis
    for (const Real twistAngle : {0.0, 0.3, 2.5, -3.0}) {
        for (const Real swingAngle : {0.0, 0.2, 1.4}) {
            for (uint32_t k = 0; k < 3; ++k) {
                const Quat start = glm::normalize(Quat(0.9, 0.1 * k, -0.3, 0.2));
                state.orientation[k] = start;
                const Vec3 axis = start * Vec3(0.0, 1.0, 0.0);
                const Vec3 across = glm::normalize(glm::cross(axis, Vec3(0.3, 0.1, 1.0)));
                const Quat swing = glm::angleAxis(swingAngle, across), twist = glm::angleAxis(twistAngle, axis);
                state.orientation[k] = glm::normalize(swing * twist * start);
                const Mat3 got = state.anchorTurn(k, start);
                const Mat3 want = k == 0   ? glm::mat3_cast(glm::normalize(swing * twist))
                                  : k == 1 ? glm::mat3_cast(swing)
                                           : Mat3(1.0);
                for (int c = 0; c < 3; ++c)
                    for (int r = 0; r < 3; ++r)
                        QVERIFY2(
                            std::abs(got[c][r] - want[c][r]) < 1e-12,
                            qPrintable(QString("body %1, twist %2, swing %3").arg(k).arg(twistAngle).arg(swingAngle)));
            }
        }
    }
}

void TestRotation::symplecticVelocitiesForSolverAreTheStepsNumbers() {
    // Likewise the velocity phase with the copy to the solver (IntegratorWide.cpp) against integrateVelocities() and
    // the copy one after the other: T-handles (the gyroscopic term: its Newton iterations in the lanes, a fast one
    // taking more of them than its neighbours), damped cubes, a sleeper, bodies past the speed and the rotation limits
    // (clamped, and counted alike), a handle whose angular velocity is not finite (stopped by the clamp).
    QFETCH(int, lanes);
    QFETCH(bool, rotation);
    const RigidData handle = tHandle();
    BodyState state;
    for (int b = 0; b < 21; ++b) {
        BodyInit init = movingHandle(handle, b);
        if (b % 3 != 0) {
            init.mass = 2.0;
            init.inertia = Mat3(0.1);
        }
        if (b == 5 || b == 16)
            init.linearVelocity = Vec3(0.0, -1500.0 - b, 300.0);
        if (b == 10 || b == 14 || b == 12)
            init.angularVelocity = Vec3(400.0 + b, -50.0, 10.0); // past pi / 4 a substep (283 rad/s)
        if (b == 9)
            init.angularVelocity = Vec3(250.0, -40.0, 15.0);
        QVERIFY(state.addBody(init).ok());
    }
    state.angularVelocity[18] = Vec3(std::numeric_limits<Real>::quiet_NaN(), 1.0, 0.0); // (addBody() refuses it)
    state.flags[7] &= static_cast<uint8_t>(~kBodyAwake);
    std::vector<uint32_t> order(21);
    for (uint32_t k = 0; k < 21; ++k)
        order[k] = (k * 8) % 21;
    const Real dt = 1.0 / 360.0;
    const Vec3 gravity(0.0, -9.81, 0.0);
    const Damping damping{0.02, 0.03};
    BodyState stepped = state, fused = state;
    std::vector<SolverBody> expected(22), got(22);
    ClampCounters steppedClamps, fusedClamps;
    integrateVelocities(stepped, order, dt, gravity, damping, Integrator::SymplecticEuler, rotation, steppedClamps);
    for (const uint32_t k : order) {
        expected[k + 1].v = stepped.linearVelocity[k];
        expected[k + 1].w = rotation ? stepped.angularVelocity[k] : Vec3(0.0);
    }
    symplecticVelocitiesForSolver(fused, order, dt, gravity, damping, rotation, fusedClamps, got, lanes);
    const auto same = [](const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    for (uint32_t k = 0; k < 21; ++k) {
        QVERIFY2(same(fused.linearVelocity[k], stepped.linearVelocity[k]), qPrintable(QString("body %1").arg(k)));
        QVERIFY2(same(fused.angularVelocity[k], stepped.angularVelocity[k]), qPrintable(QString("body %1").arg(k)));
        QVERIFY(same(got[k + 1].v, expected[k + 1].v));
        QVERIFY(same(got[k + 1].w, expected[k + 1].w));
    }
    QCOMPARE(fusedClamps.linear, steppedClamps.linear);
    QCOMPARE(fusedClamps.angular, steppedClamps.angular);
    QCOMPARE(steppedClamps.linear, uint64_t(2));
    QCOMPARE(steppedClamps.angular, rotation ? uint64_t(4) : uint64_t(0));
    QVERIFY(fused.linearVelocity[7] == state.linearVelocity[7]);
    QVERIFY(fused.linearVelocity[1] != state.linearVelocity[1]);
}

QTEST_APPLESS_MAIN(TestRotation)
#include "tst_rotation.moc"
