// The four integrators on problems with closed-form answers: free fall, linear and angular damping, the speed clamp,
// the split into velocity and position phases around a (minimal) velocity solver, and bodies they must not touch.
#include "dynamics/BodyState.h"
#include "dynamics/Gyroscopic.h"
#include "dynamics/Integrator.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace rl;

Q_DECLARE_METATYPE(rl::Integrator)

namespace {

const Integrator kAll[] = {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4};

// A 2 kg solid sphere of radius 0.1 m: isotropic inertia, so there is no gyroscopic coupling in the damping tests.
BodyInit sphere(const Vec3& position, const Vec3& velocity, const Vec3& angularVelocity) {
    BodyInit init;
    init.centerOfMass = position;
    init.mass = 2.0;
    init.inertia = Mat3(0.4 * 2.0 * 0.1 * 0.1);
    init.linearVelocity = velocity;
    init.angularVelocity = angularVelocity;
    return init;
}

// Angle of the rotation q (0..pi).
Real rotationAngle(const Quat& q) {
    return 2.0 * std::acos(std::min(1.0, std::abs(q.w)));
}

} // namespace

class TestIntegrators : public QObject {
    Q_OBJECT

private slots:
    void freeFall_data();
    void freeFall();
    void dampingDecay_data();
    void dampingDecay();
    void stiffDampingStaysFinite_data();
    void stiffDampingStaysFinite();
    void speedClamp_data();
    void speedClamp();
    void clampCatchesNonFiniteVelocity();
    void restingOnFloor_data();
    void restingOnFloor();
    void staticSleepingAndLinearOnly();
    void exponentialMapIsExact();
    void rotationFromVectorToTheLastBits_data();
    void rotationFromVectorToTheLastBits();
};

void TestIntegrators::freeFall_data() {
    // Closed forms for x(T) - exact(T) after N steps of constant gravity: explicit Euler lags by g T dt / 2 (it moves
    // with the velocity from before each kick), symplectic Euler leads by as much, Verlet and RK4 are exact.
    QTest::addColumn<Integrator>("integrator");
    QTest::addColumn<Real>("lead"); // position error in units of g T dt / 2
    QTest::newRow("explicit-euler") << Integrator::ExplicitEuler << -1.0;
    QTest::newRow("symplectic-euler") << Integrator::SymplecticEuler << 1.0;
    QTest::newRow("verlet") << Integrator::Verlet << 0.0;
    QTest::newRow("rk4") << Integrator::Rk4 << 0.0;
}

void TestIntegrators::freeFall() {
    QFETCH(Integrator, integrator);
    QFETCH(Real, lead);
    const Vec3 g(0.0, -9.81, 0.0);
    const Vec3 x0(0.5, 10.0, -1.0), v0(3.0, 4.0, 0.0);
    const Real dt = 1.0 / 240.0;
    const int steps = 480;
    const Real t = steps * dt;
    BodyState state;
    QVERIFY(state.addBody(sphere(x0, v0, Vec3(0.0))).ok());
    for (int k = 0; k < steps; ++k)
        integrateSmooth(state, allBodies(state), dt, g, Damping{}, integrator, true);
    const Vec3 exact = x0 + v0 * t + 0.5 * g * t * t;
    const Vec3 predicted = exact + lead * 0.5 * g * t * dt;
    QVERIFY2(glm::length(state.position[0] - predicted) < 1e-10,
             qPrintable(QString::number(glm::length(state.position[0] - predicted))));
    QVERIFY(glm::length(state.linearVelocity[0] - (v0 + g * t)) < 1e-10);
    QCOMPARE(state.clampCounters, ClampCounters{});
}

void TestIntegrators::dampingDecay_data() {
    QTest::addColumn<Integrator>("integrator");
    QTest::addColumn<Real>("order");
    QTest::newRow("explicit-euler") << Integrator::ExplicitEuler << 1.0;
    QTest::newRow("symplectic-euler") << Integrator::SymplecticEuler << 1.0;
    QTest::newRow("verlet") << Integrator::Verlet << 2.0;
    QTest::newRow("rk4") << Integrator::Rk4 << 4.0;
}

void TestIntegrators::dampingDecay() {
    // v' = -c v: v(T) = v0 exp(-c T), x(T) = x0 + v0 (1 - exp(-c T)) / c; the same for the spin w. Each integrator must
    // approach the exponential at its order: halving dt divides the error by 2^order.
    QFETCH(Integrator, integrator);
    QFETCH(Real, order);
    const Real c = 2.0, T = 2.0;
    const Vec3 v0(1.5, 0.0, -0.5), w0(0.0, 3.0, 0.0);
    auto errors = [&](Real dt, Real& velocityError, Real& positionError, Real& spinError) {
        BodyState state;
        BodyInit init = sphere(Vec3(0.0), v0, w0);
        init.linearDamping = 0.5 * c; // half from the body, half from the world: the rates add
        init.angularDamping = c;
        QVERIFY(state.addBody(init).ok());
        const int steps = static_cast<int>(std::lround(T / dt));
        for (int k = 0; k < steps; ++k)
            integrateSmooth(state, allBodies(state), dt, Vec3(0.0), Damping{0.5 * c, 0.0}, integrator, true);
        const Real decay = std::exp(-c * T);
        velocityError = glm::length(state.linearVelocity[0] - v0 * decay) / glm::length(v0);
        positionError = glm::length(state.position[0] - v0 * (1.0 - decay) / c) / glm::length(v0);
        spinError = glm::length(state.angularVelocity[0] - w0 * decay) / glm::length(w0);
    };
    Real v1, x1, w1, v2, x2, w2;
    errors(0.1, v1, x1, w1);
    errors(0.05, v2, x2, w2);
    const Real velocityOrder = std::log2(v1 / v2), positionOrder = std::log2(x1 / x2), spinOrder = std::log2(w1 / w2);
    qInfo("errors at dt 0.1: v %.2e x %.2e w %.2e; observed orders v %.2f x %.2f w %.2f", v1, x1, w1, velocityOrder,
          positionOrder, spinOrder);
    QVERIFY(std::abs(velocityOrder - order) < 0.15);
    QVERIFY(std::abs(positionOrder - order) < 0.15);
    QVERIFY(std::abs(spinOrder - order) < 0.15);
    // And small in absolute terms: the first-order schemes are within 25 % at c dt = 0.2, the others far closer.
    QVERIFY(v1 < (order == 1.0 ? 0.25 : 0.02));
}

void TestIntegrators::stiffDampingStaysFinite_data() {
    QTest::addColumn<Integrator>("integrator");
    for (Integrator integrator : kAll)
        QTest::newRow(integratorName(integrator).data()) << integrator;
}

void TestIntegrators::stiffDampingStaysFinite() {
    // c dt = 50: explicit updates would multiply the velocity by -49 per step. Every scheme must decay instead.
    QFETCH(Integrator, integrator);
    BodyState state;
    QVERIFY(state.addBody(sphere(Vec3(0.0), Vec3(5.0, 0.0, 0.0), Vec3(0.0, 5.0, 0.0))).ok());
    for (int k = 0; k < 100; ++k)
        integrateSmooth(state, allBodies(state), 0.1, Vec3(0.0, -9.81, 0.0), Damping{500.0, 500.0}, integrator, true);
    // The terminal velocity under gravity and drag c is g / c.
    QVERIFY(std::abs(state.linearVelocity[0].y + 9.81 / 500.0) < 1e-6);
    QVERIFY(std::abs(state.linearVelocity[0].x) < 1e-6);
    QVERIFY(glm::length(state.angularVelocity[0]) < 1e-6);
    QVERIFY(std::isfinite(state.position[0].x) && std::isfinite(state.position[0].y));
    QCOMPARE(state.clampCounters, ClampCounters{});
}

void TestIntegrators::speedClamp_data() {
    QTest::addColumn<Integrator>("integrator");
    for (Integrator integrator : kAll)
        QTest::newRow(integratorName(integrator).data()) << integrator;
}

void TestIntegrators::speedClamp() {
    QFETCH(Integrator, integrator);
    const Real dt = 1.0 / 240.0;
    BodyState state;
    QVERIFY(state.addBody(sphere(Vec3(0.0), Vec3(0.0, 0.0, 2500.0), Vec3(0.0, 1000.0, 0.0))).ok());
    QVERIFY(state.addBody(sphere(Vec3(5.0), Vec3(0.0, 0.0, 10.0), Vec3(0.0, 10.0, 0.0))).ok()); // below the limits
    const Quat q0 = state.orientation[0];
    integrateSmooth(state, allBodies(state), dt, Vec3(0.0), Damping{}, integrator, true);
    QVERIFY(std::abs(glm::length(state.linearVelocity[0]) - state.limits.maxLinearSpeed) < 1e-9);
    QVERIFY(std::abs(glm::length(state.angularVelocity[0]) * dt - state.limits.maxRotationPerSubstep) < 1e-9);
    // The body moved no further than the clamp allows in that substep.
    QVERIFY(glm::length(state.position[0]) <= state.limits.maxLinearSpeed * dt * (1.0 + 1e-12));
    QVERIFY(rotationAngle(state.orientation[0] * glm::conjugate(q0)) <= state.limits.maxRotationPerSubstep + 1e-12);
    QCOMPARE(state.clampCounters.linear, uint64_t(1));
    QCOMPARE(state.clampCounters.angular, uint64_t(1));
    QVERIFY(std::abs(glm::length(state.linearVelocity[1]) - 10.0) < 1e-12);
    // Clamped once, it stays at the limit without being counted again.
    integrateSmooth(state, allBodies(state), dt, Vec3(0.0), Damping{}, integrator, true);
    QCOMPARE(state.clampCounters.linear, uint64_t(1));
    // Limits are settings: clear() keeps them and resets the counters.
    state.limits.maxLinearSpeed = 50.0;
    state.clear();
    QCOMPARE(state.size(), 0u);
    QCOMPARE(state.limits.maxLinearSpeed, 50.0);
    QCOMPARE(state.clampCounters, ClampCounters{});
}

void TestIntegrators::clampCatchesNonFiniteVelocity() {
    // A velocity can only become NaN through a bug upstream (a solver row dividing by zero); it must not spread.
    BodyState state;
    QVERIFY(state.addBody(sphere(Vec3(1.0), Vec3(0.0), Vec3(0.0))).ok());
    state.linearVelocity[0] = Vec3(std::nan(""), 0.0, 0.0);
    state.angularVelocity[0] = Vec3(0.0, INFINITY, 0.0);
    integrateSmooth(state, allBodies(state), 0.01, Vec3(0.0, -9.81, 0.0), Damping{}, Integrator::SymplecticEuler, true);
    QVERIFY(std::isfinite(glm::length(state.position[0])));
    QVERIFY(std::isfinite(glm::length(state.linearVelocity[0])));
    QVERIFY(std::isfinite(glm::length(glm::vec<4, double>(state.orientation[0].w, state.orientation[0].x,
                                                          state.orientation[0].y, state.orientation[0].z))));
    QCOMPARE(state.clampCounters.linear, uint64_t(1));
    QCOMPARE(state.clampCounters.angular, uint64_t(1));
}

void TestIntegrators::restingOnFloor_data() {
    QTest::addColumn<Integrator>("integrator");
    for (Integrator integrator : kAll)
        QTest::newRow(integratorName(integrator).data()) << integrator;
}

void TestIntegrators::restingOnFloor() {
    // The phases around a minimal velocity solver (a floor at y = 0 that removes approaching normal velocity). A body
    // resting on it must stay exactly where it is with every integrator: this is what the position phase's rule
    // "move with the solved velocity when the solver acted" is for. A dropped body must come to rest on the floor
    // having sunk at most one substep's travel.
    QFETCH(Integrator, integrator);
    const Real dt = 1.0 / 240.0;
    const Vec3 g(0.0, -9.81, 0.0);
    BodyState state;
    QVERIFY(state.addBody(sphere(Vec3(0.0, 0.0, 0.0), Vec3(0.0), Vec3(0.0))).ok());
    QVERIFY(state.addBody(sphere(Vec3(1.0, 1.0, 0.0), Vec3(0.0), Vec3(0.0))).ok());
    Real lowest = 1.0;
    for (int k = 0; k < 480; ++k) {
        integrateVelocities(state, allBodies(state), dt, g, Damping{}, integrator, true);
        for (uint32_t i = 0; i < state.size(); ++i)
            if (state.position[i].y <= 0.0 && state.linearVelocity[i].y < 0.0)
                state.linearVelocity[i].y = 0.0;
        integratePositions(state, allBodies(state), dt, g, Damping{}, integrator, true);
        lowest = std::min(lowest, state.position[1].y);
    }
    QCOMPARE(state.position[0].y, 0.0);
    const Real impactSpeed = std::sqrt(2.0 * 9.81 * 1.0);
    QVERIFY(lowest <= 0.0);
    QVERIFY(lowest > -(impactSpeed + 9.81 * dt) * dt);
    QVERIFY(std::abs(state.position[1].y - lowest) < 1e-12); // and it stays down: no creeping up or down
}

void TestIntegrators::staticSleepingAndLinearOnly() {
    BodyState state;
    BodyInit anchor = sphere(Vec3(0.0), Vec3(0.0), Vec3(0.0));
    anchor.isStatic = true;
    QVERIFY(state.addBody(anchor).ok());
    QVERIFY(state.addBody(sphere(Vec3(1.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 2.0, 0.0))).ok());
    QVERIFY(state.addBody(sphere(Vec3(2.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 2.0, 0.0))).ok());
    state.flags[2] &= static_cast<uint8_t>(~kBodyAwake);
    QCOMPARE(state.invMass[0], 0.0);
    for (Integrator integrator : kAll) {
        const Quat spinning = state.orientation[1];
        integrateSmooth(state, allBodies(state), 0.01, Vec3(0.0, -9.81, 0.0), Damping{}, integrator, false);
        // linear-only mode: the spin is neither integrated nor changed
        QCOMPARE(state.orientation[1], spinning);
        QCOMPARE(state.angularVelocity[1], Vec3(0.0, 2.0, 0.0));
    }
    QCOMPARE(state.position[0], Vec3(0.0));
    QCOMPARE(state.linearVelocity[0], Vec3(0.0));
    QCOMPARE(state.position[2], Vec3(2.0));
    QCOMPARE(state.linearVelocity[2], Vec3(1.0, 0.0, 0.0));
    QVERIFY(state.position[1].y < 1.0);
    // A step of no time, or a non-finite one, moves nothing.
    for (Real dt : {0.0, -0.01, static_cast<Real>(std::nan("")), static_cast<Real>(INFINITY)}) {
        const Vec3 x = state.position[1], v = state.linearVelocity[1];
        integrateSmooth(state, allBodies(state), dt, Vec3(0.0, -9.81, 0.0), Damping{}, Integrator::Rk4, true);
        QCOMPARE(state.position[1], x);
        QCOMPARE(state.linearVelocity[1], v);
    }
    // A range leaves the bodies outside it alone.
    const Vec3 before = state.position[1];
    integrateSmooth(state, BodyRange{2, 3}, 0.01, Vec3(0.0, -9.81, 0.0), Damping{}, Integrator::Rk4, true);
    QCOMPARE(state.position[1], before);
}

void TestIntegrators::exponentialMapIsExact() {
    // Constant spin about a principal axis of a symmetric body: q(t) = exp(w t) for every integrator, whatever dt.
    const Vec3 w(0.0, 0.0, 2.0);
    for (Integrator integrator : kAll) {
        BodyState state;
        QVERIFY(state.addBody(sphere(Vec3(0.0), Vec3(0.0), w)).ok());
        for (int k = 0; k < 100; ++k)
            integrateSmooth(state, allBodies(state), 0.05, Vec3(0.0), Damping{}, integrator, true);
        const Quat expected = rotationFromVector(w * 5.0);
        QVERIFY2(std::abs(std::abs(glm::dot(state.shapeOrientation(0), expected)) - 1.0) < 1e-12,
                 integratorName(integrator).data());
    }
    // Small angles use the series; it must agree with the closed form where both are accurate.
    const Vec3 tiny(1e-6, -2e-6, 3e-6);
    const Quat a = rotationFromVector(tiny);
    const Real angle = glm::length(tiny);
    QVERIFY(std::abs(a.x - std::sin(0.5 * angle) * tiny.x / angle) < 1e-18);
    QVERIFY(std::abs(glm::length(glm::vec<4, double>(a.w, a.x, a.y, a.z)) - 1.0) < 1e-15);
}

void TestIntegrators::rotationFromVectorToTheLastBits_data() {
    QTest::addColumn<double>("angle");
    // Below 0.02 rad the series (to a^6), at and above it the sine and cosine.
    for (double angle : {1e-9, 1e-5, 1e-3, 0.01, 0.0199, 0.02, 0.0201, 0.3, 3.0})
        QTest::addRow("%g rad", angle) << angle;
}

void TestIntegrators::rotationFromVectorToTheLastBits() {
    QFETCH(double, angle);
    // Against cos(a/2) and sin(a/2)/a in long double, about 200 axes: every component within 2e-16.
    std::mt19937 rng(5);
    std::normal_distribution<double> n(0.0, 1.0);
    long double worst = 0.0L;
    for (int k = 0; k < 200; ++k) {
        const Vec3 axis = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
        const Vec3 theta = angle * axis;
        const long double a = std::sqrt(static_cast<long double>(glm::dot(theta, theta)));
        const long double c = std::cos(0.5L * a), s = std::sin(0.5L * a) / a;
        const Quat q = rotationFromVector(theta);
        worst = std::max({worst, std::abs(q.w - c), std::abs(q.x - s * theta.x), std::abs(q.y - s * theta.y),
                          std::abs(q.z - s * theta.z)});
    }
    QVERIFY2(worst < 2e-16L, qPrintable(QString("largest error %1").arg(static_cast<double>(worst))));
}

QTEST_APPLESS_MAIN(TestIntegrators)
#include "tst_integrators.moc"
