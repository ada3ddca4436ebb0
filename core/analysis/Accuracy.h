// The accuracy-versus-cost study behind `rigidlab-cli accuracy`: every integrator on problems with exact answers, at
// several step sizes and substep counts, with the error, the CPU time, the fitted convergence order, a CSV and an SVG
// plot.
#pragma once

#include "common/Result.h"
#include "math/Types.h"
#include "scene/WorldSettings.h"

#include <span>
#include <string>
#include <vector>

namespace rl {

// The problems. Each error is dimensionless or in radians, as stated, so that all panels share one scale.
//   oscillator            y'' = -y on [0, 2 pi], y(0) = 0, y'(0) = 1: the original project's experiment (estimate
//                         sin t with 10, 20, 40 steps), run with more step counts for the fit. Error: the state's,
//                         max over the steps of |y_k - sin t_k| and |y'_k - cos t_k| (Accuracy.cpp says why both).
//   projectile            a body under gravity, no drag; exact parabola. Error: |x(T) - exact| / |exact - x(0)|.
//   projectile-drag       the same with linear drag c (the integrators' damping); exact exponential solution.
//   tumbling-orientation  a torque-free asymmetric body spun near its intermediate axis, where errors grow fastest;
//                         reference: RK4 at a step 16 times finer than the finest row. Error: angle to it (rad).
//   tumbling-energy       the same runs: |E(T) / E0 - 1|.
//   tumbling-momentum     the same runs: | |L(T)| / |L0| - 1 |.
//   incline               a block sliding from rest down a 30 degree incline with Coulomb friction 0.3, the friction
//                         applied the way the contact solver will: as a velocity impulse between the two phases.
//                         Exact: x(t) = g (sin - mu cos) t^2 / 2. Error: |x(T) - exact| / exact.
//   bounce-per-step       a point dropped from h0 onto a floor with restitution e, the contact found at the end of each
//                         substep and resolved on the velocity (as the world does). Reference apex heights e^(2n) h0.
//                         Error: max over the first four apexes of |apex - e^(2n) h0| / h0.
//   bounce-exact          the same with the impact time located exactly inside the substep, which is split there.
// The oscillator varies the number of steps with one substep; the others run at 60 frames per second and vary the
// substep count, as the world does.
struct AccuracyRow {
    std::string problem;
    Integrator integrator = Integrator::SymplecticEuler;
    int steps = 0;         // steps (frames) over the run
    Real dt = 0.0;         // step (frame) length, s
    int substeps = 1;      // substeps per step; the integrators see dt / substeps
    Real error = 0.0;      // see the problem list
    Real cpuSeconds = 0.0; // one run: the fastest batch's time per run (see AccuracyOptions)
};

// Least-squares slope of log(error) against log(dt / substeps) over the rows in the asymptotic range (see
// AccuracyOptions). NaN when fewer than two rows qualify: the integrator is exact on the problem up to rounding.
struct AccuracyOrder {
    std::string problem;
    Integrator integrator = Integrator::SymplecticEuler;
    Real order = 0.0;
    int points = 0; // rows used by the fit
};

struct AccuracyReport {
    std::vector<AccuracyRow> rows;
    std::vector<AccuracyOrder> orders;
    std::vector<std::string> problems; // in the order they were run
};

struct AccuracyOptions {
    // Each row's run is repeated for about this long (in five batches; the fastest counts), so that neither timer
    // resolution nor preemption by other processes decides the figure.
    Real minTimingSeconds = 1e-3;
    // Errors below this are rounding, not truncation: such rows are left out of the fit.
    Real roundingFloor = 1e-11;
    // Errors above this are not yet in the asymptotic range (explicit Euler's coarse oscillator rows are off by more
    // than the amplitude): such rows are printed but left out of the fit.
    Real asymptoticCeiling = 0.1;
};

AccuracyReport runAccuracyStudy(const AccuracyOptions& options = {});

// The fit on its own: slope of log(error) over log(stepSize), using the pairs with floor < error < ceiling.
// Returns NaN (and points = 0 or 1) when fewer than two pairs qualify.
Real fitConvergenceOrder(std::span<const Real> stepSizes, std::span<const Real> errors, Real floor, Real ceiling,
                         int* points = nullptr);

// Fixed-width text: the rows, then one line per problem with the fitted order of each integrator ("exact" for NaN).
std::string formatAccuracyTable(const AccuracyReport& report);

// problem,integrator,steps,dt,substeps,step,error,cpu_seconds (step = dt / substeps), numbers round-trip exactly.
std::string accuracyCsv(const AccuracyReport& report);
Status writeAccuracyCsv(const AccuracyReport& report, const std::string& path);

// Error against CPU time, log-log, one panel per problem, one polyline per integrator, decade ticks, a legend, and
// the Pareto front across integrators (the rows no other row beats on both error and time) as a dashed line.
std::string accuracySvg(const AccuracyReport& report);
Status writeAccuracySvg(const AccuracyReport& report, const std::string& path);

} // namespace rl
