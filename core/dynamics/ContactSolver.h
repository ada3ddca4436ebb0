// Soft-step contact solver: sequential impulses with warm starting, soft (spring-damper) contacts, Coulomb friction
// on two tangents and a restitution pass after the substeps. The world calls it once per substep (DESIGN.md §2).
#pragma once

#include "collision/Manifold.h"
#include "math/Types.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace rl {

// Hot per-body state the solver reads and writes during a step. Positions are not needed: the solver measures the
// current separation from the position change since the step began (dp, dR), as Box2D v3's soft step does, so the
// collision manifolds are computed once per step and stay usable across substeps.
//
// Records are aligned to their size (alignas(256)): each is four whole cache lines, and none straddles a page. Left to
// the allocator, the array started 48 bytes into a line in one build and on a page in another, and large_pyramid's
// warm start, solve and relax stages on one pinned CPU took 1.78-1.83, 6.86-6.94 and 3.44-3.48 ms a step against
// 1.55-1.72, 6.19-6.47 and 3.10-3.28 (frames 5-45). Aligned to lines only, 2.10-2.15, 7.43-7.61 and 3.78-3.89 ms
// against 2.01-2.11, 7.22-7.44 and 3.66-3.82 aligned to 256 bytes, on a busier host (four interleaved runs,
// 2026-11-27).
struct alignas(256) SolverBody {
    Vec3 v{0.0};          // linear velocity of the centre of mass
    Vec3 w{0.0};          // angular velocity, world axes
    Vec3 dp{0.0};         // position change since the step began
    Mat3 dR{1.0};         // rotation change since the step began (a matrix: 9 multiplies per anchor)
    Real invMass = 0.0;   // 0 for anchors and kinematic proxies
    Mat3 invInertia{0.0}; // world axes, taken at the start of the step
    // Set by the caller when invInertia is, and stays through the step, a number times the identity (+0 off the
    // diagonal): a cube's, a sphere's, the zeros of an anchor. The batched sweeps then multiply by that number alone
    // where every body of a batch has it, with the same results (ContactSolverWide.cpp, isotropicTimes()).
    bool isotropic = false;
    // 32 doubles in all, so that the batches' gathers read each record as four whole blocks of eight doubles
    // (ContactSolverWide.cpp) without reading past the last one.
    Real unused[3] = {0.0, 0.0, 0.0};
};
static_assert(sizeof(SolverBody) == 256, "a solver body is four cache lines");

// Coefficients of a soft constraint for one substep length (see softness()).
struct Softness {
    Real biasRate = 0.0;     // 1/s: velocity bias per metre of overlap
    Real massScale = 1.0;    // fraction of the rigid impulse applied
    Real impulseScale = 0.0; // fraction of the accumulated impulse relaxed away
};
Softness softness(Real omega, Real dampingRatio, Real h);

// The normal rows of one struck manifold, solved together (solveImpactRows()). Row i's velocity changes by
// K_ij per unit impulse on row j, K_ij = massA + massB + angularA_i . inertiaA_j + angularB_i . inertiaB_j, where
// angular is r x n and inertia I^-1 (r x n) of each side (zero for a side that does not move).
struct ImpactRows {
    int count = 0;
    Real massA = 0.0, massB = 0.0;
    Vec3 angularA[4], angularB[4], inertiaA[4], inertiaB[4];
    Real velocity[4] = {}; // each row's velocity now
    Real target[4] = {};   // the velocity each row must reach
    Real softness[4] = {}; // a soft row's give: it stops at target - softness * impulse (0 for a rigid row)
    Real impulse[4] = {};  // in: the accumulated impulses; out: the new ones, where solveImpactRows() succeeds
    unsigned guess = 0;    // bit i: row i is likely pushing in the answer (tried first; any guess gives the answer)
};
// Row i's target and give in such a block from its separation s now, as a sweep takes them: a speculative row
// (s > 0) may close the gap within the substep; a touching one is soft while the bias pushes it apart (short of its
// target by impulseScale / (massScale * normalMass) times its impulse, where repeated sweeps leave it), and rigid in
// the relax pass.
inline void setImpactTarget(ImpactRows& rows, int i, Real s, bool useBias, Real inverseH, const Softness& soft,
                            Real maxPushoutSpeed, Real normalMass) {
    Real bias = 0.0;
    if (s > 0.0) {
        bias = s * inverseH;
    } else if (useBias) {
        bias = std::max(soft.biasRate * s, -maxPushoutSpeed);
        rows.softness[i] = soft.impulseScale / (soft.massScale * normalMass);
    }
    rows.target[i] = -bias;
}
// Finds the accumulated impulses, all at least zero, with which every row ends at its target or above it with no
// impulse (a linear complementarity problem); false, with impulse unchanged, where no set of pushing rows gives
// that (only where the block is degenerate: a problem of this kind has an answer).
bool solveImpactRows(ImpactRows& rows);

struct ContactSolverSettings {
    // Contact stiffness as a frequency. A soft contact under a load F settles F / (m_eff * omega^2) deep, so
    // stiffer is better for stacks, but above about a quarter of the substep rate the spring stops being resolved.
    // The world sets a quarter of the substep rate (Box2D v3's cap); the damping ratio of 10 is Box2D's
    // (heavily over-damped, so contacts do not ring).
    Real contactHertz = 30.0;
    Real dampingRatio = 10.0;
    // Overlap is pushed apart no faster than this (m/s). It bounds how violently deeply overlapping bodies separate.
    Real maxPushoutSpeed = 3.0;
    // Restitution applies only above this approach speed (m/s); slower impacts come to rest instead of jittering.
    Real restitutionThreshold = 1.0;
    // Gravity (m/s^2) of the moving bodies. The restitution pass uses it to turn the solver's velocities into the
    // speeds at the instant of impact (see applyRestitution()).
    Vec3 gravity{0.0};
    // The whole step (s), of which the substeps are parts. Not 0: the restitution pass bounds a bounce's energy by
    // the bodies' energy at the step start (see applyRestitution()). 0: no bound.
    Real step = 0.0;
    // Where a body's stored velocity v sits on its free flight under constant acceleration a: the integrator moves
    // it as the exact parabola through its positions whose velocity is v + flightOffset a h (h the substep). That is
    // +1/2 for symplectic Euler (x += (v + a h) h), 0 for Verlet and RK4 (exact), -1/2 for explicit Euler
    // (x += v h before v += a h). The restitution pass measures impacts and launches bounces on that parabola.
    Real flightOffset = 0.5;
    // A manifold struck this step against something that does not move (a point approaching faster than
    // restitutionThreshold at the step start; ContactConstraint::impact) has its normal rows solved as a block in
    // a sweep where one of them is more than this (m/s) off its target when its turn comes: one that takes some of
    // the blow, or gives back what the warm start applied again. Gravity alone leaves a row g h short (0.027 m/s at
    // 360 Hz). See solveConstraint(). (0.1, 0.3, 0.5 and 1.0 all pass the stacking and drop tests, 2026-12-05;
    // 0.5 solves fewer blocks than 0.1 and stays well under the 1 m/s of an impact.)
    Real impactShortfall = 0.5;
    // Blows, taken before the substeps. A sweep hands a blow on one contact at a time, and two sweeps a substep leave
    // part of it in the accumulated impulses, which the next substeps' warm starts give again: a 0.5 m box coming down
    // at 10 m/s onto an equal box resting on the floor (restitution 0) sent both up at 0.84 m/s, 43 mm high, and onto
    // a stack of four, the stack at 1.5 m/s. So the manifolds struck this step (a point closing faster than blowSpeed
    // from near enough to meet within the step) between two moving bodies, or whose moving body has another manifold,
    // and the manifolds that bear each struck body up, and those under them down to the ground (kBlowDepth bodies
    // down), are first solved as collisions from the velocities at the step start (absorbBlows()): blowPasses sweeps
    // over them, then blowShockPasses sweeps from the ground up with each lower body held still under a manifold
    // within 18 degrees of vertical (shock propagation, Guendelman et al. 2003); rigid, each manifold's rows as one
    // block, from zero impulses that are then dropped; a kind of pass that would leave the bodies more kinetic energy
    // is undone. The substeps find the blow taken and warm start with the last step's loads only. Manifolds that
    // bounce (restitution above 0, with restitution on) are left to the substeps and the restitution pass. 0 and 0:
    // none. (The world sets 4 and 2: WorldTuning::blowPasses.)
    Real blowSpeed = 1.0;
    int blowPasses = 0;
    int blowShockPasses = 0;
    bool friction = true;
    bool restitution = true;
    bool warmStarting = true;
};

struct ContactSolverCounters {
    uint64_t normalRows = 0;   // normal constraint rows solved (points x iterations)
    uint64_t frictionRows = 0; // friction rows solved: two tangents and the twist per manifold and sweep
    uint64_t restitutionRows = 0;
    uint64_t boundedBounces = 0; // launches of the restitution pass taken back to the energy of the step start
    uint64_t sweptBatches = 0;   // batches swept by the solve and relax sweeps (each of up to 8 or 4 constraints)
    uint64_t blowRows = 0;       // normal rows solved by absorbBlows() (not in normalRows)
    ContactSolverCounters& operator+=(const ContactSolverCounters& o) {
        normalRows += o.normalRows;
        frictionRows += o.frictionRows;
        restitutionRows += o.restitutionRows;
        boundedBounces += o.boundedBounces;
        sweptBatches += o.sweptBatches;
        blowRows += o.blowRows;
        return *this;
    }
};

// One manifold's solver data. bodyA/bodyB index the SolverBody array; a static body is an entry with invMass 0.
struct ContactConstraint {
    struct Point {
        // Anchors relative to each centre of mass, world axes, at the step start: rB is rA + anchorOffset (both
        // rounded to float; see setUpConstraint()). A side that does not move (entry 0) has the other side's anchor.
        Vec3 rA{0.0}, rB{0.0};
        Real baseSeparation = 0.0; // separation minus the anchor term, so dp/dq give the current separation
        // A row d reads and applies velocities through r x d for each body and that times its world inverse inertia:
        // (w x r) . d = w . (r x d), and the angular change of an impulse j d is j I^-1 (r x d). They are worked out
        // where a sweep needs them, not stored: 12 vectors a point were 70 % of a constraint's size, and prepare(),
        // storeImpulses() and the restitution pass streamed them through the cache for every constraint.
        Real normalMass = 0.0;
        Real normalImpulse = 0.0;
        Real maxNormalImpulse = 0.0; // the largest impulse one row applied; kept only while restitution is on
        Real relativeVelocity = 0.0; // normal speed at impact (prepare() projects it from the step start)
        Real leverArm = 0.0;         // distance from the friction centre: its normal impulse's share of the twist limit
    };
    uint32_t bodyA = 0, bodyB = 0;
    Vec3 anchorOffset{0.0}; // every point's rB - rA: A's centre less B's, rounded to float; zero beside entry 0
    Vec3 normal{0.0, 1.0, 0.0};
    Vec3 tangent[2];
    Real friction = 0.0;
    Real restitution = 0.0;
    Real approachAcceleration = 0.0; // normal relative acceleration from gravity, for the speed at impact
    int pointCount = 0;
    Point points[4];
    uint8_t order[4] = {0, 1, 2, 3}; // the normal rows' solve order: by separation at the step start
    bool impact = false;             // struck this step: its normal rows may be solved as a block (impactShortfall)
    bool blow = false;               // struck this step faster than blowSpeed (ContactSolverSettings::blowPasses)
    // Friction acts once per manifold, at its friction centre (the anchors' mean): the two tangent rows solved as one
    // 2x2 block and clamped to the disc of radius friction x the manifold's normal impulse, and a twist row about the
    // normal, clamped to friction x the sum of each point's normal impulse times its distance from the centre.
    // (Box3D's "central friction". Per-point friction took eight rows for a face contact where this takes three, and
    // clamped each tangent alone, a square instead of Coulomb's disc.)
    Vec3 centerA{0.0}, centerB{0.0};        // the friction centre relative to each centre of mass, world axes
    Real frictionMass[3] = {0.0, 0.0, 0.0}; // the inverse of the 2x2 tangent block: (0,0), (0,1), (1,1)
    Real frictionImpulse[2] = {0.0, 0.0};   // accumulated, along tangent[0] and tangent[1]
    Real twistMass = 0.0;
    Real twistImpulse = 0.0;
    // The scale of each side's inverse mass and inertia in this constraint: 0 for a side held still, between 0 and 1
    // for one made heavier here (see prepare()'s held), else 1. Multiplying by 1 changes no bit, so constraints that
    // hold nothing give the same numbers.
    Real scaleA = 1.0, scaleB = 1.0;
};

class ContactSolver {
public:
    static constexpr uint8_t kHoldA = 1, kHoldB = 2;
    // A speculative point this far apart (m) weighs a quarter in the friction centre: the speculative distance.
    static constexpr Real kCenterFalloff = 0.02;
    // Each point's lever arm in the twist limit is at least this (m, 2^-7, exact in float): a point contact stands for
    // a small patch, so that it resists spin about its normal (MuJoCo's default torsional friction is 5 mm x the normal
    // force; this is 7.8 mm x the friction coefficient). With none, a box wedged between two others by two corners
    // spun freely about the line through them, at up to 3.5 rad/s for seconds, and held its pile's island awake.
    static constexpr Real kPatchRadius = 0.0078125;
    // A side of a manifold held for its constraint (prepare()): kHoldA, kHoldB or 0 for none, and the scale of that
    // side's inverse mass and inertia (0: held still).
    struct Hold {
        uint8_t side = 0;
        Real scale = 0.0;
    };

    // Calls body(begin, end) for ranges that together cover [0, count) once each, on one thread or several.
    using ParallelFor = std::function<void(size_t count, const std::function<void(size_t begin, size_t end)>& body)>;

    // Builds constraints from manifolds (pointers to them: the world's contacts are not copied, some 450 bytes each;
    // storeImpulses() writes to the same ones). solverIndexA/B map each manifold to SolverBody entries; friction and
    // restitution are the combined values per manifold; centers are the bodies' centres of mass at the step start
    // (indexed like bodies). h is the substep length.
    //
    // parallelFor, if given, runs the per-constraint part of the set-up split up (each constraint is set up alone).
    //
    // bodyPart, if given, puts each solver body in part 0 or 1 (entry 0, the static one, is in none). The constraints
    // are then swept in three segments: those within part 0, those within part 1, and the boundary (a constraint
    // between a body of each part), the parts in manifold order, the boundary in an order of colours (see
    // scheduleLevels()). The two parts share no moving body, so two threads can sweep them at once with no barrier
    // between levels (segmentLevelBegin()).
    //
    // held, if given, holds one side of each manifold for its constraint (Hold: side kHoldA or kHoldB, else 0). A side
    // held with scale 0 is read but the constraint's impulses do not move it, as if it were infinitely heavy, so the
    // other body is stopped by it in one sweep (shock propagation: World holds the lower of two bodies). A scale
    // between 0 and 1 multiplies that side's inverse mass and inertia in this constraint only.
    //
    // packParts, if given, is asked once the levels of the sequential order are known (Schedule: constraints and
    // levels per segment) whether every part (without parts: all the constraints) will be swept by one thread alone.
    // If it says so, those levels are packed into batches (packPartLevels()): each level is then one batch, and the
    // sweeps take fewer batches for the same updates in the same order per body. Levels so packed are too narrow to
    // share out over a team level by level.
    static constexpr size_t kParts = 2;
    static constexpr size_t kBoundarySegment = kParts; // segments 0 .. kParts - 1 are the parts
    struct Schedule {
        std::array<size_t, kParts + 1> constraints{}, levels{}; // per segment, before any packing
    };
    using PackParts = std::function<bool(const Schedule&)>;
    void prepare(std::span<Manifold* const> manifolds, std::span<const uint32_t> solverIndexA,
                 std::span<const uint32_t> solverIndexB, std::span<const Real> friction,
                 std::span<const Real> restitution, std::span<const SolverBody> bodies, std::span<const Vec3> centers,
                 Real h, const ContactSolverSettings& settings, std::span<const uint8_t> bodyPart = {},
                 const ParallelFor& parallelFor = {}, std::span<const Hold> held = {}, const PackParts& packParts = {});

    // Takes the step's blows out of the bodies' velocities (ContactSolverSettings::blowPasses), before the substeps,
    // on the bodies as prepare() had them; keeps no impulse. A team (parallelFor) sweeps groups of them that share no
    // moving body apart: the same numbers.
    void absorbBlows(std::span<SolverBody> bodies, const ParallelFor& parallelFor = {});
    // The bodies whose velocities the last absorbBlows() may have changed (solver indices, ascending).
    const std::vector<uint32_t>& blowBodies() const { return m_blowBodies; }
    // Whether the last prepare() found blows to absorb, and (for tests) their constraints, as indices into the
    // manifolds given to prepare(), in the order absorbBlows() first sweeps them.
    bool hasBlows() const { return !m_blows.empty(); }
    const std::vector<uint32_t>& blowConstraints() const { return m_blowIndex; }
    // How far down from a struck body absorbBlows() follows the bodies that bear it up.
    static constexpr int kBlowDepth = 16;
    // From this many blows on, a team shares their set-up out (findBlows()) and their groups (absorbBlows()).
    static constexpr size_t kMinSharedBlows = 32;
    // A manifold whose nearest point is farther apart than this (m) bears nothing up for absorbBlows() unless struck.
    static constexpr Real kBlowSupportGap = 0.01;
    // The shock passes hold a lower body still only under a manifold whose normal rises at least this much (its
    // cosine from vertical: within 18 degrees). Measured 2026-12-06 over 300 piles of 1,000 boxes (four layouts, seeds
    // 1-75): within 45 degrees, as the walk down goes, 5 of the first 120 still moved in their last second (0 before
    // this pass) and the frames with a contact deeper than 1 cm fell from 2,292 to 1,210; within 18 degrees, 3 of 300
    // moved (6 before, one of them a box fallen through the floor), the frames deeper than 1 cm 3,688 (5,722).
    static constexpr Real kBlowHoldRise = 0.95;

    // Called once per substep, after the velocities were integrated: applies the accumulated impulses (those of
    // the last step at first, then this step's so far).
    void warmStart(std::span<SolverBody> bodies);
    // Whether the bodies' motion since the step began (SolverBody::dp, dR) may have changed since the last sweep.
    // A point's separation depends on nothing else, so a sweep after Moved takes it from the motion and keeps it, and
    // a sweep after Unchanged reads the kept one: the same numbers, without the anchors' two rotations and the gather
    // of dp and dR. Moved is always right; Unchanged is the caller's promise that a sweep since the last prepare()
    // took the separations and that no dp or dR changed since. (The world's substep: the velocities, the warm start
    // and the solve sweeps, the positions, the relax sweep. The separations stay the same from one relax sweep
    // through the next substep's solve sweeps.)
    enum class Motion : uint8_t { Moved, Unchanged };
    // useBias = true: the soft solve that pushes overlap apart; false: the relax pass that removes the bias velocity.
    // Motion::Unchanged is taken as Moved in the first sweep after prepare().
    void solve(std::span<SolverBody> bodies, bool useBias, Motion motion = Motion::Moved);

    // warmStart() and solve() sweep the constraints level by level (see scheduleLevels()), in batches: the
    // constraints of one level share no moving body, so they are packed into batches of laneWidth() lanes
    // (ContactSolverWide.cpp) whose lanes run side by side in vector registers, eight doubles in an AVX-512 register
    // where the CPU has it (x86-64-v4), else four. Every body still receives the same updates in the same order as in
    // the sequential sweep, segment by segment (warmStartSequential(), solveSequential(); see prepare()), so the
    // results are the same numbers, whatever the width and the order of the batches within a level. A part whose
    // levels were packed (packParts in prepare()) has one batch a level.
    //
    // The same, split up for several threads: batches begin..end within one level may run on different threads at
    // once. A substep is beginSubstep() once, then warmStartBatchRange() over every level, then sweeps of
    // solveBatchRange() over every level, each sweep followed by countSweep() once. Every range of one sweep is given
    // the same Motion (see solve()), and the first sweep after prepare() must be Moved.
    size_t levelCount() const { return m_levelStart.empty() ? 0 : m_levelStart.size() - 1; }
    size_t levelBegin(size_t level) const { return m_levelStart[level]; } // positions in solveOrder()
    size_t levelEnd(size_t level) const { return m_levelStart[level + 1]; }
    size_t batchLevelBegin(size_t level) const { return m_batchLevelStart[level]; } // batch indices
    size_t batchLevelEnd(size_t level) const { return m_batchLevelStart[level + 1]; }
    std::span<const uint32_t> solveOrder() const { return m_solveOrder; } // constraint indices, level by level
    // The levels of segment s (a part, or the boundary): [segmentLevelBegin(s), segmentLevelBegin(s + 1)). Without
    // parts, segment 0 holds every level.
    size_t segmentLevelBegin(size_t segment) const { return m_segmentLevelStart[segment]; }
    // The batches of segment s: [first, second), for sweeping a whole part with warmStartBatchRange() and
    // solveBatchRange().
    std::pair<size_t, size_t> segmentBatches(size_t segment) const {
        return {m_batchLevelStart[m_segmentLevelStart[segment]], m_batchLevelStart[m_segmentLevelStart[segment + 1]]};
    }
    void beginSubstep() { m_batchesAhead = true; }
    void warmStartBatchRange(std::span<SolverBody> bodies, size_t begin, size_t end);
    void solveBatchRange(std::span<SolverBody> bodies, bool useBias, size_t begin, size_t end,
                         Motion motion = Motion::Moved);
    void countSweep();

    // The reference: one constraint after the other, segment by segment (forEachInSequence()), with scalar arithmetic.
    // Tests compare the batched sweeps with it. Use one kind of sweep per prepare(), not both.
    void warmStartSequential(std::span<SolverBody> bodies);
    void solveSequential(std::span<SolverBody> bodies, bool useBias);

    // Bounces every point that approached faster than the threshold and pushed back: it leaves at -e times its
    // normal speed at the instant of impact (prepare() projects that from the step start, see setUpConstraint()).
    // Speeds are those of the flight the integrator actually moves along (ContactSolverSettings::flightOffset): under
    // symplectic Euler a body that leaves at the stored speed u climbs as if it had left at u + a_n h / 2, where a_n
    // is the relative acceleration along the normal (gravity on one body of the pair, not the other), so the target
    // is -e v_impact - flightOffset a_n h. Without the offsets each bounce lost (1 + e) g h / 2 of speed, and the
    // third apex of an e = 0.5 drop from 5 m came out 5.0 % low (issue 4 asks for 3 %).
    //
    // A struck manifold whose moving body also touches another bouncing manifold (a ball hitting a row of touching
    // balls, one landing on a ball that rests on the floor) is one link of a chain, and the rule above is wrong
    // there: the sweeps stopped the whole row as one lump, and each link's speed before the step says nothing of the
    // blow it passed on. Such chains are worked out as collisions one after the other, from the velocities at the
    // step start (bounceChains()), and each of their points leaves at the speed that gives.
    //
    // A manifold that holds a side (ContactConstraint::scaleA, scaleB) bounces alone and with the bodies' own masses,
    // and no bounce leaves its bodies more energy than they had at the step start: kinetic energy no more than that
    // at the start plus gravity's work over each body's motion through the step (launch()). (Until 2026-12-07 the
    // bound was the kinetic energy of free flight through the step and a substep, more than a body that landed within
    // the step ever has: boxes, cones and planks landing frictionless with e 0.95-1 while they spun gained up to 2.1 %
    // of their energy.)
    // That bound takes each body's kinetic energy at the step start with its inverse inertia then (kept by prepare()),
    // and its energy now with `poseInverseInertia(i)` for solver body i where given: its inverse inertia at its current
    // pose, where the sweeps may have taken another (BodyState::solverInverseInertia()). It is asked only for the
    // bodies of a bounce, so a step in which nothing bounces pays nothing for it. Measured in the sweeps' metric
    // instead, a rod turned 2.5 rad in the step counted its spin about its length at 200 times its energy, and its
    // bounces threw it up (2026-12-07).
    using PoseInverseInertia = std::function<Mat3(uint32_t body)>;
    void applyRestitution(std::span<SolverBody> bodies, const PoseInverseInertia& poseInverseInertia = {});
    // Writes the accumulated impulses back to the manifolds (those given to prepare()) for warm starting in the next
    // step. parallelFor, if given, shares the manifolds out (each is written alone, so the results are the same).
    void storeImpulses(std::span<Manifold* const> manifolds, const ParallelFor& parallelFor = {}) const;

    // One value per lane of a batch of W lanes (the batch storage below; ContactSolverWide.cpp loads them into
    // vectors).
    template <int W>
    struct alignas(W * sizeof(Real)) Lanes {
        Real v[W];
    };
    template <int W>
    struct alignas(W * sizeof(float)) FloatLanes {
        float v[W];
    };
    // The lanes of the batches: 8 where the CPU runs x86-64-v4 (AVX-512), else 4 (chosen by buildBatches()).
    int laneWidth() const { return m_width; }
    // The sweeps this CPU runs, for benchmark reports: "8 lanes of doubles (AVX-512)", "4 lanes of doubles (AVX2)" or,
    // on an x86-64 CPU without AVX2, "(SSE2)"; "(portable)" from a compiler other than GCC or off x86-64. (The frames
    // are the same whichever runs; the time is not: the sweeps were 23 % of ramps.obj's step and 46 % of
    // large_pyramid's with four lanes, README "Whole steps".)
    static std::string sweepsDescription();
    // Batches whose bodies are all SolverBody::isotropic (the sweeps' shorter inverse inertia products).
    size_t isotropicBatchCount() const;
    // 4 keeps every solver's batches to four lanes; 8 (the default) lets them have eight where the CPU has AVX-512.
    // For tests, which compare the two widths; it applies to the next prepare().
    static void setWidestLanes(int lanes) { s_widestLanes = lanes; }
    // The batches (and the records, where kept) are set up W constraints at a time in vectors (ContactSolverWide.cpp),
    // with the same numbers as setUpConstraint(). For tests, which compare the two: false sets every constraint up
    // alone; it applies to the next prepare().
    static void setWideSetUp(bool on) { s_wideSetUp = on; }
    // false takes every point's separation in every sweep, as if each were given Motion::Moved. For tests, which
    // compare the two; set it while no sweep runs.
    static void setKeepSeparations(bool on) { s_keepSeparations = on; }
    // false keeps the levels of the sequential order even where packParts says a thread sweeps the parts alone (see
    // prepare()). For tests and benchmarks, which compare the two; it applies to the next prepare().
    static void setPackLevels(bool on) { s_packLevels = on; }

    // The whole constraint records, in manifold order, with the impulses of the last sweep. prepare() keeps them only
    // when asked to (keepConstraints()); else this is empty. The sequential sweeps work on these records.
    const std::vector<ContactConstraint>& constraints() const {
        static const std::vector<ContactConstraint> kNone;
        syncFromBatches();
        return m_kept ? m_constraints : kNone;
    }
    // How many records the last prepare() kept for the restitution pass alone (restitution on, the records not kept
    // whole): those of the constraints that may bounce (mayBounce()).
    size_t bounceRecords() const {
        return m_bounceOnly ? static_cast<size_t>(std::count(m_bouncing.begin(), m_bouncing.end(), uint8_t(1))) : 0;
    }
    // For tests: keep the records at every prepare() from now on (the sequential sweeps need them).
    void keepConstraints(bool keep) { m_keepConstraints = keep; }
    const ContactSolverCounters& counters() const { return m_counters; }
    void resetCounters() { m_counters = {}; }

private:
    // A batch: W constraints of one level in lanes (an empty lane has bodies 0 and zero masses), with its points
    // in the store's points. Lane l's point k is its constraint's k-th point in solve order (ContactConstraint::order);
    // lanes with fewer points carry zero points, which apply no impulse. Lane l holds constraint
    // m_solveOrder[m_batchLayout[batch].first + l].
    template <int W>
    struct Batch {
        uint32_t bodyA[W] = {}, bodyB[W] = {};
        uint32_t firstPoint = 0, pointCount = 0;
        bool holds = false;     // a lane holds a side still: the sweeps scale that side's inverse mass and inertia
        bool isotropic = false; // every lane's two bodies are SolverBody::isotropic
        uint8_t impacts = 0;    // bit l: lane l's constraint is struck this step (ContactConstraint::impact)
        FloatLanes<W> normal[3], tangent[2][3];
        FloatLanes<W> anchorOffset[3]; // rB - rA of every point (ContactConstraint::anchorOffset)
        FloatLanes<W> friction;
        FloatLanes<W> centerA[3], centerB[3]; // the friction centres
        FloatLanes<W> frictionMass[3];        // the constraints' frictionMass
        FloatLanes<W> twistMass;              // likewise
        Lanes<W> frictionImpulse[2], twistImpulse;
    };
    // The constraints' scaleA and scaleB, read only by a batch that holds. (In the batch, with each lane's constraint
    // index, they made it 1,152 bytes instead of 960 with eight lanes: large_pyramid's solve and relax stages took
    // 6.28-6.59 and 3.12-3.27 ms a step, now 5.97-6.05 and 2.98-3.04 ms; its frames 5-45 on one pinned CPU, three
    // interleaved runs, 2026-11-27.)
    template <int W>
    struct BatchScales {
        Lanes<W> a, b;
    };
    // Only what a point cannot recompute is stored: the sweeps stream every point of the group through the cache
    // (54k in large_pyramid) and were bound by memory when the points carried their rows' r x d and I^-1 (r x d)
    // (1.6 kB per four lanes). Those are recomputed from the anchors and the bodies' inverse inertia, the same
    // numbers the scalar sweeps compute (ContactSolver.cpp); stored again as floats, they made large_pyramid's solve
    // stage slower (8.5 against 7.5 ms a step, 2026-11-27). Anchors, directions, friction centres, separations and
    // masses are floats (prepare() rounds them for both kinds of sweep); impulses stay double. With the anchors and
    // the batches' directions and centres in doubles, large_pyramid's warm start, solve and relax stages took 9-11 %
    // longer (three interleaved runs on one pinned CPU, 2026-11-27); ramps, whose batches stay in the cache, was about
    // 4 % faster. A float anchor is within 2^-24 of its length: 0.03 mm for a point 500 m from its body's centre.
    // Accumulated impulses rounded to float made the solve stage slower (7.5 against 6.7-6.9 ms): the rounding sits
    // in each row's chain of dependent operations.
    // A point stores one anchor: rB is rA plus the batch's anchorOffset. With rB stored too (384 bytes a point of
    // eight lanes, now 256), large_pyramid's warm start and solve stages took 1.55-1.56 and 6.11-6.13 ms a step against
    // 1.45-1.50 and 6.03-6.09 in a quiet hour, and 2.05-2.13 and 7.46-7.58 against 1.87-2.04 and 7.07-7.10 while the
    // host was busy (its frames 5-45 on one pinned CPU, interleaved runs, 2026-11-27).
    template <int W>
    struct BatchPoint {
        FloatLanes<W> rA[3]; // rB is rA + the batch's anchorOffset, added in floats
        FloatLanes<W> baseSeparation;
        FloatLanes<W> mass;     // normal
        FloatLanes<W> leverArm; // distance from the friction centre
        Lanes<W> impulse;       // accumulated normal impulse
    };
    template <int W>
    struct BatchStore {
        std::vector<Batch<W>> batches;
        std::vector<BatchScales<W>> scales; // one per batch
        std::vector<BatchPoint<W>> points;
        // Each point's maxNormalImpulse, beside the points: only the restitution pass reads it, so it is kept (and
        // this sized like points) only while restitution is on. (Kept in every point, it was read and written by
        // every row of every sweep: large_pyramid's warm start, solve and relax stages took 1.78-1.81, 7.16-7.22 and
        // 3.58-3.63 ms a step, now 1.57-1.60, 6.48-6.53 and 3.24-3.27 ms; its frames 5-45 on one pinned CPU, three
        // interleaved runs, 2026-11-27.)
        std::vector<Lanes<W>> maxImpulse;
        // Each point's separation, as the last sweep after Motion::Moved took it (sized like points).
        std::vector<Lanes<W>> separation;
    };
    // Where buildBatches() puts a batch: its first constraint in m_solveOrder, its lanes, and its point slots.
    struct BatchLayout {
        uint32_t first, lanes, firstPoint, pointCount;
    };

    // prepare()'s inputs, for the set-up in buildBatches().
    struct SetUpInputs {
        std::span<Manifold* const> manifolds;
        std::span<const uint32_t> indexA, indexB;
        std::span<const Real> friction, restitution;
        std::span<const SolverBody> bodies;
        std::span<const Vec3> centers;
        std::span<const Hold> held;
    };
    template <int W>
    void buildBatches(BatchStore<W>& store, const SetUpInputs& inputs, const ParallelFor& parallelFor);
    template <int W>
    void syncFromBatches(const BatchStore<W>& store) const;
    template <int W>
    void storeFromBatches(const BatchStore<W>& store, std::span<Manifold* const> manifolds,
                          const ParallelFor& parallelFor, bool bouncersFromRecords) const;
    // Whether the restitution pass reads c's record: its restitution is not zero, and it is between two moving bodies
    // (a link a chain's collisions may strike, see applyRestitution()) or a point approached faster than the
    // threshold. (A constraint against a still body that approached slower cannot bounce: its record was 620 bytes
    // written for nothing, in every resting contact of ramps.obj's cubes on its concrete ramps.)
    bool mayBounce(const ContactConstraint& c) const;
    // applyRestitution()'s parts: one struck manifold that shares no moving body with another record, and the chains.
    void bounceAlone(std::span<SolverBody> bodies, uint32_t constraint);
    void bounceChains(std::span<SolverBody> bodies, std::span<const uint32_t> records,
                      std::span<const uint32_t> struck);
    // A constraint's points to launch (bit k for point k) and the normal speed each leaves at.
    struct Launch {
        uint32_t constraint = 0;
        uint8_t points = 0;
        bool bodiesOwnMasses = false; // swept with the bodies' own masses, not the constraint's held scales
        Real target[4] = {0.0, 0.0, 0.0, 0.0};
    };
    // The launch of c's points in `points` (bits) at normal speeds atSurface leaving the surface: the targets of the
    // restitution pass (see applyRestitution()).
    Launch launchOf(std::span<const SolverBody> bodies, uint32_t constraint, uint8_t points, const Real atSurface[4],
                    bool sweepsFloor) const;
    // Sweeps the launches together until their impulses settle (at most `passes` sweeps), then takes them back in
    // proportion as far as needed to leave their bodies no more kinetic energy than they had at the step start and
    // gravity gave them over their motion through the step (SolverBody::dp). Unless warmStartsNext, the points'
    // accumulated impulses are left as the sweeps left them, for the next step's warm start.
    void launch(std::span<SolverBody> bodies, std::span<const Launch> launches, int passes, bool warmStartsNext);
    void sweepLaunches(std::span<SolverBody> bodies, std::span<const Launch> launches, int passes);
    // A record's impulses into its manifold.
    static void storeRecord(const ContactConstraint& c, Manifold& m);
    // The sweeps over batches begin..end of W lanes (ContactSolverWide.cpp).
    void warmStartBatches4(std::span<SolverBody> bodies, size_t begin, size_t end);
    void warmStartBatches8(std::span<SolverBody> bodies, size_t begin, size_t end);
    void solveBatches4(std::span<SolverBody> bodies, bool useBias, size_t begin, size_t end, Motion motion);
    void solveBatches8(std::span<SolverBody> bodies, bool useBias, size_t begin, size_t end, Motion motion);
    template <int W>
    void warmStartBatches(BatchStore<W>& store, std::span<SolverBody> bodies, size_t begin, size_t end);
    template <int W, bool kMaxImpulse, bool kKeptSeparation>
    void solveBatches(BatchStore<W>& store, std::span<SolverBody> bodies, bool useBias, size_t begin, size_t end);
    // Sets batch b's constraints up in its lanes, all W at once, with the constraints' m_order and m_laneOf entries
    // and, where kept, their records (ContactSolverWide.cpp). False, having written nothing, in a build without
    // vector types (setUpConstraint() then sets them up one by one).
    template <int W>
    bool setUpBatch(BatchStore<W>& store, const SetUpInputs& inputs, size_t b);
    // Whether every body of the batch laid out at `at` is SolverBody::isotropic (Batch::isotropic). Empty lanes read
    // the static entry 0, so it counts too.
    template <int W>
    bool isotropicBatch(const SetUpInputs& inputs, const BatchLayout& at) const {
        bool isotropic = true;
        for (uint32_t l = 0; l < W; ++l) {
            const uint32_t i = l < at.lanes ? m_solveOrder[at.first + l] : 0;
            const uint32_t a = l < at.lanes ? inputs.indexA[i] : 0, b = l < at.lanes ? inputs.indexB[i] : 0;
            isotropic = isotropic && inputs.bodies[a].isotropic && inputs.bodies[b].isotropic;
        }
        return isotropic;
    }
    bool setUpBatch4(const SetUpInputs& inputs, size_t b);
    bool setUpBatch8(const SetUpInputs& inputs, size_t b);
    size_t batchCount() const { return m_width == 8 ? m_store8.batches.size() : m_store4.batches.size(); }
    void buildBatches(const SetUpInputs& inputs, const ParallelFor& parallelFor);
    // After buildBatches(): absorbBlows()' records (m_blows, m_shocks) from the struck constraints (m_struck).
    void findBlows(const SetUpInputs& inputs, const ParallelFor& parallelFor);
    void shareBlows(size_t bodyCount); // absorbBlows()' groups of blows to two members of a team
    // Copies the batches' impulses and impact records back to m_constraints, if a batched sweep ran since and
    // records are kept (m_kept, or m_bounceOnly for those of the constraints that may bounce).
    void syncFromBatches() const;
    bool hasRecord(size_t i) const { return m_kept || (m_bounceOnly && m_bouncing[i] != 0); }
    // m_batchKey from the manifolds (before scheduleLevels(), which may read it).
    void batchKeys(std::span<Manifold* const> manifolds, const ParallelFor& parallelFor);
    void scheduleLevels(size_t bodyCount, std::span<const uint8_t> bodyPart, std::span<const uint32_t> bodyA,
                        std::span<const uint32_t> bodyB, const PackParts& packParts, const ParallelFor& parallelFor);
    // For scheduleLevels(): replaces the level of every constraint of segment `part` (in levelOf) by its batch
    // within the segment, at most `width` constraints a batch, and sets `batches` to the segment's batch count.
    void packPartLevels(size_t part, size_t bodyCount, size_t width, std::span<const uint32_t> bodyA,
                        std::span<const uint32_t> bodyB, std::vector<uint32_t>& levelOf, uint32_t& batches) const;
    // The lanes of a batch on this CPU: 8 with AVX-512 (x86-64-v4), else 4 (buildBatches()).
    static int laneWidthHere();
    // Calls visit(constraint index) in the order of the sequential sweeps: the parts' constraints in manifold order,
    // then the boundary's level by level.
    template <class Visit>
    void forEachInSequence(Visit&& visit) const;
    void warmStartOne(std::span<SolverBody> bodies, const ContactConstraint& c);
    // One constraint's rows, a speculative row closing its gap within 1 / inverseH seconds.
    void solveOne(std::span<SolverBody> bodies, ContactConstraint& c, bool useBias, Real inverseH) const;

    size_t m_count = 0; // constraints (one per manifold) of the last prepare()
    // Every record (m_kept); or, with restitution on, only those of the constraints that may bounce (m_bounceOnly,
    // m_bouncing); else empty. With a record of 620 bytes written for every constraint and the restitution pass
    // looking at each, ramps.obj's first 120 frames took 100-123 ms in prepare_contacts and 14-19 ms in restitution;
    // with the records of those that may bounce only, 73-93 ms and 3.5-4.3 ms, and store_impulses 11-14 ms against
    // 14-19 ms (three interleaved runs of each, one thread, the same frames; Intel Xeon, 2026-11-29).
    mutable std::vector<ContactConstraint> m_constraints;
    bool m_kept = false;             // prepare() filled every record of m_constraints
    bool m_bounceOnly = false;       // prepare() filled the records of the constraints that may bounce
    std::vector<uint8_t> m_bouncing; // per constraint, when m_bounceOnly: 1 if its record is filled
    bool m_keepConstraints = false;  // keepConstraints()
    // With restitution on: each solver body's linear and angular velocity at prepare() (the step start), from which
    // bounceChains() works out a chain's collisions.
    std::vector<std::pair<Vec3, Vec3>> m_startVelocity;
    std::vector<Mat3> m_startInverseInertia; // beside m_startVelocity: each body's inverse inertia at the step start
    const PoseInverseInertia* m_poseInverseInertia = nullptr; // during applyRestitution(): its poseInverseInertia
    std::vector<std::array<uint8_t, 4>> m_order;              // per constraint: its ContactConstraint::order
    std::vector<uint8_t> m_batchKey; // per constraint: its group within its level (buildBatches())
    std::vector<uint8_t> m_struck;   // per constraint while blowPasses or blowShockPasses: ContactConstraint::blow
    // absorbBlows()' records: in manifold order (m_blowIndex: each one's constraint), and again from the ground up,
    // each lower body held (m_shocks).
    std::vector<ContactConstraint> m_blows, m_shocks;
    std::vector<uint32_t> m_blowIndex;
    // findBlows()' scratch: per body, its constraints (m_blowFirst, m_blowList), its level in the walk down and its
    // height; the walk's queue; per constraint, whether it is taken; the order from the ground up.
    std::vector<uint32_t> m_blowFirst, m_blowList, m_blowLevel, m_blowHeight, m_blowQueue;
    std::vector<uint8_t> m_blowTaken;
    std::vector<std::pair<uint32_t, uint32_t>> m_blowOrder;
    std::vector<std::pair<Vec3, Vec3>> m_blowSaved; // absorbBlows()' velocities before a kind of pass
    std::vector<uint32_t> m_blowBodies;             // absorbBlows()' moving bodies, ascending
    std::vector<Mat3> m_blowInertia;                // beside m_blowBodies: each one's inertia (0 where not invertible)
    // shareBlows(): per body, its root among the groups and (at a root) the group's constraints, then its member;
    // the groups by size; each member's records of m_blows and of m_shocks, in their order.
    std::vector<uint32_t> m_blowRoot, m_blowWeight;
    std::vector<std::pair<uint32_t, uint32_t>> m_blowGroups;
    std::array<std::vector<uint32_t>, 2> m_blowShare, m_shockShare;
    std::vector<BatchLayout> m_batchLayout; // per batch (buildBatches())
    std::vector<uint32_t> m_laneOf;         // per constraint: its batch times the lane width, plus its lane
    std::vector<uint32_t> m_solveOrder; // constraint indices, level by level (grouped within a level: buildBatches())
    std::vector<uint8_t> m_segment;     // per constraint: its part, or kBoundarySegment
    size_t m_segmentLevelStart[kParts + 2] = {};
    std::vector<uint32_t> m_levelStart;      // level k: m_solveOrder[m_levelStart[k], m_levelStart[k + 1])
    std::vector<uint32_t> m_batchLevelStart; // level k: batches [m_batchLevelStart[k], m_batchLevelStart[k + 1])
    BatchStore<4> m_store4;                  // the batches when m_width is 4
    BatchStore<8> m_store8;                  // when it is 8
    int m_width = 4;
    static int s_widestLanes;            // 8, or 4 to keep to four lanes
    static bool s_wideSetUp;             // setWideSetUp()
    static bool s_packLevels;            // setPackLevels()
    static bool s_keepSeparations;       // setKeepSeparations()
    mutable bool m_batchesAhead = false; // the batches hold newer impulses than m_constraints
    bool m_separationsKept = false;      // a whole sweep by solve() kept the separations since prepare()
    ContactSolverSettings m_settings;
    Real m_inverseH = 0.0;
    Real m_h = 0.0;
    Softness m_soft;
    ContactSolverCounters m_counters;
    ContactSolverCounters m_sweepRows; // rows of one sweep over every constraint
};

// body over [0, count): shared out by parallelFor if there is one, else in one call on this thread.
void shareOut(const ContactSolver::ParallelFor& parallelFor, size_t count,
              const std::function<void(size_t, size_t)>& body);

// Sorts [first, last) stably, in place, by insertion: the order std::stable_sort gives with the same comparison,
// without the heap buffer it takes on every call. For short runs: a manifold's points (at most four; with
// std::stable_sort, the set-up of boxes1000 on two threads called malloc and free some 70 times a step for them,
// 2026-12-04) and the short levels of sortByKey() (ContactSolver.cpp).
template <class T, class Less>
void stableSortSmall(T* first, T* last, Less less) {
    for (T* i = first + (first != last ? 1 : 0); i < last; ++i) {
        const T value = *i;
        T* j = i;
        for (; j != first && less(value, *(j - 1)); --j)
            *j = *(j - 1);
        *j = value;
    }
}

// Two unit tangents orthogonal to n, chosen deterministically.
void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2);

} // namespace rl
