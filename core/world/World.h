// The runtime world: built from a Scene, it owns the body state, shapes, broadphase and contacts, and advances them
// one frame at a time through the named stages of DESIGN.md §2. It knows nothing of the UI.
#pragma once

#include "collision/BroadPhase.h"
#include "collision/Manifold.h"
#include "collision/Shape.h"
#include "common/Result.h"
#include "dynamics/BodyState.h"
#include "dynamics/ContactSolver.h"
#include "dynamics/Integrator.h"
#include "scene/Scene.h"
#include "world/Effects.h"
#include "world/IslandShare.h"
#include "world/Profile.h"
#include "world/TeamPacer.h"
#include "world/ThreadTeam.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rl {

struct CollideOptions; // collision/Collide.h

// Run-time overrides of the scene's world settings (the CLI's --fps, --substeps, ...).
struct WorldOptions {
    std::optional<Real> fps;
    std::optional<int> substeps;
    std::optional<int> iterations;
    std::optional<Integrator> integrator;
    std::optional<EffectsSetting> effects;
    int threads = 1; // threads of the narrowphase and the contact solve; results are identical for any count
    // With threads > 1: whether each step takes the team or member 0 alone (TeamPacer). The frames are the same.
    TeamPacing teamPacing = TeamPacing::Adaptive;
};

// Tuning constants of the contact pipeline, with where they come from.
struct WorldTuning {
    // Contacts are created this far before bodies touch, so that resting contacts never flicker (Box2D: 4 x slop).
    Real speculativeDistance = 0.02;
    // Fat-box margin of the broadphase's tree of moving bodies, m (Box2D's b2_aabbMargin is also 0.1 m). The
    // narrowphase tests only pairs whose tight boxes come within the speculative margin, so the margin trades tree
    // updates against pairs to scan: ramps.obj's frames are the same with 0.05, 0.1 and 0.2, and its first 240 frames
    // ran 6,762 M, 6,878 M and 6,981 M instructions (callgrind); timed, 0.05 was not faster than 0.1 (four
    // interleaved pairs, collision stages 324-399 ms against 350-357 ms). (Until 2026-11-25 this field was not used
    // and the tree's own default of 0.1 applied.)
    Real aabbMargin = 0.1;
    // A body is a candidate for sleep while no point of it has got farther than sleepSpeed * timeToSleep (2.5 cm)
    // from where it was when its sleep clock started: its mean speed over the window is below sleepSpeed, Box2D
    // v3's default of 5 cm/s. The sleep test of Jolt, by displacement rather than by the instantaneous speed.
    // An instantaneous |v| + radius |w| < sleepSpeed (Box2D v3's measure) kept 7 of 36 piles of 1,000 random
    // boxes awake, still moving at 1.3-8.8 cm/s after 10 s (two relax sweeps; measured 2026-11-24). In seed 9, which
    // we traced, one box resting on two single-point contacts rocked about the line between them at up to 1.9 cm/s
    // and 0.09 rad/s while its centre stayed within 1.5 mm, and held its island of 936 boxes awake (issue 4).
    Real sleepSpeed = 0.05;
    Real timeToSleep = 0.5; // s an island must stay slow before it sleeps
    // An island whose heaviest and lightest moving bodies differ by more than this mass ratio is solved with
    // refineSubsteps * sqrt(ratio / refineMassRatio) substeps in all, as a whole multiple of the scene's substeps
    // and at most maxSubstepRefinement times them (see World::substepRefinement). Random boxes of half sizes
    // 0.15-0.4 m span a ratio of 19; 1:1000 needs 16 substeps, which is 18 (3x the default 6) or 16 (4x a scene's 4).
    Real refineMassRatio = 250.0;
    Real refineSubsteps = 8.0;
    int maxSubstepRefinement = 4;
    // Likewise an island with a moving body smaller than refineExtent (m, the middle one of its extents) takes
    // refineExtentSubsteps * sqrt(refineExtent / extent) substeps in all (see World::sizeRefinement): a contact
    // settles the same depth whatever the size, so small bodies need stiffer contacts. 20-cube towers of 2 cm and
    // 3 cm cubes stood with their tops 3.3 and 2.0 mm off at 12 substeps, 0.8 and 0.5 mm at 18 (2026-12-05).
    Real refineExtent = 0.1;
    Real refineExtentSubsteps = 6.0;
    // A contact that holds a body up against gravity (normal within 45 degrees of vertical) and lies between a body
    // nearer the ground (fewer contacts from it, or as few with the lower centre) and one at least stackHoldRatio times
    // heavier holds the lower body still (shock propagation; World::heightsAboveSupport(), World::contactHold()). Only
    // the contacts where a heavier body bears on a lighter one hold: bodies of one mass among themselves are solved as
    // before. Until 2026-12-05 this took a ratio of holdMassRatio and an island with a mass ratio above
    // refineMassRatio, and a 0.5 m cube of 20 or 200 kg dropped 5 m onto one of 1 kg on the floor drove it 42 or 185 mm
    // into the floor and came down beside it; one of 5 kg from 5 m or 3 kg from 10 m went through it too. Held from a
    // ratio of 2, every such drop ends with the heavy cube on top and the deepest contact under 0.05 mm (tst_stacking),
    // and piles of 1,000 random boxes (ratios up to 19) came to rest in 144 of seeds 1-144 (again on 2026-12-05, when
    // bodies at the same height came to be held too).
    //
    // In an island whose mass ratio is above refineMassRatio, where the heavier body (at least holdMassRatio times
    // the lower one) presses the lower one down into its support less steeply than that, with the normal at least
    // wedgeRise (the sine of its angle above horizontal, seen from the lower body), the lower body is not held but
    // made heavier in that contact only, to 1/holdMassRatio of the upper one (World::contactHold()). A 1,000 kg
    // ball rolled at 10 m/s into a 1 kg box on the floor wedged the box into the floor: the sweeps passed the ball's
    // momentum down through the box a thousandth at a time, and the box sank 2.2-4.3 cm at 4, 5, 7, 8, 10 and 12
    // substeps (1.0 mm at 6, by luck) and threw the ball up to 1.1-1.4 m. Made heavier, the box sinks at most 1.2 mm at
    // any of those substep counts and the ball rolls over it (its centre rises 0.20-0.22 m; the box is 0.2 m tall). The
    // price: momentum is not conserved in that contact; the ball comes out of its first strike at 7.0 m/s instead
    // of 8.5 m/s, as if it had met a 100 kg box. (Made a tenth as heavy, 1:100, the box still sank 7.3 mm at 8
    // substeps.) A heavy block slid flat into a light cube on the floor still sends it off (2.68 m/s instead of
    // 2.76 m/s).
    Real holdMassRatio = 10.0;
    Real stackHoldRatio = 2.0;
    // A contact supports a body in the heights of shock propagation only if it is at most this much (m) farther
    // apart than the body's nearest contact (World::heightsAboveSupport()): half the speculative distance.
    Real supportGap = 0.01;
    // After the sweeps, a point of a contact between a moving body and a still one (an anchor, a sleeper) that the step
    // took deeper than this (m) moves the body out to this depth (World::pushOutOfContacts()); negative: never. It
    // took ramps.obj's first 120 frames 2.9-3.0 ms (of the 226-228 ms of all its stages) and pushed 54 contacts
    // (2026-12-05).
    Real pushOutSlop = 0.002;
    // After CCD, a contact whose bodies' turns moved a point by more than separateTurn (m) in the step is collided
    // again where the step left it, and pushed apart to separateSlop (m) where the step took it deeper than that
    // (World::separateMovedPairs()); one that began the step deeper than separateDeepStart (m; bodies created
    // overlapping) only where the step took it deeper than it began, by separateSlop. Negative separateSlop: never.
    // Measured 2026-12-06 (separateMovedPairs() says what).
    Real separateSlop = 0.002;
    Real separateTurn = 0.005;
    Real separateDeepStart = 0.01;
    // A lower body whose surface moves into the upper one faster than this (m/s) is not held (World::contactHold()).
    Real holdRiseSpeed = 3.0;
    // A hull whose faces are all at least this fraction of its farthest corner's distance from the centre of mass (a
    // UV sphere, an icosphere from Blender) is a ball to the solver (kBodyRound) in a step in which it turns through
    // more than the angle one face spans seen from that centre; one whose support distances change by at most 1 - this
    // fraction of its radius as it turns about an axis (a cylinder, a cone) is round about that axis in a step in
    // which it turns about it through more than one face (World::create(), World::updateRoundHulls()).
    Real roundHullRoundness = 0.9;
    Real wedgeRise = 0.2;
    // Sweeps of the relax pass per substep (the solve pass runs `iterations` sweeps). The relax pass removes the
    // push-apart velocity of the soft solve. One sweep leaves the velocities of a resting pile unconverged: a box on a
    // few single-point contacts comes out of each step turning at up to 0.3 rad/s one way, then the other, while its
    // centre hardly moves. Two sweeps were used while that kept 1,000-box piles awake; the displacement
    // sleep test (sleepSpeed) lets such piles sleep with one. Measured 2026-11-24 with that test, 36 piles of 1,000
    // random boxes (seeds 1-36): 34 at rest after 10 s with one sweep, 35 with two. One sweep makes the solve 20-25 %
    // cheaper (3 sweeps per substep instead of 4), and every hard case stays within its limit: some came out better
    // (40-cube tower drift 1.7 mm instead of 4.8 mm, ramps 32.9 mm deepest instead of 39.9 mm, the heavy projectile's
    // box 2.2 cm deep instead of 2.8 cm), some worse (the 1:1000 pair 7.2 mm deepest instead of 6.1 mm, mixed.obj's
    // deepest contact 1.8 mm instead of 0.05 mm).
    int relaxIterations = 1;
    // The blows' passes before the substeps (ContactSolverSettings::blowPasses, blowShockPasses). Measured
    // 2026-12-06: a 0.5 m box coming down at 10 m/s onto a stack of one, two or four equal boxes on the floor
    // (restitution 0) sent the stack up at 0.84, 1.38 and 1.50 m/s with none, at most 0.001 m/s with 4 and 2 (with 4
    // and none, 0.000, 0.40 and 1.0 m/s; with 16 and none, 0.000, 0.001 and 0.30). (Swept again in every substep
    // instead, 4 more sweeps over the struck manifolds and their bodies' others took ramps.obj's solve stage 19 %
    // longer and left the stacks of two and four at 1.10 and 1.38 m/s.)
    int blowPasses = 4;
    int blowShockPasses = 2;
    // CCD sweeps a body that moves more than this fraction of its smallest size in one step.
    Real ccdFraction = 0.5;
    // The radius of a swept body's core, a ball about its centre of mass, as a fraction of its thinnest size: swept
    // where the body began the step close to another and closed in on it fast (World::continuousCollision()).
    Real ccdCoreFraction = 0.125;
    // A box whose corners move more than this (m) in a step by its turn gets the corners the turn brings towards its
    // neighbours as contact points (addTurnedSupports(); other hulls from 1 mm on). Over 600 frames of a bouncing pile
    // of 1,000 boxes (e = 0.5), 72 frames held a contact deeper than 1 cm against 83 without, the deepest 51.2 mm
    // against 71.3; ramps.obj 20 frames against 22. ramps.obj's first 120 frames took 2.066-2.078 ms a step against
    // 2.043-2.058 at 3056342, before these corners and the clipped overlapping edges (CollideOptions), and 2.044-2.145
    // with those edges alone (`bench ramps --frames 120 --runs 3 --no-bullet`, three rounds by turns); from 2 cm on,
    // 64 frames in the pile and 2.103-2.120 ms; from 1 mm on, as for the other hulls, ramps.obj's step took 12 %
    // longer (2026-12-05). Measured 2026-12-06.
    Real boxTurnCorner = 0.05;
    // A pair's manifold is reused (its points refreshed from their local witnesses, as Bullet's persistent
    // manifolds and Jolt's body-pair cache do) while no point of B has moved more than this relative to A since it
    // was computed (m; at most a tenth of the smaller body's thinnest size). Measured 2026-11-26 (6 x 2 defaults):
    // 0.1 mm, 0.5 mm, 1 mm and 2 mm gave large_pyramid's narrowphase 386, 143, 79 and 70 ms over its first 45 frames
    // (36, 30, 28 and 33 ms a step, one noisy run each), while its top drifted 2.7, 4.3, 6.0 and 9.4 mm in 10 s and the
    // 40-cube tower's 1.8, 1.3, 5.3 and 5.3 mm. At 1 mm every hard case passes, and 71 of the 72 piles of 1,000 boxes
    // rest (70 at 0.1 mm).
    Real manifoldReuseDistance = 1e-3;
    // An island of at least this many moving bodies is cut in two parts at the median of its centres along x, y or
    // z, whatever the number of threads: the solver sweeps the constraints within each part, then those across the
    // cut (ContactSolver::prepare()), so two threads can each take a part (World::cutIslands()). 0 never cuts.
    // 1,000-box piles at rest after 10 s (seeds 1-72, measured 2026-11-24): 68 of 72 uncut, 69 as cut now; with the
    // widest spread as the axis, 67 cut from 256 bodies and 64 from 128. Ramps' piles stay under 256 (see below).
    size_t cutIslandBodies = 256;
    // An island of at least this many moving bodies that holds more than half of its group's moving bodies is cut
    // the same way, however the bodies are shared among threads (the group decides, not a thread's share of it). No
    // split of whole islands can balance such a group over two threads: ramps.obj from frame 120 on keeps a pile of
    // 150-180 awake bodies beside one of 80-90, and at every step in which that pile outweighed the rest (74 of its
    // 300) the team swept the whole group level by level, with a barrier after each level. Cut, over frames 120-300 on
    // two threads, the solve took 0.49-0.60 ms a step on average against 0.65-0.70, and the step's median 1.09-1.26 ms
    // against 1.23-1.32 (six alternating runs each, 2026-11-27). On one thread the same frames took 1.57-1.66 ms a step
    // against 1.51-1.64 (six pinned pairs: slower in four by 3-8 %, faster in two by 1 %). The piles of
    // 1,000 boxes at rest after 10 s stayed 143 of seeds 1-144, and pyramid20's top drifted 0.41 mm instead of 0.45. 0
    // never cuts by this rule.
    size_t cutDominantIslandBodies = 128;
};

// Figures of one frame for the timeline's tracks and the stability tests.
struct FrameDiagnostics {
    Real kineticEnergy = 0.0;   // J, dynamic bodies
    Real potentialEnergy = 0.0; // J, -m g.x summed over dynamic bodies
    Real maxPenetration = 0.0;  // m, deepest contact point (0 when none)
    int contactPoints = 0;
    int awakeBodies = 0;
};

class World {
public:
    static Result<World> create(const Scene& scene, const WorldOptions& options = {});

    // Advances one frame (1/fps) in `substeps` substeps, on the team or alone (WorldOptions::teamPacing).
    void step();

    // For tests, which compare the two: the islands a thread solves go through the substeps in runs of whole islands
    // of about this many bodies (kRunBodies by default); 0 solves them all at once. Set it while no world steps.
    static void setIslandRunBodies(size_t bodies) { s_runBodies = bodies; }

    size_t bodyCount() const { return m_names.size(); }
    const std::string& name(size_t i) const { return m_names[i]; }
    bool isAnchor(size_t i) const { return m_state.isStatic(static_cast<uint32_t>(i)); }
    bool isAwake(size_t i) const { return m_state.isAwake(static_cast<uint32_t>(i)); }

    Vec3 centerOfMass(size_t i) const { return m_state.position[i]; }
    // Orientation of the body's shape coordinates in the world (what the scene's `orientation` means).
    Quat shapeOrientation(size_t i) const { return m_state.shapeOrientation(static_cast<uint32_t>(i)); }
    // Rotation since the run began: identity at frame 0.
    Quat rotationSinceStart(size_t i) const;
    Vec3 linearVelocity(size_t i) const { return m_state.linearVelocity[i]; }
    Vec3 angularVelocity(size_t i) const { return m_state.angularVelocity[i]; }
    // World position of the body's vertex mean (the .bake reference point).
    Vec3 vertexMean(size_t i) const { return m_state.position[i] + rotationSinceStart(i) * m_vertexMeanOffset[i]; }
    // From the centre of mass to the vertex mean at frame 0, world axes.
    Vec3 vertexMeanOffset(size_t i) const { return m_vertexMeanOffset[i]; }
    Real mass(size_t i) const { return m_state.info[i].mass; }

    // Collision shapes live in the body's shape coordinates (a box stays a box); transform() places them.
    const Shape& shape(size_t i) const { return m_shapes[i]; }
    Transform transform(size_t i) const {
        const uint32_t k = static_cast<uint32_t>(i);
        return Transform::fromQuat(m_state.shapeOrigin(k), m_state.shapeOrientation(k));
    }

    int64_t frame() const { return m_frame; }
    Real time() const { return static_cast<Real>(m_frame) / m_fps; }
    Real fps() const { return m_fps; }
    int substeps() const { return m_substeps; }
    Integrator integrator() const { return m_integrator; }
    const Vec3& gravity() const { return m_gravity; }

    const ActiveEffects& effects() const { return m_effects.effects; }
    const EffectsDecision& effectsDecision() const { return m_effects; }
    const Profile& profile() const { return m_profile; }
    void resetProfile() { m_profile.reset(); }
    Profile& mutableProfile() { return m_profile; }
    const ClampCounters& clampCounters() const { return m_state.clampCounters; }

    FrameDiagnostics diagnostics() const;
    // FNV-1a over the bits of every body's centre of mass and shape orientation: runs that end in the same state, bit
    // for bit, have the same hash, and runs that do not almost surely differ. The determinism tests and the
    // benchmarks compare runs by it.
    uint64_t stateHash() const;
    // The current manifolds (touching or speculative), for overlays and tests.
    std::vector<Manifold> manifolds() const;

    // Wakes every body (after an edit from outside, for example).
    void wakeAll();

    // For per-body work between steps (the Baker's record of a frame): shares [0, count) out over the world's team
    // when it has one, the last steps found it paying (TeamPacer) and count is large enough to pay for a team job;
    // empty otherwise, and then the caller loops alone. Work on each body alone gives the same results either way.
    ContactSolver::ParallelFor betweenStepsParallelFor(size_t count);

    const BodyState& state() const { return m_state; }

private:
    World() = default;

    // What a pair's contact does not change while the pair lasts, per pool slot (m_contactPairs): its bodies and
    // their combined friction and restitution. Kept apart from the contact, whose lines the narrowphase and the
    // solver write every step, so that the passes that only need these read a compact array that stays in both
    // cores' caches.
    struct ContactPair {
        uint32_t bodyA = 0, bodyB = 0;
        Real friction = 0.0;
        Real restitution = 0.0;
    };
    // A pair's contact, some 610 bytes. The fields a new pair sets (startContact()) come first, so that starting one
    // in a reused slot writes a few of its lines, not the whole.
    struct Contact {
        // The speculative margin the manifold was computed with (< 0: nothing cached), and while the pair is apart the
        // axis (A's shape coordinates) that separated it last, or zero.
        Real cachedMargin = -1.0;
        Vec3 separatingAxis{0.0};
        Manifold manifold;
        // The pose of B in A's frame (centres of mass) when the manifold was last computed: while B has hardly moved
        // relative to A the manifold is refreshed from its local witness points instead of recomputed (see
        // collidePair()).
        Vec3 cachedOffset{0.0};
        Mat3 cachedRotation{1.0};
        Vec3 cachedNormal{0.0}; // the manifold's normal in A's shape coordinates
    };
    // Makes the slot's contact that of a new pair a-b, with no points and nothing cached. Its other fields are written
    // before they are read.
    void startContact(uint32_t slot, uint32_t a, uint32_t b);

    void updateBroadphase();
    // This step's broadphase pairs into the next lists (m_nextPairContacts with kNoSlot for new pairs,
    // m_nextPairBodies, m_newPairs, m_endedContacts); reads the current lists and touches no contact.
    void mergePairs(const BroadPhase::ParallelFor& parallelFor);
    // Gives the new pairs their slots and makes the next lists current.
    void commitPairs();
    // Broadphase and narrowphase: the manifold of every pair within its margin, and the touching contacts.
    void findAndCollidePairs();
    // Sets every push speed to 0 (at the step's start: the pairs collided before the lists are committed take none).
    void clearPushSpeeds();
    // The pushes of this step's new pairs, once the lists are committed; lists in m_pushedBodies the bodies whose
    // push speed rose.
    void pushSpeedsOfNewPairs();
    // Whether a and b can strike each other in the step hard enough to matter (pushSpeedsOfNewPairs()).
    bool mayPush(uint32_t a, uint32_t b) const;
    // Raises m_pushSpeed by m_pushPairs, in two passes, and lists the bodies raised.
    void applyPushes();
    void buildIslands();
    void solve();
    void countSolverRows(); // the solver's rows of this step into the profile
    void solveGroup(std::span<const uint32_t> group, int refinement);
    // The solver and scratch of the group being solved.
    struct SolveScratch {
        std::vector<uint32_t> bodies;
        std::vector<uint32_t> solverIndex; // per body of the world: its solver index in this scratch's solve, else 0
        ContactSolver solver;
        std::vector<SolverBody> solverBodies;
        std::vector<Vec3> centers;
        std::vector<uint32_t> activeContacts, indexA, indexB; // pool slots of the group's contacts; solver indices
        std::vector<Manifold*> manifolds;                     // the group's contacts' manifolds, in m_contactPool
        std::vector<Real> friction, restitution;
        std::vector<ContactSolver::Hold> held; // per contact: its hold for shock propagation (contactHold())
        std::vector<ClampCounters> clamps;     // per member of the team
        BodyState local;                       // the group's bodies through the substeps (solveSubsteps())
        std::vector<uint32_t> localIds;        // 0 .. bodies.size() - 1
        std::vector<size_t> ownedStart;        // member m integrates local bodies ownedStart[m] .. [m + 1] - 1
        std::vector<uint32_t> edgeBodies; // solved by parts: part 1's bodies (solver indices) of the cut's constraints
        std::vector<uint32_t> innerIds, edgeIds;   // part 1's local ids off the cut and on it
        std::vector<uint32_t> renumber, reordered; // numberByParts()
        std::vector<Vec3> startPosition;           // local bodies at the step start
        std::vector<Quat> startOrientation;
        std::vector<uint8_t> part;        // per solver body: its part (cutIslands())
        size_t islandsCut = 0;            // islands of the group cut in parts
        size_t partImbalance = 0;         // with islands cut: the bodies of the larger part less those of the other
        std::vector<uint32_t> islandSize; // per island root (cutIslands(), entries of the group's roots only)
        std::vector<uint8_t> islandPart;  // likewise
        std::vector<std::pair<uint32_t, uint32_t>> wholeIslands; // (bodies, root) of the islands not cut
        std::vector<std::pair<uint32_t, uint32_t>> cutBodies;    // (island root, position in bodies)
        struct CutIsland {
            uint32_t begin = 0, end = 0; // its run in cutBodies
            int axis = 0;                // the axis of the cut so far
            uint32_t boundary = 0;       // constraints across the cut along that axis
            bool whole = false;          // a body is not finite: left uncut
        };
        std::vector<CutIsland> cutIslands;
        struct AxisCut {                                 // the cut islands split along one axis
            std::vector<std::pair<Real, uint32_t>> keys; // (coordinate, position in bodies), per entry of cutBodies
            std::vector<uint8_t> part;                   // per solver body
            std::vector<uint32_t> boundary;              // per cut island: the constraints across
        };
        std::array<AxisCut, 3> axisCuts;
        std::vector<uint32_t> islandOf; // per root of a cut island: its entry in cutIslands
        // What the solves of this scratch counted since solveGroup() last took it: rows, islands cut, part imbalance.
        ContactSolverCounters rows;
        size_t islandsCutTotal = 0, partImbalanceTotal = 0;
        // solveInRuns(): per island root (entries of the roots of its islands only), the island's bodies, then its
        // run; the bodies and contacts of each run, run after run (runStart, runContactStart: where each begins).
        std::vector<uint32_t> runOfIsland;
        std::vector<uint32_t> runBodies, runContacts, runStart, runContactStart, runCursor;
        void clearContacts();
    };
    // The group of `scratch` through `substeps` substeps, then restitution; on the team when mayUseTeam is set and
    // the group is large enough, else on the calling thread. `timed`: the stages are timed (the calling thread
    // alone, so the timers are safe).
    void solveSubsteps(SolveScratch& scratch, int substeps, bool mayUseTeam, bool timed);
    // The islands of `from` (its bodies and contacts) through `substeps` substeps on the calling thread, in runs of
    // whole islands of about kRunBodies bodies, one run after the other, in `work` (whose rows, islands cut and
    // clamps add up over the runs). Islands are independent, so the results are those of one solve of them all.
    void solveInRuns(const SolveScratch& from, SolveScratch& work, int substeps, bool timed);
    // Shares m_scratch's islands out among the team's members (m_islandMember) if that is worth it; each member then
    // gathers its part (m_memberScratch) in the solve's job.
    bool splitByIslands();
    // splitByIslands() keeps the islands in runs of body order when no member gets more than this many hundredths of
    // the work times the team's size (102: 51 % of it on one of two members; shareIslandsOut()).
    static constexpr uint64_t kInOrderShare = 102;
    // Plans, for the whole group (m_scratch.bodies), how many bodies of each island to cut go to part 0
    // (m_cutShare): the other islands go whole to the part with fewer bodies, largest first, and each island to cut
    // is then split where the two parts come out even. Planned before islands are shared out among threads, so a
    // cut is the same for any number of threads.
    void planCuts();
    void stepOnce(); // step() on m_team, or alone if it is null
    // Fills scratch.part for its bodies (solver indices and contacts set): each island of cutIslandBodies or more, or
    // of cutDominantIslandBodies or more that holds most of the group (m_groupBodies), is cut in two as planCuts()
    // planned; the other islands go whole to the part with fewer bodies, largest first.
    // parallelFor, if given, shares the three axes out.
    void cutIslands(SolveScratch& scratch, const ContactSolver::ParallelFor& parallelFor = {}) const;
    // Whether an island of `bodies` moving bodies, in a group of m_groupBodies, is cut (cutIslands()).
    bool cutsIsland(size_t bodies) const;
    // After cutIslands(): numbers the group's bodies part by part (scratch.bodies, scratch.solverIndex, the contacts'
    // solver indices and scratch.part follow).
    void numberByParts(SolveScratch& scratch);
    // A group is solved by the whole team only from this many bodies on, and with at least this many constraints
    // per level of the solver's schedule on average (ramps.obj's pile: 37; the 5,050-cube pyramid: 25).
    static constexpr size_t kMinBodiesForTeam = 128;
    static constexpr size_t kMinLevelWidth = 16;
    // solveInRuns(): islands are solved in runs of about this many bodies (an island bigger than that alone), so
    // that a run's bodies, constraints and points stay in the core's cache (2 MB of L2 here) through its substeps.
    // The scaling series' 16,000 cubes in pairs (`bench --scaling`, one thread, two runs of each, 2026-11-29): the
    // solve stage over 60 frames took 2,046-2,433 ms with all islands at once, 1,330-1,772 ms in runs of 2,048
    // bodies, 1,579-1,605 of 1,024, 1,569-1,597 of 512. Runs of 512 cut ramps.obj's 642 cubes in two and its
    // prepare_contacts took 87-98 ms over 120 frames against 74-84; with 1,024 it is one run, as before.
    static constexpr size_t kRunBodies = 1024;
    static size_t s_runBodies; // setIslandRunBodies()
    // A body's principal moments within this fraction of the largest are taken as equal (create()).
    static constexpr Real kIsotropicSpread = 1e-5;
    int substepRefinement(Real massRatio) const;
    int sizeRefinement(Real extent) const;
    // Runs body(begin, end) over [0, count) shared out to the team; empty without a team. (The same type as
    // BroadPhase::ParallelFor.)
    ContactSolver::ParallelFor teamParallelFor();
    void heightsAboveSupport(std::span<const uint32_t> moving);
    // For a contact of a mixed island (m_anyHeight): the hold on its lower body (still, or heavier: see
    // WorldTuning::holdMassRatio), or none.
    ContactSolver::Hold contactHold(uint32_t slot) const;
    // Which body of a contact between moving bodies is the lower one (heightsAboveSupport()), and whether the contact
    // could hold it like the ground under the upper one (contactHold()), before looking at how it moves.
    struct HoldGeometry {
        bool lowerIsA = false;
        uint32_t lower = 0, upper = 0;
        Vec3 towardUpper{0.0}; // the normal, from the lower body to the upper one
        Real along = 0.0;      // towardUpper's rise
        bool valid = false;    // both at a height, the upper one above, the normal at least wedgeRise above horizontal
        bool stopsUpper = false; // and the normal within 45 degrees of vertical, the upper body stackHoldRatio times
                                 // heavier: held unless it rises into the upper one
    };
    HoldGeometry holdGeometry(uint32_t slot) const;
    // Whether the lower body's surface moves into the upper one faster than WorldTuning::holdRiseSpeed at a point.
    bool risingInto(uint32_t slot, const HoldGeometry& g) const;
    // Whether a third body (with a height) rests on `upper` and bears `lower` up (a loop of bodies each resting on the
    // next, as crossed sticks in a pile make), or `upper` rests on a third body that rests on `lower` (see
    // contactHold()). "Rests on": the contact's normal has any downward part (m_contactBearsUp).
    bool holdsInALoop(uint32_t upper, uint32_t lower) const;
    // An inelastic impulse at the contact's fastest closing point, repeated while the lower body rises into the
    // upper one (heightsAboveSupport()).
    void meetRisingLowerBody(uint32_t slot);
    // A touching manifold's least separation, and the side its normal bears up against gravity (+1 A, -1 B, 0 none).
    std::pair<Real, int8_t> contactSupport(const Manifold& manifold) const;
    void continuousCollision();
    void updateSleep();
    Real pairMargin(uint32_t a, uint32_t b) const;
    void collidePair(uint32_t slot, Real margin);
    // Marks the round hulls that turn through a face or more in this step round (kBodyRound), the others not.
    void updateRoundHulls();
    void pushOutOfContacts(Real slop);
    // Moves the body by a positional impulse `push` along `direction` applied at the arm (r x direction): its centre
    // by inverseMass times it, its orientation to first order by inverseInertia times the arm (pushOutOfContacts(),
    // separatePair()).
    void nudge(uint32_t body, Real push, const Vec3& direction, Real inverseMass, const Mat3& inverseInertia,
               const Vec3& arm);
    // After a correction turned a moving body from `before` to its orientation now: scales its angular velocity down
    // where the turn raised its rotational energy, to the energy it had.
    void keepSpinEnergy(uint32_t body, const Quat& before);
    void separateMovedPairs(Real slop);
    // The options of every collision of a pair (collidePair(), movedInto(), separatePair()).
    CollideOptions pairCollideOptions() const;
    // Whether the contact's bodies, placed by xfA and xfB (where the step left them), collided again, have a point
    // deeper than separationFloor() (separateMovedPairs()), or inRounds, than separationFloor(fromStart) less
    // kRoundsBeyond (groundPushedBodies()); the contact may have been apart. Reads the state.
    // Where it has one, `collision` (if given) gets the collision that found it.
    bool movedInto(uint32_t slot, Real slop, const Transform& xfA, const Transform& xfB, bool inRounds = false,
                   Manifold* collision = nullptr) const;
    // movedInto() of the touching contacts at the given positions in m_touchingContacts, where the bodies are now:
    // deep[t] for contacts[t], and collisions[t] where it is set (both sized by the caller). On the team if it has one
    // and there are enough; each test alone, so the results are the same.
    void testMovedInto(std::span<const uint32_t> contacts, Real slop, std::vector<uint8_t>& deep,
                       std::vector<Manifold>& collisions);
    // range(begin, end) over [0, count): by the team if onTeam (and there is one), the members claiming chunks of
    // `chunk` as they go (ThreadTeam::forEachClaimedChunk()), else at once on this thread.
    void forEachChunkClaimed(size_t count, size_t chunk, bool onTeam, const std::function<void(size_t, size_t)>& range);
    static constexpr size_t kSeparateChunk = 16; // tests per claim of testMovedInto()'s team
    // How deep (negative) a contact may be after the step: -slop, or for one that began the step deeper than
    // WorldTuning::separateDeepStart (or at all, fromStart, unless one of its bodies is still), its depth then less
    // slop.
    Real separationFloor(uint32_t slot, Real slop, bool fromStart = false) const;
    // The contact's bodies collided again and pushed apart (positions only) until no point is deeper than
    // separationFloor(), at most two pushes; returns the pushes. With `grounded` (per body; groundPushedBodies()), a
    // still or grounded body under one that is not is not moved, and grounds that one.
    // `collision`, if given, is the pair's collision where its bodies are now, which the first push then takes
    // instead of colliding them again.
    int separatePair(uint32_t slot, Real slop, std::vector<uint8_t>* grounded = nullptr,
                     const Manifold* collision = nullptr);
    // After separateMovedPairs()'s pushes: the pushed bodies out of the still bodies they went into, and then
    // rounds over the pairs of the bodies that moved; returns the pushes.
    uint64_t groundPushedBodies(Real slop);
    static constexpr int kSeparateRounds = 4;
    // In those rounds a pair of two moving bodies is pushed where deeper than its floor by this (m): a body pushed
    // 3-4 mm into the floor by the pushes before, at the foot of a stack of falling cubes in ramps.obj, lifted the
    // stack above it. A pair with a body that does not move (the floor, a sleeper) is pushed as soon as it is deeper
    // than its floor (roundsBeyond()).
    static constexpr Real kRoundsBeyond = 0.003;
    Real roundsBeyond(uint32_t slot) const;
    // Whether one body of the pair does not move (an anchor, a sleeper).
    bool withStillBody(uint32_t slot) const;
    void refreshTransforms();
    void wakeIsland(uint32_t body);
    void restartSleepClock(uint32_t body);

    Real m_fps = 60.0;
    int m_substeps = 4;
    int m_iterations = 1;
    Integrator m_integrator = Integrator::SymplecticEuler;
    Vec3 m_gravity{0.0};
    Damping m_damping;
    // Threads of the narrowphase and the solve (WorldOptions::threads); none for one thread. m_team is the team in a
    // step that takes it, else null (TeamPacer decides): the step's code asks m_team alone.
    std::unique_ptr<ThreadTeam> m_ownTeam;
    ThreadTeam* m_team = nullptr;
    WorldTuning m_tuning;
    EffectsDecision m_effects;
    ContactSolverSettings m_solverSettings;

    BodyState m_state;
    std::vector<std::string> m_names;
    std::vector<Shape> m_shapes;
    std::vector<Real> m_friction, m_restitution;
    std::vector<Vec3> m_vertexMeanOffset;
    std::vector<Quat> m_startFromPrincipal; // rotationSinceStart() = orientation * this
    std::vector<ProxyKey> m_proxies;
    std::vector<Real> m_sleepTime;
    std::vector<Real> m_islandSleepTime; // updateSleep(): per island root, the least sleep time of its awake bodies
    // Pose of each body when its sleep clock last started (see updateSleep()).
    std::vector<Vec3> m_sleepAnchorPosition;
    std::vector<Quat> m_sleepAnchorOrientation;
    std::vector<Real> m_minExtent;
    std::vector<Real> m_middleExtent; // per body: the middle one of its shape's three extents (sizeRefinement())
    // Per body: whether its turn within a step may bring corners into contact that its manifold, taken at the step's
    // start, does not hold (collidePair(), addTurnedSupports()): kTurnsAnyCorner for a hull other than a box, from a
    // corner's 1 mm on; kTurnsBoxCorner for a box, only from WorldTuning::boxTurnCorner on (a box face's four
    // corners are all in its manifold when they are within the margin, and from 1 mm on, ramps.obj's step took
    // 2.38-2.40 ms against 2.12-2.14, +12 %, medians of 120 frames, two runs each by turns, 2026-12-05, for the same
    // deepest contact in its first 2 s, 52.4 against 52.7 mm); 0 for none.
    std::vector<uint8_t> m_turnsThroughFeatures;
    static constexpr uint8_t kTurnsAnyCorner = 1, kTurnsBoxCorner = 2;
    // pushOutOfContacts(): per member of the team, the contacts its first pass moved a body out of, each list on
    // lines of its own.
    struct alignas(64) PushedList {
        std::vector<uint32_t> list;
    };
    std::vector<PushedList> m_pushedContacts;
    // separateMovedPairs(): per body, how far its turn moves a point of it in a step, and whether it was pushed; the
    // touching contacts to test (positions in m_touchingContacts) and movedInto() of each.
    std::vector<Real> m_turnStep;
    std::vector<uint8_t> m_separated;
    // separateMovedPairs(): the slots of the pairs apart at the step's start that may have met within it; each
    // moving body's turn in the step times its radius, and whether it strayed from its start velocity's path.
    std::vector<uint32_t> m_missedPairs;
    std::vector<Real> m_turnInStep;
    std::vector<uint8_t> m_deviated;
    std::vector<uint32_t> m_turnedContacts;
    std::vector<uint8_t> m_movedInto;
    std::vector<uint32_t> m_secondPushed; // separateMovedPairs(): the bodies its second pass pushed
    // separateMovedPairs(): the contacts its second pass tests (positions in m_touchingContacts), movedInto() of
    // each, and the collisions of the tests of either pass (testMovedInto()).
    std::vector<uint32_t> m_secondTests;
    std::vector<uint8_t> m_secondMovedInto;
    std::vector<Manifold> m_separateCollisions;
    std::vector<uint32_t> m_struck; // separateMovedPairs(): the bodies struck faster than their margins allowed
    // groundPushedBodies(): per body, whether this round pushed it and whether it is grounded; the slots of the
    // pairs to test.
    std::vector<uint8_t> m_pushedNow, m_grounded;
    std::vector<uint32_t> m_aroundPushed;
    std::vector<Transform> m_placedPose; // and per body its transform and bounds where it is, while m_placed is set
    std::vector<Aabb> m_placedBounds;
    std::vector<uint8_t> m_placed;
    std::vector<Real> m_radius; // largest distance from the centre of mass to the surface
    // Hulls shaped like balls, cylinders or cones (WorldTuning::roundHullRoundness): each with the spin (rad/s, about
    // its axis if it has one) above which it is round in a step, and that axis (principal frame; zero for a ball).
    struct RoundHull {
        uint32_t body = 0;
        Real spin = 0.0;
        Vec3 axis{0.0};
    };
    std::vector<RoundHull> m_roundHulls;
    CombineRule m_frictionRule = CombineRule::GeometricMean;
    CombineRule m_restitutionRule = CombineRule::Max;

    BroadPhase m_broadPhase;
    // Every broadphase pair's contact lives in a slot of the pool; m_pairContacts lists the slots in pair order,
    // which is the order every stage visits them in. Slots of ended pairs are reused (see commitPairs()).
    std::vector<Contact> m_contactPool;
    std::vector<ContactPair> m_contactPairs; // per slot of the pool
    std::vector<uint32_t> m_pairContacts;
    std::vector<uint32_t> m_freeContacts;
    std::vector<uint32_t> m_island; // island root per body (union-find), recomputed every step
    // Shape-to-world transform per body, taken once at the start of the step: the broadphase and every pair of
    // the narrowphase need it, and each mat3_cast costs more than the lookup.
    std::vector<Transform> m_transforms;
    std::vector<Aabb> m_bounds; // tight world boxes of the shapes, at the start of the step
    std::vector<Real> m_reach;  // |v| + |w| radius at the start of the step, m/s: how fast any point can move
    // How much a body's speed may change this step when a moving neighbour new to it strikes it, m/s
    // (pushSpeedsOfNewPairs()); nonzero only for the bodies listed in m_pushedBodies.
    std::vector<Real> m_pushSpeed;
    std::vector<uint32_t> m_pushedBodies;
    std::vector<std::pair<uint32_t, uint32_t>> m_pushPairs; // pushSpeedsOfNewPairs()'s scratch
    // Moving bodies whose proxy must be reinserted this step, with its new fat box (refreshTransforms()).
    std::vector<uint8_t> m_reinsert;
    std::vector<Aabb> m_fatBoxes;
    // Per pool slot: the contact's manifold's point count (not 0 while it touches). Kept beside the pool so that the
    // narrowphase can tell without reading the contact, which is some 610 bytes in no useful order.
    std::vector<uint8_t> m_contactTouching;
    // Per contact slot: at least how far apart the pair's bodies were at the step's start where it had no point (its
    // boxes' gap, or the margin it was collided with), for separateMovedPairs().
    std::vector<Real> m_pairStartGap;
    // Per slot: 1 while the contact is in a member's list of solved contacts (NarrowList::solved), which the chunks
    // of the narrowphase then pass over.
    std::vector<uint8_t> m_contactListed;
    std::vector<std::pair<uint32_t, uint32_t>> m_pairBodies; // the bodies of m_pairContacts[i]
    std::vector<uint32_t> m_touchingContacts; // slots of the touching contacts, in pair order, after narrowphase
    // Their bodies, so that islands and groups are found without reading the contacts.
    std::vector<std::pair<uint32_t, uint32_t>> m_touchingBodies;
    // Scratch of mergePairs() and solve(), kept between steps so that a step does not allocate.
    std::vector<uint32_t> m_nextPairContacts;
    std::vector<std::pair<uint32_t, uint32_t>> m_nextPairBodies;
    std::vector<size_t> m_newPairs;        // indices of the new pairs in the next pair list, ascending
    std::vector<size_t> m_newPairEnded;    // per new pair: how many pairs had ended before it in the merge
    std::vector<uint32_t> m_endedContacts; // slots of the pairs that ended
    bool m_pairsChanged = false;
    static constexpr uint32_t kNoSlot = UINT32_MAX;
    std::vector<uint32_t> m_group;
    std::vector<uint8_t> m_refinement; // per body: its island's substep multiplier this step, 0 when not moving
    std::vector<Real> m_islandMinMass, m_islandMaxMass;
    std::vector<Real> m_islandMinExtent; // per island root: the least middle extent of its moving bodies
    // Per body, for islands with a mass ratio of at least stackHoldRatio: the fewest contacts down to an immovable body
    // (anchor or sleeper), 1 when it touches one; 0 elsewhere or with no path (see World::heightsAboveSupport()).
    std::vector<uint32_t> m_height;
    std::vector<Real> m_contactGap; // per touching contact: its least separation (heightsAboveSupport())
    // Per touching contact: +1 when its normal bears body A up against gravity, -1 when it bears B up, 0 when neither.
    std::vector<int8_t> m_contactBearsUp;
    // Whether the narrowphase's listing of the touching contacts fills m_contactGap and m_contactBearsUp: while the
    // last step had a mixed island (m_anyHeight), when the next one most likely has one too. (Otherwise
    // heightsAboveSupport() fills them itself; the numbers are the same.)
    bool m_listGaps = false, m_gapsListed = false;
    std::vector<Real> m_nearestGap; // per body: the least separation of its touching contacts
    std::vector<uint8_t> m_mayRise; // per body with a height: whether its surface may move faster than holdRiseSpeed
    // Per body with a height: the bodies with a height it touches (each index << 2, bit 0 set when the neighbour
    // rests on the body, bit 1 when the body rests on it), sorted, from m_neighbours[m_neighbourStart[i]] on.
    std::vector<uint32_t> m_neighbourStart, m_neighbourFill;
    std::vector<uint64_t> m_neighbours;
    bool m_anyHeight = false;
    // This step: no two moving bodies far enough apart in mass for any island to take finer substeps (solve()); then
    // m_refinement is not filled and every moving body is in the one group.
    bool m_uniformRefinement = true;
    std::vector<uint32_t> m_moving;
    std::vector<uint32_t> m_activeIsland; // per contact of m_scratch.activeContacts: its island (solveGroup())
    // Per member of the team in findAndCollidePairs(): its touching contacts, the pairs whose contact may wake a
    // sleeper (their index in the pair list), and its counts.
    struct NarrowTest {
        uint32_t slot;
        uint32_t bodyA, bodyB; // the pair's bodies, for fetching their shapes ahead
        Real margin;
    };
    // One per member of the team, each on cache lines of its own: the members push to their own lists all through
    // the narrowphase, and neighbouring lists shared a line (the second list's first vector beside the first list's
    // counters). With a 50 ns round trip between the cores, ramps' and boxes1000's steps on two threads took the same
    // time either way (six interleaved runs each, 2026-12-04); the line moves between cores more slowly when the host
    // places them far apart (world/CoreRoundTrip.h).
    struct alignas(64) NarrowList {
        std::vector<NarrowTest> tests; // the pairs of its current chunk that the filter let through
        std::vector<uint32_t> touching;
        std::vector<std::pair<uint32_t, uint32_t>> touchingBodies;
        // Beside `touching` while m_listGaps: each contact's least separation and the side its normal bears up
        // (contactSupport()).
        std::vector<Real> gaps;
        std::vector<int8_t> bearsUp;
        std::vector<size_t> mayWake;
        // The contacts of the islands this member solved in the last step (listed in solveGroup()), which it collides
        // first in this step's narrowphase, before it takes chunks of the rest.
        std::vector<uint32_t> solved;
        uint64_t tested = 0, points = 0;
    };
    std::vector<NarrowList> m_narrowLists;
    static constexpr size_t kNarrowChunk = 128; // pairs per claim of the narrowphase's team
    static constexpr size_t kSetUpChunk = 128;  // contacts per claim of the solve's set-up (solveSubsteps())
    static constexpr size_t kSolvedChunk = 32;  // contacts per claim of member 0's solved contacts (NarrowList::solved)
    // Pairs the last step's narrowphase tested (findAndCollidePairs()); the first step counts as busy.
    uint64_t m_lastPairsTested = std::numeric_limits<uint64_t>::max();
    SolveScratch m_scratch;
    std::vector<SolveScratch> m_memberScratch; // islands shared out: one part per member of the team
    std::vector<SolveScratch> m_runScratch;    // per member: the runs of islands it solves (solveInRuns())
    size_t m_groupBodies = 0;                  // moving bodies of the group being solved (solveGroup())
    static constexpr uint32_t kNoMember = 0xffffffffu;
    std::vector<uint32_t> m_islandMember; // per island root: the member that solves it (splitByIslands())
    // splitByIslands(): the group's islands by their first body, and each one's work (bodies plus contacts).
    std::vector<uint32_t> m_islandRoots, m_islandWork;
    IslandShare m_islandShare;
    std::vector<uint32_t> m_cutShare;                          // per root of an island to cut: its bodies in part 0
    std::vector<std::pair<uint32_t, uint32_t>> m_wholeIslands; // planCuts(): (bodies, root) of the islands not cut
    std::vector<uint32_t> m_islandsToCut;                      // planCuts(): their roots
    std::vector<std::pair<uint32_t, Real>> m_ccdMoves;         // continuousCollision(): (body, time of impact)
    ContactSolverCounters m_solverCounters;
    // With CCD on: each dynamic body's centre and orientation at the start of the step (refreshTransforms()).
    std::vector<Vec3> m_stepStartPosition;
    std::vector<Vec3> m_stepStartVelocity; // with the position: each body's linear velocity at the step's start
    std::vector<Quat> m_stepStartOrientation;

    Profile m_profile;
    int64_t m_frame = 0;
    TeamPacing m_teamPacing = TeamPacing::Adaptive;
    TeamPacer m_pacer;
};

} // namespace rl
