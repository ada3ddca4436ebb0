// The step's named stages, their timings, and the counters that say how much work each stage did.
// The profile makes the cost of each effect visible: a skipped stage shows zero calls.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string_view>

namespace rl {

// In the order World::step runs them (DESIGN.md §2).
enum class Stage {
    UpdateBroadphase,
    FindPairs,
    Narrowphase,
    BuildIslands,
    PrepareContacts, // the solver's constraints from the manifolds: masses, friction centres, batches
    IntegrateVelocities,
    WarmStart,
    Solve,
    IntegratePositions,
    Relax,
    Restitution,
    StoreImpulses, // velocities, positions and accumulated impulses back to the bodies and manifolds
    PushOut,       // bodies the step took into anchors and sleepers moved out (World::pushOutOfContacts())
    Ccd,
    Separate, // contacts the step's turns took deeper collided again and pushed apart (World::separateMovedPairs())
    Sleep,
    StoreFrame,
    Count
};
inline constexpr int kStageCount = static_cast<int>(Stage::Count);
std::string_view stageName(Stage stage); // "update_broadphase", "find_pairs", ...

enum class Counter {
    Pairs,            // broadphase pairs
    PairsTested,      // pairs whose shapes were tested: a body moves and the tight boxes are within the margin
    Manifolds,        // touching manifolds
    ContactPoints,    // manifold points
    NormalRows,       // normal rows solved (points x passes)
    FrictionRows,     // friction rows solved
    RestitutionRows,  // restitution rows applied
    SweptBatches,     // batches of constraints swept side by side by the solve and relax sweeps (ContactSolver)
    AwakeBodies,      // awake dynamic bodies (per step)
    IntegratedBodies, // bodies moved by the integrator (per substep)
    CcdBodies,        // bodies swept by CCD
    CcdHits,          // sweeps that stopped a body
    Steps,
    IslandsSharedOut,   // solves whose islands a team of threads shared out (World::splitByIslands())
    IslandsCut,         // islands cut in two parts for the solver, on any number of threads (World::cutIslands())
    SolvedInParts,      // solves in which each of two threads swept one part (World::solveSubsteps())
    PartImbalance,      // bodies by which the larger of the two parts outnumbers the other, summed over the solves of
                        // a whole group with an island cut (World::planCuts())
    StepsAlone,         // steps a world with a team took on one thread, the team not paying (TeamPacer)
    TeamSteps,          // steps in which a world's team of threads ran at least one job together (ThreadTeam::run())
    IslandsInBodyOrder, // of IslandsSharedOut, the solves whose islands went to the members in runs of body order
    PushedContacts,     // contacts whose points World::pushOutOfContacts() moved a body out of
    BoundedBounces,     // bounces the restitution pass took back to the energy of free flight (ContactSolver::launch())
    SeparatedPairs,     // pushes World::separateMovedPairs() made (at most two a pair in each of its two passes)
    BlowRows,           // normal rows solved by the blows' passes before the substeps (ContactSolver::absorbBlows())
    Count
};
inline constexpr int kCounterCount = static_cast<int>(Counter::Count);
std::string_view counterName(Counter counter); // "pairs", "manifolds", ...

struct Profile {
    std::array<double, kStageCount> milliseconds{};
    std::array<uint64_t, kStageCount> calls{};
    std::array<uint64_t, kCounterCount> counters{};

    void add(Stage s, double ms) {
        milliseconds[static_cast<int>(s)] += ms;
        ++calls[static_cast<int>(s)];
    }
    void count(Counter c, uint64_t n) { counters[static_cast<int>(c)] += n; }
    uint64_t counter(Counter c) const { return counters[static_cast<int>(c)]; }
    double ms(Stage s) const { return milliseconds[static_cast<int>(s)]; }
    double totalMs() const;
    void reset() { *this = Profile{}; }
};

// Times one stage into a profile for the lifetime of the object.
class StageTimer {
public:
    StageTimer(Profile& profile, Stage stage) : m_profile(profile), m_stage(stage), m_start(Clock::now()) {}
    ~StageTimer() { m_profile.add(m_stage, std::chrono::duration<double, std::milli>(Clock::now() - m_start).count()); }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

private:
    using Clock = std::chrono::steady_clock;
    Profile& m_profile;
    Stage m_stage;
    Clock::time_point m_start;
};

} // namespace rl
