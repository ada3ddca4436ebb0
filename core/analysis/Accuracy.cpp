#include "analysis/Accuracy.h"

#include "dynamics/BodyState.h"
#include "dynamics/Integrator.h"
#include "io/AtomicFile.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace rl {

namespace {

constexpr std::array<Integrator, 4> kIntegrators = {Integrator::ExplicitEuler, Integrator::SymplecticEuler,
                                                    Integrator::Verlet, Integrator::Rk4};
constexpr Real kG = 9.81;
constexpr Real kFps = 60.0;                                    // the world problems run at the default frame rate
constexpr std::array<int, 6> kSubsteps = {1, 2, 4, 8, 16, 32}; // and vary the substeps (the world's default is 6)
// 10, 20 and 40: the original project's experiment. Explicit Euler reaches its first order only at small steps (its
// amplitude grows as (1 + h^2)^(n/2)): a least-squares slope over every row from 10 to 1,280 steps is 1.12, to 5,120
// 1.09, so the finer rows are there for whoever fits all of them. RK4's last two are below the fit's rounding floor.
constexpr std::array<int, 10> kOscillatorSteps = {10, 20, 40, 80, 160, 320, 640, 1280, 2560, 5120};
constexpr int kMaxTimingRepetitions = 1000000; // bounds the timing loop whatever the clock does

const Real kNaN = std::numeric_limits<Real>::quiet_NaN();

// Time per run of `run` (which returns the error, kept in `error`). The shared machine preempts us at random, so the
// runs are timed in five batches, each sized to take a fifth of minSeconds, and the fastest batch counts: preemption
// only ever adds time.
template <class Run>
Real timeRuns(const Run& run, Real minSeconds, Real& error) {
    using Clock = std::chrono::steady_clock;
    constexpr int kBatches = 5;
    const Real batchSeconds = minSeconds / kBatches;
    auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<Real>(b - a).count(); };
    // Calibrate: double the batch until it lasts long enough.
    int repetitions = 1;
    Real best = std::numeric_limits<Real>::max();
    for (;;) {
        const auto start = Clock::now();
        for (int r = 0; r < repetitions; ++r)
            error = run();
        const Real elapsed = seconds(start, Clock::now());
        best = std::min(best, elapsed / repetitions);
        if (elapsed >= batchSeconds || repetitions >= kMaxTimingRepetitions)
            break;
        repetitions *= 2;
    }
    for (int b = 1; b < kBatches; ++b) {
        const auto start = Clock::now();
        for (int r = 0; r < repetitions; ++r)
            error = run();
        best = std::min(best, seconds(start, Clock::now()) / repetitions);
    }
    return best;
}

// ---- oscillator ----

// The error is that of the whole state, max(|y - sin t|, |y' - cos t|) over the steps. Positions alone would hide
// symplectic Euler's first-order error here: with y(0) = 0 its first kick is the same as Verlet's half kick, so its
// positions are exactly Verlet's (second order) and only its velocities, half a step out of phase, show the first
// order.
Real oscillatorError(Integrator integrator, int steps) {
    const Real h = 2.0 * kPi / steps;
    Real y = 0.0, v = 1.0, worst = 0.0;
    const auto spring = [](Real x) { return -x; };
    for (int k = 1; k <= steps; ++k) {
        translationStep(integrator, y, v, h, 0.0, spring);
        worst = std::max({worst, std::abs(y - std::sin(k * h)), std::abs(v - std::cos(k * h))});
    }
    return worst;
}

// ---- projectile, with and without drag, through the body integrators ----

constexpr Real kProjectileSeconds = 2.0;
const Vec3 kProjectileVelocity(12.0, 9.0, 3.0);
constexpr Real kDrag = 2.0; // 1/s: strong enough that RK4's error stays above rounding for a few substep counts

Vec3 projectileExact(Real t, Real c) {
    const Vec3 g(0.0, -kG, 0.0);
    if (c == 0.0)
        return kProjectileVelocity * t + 0.5 * g * t * t;
    const Vec3 terminal = g / c;
    return terminal * t + (kProjectileVelocity - terminal) * ((1.0 - std::exp(-c * t)) / c);
}

Real projectileError(Integrator integrator, int steps, int substeps, Real c) {
    BodyState state;
    BodyInit init;
    init.linearVelocity = kProjectileVelocity;
    init.inertia = Mat3(1.0);
    (void)state.addBody(init); // a valid definition: cannot fail
    const Real h = kProjectileSeconds / steps / substeps;
    for (int k = 0; k < steps * substeps; ++k)
        integrateSmooth(state, allBodies(state), h, Vec3(0.0, -kG, 0.0), Damping{c, 0.0}, integrator, false);
    const Vec3 exact = projectileExact(kProjectileSeconds, c);
    return glm::length(state.position[0] - exact) / glm::length(exact);
}

// ---- torque-free tumbling ----

constexpr Real kTumblingSeconds = 4.0;
const Vec3 kTumblingMoments(2.0, 3.0, 4.0);      // kg m^2: an asymmetric body, axis 1 the intermediate one
const Vec3 kTumblingOmega(0.05, 4.0, 0.05);      // rad/s: near the intermediate axis, so the run contains a flip
constexpr int kTumblingReferenceRefinement = 16; // reference step = finest row's step / this

struct TumblingResult {
    Quat orientation;
    Real energyError = 0.0;
    Real momentumError = 0.0;
};

TumblingResult tumble(Integrator integrator, int totalSubsteps) {
    BodyState state;
    BodyInit init;
    init.mass = 1.0;
    init.inertia = Mat3(0.0);
    for (int i = 0; i < 3; ++i)
        init.inertia[i][i] = kTumblingMoments[i];
    init.angularVelocity = kTumblingOmega;
    (void)state.addBody(init);
    const Real e0 = state.rotationalEnergy(0);
    const Real l0 = glm::length(state.angularMomentum(0));
    const Real h = kTumblingSeconds / totalSubsteps;
    for (int k = 0; k < totalSubsteps; ++k)
        integrateSmooth(state, allBodies(state), h, Vec3(0.0), Damping{}, integrator, true);
    TumblingResult out;
    out.orientation = state.orientation[0];
    out.energyError = std::abs(state.rotationalEnergy(0) / e0 - 1.0);
    out.momentumError = std::abs(glm::length(state.angularMomentum(0)) / l0 - 1.0);
    return out;
}

// Angle of the rotation from a to b, by atan2 rather than acos, which loses all digits below about 1e-8 rad.
Real angleBetween(const Quat& a, const Quat& b) {
    const Quat d = glm::conjugate(glm::normalize(a)) * glm::normalize(b);
    return 2.0 * std::atan2(glm::length(Vec3(d.x, d.y, d.z)), std::abs(d.w));
}

// ---- frictional slide on an incline ----

constexpr Real kInclineAngle = kPi / 6.0; // 30 degrees: tan = 0.577 > mu, so the block slides
constexpr Real kInclineFriction = 0.3;
constexpr Real kInclineSeconds = 1.0;

Real inclineError(Integrator integrator, int steps, int substeps) {
    const Real h = kInclineSeconds / steps / substeps;
    const Real along = kG * std::sin(kInclineAngle);
    const Real frictionPerStep = kInclineFriction * kG * std::cos(kInclineAngle) * h;
    const auto slope = [along](Real) { return along; };
    Real s = 0.0, v = 0.0, displacement = 0.0, smoothVelocity = 0.0;
    for (int k = 0; k < steps * substeps; ++k) {
        translationVelocityPhase(integrator, s, v, h, 0.0, slope, displacement, smoothVelocity);
        // The solver's friction row: an impulse bounded by mu times the normal impulse (which cancels gravity's
        // normal part, g cos h per unit mass), never reversing the slide.
        if (v > 0.0)
            v = std::max(0.0, v - frictionPerStep);
        translationPositionPhase(integrator, s, v, h, 0.0, slope, displacement, smoothVelocity);
    }
    const Real exact = 0.5 * kG * (std::sin(kInclineAngle) - kInclineFriction * std::cos(kInclineAngle)) *
                       kInclineSeconds * kInclineSeconds;
    return std::abs(s - exact) / exact;
}

// ---- bouncing drop ----

constexpr Real kDropHeight = 1.0;  // m
constexpr Real kRestitution = 0.8; // the Rubber preset's
constexpr int kApexes = 4;

Real bounceSeconds() {
    // Fall, three full flights, and the rise to the fourth apex, plus a margin for the late contacts of coarse steps.
    const Real fall = std::sqrt(2.0 * kDropHeight / kG);
    Real t = fall;
    for (int n = 1; n < kApexes; ++n)
        t += 2.0 * std::pow(kRestitution, n) * fall;
    return t + std::pow(kRestitution, kApexes) * fall + 0.1;
}

Real bounceError(Integrator integrator, int steps, int substeps, bool exactEvents) {
    const Real h = 1.0 / (kFps * substeps);
    // Late contacts (and explicit Euler's energy gain) lengthen the flights: run until the fourth apex, within a bound.
    const int substepCount = 2 * steps * substeps;
    const auto gravity = [](Real) { return -kG; };
    Real y = kDropHeight, v = 0.0;
    Real apex[kApexes] = {};
    int found = 0;
    for (int k = 0; k < substepCount && found < kApexes; ++k) {
        const Real before = v;
        if (exactEvents) {
            Real remaining = h;
            // At most two impacts fit in one substep at the heights this problem reaches; the bound is a guard.
            for (int event = 0; event < 4 && remaining > 0.0; ++event) {
                const Real discriminant = v * v + 2.0 * kG * y;
                const Real hit = discriminant >= 0.0 ? (v + std::sqrt(discriminant)) / kG : kNaN;
                if (y >= 0.0 && hit >= 0.0 && hit < remaining) {
                    translationStep(integrator, y, v, hit, 0.0, gravity);
                    v = -kRestitution * v;
                    remaining -= hit;
                } else {
                    translationStep(integrator, y, v, remaining, 0.0, gravity);
                    remaining = 0.0;
                }
            }
        } else {
            Real displacement = 0.0, smoothVelocity = 0.0;
            translationVelocityPhase(integrator, y, v, h, 0.0, gravity, displacement, smoothVelocity);
            if (y <= 0.0 && v < 0.0)
                v = -kRestitution * v; // the contact found at the end of the previous substep, resolved on v
            translationPositionPhase(integrator, y, v, h, 0.0, gravity, displacement, smoothVelocity);
        }
        if (before > 0.0 && v <= 0.0)
            apex[found++] = y + v * v / (2.0 * kG); // the height this flight's energy reaches
    }
    if (found < kApexes)
        return 1.0; // bounces lost within twice the exact time: as wrong as an apex can be, and finite for the plot
    Real worst = 0.0;
    for (int n = 0; n < kApexes; ++n)
        worst = std::max(worst, std::abs(apex[n] - std::pow(kRestitution, 2 * (n + 1)) * kDropHeight) / kDropHeight);
    return worst;
}

// ---- formatting ----

std::string roundTrip(Real value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string xmlEscape(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '&':
            out += "&amp;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string formatted(const char* pattern, auto... args) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, pattern, args...);
    return buffer;
}

} // namespace

Real fitConvergenceOrder(std::span<const Real> stepSizes, std::span<const Real> errors, Real floor, Real ceiling,
                         int* points) {
    Real sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    int n = 0;
    for (size_t i = 0; i < std::min(stepSizes.size(), errors.size()); ++i) {
        if (!(errors[i] > floor && errors[i] < ceiling && stepSizes[i] > 0.0))
            continue;
        const Real x = std::log(stepSizes[i]), y = std::log(errors[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++n;
    }
    if (points)
        *points = n;
    const Real denominator = n * sxx - sx * sx;
    if (n < 2 || !(std::abs(denominator) > 0.0))
        return kNaN;
    return (n * sxy - sx * sy) / denominator;
}

AccuracyReport runAccuracyStudy(const AccuracyOptions& options) {
    AccuracyReport report;
    report.problems = {"oscillator",        "projectile", "projectile-drag", "tumbling-orientation", "tumbling-energy",
                       "tumbling-momentum", "incline",    "bounce-per-step", "bounce-exact"};
    const Real minSeconds = options.minTimingSeconds;
    auto add = [&](const std::string& problem, Integrator integrator, int steps, Real dt, int substeps, Real error,
                   Real cpu) {
        report.rows.push_back({problem, integrator, steps, dt, substeps, error, cpu});
    };

    for (Integrator integrator : kIntegrators) {
        for (int steps : kOscillatorSteps) {
            Real error = 0.0;
            const Real cpu = timeRuns([&] { return oscillatorError(integrator, steps); }, minSeconds, error);
            add("oscillator", integrator, steps, 2.0 * kPi / steps, 1, error, cpu);
        }
    }
    const int projectileSteps = static_cast<int>(std::lround(kProjectileSeconds * kFps));
    for (const Real drag : {0.0, kDrag}) {
        for (Integrator integrator : kIntegrators) {
            for (int substeps : kSubsteps) {
                Real error = 0.0;
                const Real cpu = timeRuns([&] { return projectileError(integrator, projectileSteps, substeps, drag); },
                                          minSeconds, error);
                add(drag == 0.0 ? "projectile" : "projectile-drag", integrator, projectileSteps, 1.0 / kFps, substeps,
                    error, cpu);
            }
        }
    }
    {
        const int steps = static_cast<int>(std::lround(kTumblingSeconds * kFps));
        const Quat reference =
            tumble(Integrator::Rk4, steps * kSubsteps.back() * kTumblingReferenceRefinement).orientation;
        for (Integrator integrator : kIntegrators) {
            for (int substeps : kSubsteps) {
                TumblingResult result;
                Real unused = 0.0;
                const Real cpu = timeRuns(
                    [&] {
                        result = tumble(integrator, steps * substeps);
                        return result.energyError;
                    },
                    minSeconds, unused);
                add("tumbling-orientation", integrator, steps, 1.0 / kFps, substeps,
                    angleBetween(result.orientation, reference), cpu);
                add("tumbling-energy", integrator, steps, 1.0 / kFps, substeps, result.energyError, cpu);
                add("tumbling-momentum", integrator, steps, 1.0 / kFps, substeps, result.momentumError, cpu);
            }
        }
    }
    {
        const int steps = static_cast<int>(std::lround(kInclineSeconds * kFps));
        for (Integrator integrator : kIntegrators) {
            for (int substeps : kSubsteps) {
                Real error = 0.0;
                const Real cpu = timeRuns([&] { return inclineError(integrator, steps, substeps); }, minSeconds, error);
                add("incline", integrator, steps, 1.0 / kFps, substeps, error, cpu);
            }
        }
    }
    {
        const int steps = static_cast<int>(std::ceil(bounceSeconds() * kFps));
        for (const bool exact : {false, true}) {
            for (Integrator integrator : kIntegrators) {
                for (int substeps : kSubsteps) {
                    Real error = 0.0;
                    const Real cpu =
                        timeRuns([&] { return bounceError(integrator, steps, substeps, exact); }, minSeconds, error);
                    add(exact ? "bounce-exact" : "bounce-per-step", integrator, steps, 1.0 / kFps, substeps, error,
                        cpu);
                }
            }
        }
    }

    for (const std::string& problem : report.problems) {
        for (Integrator integrator : kIntegrators) {
            std::vector<Real> steps, errors;
            for (const AccuracyRow& row : report.rows) {
                if (row.problem == problem && row.integrator == integrator) {
                    steps.push_back(row.dt / row.substeps);
                    errors.push_back(row.error);
                }
            }
            AccuracyOrder order{problem, integrator, 0.0, 0};
            order.order =
                fitConvergenceOrder(steps, errors, options.roundingFloor, options.asymptoticCeiling, &order.points);
            report.orders.push_back(order);
        }
    }
    return report;
}

std::string formatAccuracyTable(const AccuracyReport& report) {
    std::string out = formatted("%-21s %-17s %6s %10s %9s %12s %13s\n", "problem", "integrator", "steps", "dt",
                                "substeps", "error", "cpu_us");
    for (const AccuracyRow& row : report.rows) {
        out += formatted("%-21s %-17s %6d %10.6f %9d %12.4e %13.2f\n", row.problem.c_str(),
                         std::string(integratorName(row.integrator)).c_str(), row.steps, row.dt, row.substeps,
                         row.error, row.cpuSeconds * 1e6);
    }
    out += "\nfitted order (least-squares slope of log error over log step; 'exact' = at rounding level)\n";
    out += formatted("%-21s", "problem");
    for (Integrator integrator : kIntegrators)
        out += formatted(" %17s", std::string(integratorName(integrator)).c_str());
    out += "\n";
    for (const std::string& problem : report.problems) {
        out += formatted("%-21s", problem.c_str());
        for (Integrator integrator : kIntegrators) {
            for (const AccuracyOrder& order : report.orders) {
                if (order.problem == problem && order.integrator == integrator) {
                    out += std::isnan(order.order) ? formatted(" %17s", "exact")
                                                   : formatted(" %11.2f (n=%d)", order.order, order.points);
                }
            }
        }
        out += "\n";
    }
    return out;
}

std::string accuracyCsv(const AccuracyReport& report) {
    std::string out = "problem,integrator,steps,dt,substeps,step,error,cpu_seconds\n";
    for (const AccuracyRow& row : report.rows) {
        out += row.problem + "," + std::string(integratorName(row.integrator)) + "," + std::to_string(row.steps) + "," +
               roundTrip(row.dt) + "," + std::to_string(row.substeps) + "," + roundTrip(row.dt / row.substeps) + "," +
               roundTrip(row.error) + "," + roundTrip(row.cpuSeconds) + "\n";
    }
    return out;
}

Status writeAccuracyCsv(const AccuracyReport& report, const std::string& path) {
    return writeFileAtomically(path, accuracyCsv(report));
}

std::string accuracySvg(const AccuracyReport& report) {
    constexpr int kColumns = 3;
    constexpr Real kPanelWidth = 400.0, kPanelHeight = 300.0;
    constexpr Real kLeft = 70.0, kRight = 20.0, kTop = 40.0, kBottom = 50.0; // margins inside a panel
    constexpr Real kLegendHeight = 40.0;
    constexpr Real kErrorFloor = 1e-16; // plotted in place of 0 (a log axis has no 0)
    const char* colors[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd"};
    const int panels = static_cast<int>(report.problems.size());
    const int rowsOfPanels = (panels + kColumns - 1) / kColumns;
    const Real width = kColumns * kPanelWidth, height = kLegendHeight + rowsOfPanels * kPanelHeight;

    std::ostringstream svg;
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
    svg << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"white\"/>\n";
    svg << "<g class=\"legend\">\n";
    for (size_t i = 0; i < kIntegrators.size(); ++i) {
        const Real x = 20.0 + 170.0 * static_cast<Real>(i);
        svg << "<line x1=\"" << x << "\" y1=\"20\" x2=\"" << x + 24 << "\" y2=\"20\" stroke=\"" << colors[i]
            << "\" stroke-width=\"2\"/>";
        svg << "<text x=\"" << x + 30 << "\" y=\"24\">" << xmlEscape(integratorName(kIntegrators[i])) << "</text>\n";
    }
    svg << "<line x1=\"700\" y1=\"20\" x2=\"724\" y2=\"20\" stroke=\"#777\" stroke-dasharray=\"4 3\"/>";
    svg << "<text x=\"730\" y=\"24\">Pareto front (all integrators)</text>\n";
    svg << "<text x=\"" << width - 20 << "\" y=\"24\" text-anchor=\"end\">error vs CPU time per run, log-log</text>\n";
    svg << "</g>\n";

    for (int p = 0; p < panels; ++p) {
        const std::string& problem = report.problems[p];
        std::vector<const AccuracyRow*> rows;
        for (const AccuracyRow& row : report.rows)
            if (row.problem == problem)
                rows.push_back(&row);
        if (rows.empty())
            continue;
        Real minT = std::numeric_limits<Real>::max(), maxT = 0.0, minE = std::numeric_limits<Real>::max(), maxE = 0.0;
        for (const AccuracyRow* row : rows) {
            const Real t = std::max(row->cpuSeconds, 1e-12), e = std::max(row->error, kErrorFloor);
            minT = std::min(minT, t);
            maxT = std::max(maxT, t);
            minE = std::min(minE, e);
            maxE = std::max(maxE, e);
        }
        const int t0 = static_cast<int>(std::floor(std::log10(minT))),
                  t1 = std::max(t0 + 1, static_cast<int>(std::ceil(std::log10(maxT))));
        const int e0 = static_cast<int>(std::floor(std::log10(minE))),
                  e1 = std::max(e0 + 1, static_cast<int>(std::ceil(std::log10(maxE))));
        const Real ox = (p % kColumns) * kPanelWidth, oy = kLegendHeight + (p / kColumns) * kPanelHeight;
        const Real plotW = kPanelWidth - kLeft - kRight, plotH = kPanelHeight - kTop - kBottom;
        auto px = [&](Real t) { return ox + kLeft + (std::log10(t) - t0) / (t1 - t0) * plotW; };
        auto py = [&](Real e) { return oy + kTop + (e1 - std::log10(e)) / (e1 - e0) * plotH; };

        svg << "<g class=\"panel\" id=\"" << xmlEscape(problem) << "\">\n";
        svg << "<text x=\"" << ox + kLeft + plotW / 2 << "\" y=\"" << oy + 25
            << "\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" << xmlEscape(problem) << "</text>\n";
        svg << "<rect x=\"" << ox + kLeft << "\" y=\"" << oy + kTop << "\" width=\"" << plotW << "\" height=\"" << plotH
            << "\" fill=\"none\" stroke=\"black\"/>\n";
        // Decade ticks; with many decades label every second or third so the labels do not collide.
        const int tStride = (t1 - t0) > 6 ? 2 : 1, eStride = (e1 - e0) > 8 ? ((e1 - e0) > 14 ? 3 : 2) : 1;
        for (int d = t0; d <= t1; ++d) {
            const Real x = px(std::pow(10.0, d));
            svg << "<line x1=\"" << x << "\" y1=\"" << oy + kTop + plotH << "\" x2=\"" << x << "\" y2=\""
                << oy + kTop + plotH + 5 << "\" stroke=\"black\"/>";
            if ((d - t0) % tStride == 0)
                svg << "<text x=\"" << x << "\" y=\"" << oy + kTop + plotH + 18 << "\" text-anchor=\"middle\">1e" << d
                    << "</text>";
            svg << "\n";
        }
        for (int d = e0; d <= e1; ++d) {
            const Real y = py(std::pow(10.0, d));
            svg << "<line x1=\"" << ox + kLeft - 5 << "\" y1=\"" << y << "\" x2=\"" << ox + kLeft << "\" y2=\"" << y
                << "\" stroke=\"black\"/>";
            if ((d - e0) % eStride == 0)
                svg << "<text x=\"" << ox + kLeft - 8 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e" << d
                    << "</text>";
            svg << "\n";
        }
        svg << "<text x=\"" << ox + kLeft + plotW / 2 << "\" y=\"" << oy + kPanelHeight - 12
            << "\" text-anchor=\"middle\">CPU time per run (s)</text>\n";
        svg << "<text x=\"" << ox + 14 << "\" y=\"" << oy + kTop + plotH / 2
            << "\" text-anchor=\"middle\" transform=\"rotate(-90 " << ox + 14 << " " << oy + kTop + plotH / 2
            << ")\">error</text>\n";

        for (size_t i = 0; i < kIntegrators.size(); ++i) {
            std::vector<const AccuracyRow*> curve;
            for (const AccuracyRow* row : rows)
                if (row->integrator == kIntegrators[i])
                    curve.push_back(row);
            std::sort(curve.begin(), curve.end(),
                      [](const AccuracyRow* a, const AccuracyRow* b) { return a->cpuSeconds < b->cpuSeconds; });
            svg << "<polyline class=\"curve\" data-integrator=\"" << xmlEscape(integratorName(kIntegrators[i]))
                << "\" fill=\"none\" stroke=\"" << colors[i] << "\" stroke-width=\"1.5\" points=\"";
            for (const AccuracyRow* row : curve)
                svg << px(std::max(row->cpuSeconds, 1e-12)) << "," << py(std::max(row->error, kErrorFloor)) << " ";
            svg << "\"/>\n";
            for (const AccuracyRow* row : curve)
                svg << "<circle cx=\"" << px(std::max(row->cpuSeconds, 1e-12)) << "\" cy=\""
                    << py(std::max(row->error, kErrorFloor)) << "\" r=\"2\" fill=\"" << colors[i] << "\"/>";
            svg << "\n";
        }
        // Pareto front: sorted by time, keep each row that is more accurate than every faster one.
        std::vector<const AccuracyRow*> sorted = rows;
        std::sort(sorted.begin(), sorted.end(), [](const AccuracyRow* a, const AccuracyRow* b) {
            return a->cpuSeconds < b->cpuSeconds || (a->cpuSeconds == b->cpuSeconds && a->error < b->error);
        });
        svg << "<polyline class=\"pareto\" fill=\"none\" stroke=\"#777\" stroke-dasharray=\"4 3\" points=\"";
        Real best = std::numeric_limits<Real>::max();
        for (const AccuracyRow* row : sorted) {
            if (row->error < best) {
                best = row->error;
                svg << px(std::max(row->cpuSeconds, 1e-12)) << "," << py(std::max(row->error, kErrorFloor)) << " ";
            }
        }
        svg << "\"/>\n</g>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

Status writeAccuracySvg(const AccuracyReport& report, const std::string& path) {
    return writeFileAtomically(path, accuracySvg(report));
}

} // namespace rl
