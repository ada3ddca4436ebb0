#include "world/World.h"

#include "collision/Collide.h"
#include "collision/ContactCache.h"
#include "collision/Penetration.h"
#include "common/CacheLines.h"
#include "dynamics/Gyroscopic.h"
#include "scene/BodyProperties.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>
#include <optional>

namespace rl {

namespace {

// Union-find with path halving; deterministic because unions always keep the smaller index as the root.
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a == b)
        return;
    if (a < b)
        parent[b] = a;
    else
        parent[a] = b;
}

// The islands of a group that are not cut, as (bodies, root), go whole to the part with fewer bodies so far, largest
// first (ties by root, so the order is the same everywhere): the small ones then even out what the large ones left.
template <class Assign>
void shareOutWholeIslands(std::vector<std::pair<uint32_t, uint32_t>>& islands, size_t (&load)[2], Assign&& assign) {
    std::sort(islands.begin(), islands.end(), [](const auto& l, const auto& r) {
        return l.first != r.first ? l.first > r.first : l.second < r.second;
    });
    for (const auto& [bodies, root] : islands) {
        const uint8_t part = load[0] <= load[1] ? 0 : 1;
        load[part] += bodies;
        assign(root, part);
    }
}

// The bodies of an island of n to put in part 0 so that the parts come out as even as they can, with one body at
// least in each part (a lone body stays in part 0).
uint32_t evenShare(size_t n, size_t (&load)[2]) {
    if (n < 2) {
        load[0] += n;
        return static_cast<uint32_t>(n);
    }
    const int64_t wanted =
        (static_cast<int64_t>(load[1]) + static_cast<int64_t>(n) - static_cast<int64_t>(load[0])) / 2;
    const size_t share = static_cast<size_t>(std::clamp<int64_t>(wanted, 1, static_cast<int64_t>(n) - 1));
    load[0] += share;
    load[1] += n - share;
    return static_cast<uint32_t>(share);
}

// The least distance from `centre` to a face's plane over the greatest distance to a vertex of a solid polyhedron: 1
// for a ball, cos(pi / n) for a fine one whose faces span 2 pi / n, 1/sqrt(3) for a cube about its centre; 0 for a
// flat shape or a centre outside.
Real roundness(const ConvexPolyhedron& p, const Vec3& centre) {
    if (p.flat)
        return 0.0;
    Real inner = std::numeric_limits<Real>::max(), outer = 0.0;
    for (const PolyFace& f : p.faces)
        inner = std::min(inner, f.offset - glm::dot(f.normal, centre));
    for (const Vec3& v : p.vertices)
        outer = std::max(outer, glm::length(v - centre));
    return outer > 0.0 ? std::max(inner, 0.0) / outer : 0.0;
}

// The same about an axis through the centre (unit, in the points' frame): 1 - (the most any support distance
// changes as the points turn about the axis) / (their greatest distance from it). cos(pi / n) for a cylinder or a
// cone of n sides; 1 - 1/sqrt(2) for a square prism. By samples: 168 directions, each turned through 11 angles that
// are not fractions of a turn with a small denominator.
Real roundnessAbout(std::span<const Vec3> points, const Vec3& axis) {
    Real radius = 0.0;
    for (const Vec3& v : points)
        radius = std::max(radius, glm::length(v - glm::dot(v, axis) * axis));
    if (!(radius > 0.0))
        return 0.0;
    const auto support = [&points](const Vec3& d) {
        Real h = std::numeric_limits<Real>::lowest();
        for (const Vec3& v : points)
            h = std::max(h, glm::dot(v, d));
        return h;
    };
    const Vec3 across = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    Real change = 0.0;
    for (int up = -3; up <= 3; ++up)
        for (int around = 0; around < 24; ++around) {
            const Vec3 d = glm::angleAxis(2.0 * kPi * around / 24.0, axis) *
                           (std::cos(0.4 * up) * across + std::sin(0.4 * up) * axis);
            const Real h = support(d);
            for (int k = 1; k <= 11; ++k)
                change = std::max(change, std::abs(support(glm::angleAxis(0.5718 * k, axis) * d) - h));
        }
    return 1.0 - change / radius;
}

} // namespace

size_t World::s_runBodies = World::kRunBodies;

Result<World> World::create(const Scene& scene, const WorldOptions& options) {
    World w;
    const WorldSettings& ws = scene.world;
    w.m_fps = options.fps.value_or(ws.fps);
    w.m_substeps = options.substeps.value_or(ws.substeps);
    w.m_iterations = options.iterations.value_or(ws.iterations);
    w.m_integrator = options.integrator.value_or(ws.integrator);
    if (const int threads = std::clamp(options.threads, 1, 64); threads > 1) {
        w.m_ownTeam = std::make_unique<ThreadTeam>(threads);
        w.m_team = w.m_ownTeam.get();
        w.m_pacer = TeamPacer(threads);
    }
    w.m_teamPacing = options.teamPacing;
    auto settingsError = [&](std::string message) {
        Error e;
        e.file = scene.sourcePath;
        e.object = "world";
        e.message = std::move(message);
        return e;
    };
    if (!(w.m_fps > 0.0) || !std::isfinite(w.m_fps) || w.m_fps > 100000.0)
        return settingsError("fps must be between 0 and 100000 (is " + std::to_string(w.m_fps) + ")");
    if (w.m_substeps < 1 || w.m_substeps > 1000)
        return settingsError("substeps must be between 1 and 1000 (is " + std::to_string(w.m_substeps) + ")");
    if (w.m_iterations < 1 || w.m_iterations > 1000)
        return settingsError("iterations must be between 1 and 1000 (is " + std::to_string(w.m_iterations) + ")");
    const Vec3 g = ws.gravity;
    if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z))
        return settingsError("gravity is not a finite vector");
    w.m_frictionRule = ws.frictionCombine;
    w.m_restitutionRule = ws.restitutionCombine;

    const size_t n = scene.bodies.size();
    w.m_state.reserve(static_cast<uint32_t>(n));
    std::vector<Real> friction(n), restitution(n);
    std::vector<bool> dynamic(n);
    SceneFacts facts;
    Real sceneLow = std::numeric_limits<Real>::max(), sceneHigh = std::numeric_limits<Real>::lowest();
    const Vec3 down = glm::length(g) > 0.0 ? g / glm::length(g) : Vec3(0.0, -1.0, 0.0);
    std::vector<Real> initialSpeed(n);

    for (size_t i = 0; i < n; ++i) {
        const BodyDef& body = scene.bodies[i];
        Result<BodyProperties> props = computeBodyProperties(scene, body);
        if (!props) {
            Error e = props.error();
            e.file = scene.sourcePath;
            return e;
        }
        const MaterialDef material = scene.effectiveMaterial(body);
        const Quat orientation = glm::normalize(body.orientation);

        Result<Shape> shape = body.shape.type == ShapeType::Sphere ? makeSphere(body.shape.radius)
                              : body.shape.type == ShapeType::Box  ? makeBox(body.shape.halfExtents)
                                                                   : makeHull(props->hull);
        if (!shape) {
            Error e = shape.error();
            e.file = scene.sourcePath;
            e.object = body.name;
            return e;
        }

        BodyInit init;
        init.centerOfMass = props->com;
        init.orientation = orientation;
        init.comInShape = glm::conjugate(orientation) * (props->com - body.position);
        init.isStatic = body.anchor;
        init.round = body.shape.type == ShapeType::Sphere; // (its centre of mass is its centre)
        init.mass = body.anchor ? 0.0 : props->mass;
        init.inertia = props->inertia;
        // Principal moments that agree to kIsotropicSpread are the rounding of a written mesh (a cube exported with
        // six decimals: in ramps.obj, 77 of the 642 cubes spread by 1e-12 to 5e-6 of their moment), not a shape:
        // such a body is simulated with their mean, as the cube it is. Its gyroscopic torque, below that spread times
        // |I| |w|^2, is then zero, and the integrator and the solver take the isotropic paths (BodyState).
        const Vec3 moments = props->principalMoments;
        if (!body.anchor && moments.z - moments.x <= kIsotropicSpread * moments.z)
            init.inertia = Mat3((moments.x + moments.y + moments.z) / 3.0);
        init.linearVelocity = body.velocity;
        init.angularVelocity = body.angularVelocity;
        Result<uint32_t> index = w.m_state.addBody(init);
        if (!index) {
            Error e = index.error();
            e.file = scene.sourcePath;
            e.object = body.name;
            return e;
        }

        if (!body.anchor && shape->kind == ShapeKind::Polyhedron) {
            // A ball, a cylinder or a cone made of faces. The anchors of the face it lies on turn with it and follow
            // the surface while it turns through less than about one face (2 acos(roundness) seen from the centre);
            // turned farther within a step, they rise off while faces that were not in contact come down unseen, and
            // it sinks. Held round, it sinks at most by how much nearer the centre its faces are than its corners.
            // Round about an axis: two equal principal moments, the third one's axis.
            BodyInfo& info = w.m_state.info[*index];
            Vec3 axis(0.0);
            Real round = roundness(*shape->polyhedron, init.comInShape);
            if (round < w.m_tuning.roundHullRoundness) {
                const Vec3 m = info.principalMoments; // ascending
                axis = m.y - m.x <= 1e-3 * m.z ? Vec3(0, 0, 1) : m.z - m.y <= 1e-3 * m.z ? Vec3(1, 0, 0) : Vec3(0.0);
                round = 0.0;
                if (axis != Vec3(0.0) && !(m.z - m.x <= 1e-3 * m.z)) {
                    std::vector<Vec3> points; // about the centre of mass, in the principal frame
                    for (const Vec3& v : shape->polyhedron->vertices)
                        points.push_back(info.shapeFromPrincipal * (v - init.comInShape));
                    round = roundnessAbout(points, axis);
                }
            }
            if (round >= w.m_tuning.roundHullRoundness) {
                info.rollAxis = axis;
                w.m_roundHulls.push_back({*index, 2.0 * std::acos(round) * w.m_fps, axis});
            }
        }
        w.m_names.push_back(body.name);
        w.m_shapes.push_back(std::move(shape).value());
        w.m_friction.push_back(material.friction);
        w.m_restitution.push_back(material.restitution);
        w.m_vertexMeanOffset.push_back(props->vertexMean - props->com);
        // rotationSinceStart() = orientation * shapeFromPrincipal * conjugate(this starting orientation): the last two
        // taken together once here.
        w.m_startFromPrincipal.push_back(
            glm::normalize(w.m_state.info[*index].shapeFromPrincipal * glm::conjugate(orientation)));
        w.m_minExtent.push_back(w.m_shapes.back().minExtent());
        {
            const Aabb bounds = w.m_shapes.back().localBounds();
            Vec3 size = bounds.max - bounds.min;
            std::sort(&size.x, &size.x + 3);
            w.m_middleExtent.push_back(size.y);
        }
        {
            const Shape& s = w.m_shapes.back();
            w.m_turnsThroughFeatures.push_back(body.anchor || !s.polyhedron || s.polyhedron->flat ? 0
                                               : s.polyhedron->isBox                              ? kTurnsBoxCorner
                                                                                                  : kTurnsAnyCorner);
        }
        // Radius about the centre of mass: how fast a spinning body's surface can move. (The shape's own bounding
        // radius is about the shape origin, which for an OBJ object is the file's origin, far from the body.)
        Real radius = body.shape.type == ShapeType::Sphere ? body.shape.radius : 0.0;
        for (const Vec3& v : props->hull.vertices)
            radius = std::max(radius, glm::length(v - init.comInShape));
        w.m_radius.push_back(radius);
        friction[i] = material.friction;
        restitution[i] = material.restitution;
        dynamic[i] = !body.anchor;

        const Aabb box = w.m_shapes.back().worldBounds(w.transform(i));
        sceneLow = std::min(sceneLow, glm::dot(box.min, -down) < glm::dot(box.max, -down) ? glm::dot(box.min, -down)
                                                                                          : glm::dot(box.max, -down));
        sceneHigh = std::max(sceneHigh, std::max(glm::dot(box.min, -down), glm::dot(box.max, -down)));
        if (!body.anchor) {
            facts.anyDynamic = true;
            facts.anyNonSphereDynamic = facts.anyNonSphereDynamic || body.shape.type != ShapeType::Sphere;
            facts.anySpinning = facts.anySpinning || glm::length(body.angularVelocity) > 0.0;
            initialSpeed[i] = glm::length(body.velocity) + glm::length(body.angularVelocity) * w.m_radius.back();
        } else {
            facts.anyAnchor = true;
        }
    }
    facts.frictionPairs = anyPositivePair(w.m_frictionRule, friction, dynamic);
    facts.restitutionPairs = anyPositivePair(w.m_restitutionRule, restitution, dynamic);
    // The fastest a body can get by falling the height of the scene: sqrt(2 g H).
    const Real fallSpeed = n > 0 ? std::sqrt(2.0 * glm::length(g) * std::max(0.0, sceneHigh - sceneLow)) : 0.0;
    const Real dt = 1.0 / w.m_fps;
    for (size_t i = 0; i < n; ++i)
        if (dynamic[i] && (initialSpeed[i] + fallSpeed) * dt > w.m_tuning.ccdFraction * w.m_minExtent[i])
            facts.fastBodies = true;

    w.m_effects = decideEffects(scene, options.effects.value_or(ws.effects), facts);
    const ActiveEffects& fx = w.m_effects.effects;
    w.m_gravity = fx.has(Effect::Gravity) ? g : Vec3(0.0);
    // Without rotation a body neither turns nor spins: a spin the scene gives it would never act, and the frames and
    // exports would report an angular velocity the body does not have.
    if (!fx.has(Effect::Rotation))
        std::fill(w.m_state.angularVelocity.begin(), w.m_state.angularVelocity.end(), Vec3(0.0));
    if (fx.has(Effect::Damping))
        w.m_damping = Damping{ws.linearDamping, ws.angularDamping};
    w.m_solverSettings.contactHertz = 0.25 * w.m_fps * w.m_substeps;
    w.m_solverSettings.gravity = w.m_gravity;
    w.m_solverSettings.step = 1.0 / w.m_fps;
    w.m_solverSettings.flightOffset = w.m_integrator == Integrator::SymplecticEuler ? 0.5
                                      : w.m_integrator == Integrator::ExplicitEuler ? -0.5
                                                                                    : 0.0;
    w.m_solverSettings.friction = fx.has(Effect::Friction);
    w.m_solverSettings.restitution = fx.has(Effect::Restitution);
    w.m_solverSettings.blowPasses = w.m_tuning.blowPasses;
    w.m_solverSettings.blowShockPasses = w.m_tuning.blowShockPasses;

    BroadPhaseSettings broad;
    broad.dynamicTree.margin = w.m_tuning.aabbMargin;
    w.m_broadPhase = BroadPhase(broad);
    w.m_proxies.resize(n);
    w.m_bounds.resize(n);
    w.m_reach.assign(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
        const Aabb box = w.m_shapes[i].worldBounds(w.transform(i));
        w.m_bounds[i] = box;
        Result<ProxyKey> key = w.m_broadPhase.createProxy(
            box, static_cast<uint32_t>(i),
            w.m_state.isStatic(static_cast<uint32_t>(i)) ? ProxyKind::Static : ProxyKind::Dynamic);
        if (!key) {
            Error e = key.error();
            e.file = scene.sourcePath;
            e.object = w.m_names[i];
            return e;
        }
        w.m_proxies[i] = key.value();
    }
    w.m_sleepTime.assign(n, 0.0);
    w.m_sleepAnchorPosition.assign(w.m_state.position.begin(), w.m_state.position.end());
    w.m_sleepAnchorOrientation.assign(w.m_state.orientation.begin(), w.m_state.orientation.end());
    // Room for the contacts of 16 pairs a body before the pool has to move: growing by doubling copied the pool into
    // fresh memory each time, and on this project's virtual machines a page touched for the first time costs about
    // 11 us (measured 2026-11-26), so ramps.obj's pool growing to 7,667 contacts took 29 ms of its first 120 frames.
    // Reserving touches nothing: pages are faulted in as contacts are made.
    w.m_contactPool.reserve(16 * n);
    w.m_contactPairs.reserve(16 * n);
    w.m_island.resize(n);
    std::iota(w.m_island.begin(), w.m_island.end(), 0u);
    return w;
}

Quat World::rotationSinceStart(size_t i) const {
    // Each frame a bake records reads two arrays, not the bodies' bookkeeping (the constant factors: create()).
    return glm::normalize(m_state.orientation[i] * m_startFromPrincipal[i]);
}

void World::step() {
    // The team or member 0 alone (TeamPacer): the same frames either way.
    const auto start = std::chrono::steady_clock::now();
    bool alone = false;
    if (m_ownTeam) {
        switch (m_teamPacing) {
        case TeamPacing::Adaptive:
            alone = !m_pacer.useTeam();
            break;
        case TeamPacing::Always:
            break;
        case TeamPacing::EveryOtherStep:
            alone = m_frame % 2 == 1;
            break;
        }
        m_team = alone ? nullptr : m_ownTeam.get();
        m_ownTeam->takeLeaderWait(); // only this step's waits count
    }
    const uint64_t teamJobs = m_ownTeam ? m_ownTeam->teamJobs() : 0;
    stepOnce();
    if (m_ownTeam) {
        // A step of a world too small for the team (under its thresholds of bodies and pairs) runs no job on it.
        if (m_ownTeam->teamJobs() != teamJobs)
            m_profile.count(Counter::TeamSteps, 1);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        m_pacer.record(seconds, 1e-9 * static_cast<double>(m_ownTeam->takeLeaderWait()));
        m_team = m_ownTeam.get();
        if (alone)
            m_profile.count(Counter::StepsAlone, 1);
    }
}

void World::updateRoundHulls() {
    // Set before the narrowphase, which predicts the turns of bodies that are not round (collidePair()); nothing
    // changes a velocity between here and the solve.
    for (const RoundHull& r : m_roundHulls) { // round in a step in which it turns through a face or more
        const uint32_t i = r.body;
        const Vec3& w = m_state.angularVelocity[i];
        if ((r.axis == Vec3(0.0) ? glm::length(w) : std::abs(glm::dot(w, m_state.orientation[i] * r.axis))) > r.spin)
            m_state.flags[i] |= kBodyRound;
        else
            m_state.flags[i] &= static_cast<uint8_t>(~kBodyRound);
    }
}

void World::pushOutOfContacts(Real slop) {
    // The rows of the step's sweeps hold, at anchors fixed at the step's start, the normal velocities that keep their
    // points out; a body that turns fast follows an arc while those velocities follow its chord, and its points went
    // into what they rest on: a top spinning at 80 rad/s on its tip, 34 mm a frame; a cone struck spinning at 65
    // rad/s, 28 mm. So, after the sweeps, each point of a contact between a moving body and one that does not move
    // (an anchor, a sleeper) that the step took more than `slop` inside, and the moving body's corner deepest along
    // the contact's normal (a cylinder tumbling at 40 rad/s onto its end: a corner of its 32-gon that the manifold's
    // four did not hold, 7.4 mm; now 2.0), moves the body out to `slop`, positions only (post-stabilisation; Cline and
    // Pai 2003), two passes. Contacts between two moving bodies are left to the sweeps: pushed apart, one went into
    // whatever held it on its other side.
    //
    // Each body moves alone (the still side stays where the step started), so on a team each member takes the
    // contacts of its share of the bodies, each body's in the same order as one thread: the same numbers.
    const size_t bodyCount = m_state.size();
    const int members = m_team && m_touchingContacts.size() >= kMinBodiesForTeam ? m_team->size() : 1;
    m_pushedContacts.resize(std::max(m_pushedContacts.size(), static_cast<size_t>(members)));
    const auto job = [&](int member) {
        const auto [firstBody, lastBody] = ThreadTeam::share(0, bodyCount, member, members);
        std::vector<uint32_t>& pushed = m_pushedContacts[static_cast<size_t>(member)].list;
        pushed.clear();
        for (int pass = 0; pass < 2; ++pass) {
            const size_t count = pass == 0 ? m_touchingContacts.size() : pushed.size();
            for (size_t s = 0; s < count; ++s) {
                // The first pass reads the bodies from the compact list beside the contacts (m_touchingBodies), and the
                // contact itself only where it moves a body.
                const auto [a, b] = pass == 0
                                        ? m_touchingBodies[s]
                                        : std::pair{m_contactPairs[pushed[s]].bodyA, m_contactPairs[pushed[s]].bodyB};
                const bool movesA = m_state.isMoving(a);
                if (movesA == m_state.isMoving(b))
                    continue;
                const uint32_t body = movesA ? a : b;
                if (body < firstBody || body >= lastBody)
                    continue;
                // A body that ends the step too slow to have moved slop within it is left alone (the sweeps keep a slow
                // body's points where they hold them); this takes most resting contacts out before any transform.
                if (pass == 0) {
                    const Real travel = (glm::length(m_state.linearVelocity[body]) +
                                         glm::length(m_state.angularVelocity[body]) * m_radius[body]) /
                                        m_fps;
                    if (!(travel > slop))
                        continue;
                }
                const uint32_t slot = pass == 0 ? m_touchingContacts[s] : pushed[s];
                const Manifold& m = m_contactPool[slot].manifold;
                if (m.pointCount == 0)
                    continue;
                bool moved = false, movedAny = false;
                // The still side's transform is that of the step's start.
                const Transform& still = m_transforms[movesA ? b : a];
                // Moves the body out along `out` by what the point p is deeper than slop in the still shape, measured
                // from outside along the normal (a point that slid past the edge of the face it rested on is below its
                // plane but not in it); `estimate` is its separation against that plane.
                Transform now;
                Vec3 out;
                const auto pushOut = [&](const Vec3& p, Real estimate) {
                    const Real reach = 0.01 - estimate;
                    const std::optional<Real> t = distanceAlong(m_shapes[movesA ? b : a], still, p + reach * out, -out);
                    if (!t || !(*t - reach < -slop))
                        return;
                    const Real sep = *t - reach;
                    const Vec3 r = p - m_state.position[body];
                    const Mat3 inverseInertia = m_state.worldInverseInertia(body);
                    const Vec3 c = glm::cross(r, out);
                    const Real w = m_state.invMass[body] + glm::dot(c, inverseInertia * c);
                    if (!(w > 0.0))
                        return;
                    const Real push = -(sep + slop) / w; // along `out`
                    nudge(body, push, out, m_state.invMass[body], inverseInertia, c);
                    moved = movedAny = true;
                };
                // The manifold's points, then the body's corner deepest along the normal, which a fast turn may have
                // brought down without a point of its own. The body's pose, and the direction out of the still shape
                // (the normal turns with A, collidePair()), taken again after each push.
                const auto pose = [&] {
                    now = transform(body);
                    out = movesA ? -(now.rotation * (glm::transpose(m_transforms[a].rotation) * m.normal)) : m.normal;
                    moved = false;
                };
                pose();
                const Vec3 stillPoint = movesA ? still.apply(m.points[0].localB) : still.apply(m.points[0].localA);
                for (int k = 0; k <= m.pointCount; ++k) {
                    if (moved)
                        pose();
                    const Vec3 p = k < m.pointCount
                                       ? (movesA ? now.apply(m.points[k].localA) : now.apply(m.points[k].localB))
                                       : now.apply(m_shapes[body].support(now.rotateInverse(-out)));
                    const Vec3 onStill =
                        k < m.pointCount ? (movesA ? still.apply(m.points[k].localB) : still.apply(m.points[k].localA))
                                         : stillPoint;
                    const Real estimate = glm::dot(out, p - onStill);
                    if (estimate < -slop)
                        pushOut(p, estimate);
                }
                if (pass == 0 && movedAny)
                    pushed.push_back(slot);
            }
        }
    };
    if (members > 1)
        m_team->run(job);
    else
        job(0);
    for (int m = 0; m < members; ++m)
        m_profile.count(Counter::PushedContacts, m_pushedContacts[static_cast<size_t>(m)].list.size());
}

void World::nudge(uint32_t body, Real push, const Vec3& direction, Real inverseMass, const Mat3& inverseInertia,
                  const Vec3& arm) {
    m_state.position[body] += inverseMass * push * direction;
    // (First order: a push turns most bodies by little, though a thin one it may turn far, keepSpinEnergy(). The
    // exponential map, rotationFromVector(), changes the frames, and with it two of the 144 piles of tst_piles' kind,
    // seeds 7 and 36, were still moving at 10 s, 2026-12-05.)
    const Vec3 theta = push * (inverseInertia * arm);
    Quat& q = m_state.orientation[body];
    const Quat before = q;
    q = glm::normalize(q + 0.5 * Quat(0.0, theta.x, theta.y, theta.z) * q);
    keepSpinEnergy(body, before);
}

void World::keepSpinEnergy(uint32_t body, const Quat& before) {
    // A correction (a push out of an overlap, CCD's rewind) turns the pose and leaves the angular velocity in world
    // axes, as Box2D and Jolt leave it; a spin about a body's easy axis may then lie along a hard one, with more
    // energy. A push turns a body by its inverse inertia times the arm, which about the length of a needle of 20 x
    // 0.2 x 0.2 cm is 5,000 times that about its width: one push turned a needle spinning at 615 rad/s about its
    // length by about 1 rad, and its kinetic energy went from 0.0028 J to 0.15 J, 41 times what its fall from 0.5 m
    // gave it (2026-12-07). So where the turn raised the spin's energy, the angular velocity is scaled back to the
    // energy it had. (Turned with the pose instead, the spin keeps its energy too, but a 3 kg cone spinning at 52
    // rad/s under a 536 kg cylinder, pushed out and turned, then drove the cylinder by friction as a held body, and
    // tst_motion's capturedBouncesGainNoEnergy gained 3.9 % in 2 s where this gains nothing.)
    if (!m_state.isMoving(body))
        return;
    Vec3& w = m_state.angularVelocity[body];
    const Vec3 moments = m_state.info[body].principalMoments;
    const Vec3 wBefore = glm::conjugate(before) * w, wNow = glm::conjugate(m_state.orientation[body]) * w;
    const Real energyBefore = glm::dot(wBefore, moments * wBefore), energyNow = glm::dot(wNow, moments * wNow);
    if (energyNow > energyBefore)
        w *= std::sqrt(energyBefore / energyNow);
}

CollideOptions World::pairCollideOptions() const {
    CollideOptions options;
    // Overlapping edges are clipped like edges apart (CollideOptions) where the pair's margin is at least twice the
    // speculative distance, that is where its bodies' speeds and turns may close it by that much within the step.
    options.clipOverlappingEdgesFrom = 2.0 * m_tuning.speculativeDistance;
    return options;
}

bool World::withStillBody(uint32_t slot) const {
    return !m_state.isMoving(m_contactPairs[slot].bodyA) || !m_state.isMoving(m_contactPairs[slot].bodyB);
}

Real World::roundsBeyond(uint32_t slot) const {
    // With kRoundsBeyond for every pair, a box on the floor that separateMovedPairs() pushed down, parting it from one
    // that landed on it turning, stayed up to slop + kRoundsBeyond (5 mm) in the floor: in piles of 1,000 boxes
    // (bench_piles grid16, grid16h and grid12, seeds 1-75) the lowest point of each pile was -4.96 mm on average,
    // -9.13 mm at worst, in Blender's boxes1000.obj -4.99 mm and in ramps.obj -4.65 mm. Pushed from the floor's slop,
    // -2.46 mm on average and -6.24 at worst, -2.00 and -2.00 mm (2026-12-07); the deepest contact between two boxes of
    // a pile 0.8 mm less in grid16, 1.9 and 2.0 mm more in grid16h and grid12 (averages of 75 piles: 21.8, 34.5, 20.8).
    return withStillBody(slot) ? 0.0 : kRoundsBeyond;
}

Real World::separationFloor(uint32_t slot, Real slop, bool fromStart) const {
    const Manifold& m = m_contactPool[slot].manifold;
    Real start = 0.0; // the deepest point at the step's start, or 0
    for (int k = 0; k < m.pointCount; ++k)
        start = std::min(start, m.points[k].separation);
    // A body in an anchor or a sleeper has -slop for its floor in the rounds too, as in pushOutOfContacts(), not its
    // depth at the step's start: that depth was where the pushes of the step before had left it, and in piles of
    // 1,000 random boxes those pushed a box on the floor into it again step after step (-3.1, -3.6, -4.5, -8.1 and
    // -12.4 mm, the pushes out of the floor taking it back to -2 mm each time), with the floor of the rounds following
    // it down. Measured 2026-12-06 over 48 piles (10 x 10 x 10 grids 1.2 and 1.6 m apart, from 1 m and 10 m up, boxes
    // of 0.3-0.8 m): lowest vertex below the floor at most 8.5 mm, one pile beyond 6 mm, against 14.6 mm and 12 piles
    // beyond 10 mm; the deepest contact anywhere 33.7 mm on average against 33.0.
    const bool still = withStillBody(slot);
    return (fromStart && !still) || start < -m_tuning.separateDeepStart ? start - slop : -slop;
}

bool World::movedInto(uint32_t slot, Real slop, const Transform& xfA, const Transform& xfB, bool inRounds,
                      Manifold* collision) const {
    const uint32_t a = m_contactPairs[slot].bodyA, b = m_contactPairs[slot].bodyB;
    const Contact& c = m_contactPool[slot];
    const Manifold& m = c.manifold;
    if (!m_state.isMoving(a) && !m_state.isMoving(b))
        return false;
    const Real limit = (inRounds ? roundsBeyond(slot) : 0.0) - separationFloor(slot, slop, inRounds); // deeper counts
    // The shapes overlap by no more than they do along any one direction: along the contact's normal turned with A
    // and turned with B, or for a pair apart at the step's start, along the axis that separated it turned with A.
    // Most turning contacts end here (a box resting tilted on another's edge overlaps it far more along the normal
    // turned with one of them than the two overlap). A box's reach along a direction takes no support query
    // (Shape::reachAlong()).
    const auto overlapAlong = [&](const Vec3& n) { return overlapAlongAxis(m_shapes[a], xfA, m_shapes[b], xfB, n); };
    if (m.pointCount > 0) {
        if (!(overlapAlong(xfA.rotation * (glm::transpose(m_transforms[a].rotation) * m.normal)) > limit) ||
            !(overlapAlong(xfB.rotation * (glm::transpose(m_transforms[b].rotation) * m.normal)) > limit))
            return false;
    } else if (c.separatingAxis != Vec3(0.0) && !(overlapAlong(xfA.rotate(c.separatingAxis)) > limit)) {
        return false;
    }
    Manifold fresh;
    if (!collide(m_shapes[a], xfA, m_shapes[b], xfB, 0.0, fresh, pairCollideOptions()))
        return false;
    for (int k = 0; k < fresh.pointCount; ++k)
        if (fresh.points[k].separation < -limit) {
            if (collision)
                *collision = fresh;
            return true;
        }
    return false;
}

int World::separatePair(uint32_t slot, Real slop, std::vector<uint8_t>* grounded, const Manifold* collision) {
    const uint32_t a = m_contactPairs[slot].bodyA, b = m_contactPairs[slot].bodyB;
    // Pushed to the floor when deeper than it. In rounds (groundPushedBodies()), the floor is the slop under the
    // contact's depth at the step's start, whatever that was: at the foot of a stack of falling cubes, 2-3 mm in each
    // other after the step, pushing the lowest out of the floor to 2 mm lifted the next by as much plus its own depth,
    // and so on up (5.7, 6.7, 8.4, 9.9 mm in ramps.obj), and left the last pair 10.9 mm deep. (A pair with a still
    // body has -slop for its floor in the rounds too: separationFloor().) A pair of moving bodies is pushed in rounds
    // when kRoundsBeyond deeper than the floor, to half the slop inside it, so that the pairs the pushes before left
    // at the floor are not pushed again for their rounding, nor a body between two others to and fro between them; a
    // pair with a still body as soon as it is deeper than the floor (roundsBeyond()).
    const Real floor = separationFloor(slot, slop, grounded != nullptr);
    const Real target = grounded ? floor - roundsBeyond(slot) : floor; // no point deeper than this
    const Real aim = grounded ? floor + 0.5 * slop : floor;
    const Real gravity = glm::length(m_gravity);
    const Vec3 up = gravity > 0.0 ? -m_gravity / gravity : Vec3(0.0);
    const CollideOptions options = pairCollideOptions();
    int pushes = 0;
    for (; pushes < 2; ++pushes) {
        Manifold fresh;
        if (pushes == 0 && collision)
            fresh = *collision; // the same collision, where the bodies are now
        else if (!collide(m_shapes[a], transform(a), m_shapes[b], transform(b), 0.0, fresh, options))
            break;
        int deepest = -1;
        for (int k = 0; k < fresh.pointCount; ++k)
            if (deepest < 0 || fresh.points[k].separation < fresh.points[deepest].separation)
                deepest = k;
        if (deepest < 0 || !(fresh.points[deepest].separation < target))
            break;
        const Vec3 n = fresh.normal, p = fresh.points[deepest].position;
        // In rounds, a body that does not move or is grounded, under one that is not (the normal within 45 degrees of
        // the vertical), stays where it is, and the upper one takes the whole push, along the normal alone, which
        // takes every point of it out by as much (a push at the deepest point that also turned it brought a thin box
        // spinning at 87 rad/s from 54 to 40 mm out of the floor in two pushes); that one is grounded then. Side by
        // side, as cubes in a row on a ramp, the two share the push as elsewhere.
        bool movesA = m_state.isMoving(a), movesB = m_state.isMoving(b);
        bool holdA = false, holdB = false;
        if (grounded) {
            const bool baseA = !movesA || (*grounded)[a], baseB = !movesB || (*grounded)[b];
            holdA = baseA && !baseB && glm::dot(n, up) > std::sqrt(0.5);  // B above A
            holdB = baseB && !baseA && glm::dot(n, up) < -std::sqrt(0.5); // A above B
            movesA = movesA && !holdA;
            movesB = movesB && !holdB;
        }
        if (!movesA && !movesB)
            break;
        const bool translateOnly = holdA || holdB;
        // The deepest point out to the target along the new normal, the two bodies sharing the push by their
        // inverse masses at that point (positions only: post-stabilisation, as pushOutOfContacts()).
        const Vec3 cA = glm::cross(p - m_state.position[a], n), cB = glm::cross(p - m_state.position[b], n);
        const Mat3 inertiaA = movesA && !translateOnly ? m_state.worldInverseInertia(a) : Mat3(0.0);
        const Mat3 inertiaB = movesB && !translateOnly ? m_state.worldInverseInertia(b) : Mat3(0.0);
        const Real wA = movesA ? m_state.invMass[a] : 0.0, wB = movesB ? m_state.invMass[b] : 0.0;
        const Real w = wA + wB + glm::dot(cA, inertiaA * cA) + glm::dot(cB, inertiaB * cB);
        if (!(w > 0.0))
            break;
        const Real push = (aim - fresh.points[deepest].separation) / w; // along n, B from A
        if (movesA)
            nudge(a, -push, n, wA, inertiaA, cA);
        if (movesB)
            nudge(b, push, n, wB, inertiaB, cB);
        if (holdA)
            (*grounded)[b] = 1;
        if (holdB)
            (*grounded)[a] = 1;
    }
    return pushes;
}

void World::forEachChunkClaimed(size_t count, size_t chunk, bool onTeam,
                                const std::function<void(size_t, size_t)>& range) {
    if (!onTeam || !m_team) {
        range(0, count);
        return;
    }
    std::atomic<size_t> claimed{0};
    m_team->run(
        [&](int member) { ThreadTeam::forEachClaimedChunk(claimed, count, chunk, member, m_team->size(), range); });
}

void World::testMovedInto(std::span<const uint32_t> contacts, Real slop, std::vector<uint8_t>& deep,
                          std::vector<Manifold>& collisions) {
    // Claimed in chunks as the members go: a test that collides costs many times one that a direction turns away,
    // and in even halves one member waited for the other. (The tests of boxes1000.obj's first 120 frames took 16.2-16.6
    // ms on two threads in even halves, 15.0-15.6 in chunks, and 26.0-28.7 on one; timers in a scratch build, two runs
    // each, 2026-12-06.)
    forEachChunkClaimed(
        contacts.size(), kSeparateChunk, contacts.size() >= kMinBodiesForTeam, [&](size_t begin, size_t end) {
            for (size_t t = begin; t < end; ++t) {
                const auto [a, b] = m_touchingBodies[contacts[t]];
                const bool in =
                    movedInto(m_touchingContacts[contacts[t]], slop, transform(a), transform(b), false, &collisions[t]);
                deep[t] = in ? 1 : 0;
            }
        });
}

void World::separateMovedPairs(Real slop) {
    // The sweeps keep the manifold's points out, and addTurnedSupports() the corners that a turn known at the step's
    // start brings down; a blow within the step can set a body turning so that other features go in, unseen until
    // the next step. In ramps.obj a cube falling at 8.5 m/s onto another's edge met it at one point, was set
    // spinning at 25 rad/s and swung its side 46.4 mm into the other; a box thrown onto an anchored box turned so
    // that the anchor's corner went 42.5 mm into its side; a domino's top edge slid 4.3 mm (mu 0.5) and 7.7 mm (mu
    // 0.1) into the next one's face. So after CCD (which moves fast bodies back along their paths, in ramps.obj once
    // 38 mm into a neighbour they had cleared), each contact whose bodies' turns at the step's end move a point by
    // more than WorldTuning::separateTurn a step is collided again where the step left it (movedInto(); two support
    // queries turn most away first), and one deeper than slop is pushed apart to slop, positions only, the two
    // bodies sharing the push by their inverse masses (separatePair()). A contact that began the step deeper than
    // WorldTuning::separateDeepStart (bodies created overlapping) keeps that depth: the solver parts those at a
    // bounded speed. The tests run on the team, reading the state only; the pushes follow one after the other in the
    // contacts' order, so the frames are the same on any number of threads.
    //
    // Measured 2026-12-06, against 10942cb: ramps.obj's first 900 frames held a contact deeper than 1 cm in 0 frames
    // against 20, deeper than 5 mm in 0 against 69, the deepest 5.0 mm against 46.4; over its first 120 frames from
    // 17 starts (every cube moved by up to 0.1 mm), the deepest 3.6-16.0 mm against 43.1-56.8 (9.2-23.3 with the
    // first pass of pushes alone). Piles of 1,000 boxes, seeds 1-144, 600 frames (from frame 5 on: the piles begin
    // overlapping): 524 frames deeper than 1 cm in all against 3,753, the deepest 21.3 mm on average against 38.9;
    // 285 of seeds 1-288 at rest at 10 s either way (other seeds). Dominoes (tst_motion): 2.0-2.1 mm. The pass took
    // 3.0 % of the stages' time over ramps.obj's 900 frames and 4.8 % over its first 120, 4.2 % over boxes1000's 300
    // and 7.1 % over its first 120, 0.1 % in large_pyramid (the loop over the bodies); no step was slower for it:
    // one thread, each frame's least of two runs, three rounds by turns, ramps.obj's 120 frames 2.079-2.095 ms
    // against 2.142-2.177, boxes1000's 4.02-4.08 ms against 4.02-4.27 (the frames differ: over ramps.obj's 120
    // frames the other stages took 16-23 ms less in all). Linear velocity is not looked at: a translation alone
    // keeps the manifold's deepest features deepest, and counting it (with 2 mm; one pass) cost 1.2 % in
    // large_pyramid and left ramps.obj's contacts as deep. Pushed without turning the bodies (tried), the 17 starts
    // gave 3.7-18.0 mm.
    //
    // First each body: whether its turn moves a point of it by more than half separateTurn in a step (a pile at
    // rest, or a pyramid settling with 49,000 contacts, ends here).
    //
    // Also each body struck within the step faster than its pairs' margins allowed for (its speed at the step's end,
    // its turn's included, above its speed and push speed at the start by more than the speculative distance in the
    // step): where its pairs with still bodies had no points, the sweeps could not keep it out of them. Those pairs
    // are collided again by groundPushedBodies(), as those of a pushed body. (A 0.6 m box of 2,160 kg falling at 10
    // m/s onto a 0.5 m one of 125 kg that was falling onto the floor drove it 26.6 mm into the floor, 1.1 mm now; in
    // a pile of 1,000 boxes, a box 53 mm above the floor was struck 35 mm into it by a box of the layer above.)
    const size_t bodies = m_state.size();
    const Real dt = 1.0 / m_fps;
    m_turnStep.assign(bodies, 0.0);
    m_struck.clear();
    bool any = false;
    // With CCD on (which keeps where each body began the step), also each body's turn in the step and whether it
    // strayed from its start velocity's path, for the pairs that had no points at the start (below).
    const bool tracksStart = m_stepStartPosition.size() == bodies;
    bool anyDeviated = false;
    if (tracksStart) {
        m_turnInStep.assign(bodies, 0.0);
        m_deviated.assign(bodies, 0);
    }
    for (uint32_t i = 0; i < bodies; ++i) {
        if (!m_state.isMoving(i))
            continue;
        const Real spin = glm::length(m_state.angularVelocity[i]) * m_radius[i];
        m_turnStep[i] = spin / m_fps;
        any = any || m_turnStep[i] > 0.5 * m_tuning.separateTurn;
        if ((glm::length(m_state.linearVelocity[i]) + spin - m_reach[i] - m_pushSpeed[i]) * dt >
            m_tuning.speculativeDistance)
            m_struck.push_back(i);
        if (tracksStart) {
            const Real c = std::abs(glm::dot(m_stepStartOrientation[i], m_state.orientation[i]));
            const Real s = std::sqrt(std::max(1.0 - c * c, 0.0));
            m_turnInStep[i] = (2.0 * s < glm::pi<Real>() * c ? 2.0 * s / c : glm::pi<Real>()) * m_radius[i];
            const Real startSpin = m_reach[i] - glm::length(m_stepStartVelocity[i]);
            const Vec3 off = m_state.position[i] - m_stepStartPosition[i] - m_stepStartVelocity[i] * dt;
            m_deviated[i] =
                glm::length(off) + std::max(m_turnInStep[i] - startSpin * dt, 0.0) > 0.5 * m_tuning.speculativeDistance;
            anyDeviated = anyDeviated || m_deviated[i];
        }
    }
    // Also each pair of moving bodies that had no points at the step's start, so was more than its margin apart
    // (at least the speculative distance), and whose bodies came nearer to each other in the step than that by
    // their travels and turns: the margin counts the speeds at the start, and a body stopped within the step by
    // another contact is caught up by the one behind it. In ramps.obj a cube sliding down at 4.4 m/s went 27.5 mm
    // into the one ahead of it, which the floor at the ramp's foot stopped from 4.4 m/s to 1.3 within the step
    // (2026-12-08; over 104 starts the deepest contact of the first 2 s was 4.5-26.0 mm before, 4.5-14.7 mm with
    // this pass, 4.2-14.2 mm with the CCD change of the same day too). Those pairs are collided again where the step
    // left them and pushed apart as the others below. (Only with CCD on, which keeps where each body began the step.)
    m_missedPairs.clear();
    if (tracksStart) {
        // Two bodies came nearer by at most their travels' difference plus their turns times their radii. That is
        // at most what the margin covers (their speeds' difference and their spins at the start, times the step)
        // plus each one's deviation: its travel less its start velocity times the step, plus what its turn exceeds
        // its start spin by. So only pairs with a body that deviated by more than half the speculative distance are
        // looked at. (Where the margin was capped at the bodies' size, one of them moved more than half its own and
        // CCD swept it. A turn's angle 2 asin s, with s and c the sine and cosine of its half, is at most 2 s / c: no
        // arc sine.)
        for (size_t i = 0; anyDeviated && i < m_pairContacts.size(); ++i) {
            const auto [a, b] = m_pairBodies[i];
            if (!m_deviated[a] && !m_deviated[b])
                continue;
            const uint32_t slot = m_pairContacts[i];
            if (m_contactTouching[slot] || !m_state.isMoving(a) || !m_state.isMoving(b) ||
                !(glm::length((m_state.position[a] - m_stepStartPosition[a]) -
                              (m_state.position[b] - m_stepStartPosition[b])) +
                      m_turnInStep[a] + m_turnInStep[b] >
                  m_pairStartGap[slot]))
                continue;
            m_missedPairs.push_back(slot);
        }
    }
    // (Without a turn above half separateTurn no contact's two turns pass separateTurn: with struck bodies alone,
    // nothing below is tested or pushed until their rounds.)
    if (!any && m_struck.empty() && m_missedPairs.empty())
        return;
    // The touching contacts whose two turns together move a point by more than separateTurn. The tests take each
    // body's transform again rather than share one list of them: on two threads with the cores far apart, a list
    // taken by member 0 made the stage slower over boxes1000's first 120 frames (26.2-27.1 ms against 23.4-23.6
    // before this list of contacts; 19.1 ms without it; 2026-12-06).
    const size_t n = m_touchingContacts.size();
    m_turnedContacts.clear();
    // (The bodies of the touching contacts from their compact list, not from the contacts in the pool.)
    for (size_t k = 0; k < n; ++k) {
        const auto [a, b] = m_touchingBodies[k];
        if (m_turnStep[a] + m_turnStep[b] > m_tuning.separateTurn)
            m_turnedContacts.push_back(static_cast<uint32_t>(k));
    }
    const size_t tests = m_turnedContacts.size();
    // Each test's collision is kept where the pair went in, for its push below.
    m_movedInto.assign(tests, 0);
    if (m_separateCollisions.size() < tests)
        m_separateCollisions.resize(tests);
    testMovedInto(m_turnedContacts, slop, m_movedInto, m_separateCollisions);
    // Then the pushes, and a second pass over every contact of a body pushed in the first (whatever its turn): a push
    // drives a body into its other neighbours, and turning it can bring another of its corners into the same one (in
    // ramps.obj from one of the 17 starts, a pair 39.9 mm deep was 48.0 mm deep after one push). A push's first
    // collision is the test's while neither body has moved since; the numbers are the same as colliding again.
    uint64_t pushes = 0;
    std::vector<uint8_t>& pushed = m_separated;
    pushed.assign(bodies, 0);
    bool anyPushed = false;
    for (size_t t = 0; t < tests; ++t) {
        if (!m_movedInto[t])
            continue;
        const uint32_t slot = m_touchingContacts[m_turnedContacts[t]];
        const auto [a, b] = m_touchingBodies[m_turnedContacts[t]];
        const Manifold* collision = pushed[a] || pushed[b] ? nullptr : &m_separateCollisions[t];
        if (const int p = separatePair(slot, slop, nullptr, collision); p > 0) {
            pushes += static_cast<uint64_t>(p);
            pushed[a] = pushed[b] = 1;
            anyPushed = true;
        }
    }
    if (anyPushed) {
        // The contacts of the pushed bodies are tested on the team where they are now, and then taken in order: one
        // whose body a push of this pass has moved since is tested again (the same numbers as testing each in turn,
        // on any number of threads).
        std::vector<uint32_t>& candidates = m_secondTests; // positions in m_touchingContacts
        candidates.clear();
        for (size_t k = 0; k < n; ++k) {
            const auto [a, b] = m_touchingBodies[k];
            if (pushed[a] || pushed[b])
                candidates.push_back(static_cast<uint32_t>(k));
        }
        const size_t count = candidates.size();
        m_secondMovedInto.assign(count, 0);
        if (m_separateCollisions.size() < count)
            m_separateCollisions.resize(count);
        const bool tested = m_team && count >= kMinBodiesForTeam;
        if (tested)
            testMovedInto(candidates, slop, m_secondMovedInto, m_separateCollisions);
        std::vector<uint8_t>& moved = m_pushedNow; // by this pass
        moved.assign(bodies, 0);
        std::vector<uint32_t>& second = m_secondPushed; // the bodies this second pass pushes
        second.clear();
        Manifold collision;
        for (size_t t = 0; t < count; ++t) {
            const uint32_t slot = m_touchingContacts[candidates[t]];
            const auto [a, b] = m_touchingBodies[candidates[t]];
            const Manifold* found = &m_separateCollisions[t];
            if (!tested || moved[a] || moved[b]) {
                if (!movedInto(slot, slop, transform(a), transform(b), false, &collision))
                    continue;
                found = &collision;
            } else if (!m_secondMovedInto[t]) {
                continue;
            }
            if (const int p = separatePair(slot, slop, nullptr, found); p > 0) {
                pushes += static_cast<uint64_t>(p);
                second.push_back(a);
                second.push_back(b);
                moved[a] = moved[b] = 1;
            }
        }
        for (const uint32_t i : second)
            pushed[i] = 1;
    }
    for (const uint32_t slot : m_missedPairs) {
        const uint32_t a = m_contactPairs[slot].bodyA, b = m_contactPairs[slot].bodyB;
        Manifold collision;
        if (!movedInto(slot, slop, transform(a), transform(b), false, &collision))
            continue;
        if (const int p = separatePair(slot, slop, nullptr, &collision); p > 0) {
            pushes += static_cast<uint64_t>(p);
            pushed[a] = pushed[b] = 1;
            anyPushed = true;
        }
    }
    for (const uint32_t i : m_struck)
        pushed[i] = 1;
    if (anyPushed || !m_struck.empty())
        pushes += groundPushedBodies(slop);
    m_profile.count(Counter::SeparatedPairs, pushes);
}

uint64_t World::groundPushedBodies(Real slop) {
    // The pushes above can drive a body into an anchor (or a sleeper), and their two pushes at most, each at the
    // deepest point and turning the body too, may not take it out again: a thrown 2.3 kg box struck onto the floor in
    // mid-air by a 107 kg ball (random mixed scenes, 2026-12-06) was pushed out of the ball 62.8 mm into the floor,
    // where it had only speculative points at the step's start. So each pushed body's pairs with bodies that do not
    // move are collided where the step left them, and a body found in one is pushed out of it. Pushed out of the
    // floor, the box is back in the ball, and a mass-weighted push would drive it into the floor again: so a body
    // pushed up out of a still one is grounded, and stays where it is under a body that is not, which takes the whole
    // push and is grounded in turn (shock propagation, in positions; separatePair()). In rounds: the pairs of the
    // bodies that the round before moved, touching or not, until a round pushes none (at most kSeparateRounds). Only
    // a body found in a still one starts the rounds: started from every pushed body, they changed ramps.obj's frames
    // where nothing went into an anchor, and its first 120 frames took 2.163-2.169 ms a step against 2.083-2.107
    // (2026-12-06; 0.49 of Bullet's against 0.47-0.48), most of it from the other frames.
    std::vector<uint8_t>& last = m_separated; // the bodies pushed in both passes; then those pushed in the round before
    std::vector<uint8_t>& now = m_pushedNow;
    now.assign(last.size(), 0);
    std::vector<uint8_t>& grounded = m_grounded;
    grounded.assign(last.size(), 0);
    std::vector<uint32_t>& around = m_aroundPushed; // slots, in pair order
    // Each body's transform and bounds where it is now, taken once until a push moves it (a body has some ten pairs).
    m_placedPose.resize(last.size());
    m_placedBounds.resize(last.size());
    std::vector<uint8_t>& placed = m_placed;
    placed.assign(last.size(), 0);
    const auto place = [&](uint32_t i) {
        if (!placed[i]) {
            m_placedPose[i] = transform(i);
            m_placedBounds[i] = m_shapes[i].worldBounds(m_placedPose[i]);
            placed[i] = 1;
        }
    };
    uint64_t pushes = 0;
    for (int round = 0; round <= kSeparateRounds; ++round) {
        around.clear();
        for (size_t i = 0; i < m_pairContacts.size(); ++i) {
            const auto [a, b] = m_pairBodies[i];
            const uint32_t slot = m_pairContacts[i];
            if (round == 0 ? (last[a] && !m_state.isMoving(b)) || (last[b] && !m_state.isMoving(a))
                           : last[a] || last[b])
                around.push_back(slot);
        }
        bool any = false;
        for (const uint32_t slot : around) {
            const uint32_t a = m_contactPairs[slot].bodyA, b = m_contactPairs[slot].bodyB;
            if (!m_state.isMoving(a) && !m_state.isMoving(b))
                continue;
            // Boxes apart where the bodies are now: nothing to push. Then the bounds and the collision of
            // movedInto(), which separatePair() repeats for the few it pushes.
            place(a);
            place(b);
            if (!m_placedBounds[a].overlaps(m_placedBounds[b]) ||
                !movedInto(slot, slop, m_placedPose[a], m_placedPose[b], true))
                continue;
            const int p = separatePair(slot, slop, &grounded);
            if (p == 0)
                continue;
            placed[a] = placed[b] = 0;
            pushes += static_cast<uint64_t>(p);
            any = true;
            now[a] = now[b] = 1;
        }
        if (!any)
            break;
        last.swap(now);
        std::fill(now.begin(), now.end(), 0);
    }
    return pushes;
}

void World::stepOnce() {
    updateRoundHulls();
    {
        StageTimer t(m_profile, Stage::UpdateBroadphase);
        refreshTransforms();
    }
    findAndCollidePairs(); // times update_broadphase (the reinsertions), find_pairs and narrowphase
    {
        StageTimer t(m_profile, Stage::BuildIslands);
        buildIslands();
    }
    solve(); // times its own stages: integrate velocities, warm start, solve, integrate positions, relax, restitution
    m_listGaps = m_anyHeight;
    {
        StageTimer t(m_profile, Stage::PushOut);
        if (m_tuning.pushOutSlop >= 0.0)
            pushOutOfContacts(m_tuning.pushOutSlop);
    }
    if (m_effects.effects.has(Effect::Ccd)) {
        StageTimer t(m_profile, Stage::Ccd);
        continuousCollision();
    }
    if (m_tuning.separateSlop >= 0.0 && m_effects.effects.has(Effect::Rotation)) {
        StageTimer t(m_profile, Stage::Separate);
        separateMovedPairs(m_tuning.separateSlop);
    }
    if (m_effects.effects.has(Effect::Sleeping)) {
        StageTimer t(m_profile, Stage::Sleep);
        updateSleep();
    }
    ++m_frame;
    m_profile.count(Counter::Steps, 1);
}

namespace {

// Bodies ahead whose polyhedra the loops over bodies and pairs fetch (refreshTransforms(), the narrowphase).
constexpr size_t kShapeAhead = 6;

// Fetches a shape's polyhedron record (its box features and the vectors' pointers) into the cache.
void prefetchPolyhedron(const Shape& shape) {
    if (const ConvexPolyhedron* p = shape.polyhedron.get()) {
        const char* bytes = reinterpret_cast<const char*>(p);
        for (size_t line = 0; line < sizeof(ConvexPolyhedron); line += 64)
            __builtin_prefetch(bytes + line);
    }
}

} // namespace

void World::refreshTransforms() {
    // Bodies move only in solve() and CCD, both after the narrowphase, so these stay valid for the whole of
    // broadphase and narrowphase. Every body, not only the moving ones: one that fell asleep last step moved first.
    // Anchors never move: their boxes are taken once (create()) and their reach stays 0.
    // Each moving body's proxy is tested here too (updateBroadphase() reinserts the ones that left their fat box):
    // the test reads only the body's own node of the tree.
    // Each body alone, so a team shares the bodies out with the same results.
    const size_t n = m_state.size();
    const Real dt = 1.0 / m_fps;
    m_transforms.resize(n);
    m_reinsert.resize(n);
    m_fatBoxes.resize(n);
    // CCD's record of where each body began the step, taken here: nothing moves a body before the solve. (Taken in
    // the solver's set-up until 2026-12-05, where two members solving islands apart wrote the same lines whenever
    // their islands' bodies sat side by side in body order. Over ramps.obj's first 120 frames on two threads with
    // the cores 320-380 ns apart, each member's set-up took 2.0-2.1 ms against 5.0-5.4, the refresh 7.7 against 6.8
    // ms, the whole step 134 against 140 ms; medians of six runs taken in turns.)
    const bool ccd = m_effects.effects.has(Effect::Ccd);
    if (ccd) {
        m_stepStartPosition.resize(n);
        m_stepStartOrientation.resize(n);
        m_stepStartVelocity.resize(n);
    }
    const auto refresh = [&](size_t begin, size_t end) {
        // On a team, the other members read many of these in the last narrowphase: take them back in one go
        // (claimLines()). (Over ramps.obj's first 120 frames on two threads with the cores 320-370 ns apart
        // (CoreRoundTrip.h), this pass took 11.2 ms before, medians of 13 runs, and 7.3 ms after, of 11; claimed 8
        // or 16 bodies ahead in the loop, 9.9 ms, of 12 and 13; 2026-12-05.)
        if (m_team) {
            claimLines(m_transforms.data() + begin, (end - begin) * sizeof(Transform));
            claimLines(m_bounds.data() + begin, (end - begin) * sizeof(Aabb));
            claimLines(m_reach.data() + begin, (end - begin) * sizeof(Real));
            if (ccd) {
                claimLines(m_stepStartPosition.data() + begin, (end - begin) * sizeof(Vec3));
                claimLines(m_stepStartOrientation.data() + begin, (end - begin) * sizeof(Quat));
                claimLines(m_stepStartVelocity.data() + begin, (end - begin) * sizeof(Vec3));
            }
        }
        for (size_t k = begin; k < end; ++k) {
            const uint32_t i = static_cast<uint32_t>(k);
            // Each body's polyhedron sits in a heap block of its own: fetch a later body's while this one is taken.
            if (k + kShapeAhead < end)
                prefetchPolyhedron(m_shapes[k + kShapeAhead]);
            m_transforms[i] = transform(i);
            m_reinsert[i] = 0;
            if (m_state.isStatic(i))
                continue;
            if (ccd) {
                m_stepStartPosition[i] = m_state.position[i];
                m_stepStartOrientation[i] = m_state.orientation[i];
                m_stepStartVelocity[i] = m_state.linearVelocity[i];
            }
            const Aabb& tight = m_bounds[i] = m_shapes[i].worldBounds(m_transforms[i]);
            m_reach[i] = glm::length(m_state.linearVelocity[i]) + glm::length(m_state.angularVelocity[i]) * m_radius[i];
            if (!m_state.isMoving(i))
                continue;
            // The proxy must cover everything this step's speculative contacts may need: the box swept by this
            // step's motion, grown by the speculative distance. The tree only reinserts when that leaves the fat
            // box, so a body that turns around (a ball at the top of its bounce) still finds the floor in time.
            const Vec3 motion = m_state.linearVelocity[i] * dt;
            const Vec3 grow(m_tuning.speculativeDistance + glm::length(m_state.angularVelocity[i]) * m_radius[i] * dt);
            const Aabb swept{glm::min(tight.min, tight.min + motion) - grow,
                             glm::max(tight.max, tight.max + motion) + grow};
            // A body that became non-finite is left where its proxy was; the world reports it through diagnostics.
            if (const std::optional<Aabb> fat = m_broadPhase.fatBoxIfMoved(m_proxies[i], swept, motion)) {
                m_reinsert[i] = 1;
                m_fatBoxes[i] = *fat;
            }
        }
    };
    if (m_team && n >= kMinBodiesForTeam)
        teamParallelFor()(n, refresh);
    else
        refresh(0, n);
}

void World::updateBroadphase() {
    // The tree changes here, so one thread reinserts, in body order. (Tested and reinserted in one serial pass,
    // large_pyramid's update_broadphase on two threads took 0.41-0.45 ms a step over its frames 5-45, tested in the
    // team's pass 0.35-0.36 ms; boxes1000's, with some 33 reinsertions a step, 0.15-0.16 ms either way: three
    // interleaved runs, 2026-11-27.)
    for (uint32_t i = 0; i < m_state.size(); ++i)
        if (m_reinsert[i] != 0)
            m_broadPhase.reinsertProxy(m_proxies[i], m_fatBoxes[i]);
}

ContactSolver::ParallelFor World::teamParallelFor() {
    if (!m_team)
        return {};
    return [this](size_t count, const std::function<void(size_t, size_t)>& body) {
        m_team->run([&](int member) {
            const auto [begin, end] = ThreadTeam::share(0, count, member, m_team->size());
            body(begin, end);
        });
    };
}

ContactSolver::ParallelFor World::betweenStepsParallelFor(size_t count) {
    // Between steps m_team is m_ownTeam (step()); whether the next step will take the team decides here too, so
    // that a machine whose other core is busy does not make the record wait for it.
    const bool pays = m_teamPacing != TeamPacing::Adaptive || m_pacer.useTeam();
    if (!m_ownTeam || !pays || count < kMinBodiesForTeam)
        return {};
    return teamParallelFor();
}

void World::mergePairs(const BroadPhase::ParallelFor& parallelFor) {
    m_broadPhase.updatePairs(parallelFor);
    const auto pairs = m_broadPhase.pairs();
    // Most steps the pair list is the one we already hold; then there is nothing to merge.
    // The bodies of each contact are kept beside the slot list (m_pairBodies), so neither this test nor the merge
    // below reads the contacts themselves.
    const auto sameBodies = [](const BroadPhasePair& p, const std::pair<uint32_t, uint32_t>& bodies) {
        return p.idA == bodies.first && p.idB == bodies.second;
    };
    m_newPairs.clear();
    m_newPairEnded.clear();
    m_endedContacts.clear();
    m_pairsChanged = !(pairs.size() == m_pairBodies.size() &&
                       std::equal(pairs.begin(), pairs.end(), m_pairBodies.begin(), sameBodies));
    if (!m_pairsChanged)
        return;
    // Merge the sorted pair list with the sorted contact list into the next lists. A pair that persists keeps its
    // slot of the pool, and with it its manifold; only the slot numbers move. (Copying the contacts themselves, some
    // 660 bytes each, made this stage 0.7 ms per step over ramps.obj's first 120 frames, ~6,000 pairs; moving slot
    // numbers, 0.4 ms.) The current lists and the contacts are only read: other members of the team may be
    // colliding the current pairs meanwhile (findAndCollidePairs()). New pairs get their slots in commitPairs().
    // On a team, the next lists are the ones the other members' filter read a step ago: taken back in one go
    // (claimLines()), this stage took 20.8 ms of ramps.obj's first 120 frames on two threads with the cores far
    // apart, against 26.6 ms (medians of 14 runs each, 2026-12-05).
    std::vector<uint32_t>& next = m_nextPairContacts;
    next.resize(pairs.size());
    m_nextPairBodies.resize(pairs.size());
    if (m_ownTeam) {
        claimLines(next.data(), next.size() * sizeof(next[0]));
        claimLines(m_nextPairBodies.data(), m_nextPairBodies.size() * sizeof(m_nextPairBodies[0]));
    }
    size_t old = 0;
    for (size_t i = 0; i < pairs.size(); ++i) {
        const BroadPhasePair& p = pairs[i];
        m_nextPairBodies[i] = {p.idA, p.idB};
        while (old < m_pairContacts.size() && m_pairBodies[old] < std::make_pair(p.idA, p.idB))
            m_endedContacts.push_back(m_pairContacts[old++]);
        if (old < m_pairContacts.size() && sameBodies(p, m_pairBodies[old])) {
            next[i] = m_pairContacts[old++];
            continue;
        }
        m_newPairs.push_back(i);
        m_newPairEnded.push_back(m_endedContacts.size());
        next[i] = kNoSlot;
    }
    while (old < m_pairContacts.size())
        m_endedContacts.push_back(m_pairContacts[old++]);
}

void World::commitPairs() {
    if (m_pairsChanged) {
        // Slots of pairs that ended are reused by new pairs, last freed first, as one walk of the merged list freed
        // and took them before the merge was split from this: a new pair mostly takes the slot of a pair that ended
        // near it in pair order, the order every later stage visits the contacts in. (Freeing all of them before
        // taking any hands them out in reverse; no difference in time was measured between the two.) Only the slots are
        // handed out here: the list job below starts each new contact (startContact()), each member an even part of
        // them, just before it collides them.
        size_t freed = 0;
        for (size_t k = 0; k < m_newPairs.size(); ++k) {
            const size_t i = m_newPairs[k];
            for (; freed < m_newPairEnded[k]; ++freed)
                m_freeContacts.push_back(m_endedContacts[freed]);
            uint32_t slot;
            if (m_freeContacts.empty()) {
                slot = static_cast<uint32_t>(m_contactPool.size());
                m_contactPool.emplace_back();
                m_contactPairs.emplace_back();
                m_contactTouching.push_back(0);
                m_contactListed.push_back(0);
                m_pairStartGap.push_back(0.0);
            } else {
                slot = m_freeContacts.back();
                m_freeContacts.pop_back();
                m_contactTouching[slot] = 0;
            }
            m_nextPairContacts[i] = slot;
        }
        m_freeContacts.insert(m_freeContacts.end(), m_endedContacts.begin() + static_cast<std::ptrdiff_t>(freed),
                              m_endedContacts.end());
        std::swap(m_pairContacts, m_nextPairContacts);
        std::swap(m_pairBodies, m_nextPairBodies);
    }
    m_profile.count(Counter::Pairs, m_pairContacts.size());
}

void World::startContact(uint32_t slot, uint32_t a, uint32_t b) {
    // Only what a new pair needs: the rest of a reused slot (points, cached pose) is written before it is read, so
    // the whole contact is not copied over it.
    m_contactPairs[slot] = {a, b, combine(m_frictionRule, m_friction[a], m_friction[b]),
                            combine(m_restitutionRule, m_restitution[a], m_restitution[b])};
    Contact& c = m_contactPool[slot];
    c.cachedMargin = -1.0;
    c.separatingAxis = Vec3(0.0);
    c.manifold.bodyA = a;
    c.manifold.bodyB = b;
    c.manifold.pointCount = 0;
}

Real World::pairMargin(uint32_t a, uint32_t b) const {
    const Real dt = 1.0 / m_fps;
    // Speculative margin: the base distance plus how far the two surfaces can approach within this step, so a
    // falling body meets its contact before it gets there rather than after it has sunk in.
    // A moving neighbour that strikes a or b in the step can make the two approach faster still
    // (pushSpeedsOfNewPairs()).
    const Vec3 relative = m_state.linearVelocity[b] - m_state.linearVelocity[a];
    const Real spin =
        glm::length(m_state.angularVelocity[a]) * m_radius[a] + glm::length(m_state.angularVelocity[b]) * m_radius[b];
    const Real margin =
        m_tuning.speculativeDistance + (glm::length(relative) + spin + m_pushSpeed[a] + m_pushSpeed[b]) * dt;
    // Beyond the bodies' own size a speculative contact is meaningless; CCD takes over there.
    return std::min(margin, m_tuning.speculativeDistance + std::max(m_minExtent[a], m_minExtent[b]));
}

void World::collidePair(uint32_t slot, Real margin) {
    Contact& c = m_contactPool[slot];
    const uint32_t a = m_contactPairs[slot].bodyA, b = m_contactPairs[slot].bodyB;

    const Transform& xfA = m_transforms[a];
    const Transform& xfB = m_transforms[b];
    const Mat3 rAT = glm::transpose(xfA.rotation);
    const Vec3 offset = rAT * (m_state.position[b] - m_state.position[a]);
    const Mat3 rotation = rAT * xfB.rotation;
    // Reuse: B has moved less than manifoldReuseDistance relative to A (translation of its centre plus rotation
    // times its radius), and the margin has not grown. The points keep their features and impulses; their world
    // positions and separations follow the bodies. The test is against the pose of the last real computation, so
    // slow creep cannot accumulate past the tolerance.
    if (c.cachedMargin >= 0.0 && margin <= c.cachedMargin + 1e-3) {
        const Real tolerance = std::min(m_tuning.manifoldReuseDistance, 0.1 * std::min(m_minExtent[a], m_minExtent[b]));
        const Vec3 dp = offset - c.cachedOffset;
        Real rotationChange2 = 0.0; // |R - R0|_F^2 = 4 (1 - cos angle), about angle^2 * 2
        for (int k = 0; k < 3; ++k) {
            const Vec3 d = rotation[k] - c.cachedRotation[k];
            rotationChange2 += glm::dot(d, d);
        }
        const Real angle = std::sqrt(0.5 * rotationChange2);
        if (glm::length(dp) + angle * m_radius[b] <= tolerance) {
            Manifold& m = c.manifold;
            m.normal = xfA.rotate(c.cachedNormal);
            for (int k = 0; k < m.pointCount; ++k) {
                ContactPoint& p = m.points[k];
                const Vec3 pa = xfA.apply(p.localA);
                const Vec3 pb = xfB.apply(p.localB);
                p.position = 0.5 * (pa + pb);
                p.separation = glm::dot(m.normal, pb - pa);
            }
            return;
        }
    }

    // A pair that was apart: if last step's separating axis still separates it by more than the margin, there is
    // no contact (the SAT or GJK would say the same, since the distance is at least that), and nothing to compute.
    // Flat polygons are left out: their one-sided rule can report a contact for shapes apart on the wrong side. (A
    // box's reach along the axis is taken from its centre and axes, Shape::reachAlong().)
    if (c.manifold.pointCount == 0 && c.separatingAxis != Vec3(0.0)) {
        const Vec3 n = xfA.rotate(c.separatingAxis);
        if (-overlapAlongAxis(m_shapes[a], xfA, m_shapes[b], xfB, n) > margin)
            return;
    }

    Manifold fresh;
    fresh.bodyA = a;
    fresh.bodyB = b;
    collide(m_shapes[a], xfA, m_shapes[b], xfB, margin, fresh, pairCollideOptions());
    if (fresh.pointCount > 0 && (m_turnsThroughFeatures[a] || m_turnsThroughFeatures[b])) {
        const Real dt = 1.0 / m_fps;
        const auto turn = [&](uint32_t i) {
            const Vec3& w = m_state.angularVelocity[i];
            // No corner moves 1 mm (a box: WorldTuning::boxTurnCorner).
            const Real least = m_turnsThroughFeatures[i] == kTurnsBoxCorner ? m_tuning.boxTurnCorner : 1e-3;
            if (!m_turnsThroughFeatures[i] || !(glm::length(w) * dt * m_radius[i] > least))
                return identityQuat();
            // What the solver's anchors will turn by (round bodies: none, or the swing about their roll axis).
            return m_state.anchorTurnQuat(i, rotationFromVector(w * dt), m_state.orientation[i]);
        };
        addTurnedSupports(m_shapes[a], xfA, turn(a), m_shapes[b], xfB, turn(b), fresh);
    }
    const bool flat =
        (m_shapes[a].isPolyhedral() && m_shapes[a].isFlat()) || (m_shapes[b].isPolyhedral() && m_shapes[b].isFlat());
    c.separatingAxis = fresh.pointCount == 0 && !flat && glm::dot(fresh.normal, fresh.normal) > 0.5
                           ? xfA.rotateInverse(fresh.normal)
                           : Vec3(0.0);
    // Points that persist (same features, or nearly the same place) keep their impulses for warm starting.
    warmStart(c.manifold, fresh);
    c.manifold = fresh;
    m_contactTouching[slot] = static_cast<uint8_t>(fresh.pointCount);
    c.cachedOffset = offset;
    c.cachedRotation = rotation;
    c.cachedNormal = xfA.rotateInverse(fresh.normal);
    c.cachedMargin = margin;
}

void World::clearPushSpeeds() {
    if (m_pushSpeed.size() != m_state.size()) {
        m_pushSpeed.assign(m_state.size(), 0.0);
        m_pushedBodies.clear();
    }
    for (const uint32_t i : m_pushedBodies)
        m_pushSpeed[i] = 0.0;
    m_pushedBodies.clear();
}

void World::pushSpeedsOfNewPairs() {
    // A light body struck by a heavy one in mid-air leaves at about the heavy one's speed, which its own speed at the
    // step's start says nothing of: its margins to the floor and to its other neighbours must cover that too, or its
    // contacts there are not made in time and the blow drives it through them within the step. (A 314 kg ball
    // falling at 6 m/s onto a 4.5 kg ball 40 mm above the floor, both new to the world, went 62 mm into it, the light
    // ball stopped short of the floor by CCD, when the light ball's margin to the floor counted only its own 1.05
    // m/s; 2026-12-05.)
    //
    // Struck by a body j that can reach it in the step, body i's velocity changes by at most |vj - vi| mj / (mi + mj)
    // (the two move on together, the blow taken whole), and that change is its push speed; a second pass passes
    // the pushes of the first on along chains of bodies. Pairs of bodies that cannot approach by more than half the
    // speculative distance in the step add too little to matter and are passed over early. Anchors and sleepers
    // push nothing, and are not pushed.
    //
    // Only new pairs push. Where the pair of the two was there in the step before, the speculative contact between them
    // was too, and the blow was taken in a step that moved the light body no further than free fall would have (16.4 mm
    // in one such drop); in the next its own speed covers its margins (138 vertical drops of a 314 kg ball onto a 4.5
    // kg one 10-120 mm above the floor at 3-12 m/s, e = 0, the pair there four frames before: at most 2.5 mm deep with
    // or without pushes). Pushed by every pair, ramps.obj tested 41 % more pairs and made 42 % more manifolds over its
    // first 120 frames (the tumbling cubes' relative speeds widened most margins), and its bake took 2.48 ms a step on
    // one thread against 1.85 (one run each); pushed by the new pairs, 0.1 % more pairs tested, the same time.
    m_pushPairs.clear();
    for (const size_t i : m_newPairs)
        if (const auto [a, b] = m_pairBodies[i]; mayPush(a, b))
            m_pushPairs.emplace_back(a, b);
    applyPushes();
}

bool World::mayPush(uint32_t a, uint32_t b) const {
    if (!m_state.isMoving(a) || !m_state.isMoving(b))
        return false;
    const Real dt = 1.0 / m_fps, spec = m_tuning.speculativeDistance;
    const Real reach = (m_reach[a] + m_reach[b]) * dt;
    if (reach < 0.5 * spec)
        return false;
    return m_bounds[a].gapTo(m_bounds[b]) <= spec + reach;
}

void World::applyPushes() {
    const auto push = [&](uint32_t i, Real speed) {
        if (speed <= m_pushSpeed[i])
            return;
        if (m_pushSpeed[i] == 0.0)
            m_pushedBodies.push_back(i);
        m_pushSpeed[i] = speed;
    };
    for (int pass = 0; pass < 2; ++pass) {
        for (const auto& [a, b] : m_pushPairs) {
            const Real wA = m_state.invMass[a], wB = m_state.invMass[b];
            const Real relative = glm::length(m_state.linearVelocity[b] - m_state.linearVelocity[a]);
            // On the second pass, a body pushed in the first strikes its neighbour faster by as much.
            const Real intoA = relative + (pass == 1 ? m_pushSpeed[b] : 0.0);
            const Real intoB = relative + (pass == 1 ? m_pushSpeed[a] : 0.0);
            push(a, intoA * wA / (wA + wB));
            push(b, intoB * wB / (wA + wB));
        }
    }
}

void World::findAndCollidePairs() {
    clearPushSpeeds();
    // Pairs where neither body moves keep their manifold (both asleep, or asleep against an anchor).
    // A pair whose tight boxes are apart by more than its margin along some axis has no contact: the shapes are at
    // least that far apart. The fat boxes of the broadphase overlap far more often than the shapes come within the
    // margin (over ramps.obj's first 600 frames, 12 % of the pairs are tested), so this test, on the compact list of
    // pair bodies and the bodies' boxes, spares most pairs a visit to their contact, some 700 bytes each. (The stage
    // went from 368-394 ms to 297-308 ms over the first 240 frames, three interleaved runs, with the same frames.)
    // The clip's speculative separations are lower bounds of the distance, so it could keep a point for a pair that
    // cannot touch within the step; this test drops such points (27 times in 600 frames of a 1,000-box pile).
    const Real dt = 1.0 / m_fps;
    // Adds the contact in `slot`, that of the pair a-b, to `tests` if it passes the filter.
    const auto filter = [&](uint32_t slot, uint32_t a, uint32_t b, std::vector<NarrowTest>& tests) {
        if (!m_state.isMoving(a) && !m_state.isMoving(b))
            return;
        const Real apart = m_bounds[a].gapTo(m_bounds[b]);
        // Most pairs are told apart by a bound of the margin from each body's own speed (|vB - vA| <= |vA| +
        // |vB|; the factor covers rounding), which costs no square root; the rest by the margin itself.
        const Real bound =
            std::min(m_tuning.speculativeDistance + (m_reach[a] + m_reach[b] + m_pushSpeed[a] + m_pushSpeed[b]) * dt,
                     m_tuning.speculativeDistance + std::max(m_minExtent[a], m_minExtent[b]));
        Real margin = 0.0;
        if (apart > bound * (1.0 + 1e-9) || apart > (margin = pairMargin(a, b))) {
            m_pairStartGap[slot] = apart;
            if (m_contactTouching[slot]) {
                Contact& c = m_contactPool[slot];
                c.manifold.pointCount = 0;
                c.cachedMargin = -1.0;
                m_contactTouching[slot] = 0;
            }
            return;
        }
        m_pairStartGap[slot] = margin; // apart by more, where the collision finds no point
        tests.push_back({slot, a, b, margin});
    };
    // Collides the pairs in `tests`; returns how many.
    const auto collideTests = [&](const std::vector<NarrowTest>& tests) {
        // The contacts sit in the pool in no useful order for the cache (about 700 bytes each, some 6,000 pairs in
        // ramps.obj): a few pairs ahead, every line of the next contact is fetched while this one is computed.
        // (Over ramps.obj's first 240 frames the stage went from 389-429 ms to 335-410 ms, in seven interleaved
        // pairs.)
        // On a team, the contacts to be written are taken for this core first, all of them (claimLines()): the
        // other member's core may hold them from the solve. (With the cores far apart, the two members' collisions
        // took 77.5 ms of the first 120 frames against 80.3, medians of 14 runs, 2026-12-05.)
        if (m_team)
            for (const NarrowTest& test : tests)
                claimLines(&m_contactPool[test.slot], sizeof(Contact));
        constexpr size_t kAhead = 4;
        for (size_t k = 0; k < tests.size(); ++k) {
            if (k + kAhead < tests.size()) {
                const char* ahead = reinterpret_cast<const char*>(&m_contactPool[tests[k + kAhead].slot]);
                for (size_t line = 0; line < sizeof(Contact); line += 64)
                    __builtin_prefetch(ahead + line);
            }
            if (k + kShapeAhead < tests.size()) {
                prefetchPolyhedron(m_shapes[tests[k + kShapeAhead].bodyA]);
                prefetchPolyhedron(m_shapes[tests[k + kShapeAhead].bodyB]);
            }
            collidePair(tests[k].slot, tests[k].margin);
        }
        return tests.size();
    };
    const int teamSize = m_team ? m_team->size() : 1;
    // As many lists as the team has members, even in a step member 0 takes alone: the lists of solved contacts
    // stay until solve() forgets them.
    m_narrowLists.resize(std::max(m_narrowLists.size(), static_cast<size_t>(teamSize)));
    for (NarrowList& list : m_narrowLists) {
        list.tested = 0;
        list.points = 0;
        list.touching.clear();
        list.touchingBodies.clear();
        list.mayWake.clear();
    }
    std::optional<StageTimer> timer;

    // First the pairs of the last step are collided while the broadphase finds this step's pairs: a pair's manifold
    // depends only on its two bodies and its own contact, not on the other pairs, and the merge of the pair lists
    // (mergePairs()) reads only the current lists and writes only the next ones. Pairs that ended are collided for
    // nothing, which the filter above mostly turns away. On a team, member 0 reinserts the proxies and merges the pair
    // lists, serial work, while the others collide, and then joins them. (When the team waited for those serial
    // stretches, ramps' step on two threads took 1.49-1.57 ms, now 1.39-1.44; boxes1000's 3.06-3.32 and 3.02-3.27 ms;
    // large_pyramid's the same within the noise; the first 120 frames, 45 for large_pyramid, four interleaved runs,
    // 2026-11-27. The same frames, and the same times on one thread.)
    //
    // The collisions are taken in chunks: a full SAT costs many times an early out, and even halves of the list kept
    // one thread waiting for the other. (With the filter a serial pass of its own before the team's collisions, it
    // took 64-98 us of a step on two threads in ramps.obj and boxes1000, medians of their first 120 frames.) Batches
    // of 16 tested pairs made the two members fight over the counter (and over neighbouring touching flags): in
    // large_pyramid at rest, where most manifolds are reused, the stage took 1.37 ms a step on two threads against
    // 0.82 ms on one; with 64, 0.80-0.89 ms (2026-11-27, frames 60-120).
    //
    // A team of two takes its chunks from the two ends of the list: member 0 from the front, member 1 from the
    // back, until they meet. Each member then mostly reads the contacts whose manifolds it wrote in the last step
    // (the solver's set-up and storeImpulses() share the touching contacts out in halves, in pair order too), which
    // the other core would have to fetch from this one's cache. (large_pyramid, frames 60-120 on two threads, seven
    // interleaved runs: 0.65-0.85 ms a step against 0.62-1.09 ms, medians 0.74 and 0.88; 2026-11-27.)
    //
    // A step in which few pairs were tested the last time (a scene at rest or asleep: pyramid20 asleep has some 600
    // pairs and none to test) is collided by member 0 alone, and so are its new pairs if they are few too: a team job
    // costs the other member a wake-up for nothing. (The frames are the same either way.)
    const bool fewTests = m_lastPairsTested < kNarrowChunk;
    {
        const size_t pairCount = m_pairContacts.size();
        const int members = m_team && pairCount >= 2 * kNarrowChunk && !fewTests ? teamSize : 1;
        // One thread takes all the pairs as one chunk: it filters every pair before it collides any, so the fetching
        // ahead runs through the whole list instead of starting again at every chunk. (On one core, ramps'
        // narrowphase medians were the same within this machine's noise either way: 0.81-0.83 and 0.81-0.86 ms,
        // 2026-11-27.)
        const size_t chunk = members == 1 ? std::max<size_t>(pairCount, 1) : kNarrowChunk;
        const size_t chunks = (pairCount + chunk - 1) / chunk;
        std::atomic<size_t> claimed{0};
        // Member 0's solved contacts in chunks: in a team of two, member 1 takes them from the back once it has
        // nothing else left (member 0 reinserts and merges first), claimed from both ends like the pairs' chunks.
        const std::vector<uint32_t>& firstSolved = m_narrowLists[0].solved;
        const size_t solvedChunks = (firstSolved.size() + kSolvedChunk - 1) / kSolvedChunk;
        std::atomic<size_t> solvedClaimed{0};
        const auto job = [&](int member) {
            if (member == 0) {
                {
                    StageTimer t(m_profile, Stage::UpdateBroadphase);
                    updateBroadphase();
                }
                {
                    // Alone, member 0 can share the broadphase's queries out over the idle team.
                    StageTimer t(m_profile, Stage::FindPairs);
                    mergePairs(members == 1 ? teamParallelFor() : BroadPhase::ParallelFor());
                }
                timer.emplace(m_profile, Stage::Narrowphase);
            }
            // On a team, each member first collides the contacts of the islands it solved in the last step
            // (the solve job of solveGroup() lists them): their manifolds are in its core's cache from that solve, and
            // the islands mostly stay with it, so this step's solve reads them there again. Taken only by chunks of the
            // pair list, 47 % of the touching contacts that ramps.obj's first 120 frames solved on two threads had
            // been collided by the other member (the contacts with a ramp come first in the pair list, by the
            // ramp's number), and 17 % with the lists. (With the cores 340-370 ns apart, `bench ramps --frames 120
            // --threads 2 --runs 2` by turns: 1.59-1.61x without the lists, 1.62-1.64x with them, the threaded
            // median 1.232-1.233 against 1.201-1.212 ms, three runs each, 2026-12-05.)
            NarrowList& mine = m_narrowLists[static_cast<size_t>(member)];
            const auto collideSolved = [&](std::span<const uint32_t> slots) {
                mine.tests.clear();
                for (const uint32_t slot : slots)
                    filter(slot, m_contactPairs[slot].bodyA, m_contactPairs[slot].bodyB, mine.tests);
                mine.tested += collideTests(mine.tests);
            };
            // Chunk `at` of member 0's solved contacts.
            const auto collideFirstSolved = [&](size_t at) {
                const size_t begin = at * kSolvedChunk, end = std::min(firstSolved.size(), begin + kSolvedChunk);
                collideSolved(std::span<const uint32_t>(firstSolved).subspan(begin, end - begin));
            };
            // Member 0's list, claimed by member 0 now and by member 1 at the end (a team of two).
            const auto claimFirstSolved = [&] {
                for (size_t k = 0;; ++k) {
                    const size_t claim = solvedClaimed.fetch_add(1, std::memory_order_relaxed);
                    if (claim >= solvedChunks)
                        break;
                    collideFirstSolved(ThreadTeam::chunkOfClaim(claim, k, member, members, solvedChunks));
                }
            };
            if (members > 1 && member == 0)
                claimFirstSolved();
            else if (members > 1)
                collideSolved(mine.solved);
            // Every claim is one chunk; a team of two takes them from the two ends (ThreadTeam::chunkOfClaim()).
            for (size_t k = 0;; ++k) {
                const size_t claim = members == 1 ? k : claimed.fetch_add(1, std::memory_order_relaxed);
                if (claim >= chunks)
                    break;
                const size_t at = ThreadTeam::chunkOfClaim(claim, k, member, members, chunks);
                mine.tests.clear();
                for (size_t i = at * chunk, end = std::min(pairCount, (at + 1) * chunk); i < end; ++i) {
                    const uint32_t slot = m_pairContacts[i];
                    if (members == 1 || !m_contactListed[slot])
                        filter(slot, m_pairBodies[i].first, m_pairBodies[i].second, mine.tests);
                }
                mine.tested += collideTests(mine.tests);
            }
            if (members == 2 && member == 1)
                claimFirstSolved();
        };
        if (members > 1)
            m_team->run(job);
        else
            job(0);
    }
    timer.reset();
    {
        StageTimer t(m_profile, Stage::FindPairs);
        commitPairs();
    }
    pushSpeedsOfNewPairs();
    if (!m_pushedBodies.empty()) {
        // A new neighbour can push some bodies faster than the pairs already collided allowed for: those of their
        // pairs that did not touch are filtered and collided again with the wider margins, in pair order, by member
        // 0 (a fast body meets a new neighbour: 4 times in ramps.obj's first 120 frames). The new pairs are
        // collided below.
        StageTimer t(m_profile, Stage::Narrowphase);
        std::vector<NarrowTest>& tests = m_narrowLists[0].tests;
        tests.clear();
        size_t nextNew = 0;
        for (size_t i = 0; i < m_pairContacts.size(); ++i) {
            if (nextNew < m_newPairs.size() && m_newPairs[nextNew] == i) {
                ++nextNew;
                continue;
            }
            const auto [a, b] = m_pairBodies[i];
            const uint32_t slot = m_pairContacts[i];
            if ((m_pushSpeed[a] > 0.0 || m_pushSpeed[b] > 0.0) && !m_contactTouching[slot])
                filter(slot, a, b, tests);
        }
        m_narrowLists[0].tested += collideTests(tests);
    }

    // Then the new pairs are started and collided, each member taking an even part of them, and the touching
    // contacts are listed once, in pair order, each member taking an even part of the pair list: from here on only
    // they matter. A contact that may wake a sleeper (below) has a body that is neither moving nor static. (Started
    // by member 0 alone in commitPairs(), the new contacts of ramps.obj took most of the 24-31 us a step that member
    // 0 worked alone there, frames 40-120 on two threads, 2026-12-01. The new pairs gather at the end of the pair
    // list, so each member takes an even part of them rather than those in its part of the list.)
    timer.emplace(m_profile, Stage::Narrowphase);
    const size_t pairCount = m_pairContacts.size();
    const bool fewNew = m_newPairs.size() < kNarrowChunk;
    const int members = m_team && pairCount >= 2 * kNarrowChunk && !(fewTests && fewNew) ? teamSize : 1;
    // While the last step had a mixed island, each touching contact's least separation and the side it bears up
    // are read here, each member from the manifolds it mostly wrote itself, for heightsAboveSupport(). (Read there by
    // member 0 alone, boxes1000's manifolds took 0.05 ms a step of serial work on two threads, frames 45-120.)
    m_gapsListed = m_listGaps;
    const auto list = [&](int member) {
        NarrowList& mine = m_narrowLists[static_cast<size_t>(member)];
        mine.tests.clear();
        mine.gaps.clear();
        mine.bearsUp.clear();
        const auto [first, last] = ThreadTeam::share(0, m_newPairs.size(), member, members);
        for (size_t k = first; k < last; ++k) {
            const size_t i = m_newPairs[k];
            const auto [a, b] = m_pairBodies[i];
            startContact(m_pairContacts[i], a, b);
            filter(m_pairContacts[i], a, b, mine.tests);
        }
        mine.tested += collideTests(mine.tests);
        // The listing reads the touching flags of the new contacts, which either member may have collided.
        if (members > 1)
            m_team->barrier();
        const auto [begin, end] = ThreadTeam::share(0, pairCount, member, members);
        for (size_t i = begin; i < end; ++i) {
            const uint32_t slot = m_pairContacts[i];
            if (!m_contactTouching[slot])
                continue;
            mine.touching.push_back(slot);
            mine.touchingBodies.push_back(m_pairBodies[i]);
            mine.points += m_contactTouching[slot];
            if (m_gapsListed) {
                const auto [gap, bearsUp] = contactSupport(m_contactPool[slot].manifold);
                mine.gaps.push_back(gap);
                mine.bearsUp.push_back(bearsUp);
            }
            const auto [a, b] = m_pairBodies[i];
            if ((!m_state.isMoving(a) && !m_state.isStatic(a)) || (!m_state.isMoving(b) && !m_state.isStatic(b)))
                mine.mayWake.push_back(i);
        }
    };
    if (members > 1)
        m_team->run(list);
    else
        list(0);
    m_touchingContacts.clear();
    m_touchingBodies.clear();
    m_contactGap.clear();
    m_contactBearsUp.clear();
    uint64_t tested = 0, points = 0;
    for (const NarrowList& l : m_narrowLists) {
        m_touchingContacts.insert(m_touchingContacts.end(), l.touching.begin(), l.touching.end());
        m_touchingBodies.insert(m_touchingBodies.end(), l.touchingBodies.begin(), l.touchingBodies.end());
        m_contactGap.insert(m_contactGap.end(), l.gaps.begin(), l.gaps.end());
        m_contactBearsUp.insert(m_contactBearsUp.end(), l.bearsUp.begin(), l.bearsUp.end());
        tested += l.tested;
        points += l.points;
    }
    m_profile.count(Counter::PairsTested, tested);
    m_lastPairsTested = tested;

    // A touching contact between an awake body and a sleeping one wakes the sleeper's island, in pair order (a woken
    // island can wake the next).
    if (m_effects.effects.has(Effect::Sleeping)) {
        for (const NarrowList& l : m_narrowLists)
            for (const size_t i : l.mayWake) {
                const auto [a, b] = m_pairBodies[i];
                const bool movingA = m_state.isMoving(a), movingB = m_state.isMoving(b);
                if (movingA && !movingB && !m_state.isStatic(b))
                    wakeIsland(b);
                else if (movingB && !movingA && !m_state.isStatic(a))
                    wakeIsland(a);
            }
    }
    m_profile.count(Counter::Manifolds, m_touchingContacts.size());
    m_profile.count(Counter::ContactPoints, points);
}

void World::restartSleepClock(uint32_t i) {
    m_sleepTime[i] = 0.0;
    m_sleepAnchorPosition[i] = m_state.position[i];
    m_sleepAnchorOrientation[i] = m_state.orientation[i];
}

void World::wakeIsland(uint32_t body) {
    const uint32_t root = m_island[body];
    for (uint32_t i = 0; i < m_state.size(); ++i) {
        if (m_island[i] == root && !m_state.isStatic(i)) {
            m_state.flags[i] |= kBodyAwake;
            restartSleepClock(i);
        }
    }
}

void World::wakeAll() {
    for (uint32_t i = 0; i < m_state.size(); ++i) {
        if (!m_state.isStatic(i)) {
            m_state.flags[i] |= kBodyAwake;
            restartSleepClock(i);
        }
    }
}

void World::buildIslands() {
    std::iota(m_island.begin(), m_island.end(), 0u);
    for (const auto& [a, b] : m_touchingBodies) {
        if (m_state.isStatic(a) || m_state.isStatic(b))
            continue; // anchors do not join islands: a floor would glue the whole scene into one
        unite(m_island, a, b);
    }
    for (uint32_t i = 0; i < m_island.size(); ++i)
        m_island[i] = findRoot(m_island, i);
}

int World::substepRefinement(Real massRatio) const {
    // A soft contact settles F / (m_eff omega^2) deep, and omega grows with the substep rate, so k times the
    // substeps make a light body under a heavy one sink k^2 times less. The 1 kg cube under 1,000 kg settles
    // 1.8 cm deep at 8 substeps (measured): the depth grows with the ratio, so the substeps it needs grow with its
    // square root, from refineSubsteps at refineMassRatio. The island gets that many substeps in all, whatever the
    // scene's own count: a scene written with 4 substeps (DESIGN.md's example) let the same pair sink 2.6 cm when
    // the factor multiplied the scene's count instead.
    if (!(massRatio > m_tuning.refineMassRatio))
        return 1;
    const Real needed = m_tuning.refineSubsteps * std::sqrt(massRatio / m_tuning.refineMassRatio);
    const Real k = std::ceil(needed / m_substeps - 1e-9);
    return static_cast<int>(std::clamp<Real>(k, 1.0, static_cast<Real>(m_tuning.maxSubstepRefinement)));
}

int World::sizeRefinement(Real extent) const {
    // The same depth, F / (m_eff omega^2), is the same few tenths of a millimetre per contact whatever the bodies'
    // size, and a stack sinks by it at every contact: 12 mm for a tower of 20 cubes. For cubes of 1 m that is
    // nothing; for cubes of 2 cm it is more than half of one, and the tower fell while it settled (its top 0.38 m lower
    // after 1 s; 3 cm cubes stood, with the top 14 mm off; measured 2026-12-05). So an island with a body smaller than
    // refineExtent takes refineExtentSubsteps * sqrt(refineExtent / extent) substeps in all, which keeps the depth's
    // share of the body no larger than at refineExtent. A body's size here is its middle extent, so that a stack of
    // coins counts as small and a card standing on its edge does not: the card house (2 mm cards 0.3 m wide) needs
    // no more substeps, its cards 3.3 mm from where they were put at 6 substeps (0.24 mm at 24, 0.14 mm at 48, once
    // they no longer started 2 mm inside each other; before, 8.0 mm at 24 and fallen at 48; 2026-12-05).
    if (!(extent < m_tuning.refineExtent))
        return 1;
    const Real needed = m_tuning.refineExtentSubsteps * std::sqrt(m_tuning.refineExtent / std::max(extent, 1e-9));
    const Real k = std::ceil(needed / m_substeps - 1e-9);
    return static_cast<int>(std::clamp<Real>(k, 1.0, static_cast<Real>(m_tuning.maxSubstepRefinement)));
}

void World::heightsAboveSupport(std::span<const uint32_t> moving) {
    // A light body under a heavy one: the sweeps take the heavy body's momentum out through the light one a little
    // at a time, and the soft contact under the light body is only as stiff as suits the light mass, so a 1,000 kg
    // cube dropped 1 m onto a 1 kg one sank 59 mm into it for a few frames. In islands with a mass ratio of at least
    // stackHoldRatio, each moving body's height is the fewest contacts from it down to an immovable body (1 when it
    // touches one). A contact holds the lower of its bodies still (shock propagation, Guendelman et al. 2003) when it
    // holds the upper one up against gravity and the upper one is stackHoldRatio times heavier (contactHold()), so
    // the upper body is stopped by it as by the ground. Heights are shortest paths, the same whatever the order of the
    // contacts. Other islands are left as they are, to the bit.
    const auto inMixedIsland = [&](uint32_t i) {
        const uint32_t root = m_island[i];
        return !(m_islandMaxMass[root] < m_tuning.stackHoldRatio * m_islandMinMass[root]);
    };
    m_anyHeight = std::any_of(moving.begin(), moving.end(), inMixedIsland);
    if (!m_anyHeight)
        return;
    m_height.assign(m_state.size(), 0);
    constexpr uint32_t kUnknown = 0xffffffffu;
    for (uint32_t i : moving)
        if (inMixedIsland(i))
            m_height[i] = kUnknown;
    // A body rests on its nearest contacts: one farther off than its nearest by more than supportGap (a speculative
    // contact that a fast body would meet only after going through the nearer one) does not support it. A 1,000 kg
    // cube of 1 m falling at 9.8 m/s onto a 1 kg cube of 10 cm had contacts 8 cm above the small cube and 18 cm
    // above the floor; counted as resting on the floor, it was only made heavier against the small cube (not held
    // by it), crushed it into the floor, and both flew up at 3.4 m/s.
    const size_t contacts = m_touchingBodies.size();
    if (!m_gapsListed) { // the narrowphase's listing did not read them (m_listGaps)
        m_contactGap.resize(contacts);
        m_contactBearsUp.resize(contacts);
        for (size_t k = 0; k < contacts; ++k)
            std::tie(m_contactGap[k], m_contactBearsUp[k]) =
                contactSupport(m_contactPool[m_touchingContacts[k]].manifold);
    }
    // The nearest is of the contacts that can bear the body up (whose push on it rises): a 3 kg ball 3.2 cm over
    // the floor with a 580 kg ball 1.7 cm above it was not resting on the floor, not held, and was crushed 20 mm
    // into the floor when the heavy ball's held impulses fell on it.
    m_nearestGap.assign(m_state.size(), std::numeric_limits<Real>::max());
    for (size_t k = 0; k < contacts; ++k) {
        const auto [a, b] = m_touchingBodies[k];
        if (m_contactBearsUp[k] > 0)
            m_nearestGap[a] = std::min(m_nearestGap[a], m_contactGap[k]);
        if (m_contactBearsUp[k] < 0)
            m_nearestGap[b] = std::min(m_nearestGap[b], m_contactGap[k]);
    }
    const auto supports = [&](size_t k, uint32_t body) {
        return !(m_contactGap[k] > m_nearestGap[body] + m_tuning.supportGap);
    };
    for (size_t k = 0; k < contacts; ++k) {
        const auto [a, b] = m_touchingBodies[k];
        if (m_height[a] == kUnknown && !m_state.isMoving(b) && supports(k, a))
            m_height[a] = 1;
        if (m_height[b] == kUnknown && !m_state.isMoving(a) && supports(k, b))
            m_height[b] = 1;
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t k = 0; k < contacts; ++k) {
            const auto [a, b] = m_touchingBodies[k];
            if (m_height[a] == 0 || m_height[b] == 0)
                continue; // not both in such an island
            if (m_height[a] != kUnknown && (m_height[b] == kUnknown || m_height[a] + 1 < m_height[b]) &&
                supports(k, b)) {
                m_height[b] = m_height[a] + 1;
                changed = true;
            }
            if (m_height[b] != kUnknown && (m_height[a] == kUnknown || m_height[b] + 1 < m_height[a]) &&
                supports(k, a)) {
                m_height[a] = m_height[b] + 1;
                changed = true;
            }
        }
    }
    // A body with no path to a support (a heap in free fall) holds nothing and is held by nothing.
    for (uint32_t i : moving)
        if (m_height[i] == kUnknown)
            m_height[i] = 0;
    // A light body rising into a heavy one faster than holdRiseSpeed is not held (contactHold()); then the sweeps must
    // take the heavy body's momentum out through it, a little at a time, and a 3 kg ball bounced off the floor at
    // 4 m/s into a 580 kg one falling at 12 m/s was driven 110 mm into the floor. So the two first meet: an inelastic
    // impulse along the normal at the contact's fastest closing point stops the light body's rise into the heavy one
    // (momentum kept, energy only lost), and the contact then holds it like the ground.
    // (Only bodies whose surface can move that fast: in a pile of 1,000 boxes, calling it for every contact cost 2 %
    // of the step.)
    // Each body's speed is taken once, and again for the two bodies of a contact that met (the velocities it
    // changed). (Taken at every contact for both bodies, this loop took 0.03 ms a step of boxes1000's frames 45-120.)
    const auto mayRise = [&](uint32_t i) {
        return glm::length(m_state.linearVelocity[i]) + glm::length(m_state.angularVelocity[i]) * m_radius[i] >
               m_tuning.holdRiseSpeed;
    };
    // Each body with a height: the bodies with a height it touches, sorted (holdsInALoop()).
    m_neighbourStart.assign(m_state.size() + 1, 0);
    for (size_t k = 0; k < contacts; ++k)
        if (const auto [a, b] = m_touchingBodies[k]; m_height[a] != 0 && m_height[b] != 0) {
            ++m_neighbourStart[a + 1];
            ++m_neighbourStart[b + 1];
        }
    for (size_t i = 0; i < m_state.size(); ++i)
        m_neighbourStart[i + 1] += m_neighbourStart[i];
    m_neighbours.resize(m_neighbourStart.back());
    m_neighbourFill.assign(m_neighbourStart.begin(), m_neighbourStart.end() - 1);
    for (size_t k = 0; k < contacts; ++k)
        if (const auto [a, b] = m_touchingBodies[k]; m_height[a] != 0 && m_height[b] != 0) {
            // The neighbour in the high bits; bit 0: it rests on the body, bit 1: the body rests on it.
            const uint64_t aOnB = m_contactBearsUp[k] > 0 ? 1u : 0u, bOnA = m_contactBearsUp[k] < 0 ? 1u : 0u;
            m_neighbours[m_neighbourFill[a]++] = uint64_t(b) << 2 | bOnA | aOnB << 1;
            m_neighbours[m_neighbourFill[b]++] = uint64_t(a) << 2 | aOnB | bOnA << 1;
        }
    for (uint32_t i : moving)
        std::sort(m_neighbours.begin() + m_neighbourStart[i], m_neighbours.begin() + m_neighbourStart[i + 1]);
    m_mayRise.resize(m_state.size());
    bool anyRise = false;
    for (uint32_t i : moving)
        if (m_height[i] != 0) {
            m_mayRise[i] = mayRise(i) ? 1 : 0;
            anyRise = anyRise || m_mayRise[i] != 0;
        }
    if (!anyRise)
        return;
    // Only an upper body stackHoldRatio times heavier than the lower one is stopped (holdGeometry()): a contact
    // between bodies of closer masses is passed over before its manifold is read, whichever is lower.
    const auto closeMasses = [&](uint32_t a, uint32_t b) {
        const Real ma = m_state.info[a].mass, mb = m_state.info[b].mass, ratio = m_tuning.stackHoldRatio;
        return ratio * ma > mb && ratio * mb > ma;
    };
    for (size_t k = 0; k < contacts; ++k) {
        const auto [a, b] = m_touchingBodies[k];
        if (m_height[a] != 0 && m_height[b] != 0 && (m_mayRise[a] != 0 || m_mayRise[b] != 0) && !closeMasses(a, b)) {
            meetRisingLowerBody(m_touchingContacts[k]);
            m_mayRise[a] = mayRise(a) ? 1 : 0;
            m_mayRise[b] = mayRise(b) ? 1 : 0;
        }
    }
}

std::pair<Real, int8_t> World::contactSupport(const Manifold& manifold) const {
    Real gap = std::numeric_limits<Real>::max();
    for (int p = 0; p < manifold.pointCount; ++p)
        gap = std::min(gap, manifold.points[p].separation);
    const Real sinks = glm::dot(manifold.normal, m_gravity); // above zero: pushes A up, below: pushes B up
    return {gap, static_cast<int8_t>(sinks > 0.0 ? 1 : sinks < 0.0 ? -1 : 0)};
}

void World::meetRisingLowerBody(uint32_t slot) {
    const HoldGeometry g = holdGeometry(slot);
    if (!g.stopsUpper)
        return;
    const Manifold& manifold = m_contactPool[slot].manifold;
    const uint32_t lower = g.lower, upper = g.upper;
    const bool rotation = m_effects.effects.has(Effect::Rotation);
    for (int pass = 0; pass < 4 && risingInto(slot, g); ++pass) { // an impulse turns the bodies: the points again
        Real closing = 0.0;
        int at = -1;
        for (int p = 0; p < manifold.pointCount; ++p) {
            const Vec3& x = manifold.points[p].position;
            if (const Real rate =
                    glm::dot(m_state.pointVelocity(lower, x) - m_state.pointVelocity(upper, x), g.towardUpper);
                rate > closing) {
                closing = rate;
                at = p;
            }
        }
        if (at < 0)
            return;
        const Vec3 rl = manifold.points[at].position - m_state.position[lower];
        const Vec3 ru = manifold.points[at].position - m_state.position[upper];
        const Mat3 il = rotation ? m_state.worldInverseInertia(lower) : Mat3(0.0);
        const Mat3 iu = rotation ? m_state.worldInverseInertia(upper) : Mat3(0.0);
        const Vec3 al = glm::cross(rl, g.towardUpper), au = glm::cross(ru, g.towardUpper);
        const Real k = m_state.invMass[lower] + m_state.invMass[upper] + glm::dot(al, il * al) + glm::dot(au, iu * au);
        if (!(k > 0.0))
            return;
        const Real impulse = closing / k;
        m_state.linearVelocity[lower] -= impulse * m_state.invMass[lower] * g.towardUpper;
        m_state.angularVelocity[lower] -= impulse * (il * al);
        m_state.linearVelocity[upper] += impulse * m_state.invMass[upper] * g.towardUpper;
        m_state.angularVelocity[upper] += impulse * (iu * au);
    }
}

World::HoldGeometry World::holdGeometry(uint32_t slot) const {
    // Of two moving bodies that both rest on something (heightsAboveSupport()), the lower one is the one fewer
    // contacts from an immovable body, or at the same count the one whose centre is lower.
    HoldGeometry g;
    const ContactPair& contact = m_contactPairs[slot];
    const uint32_t ha = m_height[contact.bodyA], hb = m_height[contact.bodyB];
    const Real g2 = glm::dot(m_gravity, m_gravity);
    if (ha == 0 || hb == 0 || !(g2 > 0.0))
        return g;
    const Vec3 up = -m_gravity / std::sqrt(g2);
    g.lowerIsA =
        ha != hb ? ha < hb : glm::dot(m_state.position[contact.bodyB] - m_state.position[contact.bodyA], up) > 0.0;
    g.lower = g.lowerIsA ? contact.bodyA : contact.bodyB;
    g.upper = g.lowerIsA ? contact.bodyB : contact.bodyA;
    // Along the normal and by centres, from the lower body to the upper one (the normal points from A to B).
    g.towardUpper = (g.lowerIsA ? 1.0 : -1.0) * m_contactPool[slot].manifold.normal;
    g.along = glm::dot(g.towardUpper, up);
    g.valid =
        glm::dot(m_state.position[g.upper] - m_state.position[g.lower], up) > 0.0 && g.along >= m_tuning.wedgeRise;
    g.stopsUpper = g.valid && g.along >= std::sqrt(0.5) &&
                   !(m_tuning.stackHoldRatio * m_state.info[g.lower].mass > m_state.info[g.upper].mass);
    return g;
}

bool World::holdsInALoop(uint32_t upper, uint32_t lower) const {
    // The two lists are sorted by neighbour: walked together, they meet at each body both touch.
    const uint64_t* i = m_neighbours.data() + m_neighbourStart[upper];
    const uint64_t* const iEnd = m_neighbours.data() + m_neighbourStart[upper + 1];
    const uint64_t* j = m_neighbours.data() + m_neighbourStart[lower];
    const uint64_t* const jEnd = m_neighbours.data() + m_neighbourStart[lower + 1];
    while (i != iEnd && j != jEnd) {
        const uint64_t x = *i >> 2, y = *j >> 2;
        if (x < y) {
            ++i;
        } else if (y < x) {
            ++j;
        } else {
            // A third body resting on the upper one and bearing the lower one up, or the upper one resting on a
            // third body that rests on the lower one.
            if (((*i & 1u) != 0 && (*j & 2u) != 0) || ((*i & 2u) != 0 && (*j & 1u) != 0))
                return true;
            ++i;
            ++j;
        }
    }
    return false;
}

bool World::risingInto(uint32_t slot, const HoldGeometry& g) const {
    const Manifold& manifold = m_contactPool[slot].manifold;
    for (int k = 0; k < manifold.pointCount; ++k)
        if (glm::dot(m_state.pointVelocity(g.lower, manifold.points[k].position), g.towardUpper) >
            m_tuning.holdRiseSpeed)
            return true;
    return false;
}

ContactSolver::Hold World::contactHold(uint32_t slot) const {
    // The lower body (holdGeometry()) is held still when the contact holds the upper one up against gravity (its
    // normal within 45 degrees of vertical, the lower body below) and the upper one is stackHoldRatio times heavier,
    // at different heights or at the same height: a heavy plank landing across a light cube and the floor at once
    // rests on both (its two contacts within supportGap), and while the two were left unheld at the same height the
    // sweeps took the plank's momentum out through the cube a little at a time: deepest contact up to 9.8 mm
    // (tst_stacking; 0.75 mm held, 2026-12-05). A contact that presses the lower body down from the side (the
    // normal at least wedgeRise above horizontal) makes it heavier instead, to 1/holdMassRatio of the upper body (see
    // WorldTuning::holdMassRatio). A heavy body swung flat into a light one on the floor is not stopped by it, however
    // many contacts lie between the light one and the floor.
    // No hold where the two lie in a loop with a third body (holdsInALoop()): one resting on the upper body that bears
    // the lower one up, as crossed sticks in a pile lie, or one that the upper body rests on and that rests on the
    // lower one. The held body, read but never moved by the upper one, is then pushed by the third, which the upper
    // one pushes in turn, and it lifts the upper one as an immovable piston would, a little further at each sweep:
    // a pile of 120 sticks went from 331 J to 13 kJ within one step's 24 substeps, and 3 of 159 such piles gained
    // 7-119 % of their energy (2026-12-07; tst_motion's pilesOfCrossedSticksGainNoEnergy). A loop through contacts
    // within 45 degrees of vertical (or 11.5) let one or two of those through. Piles of 1,000 boxes (bench_piles,
    // 225) settle much as before: lowest corner -2.45 mm on average against -2.43, 5 moving at 10 s against 4, the
    // deepest -6.61 mm for a frame against -4.58 (boxes1000.obj's -2.50 against -2.00).
    const HoldGeometry g = holdGeometry(slot);
    if (!g.valid || holdsInALoop(g.upper, g.lower))
        return {};
    const uint8_t side = g.lowerIsA ? ContactSolver::kHoldA : ContactSolver::kHoldB;
    // Only a lower body that is not itself rising into the upper one holds it like the ground: held, a body that
    // moves into the contact pushes the upper one as an immovable body would, and gives it energy from nowhere. A
    // 463 kg cube falling onto a 0.128 kg box of 1.2 m that was still bouncing on the floor (e = 0.6) was thrown up,
    // the scene's energy rising to 3.4 times its start at 57ad949 and 25 times at 3802b6c, whose heights held the box
    // more often (2026-12-05). (A rising body first meets the upper one, meetRisingLowerBody(), and is then held
    // unless both rise.) Sliding or turning in the contact plane still holds, and a held body that slides fast drags
    // the upper one along by friction as a conveyor belt would: a 3 kg cone spinning at 52 rad/s under a 536 kg
    // cylinder falling onto it gave its scene 0.73 % of its energy with e = 0 (tst_motion's
    // capturedBouncesGainNoEnergy). Tried on 2026-12-05: not holding a lower body whose surface slides across the
    // contact faster than holdRiseSpeed let a 17 kg cylinder tumbling on a ball be crushed 187 mm into a 7,500 kg
    // one falling onto it (4.9 mm held; capturedHeavyLandingCrushesNothing); holding it only as heavy as the upper
    // body crushed nothing and made no energy there, but left 4 of 288 piles of 1,000 boxes moving at 10 s (0 held
    // still; all at rest by 12 s).
    if (g.stopsUpper && !risingInto(slot, g))
        return {side, 0.0};
    // Made heavier: only in an island whose mass ratio is above refineMassRatio, as all holds were until 2026-12-05.
    const Real lowerMass = m_state.info[g.lower].mass, upperMass = m_state.info[g.upper].mass;
    const uint32_t root = m_island[g.lower];
    if (!(m_islandMaxMass[root] > m_tuning.refineMassRatio * m_islandMinMass[root]) ||
        m_tuning.holdMassRatio * lowerMass > upperMass)
        return {};
    return {side, m_tuning.holdMassRatio * lowerMass / upperMass};
}

void World::solve() {
    const uint32_t n = m_state.size();
    for (NarrowList& list : m_narrowLists) {
        for (const uint32_t slot : list.solved)
            m_contactListed[slot] = 0;
        list.solved.clear();
    }
    std::vector<uint32_t>& moving = m_moving;
    moving.clear();
    Real leastInverseMass = std::numeric_limits<Real>::max(), mostInverseMass = 0.0;
    Real leastExtent = std::numeric_limits<Real>::max();
    for (uint32_t i = 0; i < n; ++i)
        if (m_state.isMoving(i)) {
            moving.push_back(i);
            leastInverseMass = std::min(leastInverseMass, m_state.invMass[i]);
            mostInverseMass = std::max(mostInverseMass, m_state.invMass[i]);
            leastExtent = std::min(leastExtent, m_middleExtent[i]);
        }
    m_profile.count(Counter::AwakeBodies, moving.size());

    // Each island's mass ratio decides its substep count (substepRefinement()); islands are independent, so an
    // island with a light body under a heavy one can take finer substeps without making the rest of the world pay.
    // No island's ratio is above that of the heaviest and the lightest moving bodies anywhere: when that one is
    // below stackHoldRatio (and so below refineMassRatio), every body takes the scene's substeps and no contact holds
    // a side, and the passes per island are skipped. (The inverse masses, contiguous, stand in for the masses, to their
    // rounding: the margin of 1e-9 keeps a ratio within a few bits of the limit on the per-island path. With those
    // passes and the copy of the step's start, this serial stretch took 0.18 ms a step of the 5,050-cube pyramid on two
    // threads, now 0.01 ms, 2026-12-01.) So does an island of small bodies (sizeRefinement()): none holds a body
    // smaller than the smallest moving body anywhere.
    m_uniformRefinement = !(mostInverseMass >= (1.0 - 1e-9) * m_tuning.stackHoldRatio * leastInverseMass) &&
                          sizeRefinement(leastExtent) == 1;
    m_solverCounters = {};
    if (m_uniformRefinement) {
        m_anyHeight = false;
        if (!moving.empty())
            solveGroup(moving, 1);
        countSolverRows();
        return;
    }
    m_refinement.assign(n, 0);
    m_islandMinMass.assign(n, std::numeric_limits<Real>::max());
    m_islandMaxMass.assign(n, 0.0);
    m_islandMinExtent.assign(n, std::numeric_limits<Real>::max());
    for (uint32_t i : moving) {
        const uint32_t root = m_island[i];
        m_islandMinMass[root] = std::min(m_islandMinMass[root], m_state.info[i].mass);
        m_islandMaxMass[root] = std::max(m_islandMaxMass[root], m_state.info[i].mass);
        m_islandMinExtent[root] = std::min(m_islandMinExtent[root], m_middleExtent[i]);
    }
    heightsAboveSupport(moving);
    int finest = 1;
    for (uint32_t i : moving) {
        const uint32_t root = m_island[i];
        const int k = std::max(substepRefinement(m_islandMaxMass[root] / m_islandMinMass[root]),
                               sizeRefinement(m_islandMinExtent[root]));
        m_refinement[i] = static_cast<uint8_t>(k);
        finest = std::max(finest, k);
    }

    for (int k = 1; k <= finest; ++k) {
        std::vector<uint32_t>& group = m_group;
        group.clear();
        for (uint32_t i : moving)
            if (m_refinement[i] == k)
                group.push_back(i);
        if (!group.empty())
            solveGroup(group, k);
    }
    countSolverRows();
}

void World::countSolverRows() {
    const ContactSolverCounters& sc = m_solverCounters;
    m_profile.count(Counter::NormalRows, sc.normalRows);
    m_profile.count(Counter::FrictionRows, sc.frictionRows);
    m_profile.count(Counter::RestitutionRows, sc.restitutionRows);
    m_profile.count(Counter::BoundedBounces, sc.boundedBounces);
    m_profile.count(Counter::SweptBatches, sc.sweptBatches);
    m_profile.count(Counter::BlowRows, sc.blowRows);
}

void World::solveGroup(std::span<const uint32_t> group, int refinement) {
    SolveScratch& scratch = m_scratch;
    scratch.bodies.assign(group.begin(), group.end());
    m_groupBodies = group.size();
    // The group's contacts: those with a moving body of this group. (Two moving bodies that touch share an island,
    // and so a refinement, so a contact never straddles two groups.)
    const auto inGroup = [&](uint32_t body) {
        return m_state.isMoving(body) && (m_uniformRefinement || m_refinement[body] == refinement);
    };
    scratch.clearContacts();
    // Each contact's island beside it (that of its moving body), for sharing the islands out (splitByIslands()).
    m_activeIsland.clear();
    for (size_t k = 0; k < m_touchingContacts.size(); ++k) {
        const auto [a, b] = m_touchingBodies[k];
        if (inGroup(a) || inGroup(b)) {
            scratch.activeContacts.push_back(m_touchingContacts[k]);
            m_activeIsland.push_back(m_island[m_state.isMoving(a) ? a : b]);
        }
    }
    const int substeps = m_substeps * refinement;
    planCuts();
    std::span<SolveScratch> solved(&scratch, 1);
    const size_t members = m_team ? static_cast<size_t>(m_team->size()) : 1;
    m_runScratch.resize(members);
    if (splitByIslands()) {
        m_profile.count(Counter::IslandsSharedOut, 1);
        StageTimer timer(m_profile, Stage::Solve);
        m_team->run([&](int member) {
            // Each member gathers the bodies and contacts of its own islands, in the group's order. (Gathered by
            // member 0 for both before the job, this took 1.0 ms of ramps.obj's first 120 frames on two threads with
            // the cores near, 1.8 far; the split now takes 0.6 and 0.8, and the solve job the same within 0.5 ms:
            // medians of 11-12 runs near, 2 far, 2026-12-05.)
            const size_t m = static_cast<size_t>(member);
            SolveScratch& part = m_memberScratch[m];
            part.bodies.clear();
            part.clearContacts();
            for (uint32_t i : scratch.bodies)
                if (m_islandMember[m_island[i]] == m)
                    part.bodies.push_back(i);
            std::vector<uint32_t>& solvedList = m_narrowLists[m].solved;
            for (size_t k = 0; k < scratch.activeContacts.size(); ++k)
                if (m_islandMember[m_activeIsland[k]] == m) {
                    const uint32_t slot = scratch.activeContacts[k];
                    part.activeContacts.push_back(slot);
                    solvedList.push_back(slot);
                    m_contactListed[slot] = 1;
                }
            solveInRuns(part, m_runScratch[m], substeps, false);
        });
        solved = m_runScratch;
    } else if (!m_team || group.size() < kMinBodiesForTeam) {
        solveInRuns(scratch, m_runScratch[0], substeps, true);
        solved = std::span<SolveScratch>(m_runScratch.data(), 1);
        m_profile.count(Counter::PartImbalance, m_runScratch[0].partImbalanceTotal);
    } else {
        solveSubsteps(scratch, substeps, true, true);
        m_profile.count(Counter::PartImbalance, scratch.partImbalance);
    }
    for (SolveScratch& part : solved) {
        m_profile.count(Counter::IslandsCut, part.islandsCutTotal);
        m_solverCounters += part.rows;
        part.rows = {};
        part.islandsCutTotal = part.partImbalanceTotal = 0;
        for (ClampCounters& clamps : part.clamps) {
            m_state.clampCounters.linear += clamps.linear;
            m_state.clampCounters.angular += clamps.angular;
            clamps = {};
        }
    }
    m_profile.count(Counter::IntegratedBodies, group.size() * static_cast<uint64_t>(substeps));
}

bool World::splitByIslands() {
    // Islands share no moving body, so a team can solve whole islands apart, with no synchronisation at all: each
    // member takes its islands through every substep with a solver of its own. Each body still sees the operations
    // of one thread in the same order (the constraints of its island, in manifold order), so the results are the
    // same numbers. Islands go to members in runs of body order when that is fair, else largest first, each to the
    // least loaded (by bodies plus contacts; shareIslandsOut()); a group whose islands cannot be shared out fairly
    // (one island of most of the work: a pile, a pyramid) is left to the level-by-level team of solveSubsteps().
    const SolveScratch& scratch = m_scratch;
    if (!m_team || scratch.bodies.size() < kMinBodiesForTeam)
        return false;
    const size_t members = static_cast<size_t>(m_team->size());
    // One island cannot be shared out. (For the 5,050-cube pyramid, counting its load first took some 70 us a step
    // of serial work, 2026-12-01.)
    const uint32_t firstIsland = m_island[scratch.bodies.front()];
    if (std::all_of(scratch.bodies.begin(), scratch.bodies.end(),
                    [&](uint32_t i) { return m_island[i] == firstIsland; }))
        return false;
    // m_islandMember first holds each island's entry in m_islandRoots and m_islandWork, then (below) its member.
    m_islandMember.resize(m_state.size());
    m_islandRoots.clear();
    m_islandWork.clear();
    for (uint32_t i : scratch.bodies)
        m_islandMember[m_island[i]] = kNoMember;
    const auto add = [&](uint32_t root) {
        if (m_islandMember[root] == kNoMember) {
            m_islandMember[root] = static_cast<uint32_t>(m_islandRoots.size());
            m_islandRoots.push_back(root);
            m_islandWork.push_back(0);
        }
        ++m_islandWork[m_islandMember[root]];
    };
    for (uint32_t i : scratch.bodies)
        add(m_island[i]);
    for (uint32_t root : m_activeIsland)
        add(root);
    // In runs of body order if that is fair enough, else largest first (IslandShare.h). Largest first alone, an
    // island's member followed from the sizes of the others, not from where its bodies sit in the body order that
    // refreshTransforms() and the narrowphase share out by halves, so a core often took up bodies the other had just
    // written. Over ramps.obj's first 120 frames on two threads, medians of five interleaved runs, 2026-12-05: with
    // the cores 50-65 ns apart (CoreRoundTrip.h), 1.057 and 1.062 ms a step before, 1.040 and 1.045 in runs; with
    // them 340-350 ns apart, 1.376, 1.383 and 1.561 ms before, 1.353, 1.343 and 1.370 in runs (three pairs).
    shareIslandsOut(m_islandWork, members, kInOrderShare, m_islandShare);
    // The slowest member's share against a perfect one: at most 60 % of the work on one of two members.
    if (10 * m_islandShare.largest * members > 12 * m_islandShare.all)
        return false;
    for (size_t k = 0; k < m_islandRoots.size(); ++k)
        m_islandMember[m_islandRoots[k]] = m_islandShare.member[k];
    if (m_islandShare.inBodyOrder)
        m_profile.count(Counter::IslandsInBodyOrder, 1);
    m_memberScratch.resize(members);
    return true;
}

void World::planCuts() {
    const std::vector<uint32_t>& group = m_scratch.bodies;
    if (!cutsIsland(group.size())) // an island is no bigger than the group, so none of them is cut
        return;
    // m_cutShare first counts each island's bodies, then holds the share of those to cut.
    m_cutShare.resize(m_state.size());
    for (uint32_t i : group)
        m_cutShare[m_island[i]] = 0;
    std::vector<uint32_t>& toCut = m_islandsToCut;
    toCut.clear();
    m_wholeIslands.clear();
    for (uint32_t i : group)
        ++m_cutShare[m_island[i]];
    for (uint32_t i : group) {
        const uint32_t root = m_island[i];
        if (m_cutShare[root] == 0)
            continue; // listed already
        if (cutsIsland(m_cutShare[root]))
            toCut.push_back(root);
        else
            m_wholeIslands.emplace_back(m_cutShare[root], root);
        m_cutShare[root] = 0; // marks it listed; the share is set below
    }
    // Counted again for the islands to cut, whose shares follow in the order of their roots, as cutIslands() takes
    // them.
    for (uint32_t i : group)
        ++m_cutShare[m_island[i]];
    size_t load[ContactSolver::kParts] = {0, 0};
    shareOutWholeIslands(m_wholeIslands, load, [](uint32_t, uint8_t) {});
    std::sort(toCut.begin(), toCut.end());
    for (uint32_t root : toCut)
        m_cutShare[root] = evenShare(m_cutShare[root], load);
}

void World::cutIslands(SolveScratch& scratch, const ContactSolver::ParallelFor& parallelFor) const {
    // Runs on a member of the team when islands are shared out, so it touches only the scratch and reads the state.
    const std::vector<uint32_t>& group = scratch.bodies;
    std::vector<uint8_t>& part = scratch.part;
    part.assign(group.size() + 1, 0);
    scratch.islandsCut = 0;
    scratch.partImbalance = 0;
    if (!cutsIsland(group.size())) // an island is no bigger than the group, so none of them is cut
        return;
    std::vector<uint32_t>& size = scratch.islandSize;
    size.resize(m_state.size());
    for (uint32_t i : group)
        size[m_island[i]] = 0;
    for (uint32_t i : group)
        ++size[m_island[i]];
    // The bodies of the islands to cut, island by island: (island root, position in the group).
    std::vector<std::pair<uint32_t, uint32_t>>& cutBodies = scratch.cutBodies;
    cutBodies.clear();
    for (size_t k = 0; k < group.size(); ++k)
        if (cutsIsland(size[m_island[group[k]]]))
            cutBodies.emplace_back(m_island[group[k]], static_cast<uint32_t>(k));
    if (cutBodies.empty())
        return;
    if (!std::is_sorted(cutBodies.begin(), cutBodies.end())) // one island is listed in order already
        std::sort(cutBodies.begin(), cutBodies.end());
    // Each island is cut across x, y or z, its first m_cutShare[root] bodies along the axis in part 0 (planCuts();
    // ties by position in the group, so the cut is one and the same on any machine and for any number of threads):
    // along the axis that leaves the fewest constraints across the cut, which are swept after both parts. (The
    // 5,050-cube pyramid, one cube deep, is cut along a row: over its first 30 frames 19 batches a step across the
    // cut, in three levels by colour (ContactSolver::scheduleLevels()); down the middle, 27.) An island with a body
    // that is not finite (the world reports it) is left whole: its split would be undefined.
    std::vector<SolveScratch::CutIsland>& islands = scratch.cutIslands;
    islands.clear();
    for (size_t begin = 0; begin < cutBodies.size(); begin += size[cutBodies[begin].first]) {
        SolveScratch::CutIsland island;
        island.begin = static_cast<uint32_t>(begin);
        island.end = static_cast<uint32_t>(begin + size[cutBodies[begin].first]);
        island.boundary = std::numeric_limits<uint32_t>::max();
        for (uint32_t e = island.begin; e < island.end; ++e) {
            const Vec3& p = m_state.position[group[cutBodies[e].second]];
            island.whole = island.whole || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z);
        }
        islands.push_back(island);
    }
    std::vector<uint32_t>& islandOf = scratch.islandOf; // the island's entry in `islands`, per root
    islandOf.resize(m_state.size());
    for (uint32_t n = 0; n < islands.size(); ++n)
        islandOf[cutBodies[islands[n].begin].first] = n;
    // Each axis is tried on its own: the islands' bodies are split at their share along it (nth_element over
    // (coordinate, position in the group) keys, so ties are broken the same way everywhere), and the constraints
    // across are counted; the best axis's split is then copied, not made again. (Comparing coordinates read through
    // the group and splitting the best axis a second time, cutting the 5,050-cube pyramid took 240 us a step, now
    // 139 us: medians of its first 45 frames, one thread, 2026-11-27. Shared out over two threads, the three axes
    // took no less then, 136-148 us. With the team's members spinning between jobs (ThreadTeam), shared out, the
    // whole cut took 0.19-0.21 ms a step of its first 45 frames on two threads against 0.22-0.28, three runs each,
    // 2026-12-01: the member with two axes takes 0.10-0.12 ms of it.)
    const auto tryAxis = [&](int axis) {
        SolveScratch::AxisCut& at = scratch.axisCuts[static_cast<size_t>(axis)];
        at.keys.resize(cutBodies.size());
        for (size_t e = 0; e < cutBodies.size(); ++e)
            at.keys[e] = {m_state.position[group[cutBodies[e].second]][axis], cutBodies[e].second};
        at.part.assign(group.size() + 1, 0);
        for (const SolveScratch::CutIsland& island : islands) {
            if (island.whole)
                continue;
            const auto first = at.keys.begin() + island.begin, last = at.keys.begin() + island.end;
            const auto split = first + m_cutShare[cutBodies[island.begin].first];
            std::nth_element(first, split, last);
            for (auto e = split; e != last; ++e)
                at.part[e->second + 1] = 1;
        }
        at.boundary.assign(islands.size(), 0);
        for (size_t c = 0; c < scratch.indexA.size(); ++c) {
            const uint32_t a = scratch.indexA[c], b = scratch.indexB[c];
            if (a != 0 && b != 0 && at.part[a] != at.part[b])
                ++at.boundary[islandOf[m_island[group[a - 1]]]];
        }
    };
    shareOut(parallelFor, 3, [&](size_t first, size_t last) {
        for (size_t axis = first; axis < last; ++axis)
            tryAxis(static_cast<int>(axis));
    });
    for (int axis = 0; axis < 3; ++axis)
        for (size_t n = 0; n < islands.size(); ++n)
            if (scratch.axisCuts[static_cast<size_t>(axis)].boundary[n] < islands[n].boundary) {
                islands[n].axis = axis;
                islands[n].boundary = scratch.axisCuts[static_cast<size_t>(axis)].boundary[n];
            }
    for (const SolveScratch::CutIsland& island : islands) {
        if (island.whole)
            continue; // all in part 0
        const std::vector<uint8_t>& best = scratch.axisCuts[static_cast<size_t>(island.axis)].part;
        for (uint32_t e = island.begin; e < island.end; ++e)
            part[cutBodies[e].second + 1] = best[cutBodies[e].second + 1];
        ++scratch.islandsCut;
    }
    // The other islands go whole to the part with fewer bodies so far, largest first, as planCuts() planned for the
    // whole group, where the island to cut then evens the parts out. (Before, islands cut in halves and the others
    // taken in the order of the group, ramps.obj's parts over frames 220-260 held 104-151 and 164-175 bodies, its pile
    // of 169-179 bodies cut in two; now 143-157 and 144-158. Member 0 then waited for member 1 in the solve over
    // frames 216-299 238-277 us a step in five runs of six (394 in the sixth), now 113-115 us in two; 2026-11-28,
    // Intel Xeon at 2.5 GHz.)
    std::vector<uint8_t>& islandPart = scratch.islandPart;
    islandPart.resize(m_state.size());
    constexpr uint8_t kUnassigned = 0xff;
    for (uint32_t i : group)
        islandPart[m_island[i]] = kUnassigned;
    std::vector<std::pair<uint32_t, uint32_t>>& whole = scratch.wholeIslands;
    whole.clear();
    for (uint32_t i : group) {
        const uint32_t root = m_island[i];
        if (!cutsIsland(size[root]) && islandPart[root] == kUnassigned) {
            whole.emplace_back(size[root], root);
            islandPart[root] = 0;
        }
    }
    size_t load[ContactSolver::kParts] = {0, 0};
    shareOutWholeIslands(whole, load, [&](uint32_t root, uint8_t p) { islandPart[root] = p; });
    for (size_t k = 0; k < group.size(); ++k) {
        const uint32_t root = m_island[group[k]];
        if (!cutsIsland(size[root]))
            part[k + 1] = islandPart[root];
    }
    if (scratch.islandsCut > 0) {
        const size_t inPart0 = static_cast<size_t>(std::count(part.begin() + 1, part.end(), uint8_t(0)));
        const size_t inPart1 = group.size() - inPart0;
        scratch.partImbalance = inPart0 > inPart1 ? inPart0 - inPart1 : inPart1 - inPart0;
    }
}

bool World::cutsIsland(size_t bodies) const {
    const size_t cut = m_tuning.cutIslandBodies, dominant = m_tuning.cutDominantIslandBodies;
    return (cut != 0 && bodies >= cut) || (dominant != 0 && bodies >= dominant && 2 * bodies > m_groupBodies);
}

void World::numberByParts(SolveScratch& scratch) {
    // The bodies of part 0 first, then those of part 1, each in the group's order: each member of the team then
    // integrates one contiguous run of the bodies, the part it sweeps, and no cache line of the bodies' arrays is
    // written by both. (The numbering names the bodies only: every body sees the same operations in the same order
    // whatever its number, so the frames are the same.)
    if (scratch.islandsCut == 0)
        return;
    std::vector<uint32_t>& group = scratch.bodies;
    const size_t n = group.size();
    std::vector<uint32_t>& renumber = scratch.renumber; // old solver index -> new
    renumber.resize(n + 1);
    renumber[0] = 0;
    const size_t inPart0 = static_cast<size_t>(std::count(scratch.part.begin() + 1, scratch.part.end(), uint8_t(0)));
    uint32_t next[ContactSolver::kParts] = {1, static_cast<uint32_t>(inPart0 + 1)};
    for (size_t k = 0; k < n; ++k)
        renumber[k + 1] = next[scratch.part[k + 1]]++;
    std::vector<uint32_t>& reordered = scratch.reordered;
    reordered.resize(n);
    for (size_t k = 0; k < n; ++k)
        reordered[renumber[k + 1] - 1] = group[k];
    std::swap(group, reordered);
    for (size_t k = 0; k < n; ++k)
        scratch.solverIndex[group[k]] = static_cast<uint32_t>(k + 1);
    for (uint32_t& index : scratch.indexA)
        index = renumber[index];
    for (uint32_t& index : scratch.indexB)
        index = renumber[index];
    // The new numbering is part by part.
    std::fill(scratch.part.begin() + 1, scratch.part.begin() + 1 + static_cast<std::ptrdiff_t>(inPart0), uint8_t(0));
    std::fill(scratch.part.begin() + 1 + static_cast<std::ptrdiff_t>(inPart0), scratch.part.end(), uint8_t(1));
}

void World::SolveScratch::clearContacts() {
    activeContacts.clear();
    manifolds.clear();
    indexA.clear();
    indexB.clear();
    friction.clear();
    restitution.clear();
    held.clear();
}

void World::solveInRuns(const SolveScratch& from, SolveScratch& work, int substeps, bool timed) {
    const std::vector<uint32_t>& bodies = from.bodies;
    if (s_runBodies == 0) { // all at once
        work.bodies.assign(bodies.begin(), bodies.end());
        work.clearContacts();
        work.activeContacts.assign(from.activeContacts.begin(), from.activeContacts.end());
        solveSubsteps(work, substeps, false, timed);
        return;
    }
    // Each island's bodies, then its run: islands go to runs in the order of their first bodies, a run closed once
    // it holds kRunBodies bodies.
    std::vector<uint32_t>& runOf = work.runOfIsland;
    if (runOf.size() < m_state.size())
        runOf.resize(m_state.size());
    for (uint32_t i : bodies)
        runOf[m_island[i]] = 0;
    for (uint32_t i : bodies)
        ++runOf[m_island[i]];
    constexpr uint32_t kAssigned = 0x80000000u;
    std::vector<uint32_t>& start = work.runStart;
    start.assign(1, 0);
    for (uint32_t i : bodies) {
        uint32_t& entry = runOf[m_island[i]];
        if (entry & kAssigned)
            continue;
        if (start.back() >= s_runBodies)
            start.push_back(0);
        start.back() += entry;
        entry = kAssigned | static_cast<uint32_t>(start.size() - 1);
    }
    const size_t runs = start.size();
    // start[r] holds run r's bodies: turned into where each run begins, and the runs' contacts counted likewise.
    std::vector<uint32_t>& contactStart = work.runContactStart;
    contactStart.assign(runs + 1, 0);
    const auto runOfContact = [&](uint32_t slot) {
        const ContactPair& c = m_contactPairs[slot];
        return runOf[m_island[m_state.isMoving(c.bodyA) ? c.bodyA : c.bodyB]] & ~kAssigned;
    };
    for (uint32_t slot : from.activeContacts)
        ++contactStart[runOfContact(slot) + 1];
    start.insert(start.begin(), 0);
    for (size_t r = 0; r < runs; ++r) {
        start[r + 1] += start[r];
        contactStart[r + 1] += contactStart[r];
    }
    // Each run's bodies and contacts in their order in `from`.
    work.runBodies.resize(bodies.size());
    work.runContacts.resize(from.activeContacts.size());
    std::vector<uint32_t>& at = work.runCursor;
    at.assign(start.begin(), start.end() - 1);
    for (uint32_t i : bodies)
        work.runBodies[at[runOf[m_island[i]] & ~kAssigned]++] = i;
    at.assign(contactStart.begin(), contactStart.end() - 1);
    for (uint32_t slot : from.activeContacts)
        work.runContacts[at[runOfContact(slot)]++] = slot;
    for (size_t r = 0; r < runs; ++r) {
        work.bodies.assign(work.runBodies.begin() + start[r], work.runBodies.begin() + start[r + 1]);
        work.clearContacts();
        work.activeContacts.assign(work.runContacts.begin() + contactStart[r],
                                   work.runContacts.begin() + contactStart[r + 1]);
        solveSubsteps(work, substeps, false, timed);
    }
}

void World::solveSubsteps(SolveScratch& scratch, int substeps, bool mayUseTeam, bool timed) {
    const Real dt = 1.0 / m_fps;
    const Real h = dt / substeps;
    const bool rotation = m_effects.effects.has(Effect::Rotation);
    const std::vector<uint32_t>& group = scratch.bodies;
    // Islands shared out run on the team's members, whose caller times the whole solve (timed is false): the stage
    // timers are not thread safe.
    std::optional<StageTimer> prepareTimer;
    if (timed)
        prepareTimer.emplace(m_profile, Stage::PrepareContacts);

    // A big group's set-up is shared out over the team: each body and each contact is set up alone, so the results
    // are the same. (Done by one thread, the records it wrote were read by the other core's half of the constraint
    // set-up, which then took twice as long as the writer's half.)
    ContactSolver::ParallelFor parallelFor;
    if (mayUseTeam && group.size() >= kMinBodiesForTeam)
        parallelFor = teamParallelFor();

    // Solver indices: entry 0 stands for every immovable body (anchors and sleepers); the group's bodies follow.
    // Each scratch holds its own, all 0 between solves, so that members solving islands apart do not write the
    // same lines.
    std::vector<uint32_t>& solverIndex = scratch.solverIndex;
    if (solverIndex.size() != m_state.size())
        solverIndex.assign(m_state.size(), 0);
    for (size_t k = 0; k < group.size(); ++k)
        solverIndex[group[k]] = static_cast<uint32_t>(k + 1);
    const size_t contactCount = scratch.activeContacts.size();
    scratch.manifolds.resize(contactCount);
    scratch.indexA.resize(contactCount);
    scratch.indexB.resize(contactCount);
    scratch.friction.resize(contactCount);
    scratch.restitution.resize(contactCount);
    scratch.held.resize(contactCount);
    const auto setUpContacts = [&](size_t first, size_t last) {
        for (size_t k = first; k < last; ++k) {
            const uint32_t slot = scratch.activeContacts[k];
            const ContactPair& contact = m_contactPairs[slot];
            scratch.manifolds[k] = &m_contactPool[slot].manifold; // its address only: the solver reads it
            // Sleepers and anchors have solver index 0; so does a moving body of another group, which cannot touch.
            scratch.indexA[k] = solverIndex[contact.bodyA];
            scratch.indexB[k] = solverIndex[contact.bodyB];
            scratch.friction[k] = contact.friction;
            scratch.restitution[k] = contact.restitution;
            const ContactSolver::Hold hold = m_anyHeight ? contactHold(slot) : ContactSolver::Hold{};
            Manifold& manifold = m_contactPool[slot].manifold;
            // Impulses solved with a hold fell on the heavy side only: warm started without it, they would throw the
            // light one (a 3 kg ball held under a 580 kg one took 1,368 N s the step it landed, and 454 m/s when the
            // next step's heights no longer held it). That contact starts cold.
            if (manifold.heldImpulses && hold.side == 0) {
                for (int p = 0; p < manifold.pointCount; ++p)
                    manifold.points[p].normalImpulse = 0.0;
                manifold.frictionImpulse = Vec3(0.0);
                manifold.twistImpulse = 0.0;
            }
            if (manifold.heldImpulses != (hold.side != 0)) // (no store for the contacts that never hold)
                manifold.heldImpulses = hold.side != 0;
            scratch.held[k] = hold;
        }
    };
    // Claimed in chunks by the team: the contacts with an anchor come first in pair order, and take no hold. (In even
    // halves, member 1 took 0.041 ms a step of boxes1000's frames 45-120 and member 0 0.025, the whole 0.044; in
    // chunks 0.033-0.039 each, the whole 0.039-0.041; scratch timers, 2026-12-06.)
    forEachChunkClaimed(contactCount, kSetUpChunk, static_cast<bool>(parallelFor), setUpContacts);
    cutIslands(scratch, parallelFor);
    numberByParts(scratch);

    // The substeps integrate a copy of the group's bodies (group[k] is local body k), written back after them; the
    // solver sweeps its own copy of what it needs (SolverBody). Both are made in one pass, shared out like the rest
    // of the set-up: each body alone, so the results are the same. (Copied by one thread, the 5,050-cube pyramid's
    // bodies took 0.3 ms a step of serial work, 2026-11-27.)
    std::vector<SolverBody>& bodies = scratch.solverBodies;
    bodies.resize(group.size() + 1);
    bodies[0] = SolverBody{};
    bodies[0].isotropic = true; // zero inverse mass and inertia
    scratch.centers.resize(group.size() + 1);
    scratch.centers[0] = Vec3(0.0);
    BodyState& local = scratch.local;
    local.sizeFor(m_state, group.size());
    scratch.localIds.resize(group.size());
    std::iota(scratch.localIds.begin(), scratch.localIds.end(), 0u);
    scratch.startPosition.resize(group.size());
    scratch.startOrientation.resize(group.size());
    shareOut(parallelFor, group.size(), [&](size_t first, size_t last) {
        local.gatherRange(m_state, group, first, last);
        for (size_t k = first; k < last; ++k) {
            const uint32_t i = group[k];
            SolverBody& b = bodies[k + 1];
            b = SolverBody{};
            b.invMass = m_state.invMass[i];
            // Linear-only mode: the solver must not spin bodies either.
            b.invInertia = rotation ? m_state.worldInverseInertia(i) : Mat3(0.0);
            // The substeps below take the inverse inertia again at each pose: an isotropic one stays d times the
            // identity.
            b.isotropic = !rotation || m_state.hasIsotropicInverseInertia(i);
            // prepare() records each point's approach speed for restitution, so it must see the current velocities.
            b.v = local.linearVelocity[k];
            b.w = rotation ? local.angularVelocity[k] : Vec3(0.0);
            scratch.centers[k + 1] = m_state.position[i];
            scratch.startPosition[k] = local.position[k];
            scratch.startOrientation[k] = local.orientation[k];
        }
    });
    // Velocities between the local bodies and the solver's copy, for the given local bodies.
    const auto toSolver = [&](std::span<const uint32_t> ids) {
        for (const uint32_t k : ids) {
            bodies[k + 1].v = local.linearVelocity[k];
            bodies[k + 1].w = rotation ? local.angularVelocity[k] : Vec3(0.0);
        }
    };
    const auto fromSolver = [&](std::span<const uint32_t> ids) {
        for (const uint32_t k : ids) {
            local.linearVelocity[k] = bodies[k + 1].v;
            if (rotation)
                local.angularVelocity[k] = bodies[k + 1].w;
        }
    };
    const std::span<const uint32_t> allLocal(scratch.localIds);
    ContactSolverSettings settings = m_solverSettings;
    settings.contactHertz = 0.25 * m_fps * substeps; // a quarter of the substep rate (see ContactSolverSettings)

    ContactSolver& solver = scratch.solver;
    solver.resetCounters();
    // How the group is swept (below) is decided from the solver's levels once it has them: by parts (when neither
    // part holds more than three quarters of the two parts' constraints), level by level on the team, or by one
    // thread. Where each part (or the whole group) is swept by one thread, the solver packs its levels into full
    // batches (ContactSolver::packPartLevels()); the frames are the same either way. (The parts were weighed by
    // their batches until 2026-12-02; packed, those are no longer known before the set-up.)
    const bool teamMay = mayUseTeam && m_team && group.size() >= kMinBodiesForTeam;
    bool byParts = false, byLevels = false;
    const auto plan = [&](const ContactSolver::Schedule& schedule) {
        const size_t part0 = schedule.constraints[0], part1 = schedule.constraints[1];
        byParts = teamMay && scratch.islandsCut > 0 && 4 * std::min(part0, part1) >= part0 + part1;
        size_t constraints = 0, levels = 0;
        for (size_t segment = 0; segment < schedule.levels.size(); ++segment) {
            constraints += schedule.constraints[segment];
            levels += schedule.levels[segment];
        }
        byLevels = !byParts && teamMay && levels > 0 && constraints / levels >= kMinLevelWidth;
        return !byLevels;
    };
    // A big group's constraints are set up by the whole team too (each one alone).
    solver.prepare(scratch.manifolds, scratch.indexA, scratch.indexB, scratch.friction, scratch.restitution, bodies,
                   scratch.centers, h, settings,
                   scratch.islandsCut > 0 ? std::span<const uint8_t>(scratch.part) : std::span<const uint8_t>(),
                   parallelFor, scratch.held, plan);
    // The step's blows, taken out of the velocities before the substeps (ContactSolver::absorbBlows()), groups of them
    // by the team: the same numbers. The solver's velocities are the local bodies' still (the copy above), and only
    // the blows' bodies are copied back.
    if (solver.hasBlows()) {
        solver.absorbBlows(bodies, parallelFor);
        for (const uint32_t x : solver.blowBodies()) {
            local.linearVelocity[x - 1] = bodies[x].v;
            if (rotation)
                local.angularVelocity[x - 1] = bodies[x].w;
        }
    }

    // The team solves the group together: bodies are split evenly for the integration, and each level of the
    // solver's schedule is split evenly for the contacts, with a barrier after every level. Every body sees the
    // same operations in the same order as on one thread, so the results are identical for any team size. A group
    // too small to pay for the barriers is solved by member 0 alone, and so is one whose levels are too narrow:
    // pyramid20's 590 constraints in 111 levels took 14 % longer on average on two threads than on one.
    //
    // A group with an island cut in parts (cutIslands()) is solved part by part instead: member 0 sweeps every
    // level of part 0 while member 1 sweeps part 1, with one barrier, then the constraints across the cut follow.
    // The 5,050-cube pyramid has 591 levels, 376 of them with fewer than 32 constraints, which left one member
    // waiting at most barriers.
    prepareTimer.reset();
    constexpr size_t kBoundary = ContactSolver::kBoundarySegment;
    const auto levelWidthOf = [&](size_t firstLevel, size_t lastLevel) -> size_t {
        return lastLevel > firstLevel
                   ? (solver.levelEnd(lastLevel - 1) - solver.levelBegin(firstLevel)) / (lastLevel - firstLevel)
                   : 0;
    };
    const bool boundaryShared =
        levelWidthOf(solver.segmentLevelBegin(kBoundary), solver.segmentLevelBegin(kBoundary + 1)) >= kMinLevelWidth;
    const int members = byParts || byLevels ? m_team->size() : 1;
    scratch.clamps.resize(static_cast<size_t>(members));
    // Which member integrates which local bodies: ownedStart[m] .. ownedStart[m + 1]. Solved by parts, each member
    // integrates the part it sweeps (numberByParts() made each part one run), so that a body's lines stay in one
    // core's cache through the substeps; otherwise the group is cut into even runs. Each body is integrated alone,
    // so the results are the same either way. (Integrated in even halves, a body was written by one member and swept
    // by the other on every substep: boxes1000's solve stages over its first 120 frames on two threads took
    // 1.42-1.61 ms a step, with each part integrated by its sweeper 1.14 ms; three interleaved runs, 2026-11-27.)
    std::vector<size_t>& ownedStart = scratch.ownedStart;
    ownedStart.assign(static_cast<size_t>(members) + 1, group.size());
    ownedStart[0] = 0;
    if (byParts) {
        ownedStart[1] = static_cast<size_t>(std::count(scratch.part.begin() + 1, scratch.part.end(), uint8_t(0)));
    } else {
        for (int m = 0; m < members; ++m)
            ownedStart[static_cast<size_t>(m) + 1] = ThreadTeam::share(0, group.size(), m, members).second;
    }
    // The per-stage timers are not thread safe: for a team, or islands shared out (!timed), the caller times the
    // whole solve.
    const bool timedStages = members == 1 && timed;
    std::optional<StageTimer> solveTimer;
    if (members > 1)
        solveTimer.emplace(m_profile, Stage::Solve);
    if (byParts)
        m_profile.count(Counter::SolvedInParts, 1);
    const size_t levels = solver.levelCount();

    // Member 0's sweeps of the cut's constraints so far, when it sweeps them alone (member 1 waits on it).
    std::atomic<uint32_t> cutsSwept{0};
    auto job = [&](int member) {
        const size_t m = static_cast<size_t>(member);
        const std::span<const uint32_t> mine(scratch.localIds.data() + ownedStart[m],
                                             ownedStart[m + 1] - ownedStart[m]);
        const auto barrier = [&] {
            if (members > 1)
                m_team->barrier();
        };
        // One sweep of a solver pass over every level, each level's batches shared out. (A team of one sweeps all
        // batches through ContactSolver::solve(), with no barriers.)
        const auto levelByLevel = [&](size_t firstLevel, size_t lastLevel, auto&& range) {
            for (size_t level = firstLevel; level < lastLevel; ++level) {
                const auto [begin, end] =
                    ThreadTeam::share(solver.batchLevelBegin(level), solver.batchLevelEnd(level), member, members);
                range(begin, end);
                barrier();
            }
        };
        // Part 1's bodies of the cut's constraints, which member 0 sweeps alone (see below).
        const auto claimEdge = [&] {
            for (const uint32_t x : scratch.edgeBodies)
                claimLines(&bodies[x], sizeof(SolverBody));
        };
        // In a team of two, member 1 waits for member 0's sweep of the cut only where it touches part 1's bodies on
        // the cut: it integrates its other bodies meanwhile (edgeOwed), and member 0 goes on without waiting for it.
        // Every body still sees the same operations in the same order. (Both waited at a barrier after the cut's
        // sweep until 2026-12-06: boxes1000's frames 45-120 on two threads took 2.79-2.85 ms a step against
        // 2.75-2.76, each frame's best of six runs, two rounds by turns.)
        bool edgeOwed = false;
        uint32_t cutsOwed = 0;
        const auto awaitCut = [&] {
            if (!edgeOwed)
                return;
            ThreadTeam::awaitAtLeast(cutsSwept, cutsOwed);
            edgeOwed = false;
            claimEdge();
        };
        const auto sweep = [&](auto&& range) {
            if (!byParts) {
                levelByLevel(0, levels, range);
                return;
            }
            awaitCut();
            if (static_cast<size_t>(member) < ContactSolver::kParts) {
                const auto [begin, end] = solver.segmentBatches(static_cast<size_t>(member));
                range(begin, end);
            }
            barrier();
            const auto [begin, end] = solver.segmentBatches(kBoundary);
            if (begin == end)
                return;
            if (boundaryShared) {
                levelByLevel(solver.segmentLevelBegin(kBoundary), solver.segmentLevelBegin(kBoundary + 1), range);
            } else if (members != 2) { // a team of three or more: every member waits at a barrier
                if (member == 0) {
                    claimEdge();
                    range(begin, end);
                }
                barrier();
                if (member == 1)
                    claimEdge();
            } else if (member == 0) {
                claimEdge();
                range(begin, end);
                cutsSwept.fetch_add(1, std::memory_order_release);
                cutsSwept.notify_all();
            } else {
                ++cutsOwed;
                edgeOwed = true;
            }
        };
        // Member 0 sweeps the cut's constraints alone, and with them part 1's bodies on the cut, whose records then
        // move between the cores twice a sweep: each member takes them back to back (claimLines()) before it
        // touches them, member 0 before the cut's sweep, member 1 after it, rather than one miss after another in
        // the sweep or the integration. (Member 1 lists them while member 0 sets the substep up; member 0 reads the
        // list after the first barrier.)
        if (byParts && member == 1) {
            std::vector<uint32_t>& edge = scratch.edgeBodies;
            edge.clear();
            for (size_t c = 0; c < scratch.indexA.size(); ++c) {
                const uint32_t a = scratch.indexA[c], b = scratch.indexB[c];
                if (a != 0 && b != 0 && scratch.part[a] != scratch.part[b])
                    edge.push_back(scratch.part[a] == 1 ? a : b);
            }
            std::sort(edge.begin(), edge.end());
            edge.erase(std::unique(edge.begin(), edge.end()), edge.end());
            // Its bodies in two lists of local ids: those not on the cut, and those on it.
            scratch.innerIds.clear();
            scratch.edgeIds.clear();
            size_t next = 0;
            for (const uint32_t k : mine) {
                const bool onCut = next < edge.size() && edge[next] == k + 1;
                (onCut ? scratch.edgeIds : scratch.innerIds).push_back(k);
                next += onCut ? 1 : 0;
            }
        }
        std::optional<StageTimer> t;
        const auto timer = [&](Stage stage) {
            t.reset();
            if (timedStages)
                t.emplace(m_profile, stage);
        };
        // Whether dp and dR changed since the last sweep: the first sweep after a position phase takes the points'
        // separations, and the sweeps after it until the next one reuse them (ContactSolver::Motion).
        bool moved = true;
        const auto motion = [&moved] {
            const ContactSolver::Motion m = moved ? ContactSolver::Motion::Moved : ContactSolver::Motion::Unchanged;
            moved = false;
            return m;
        };
        const auto integrateVelocitiesOf = [&](std::span<const uint32_t> ids) {
            if (m_integrator == Integrator::SymplecticEuler) {
                // The velocity phase and the copy to the solver in one pass, several bodies at a time.
                symplecticVelocitiesForSolver(local, ids, h, m_gravity, m_damping, rotation, scratch.clamps[m], bodies);
            } else {
                integrateVelocities(local, ids, h, m_gravity, m_damping, m_integrator, rotation, scratch.clamps[m]);
                toSolver(ids);
            }
        };
        const auto integratePositionsOf = [&](std::span<const uint32_t> ids) {
            if (m_integrator == Integrator::SymplecticEuler) {
                // All of that in one pass, several bodies at a time, with the same numbers. Its position phase
                // leaves the velocities as the solver left them.
                symplecticPositionsForSolver(local, ids, h, rotation, scratch.startPosition, scratch.startOrientation,
                                             bodies);
            } else {
                fromSolver(ids);
                integratePositions(local, ids, h, m_gravity, m_damping, m_integrator, rotation);
                for (const uint32_t k : ids) {
                    bodies[k + 1].dp = local.position[k] - scratch.startPosition[k];
                    bodies[k + 1].dR = local.anchorTurn(k, scratch.startOrientation[k]);
                    if (rotation)
                        bodies[k + 1].invInertia = local.solverInverseInertia(k, scratch.startOrientation[k]);
                }
                // These schemes' position phases change the velocities (Verlet's closing half kick, explicit Euler's
                // turn of w).
                toSolver(ids);
            }
        };
        // Member 1's bodies off the cut whose next velocity phase ran while member 0 swept the cut.
        bool innerAhead = false;
        for (int s = 0; s < substeps; ++s) {
            timer(Stage::IntegrateVelocities);
            integrateVelocitiesOf(innerAhead ? std::span<const uint32_t>(scratch.edgeIds) : mine);
            innerAhead = false;
            if (members == 1) {
                timer(Stage::WarmStart);
                solver.warmStart(bodies);
                timer(Stage::Solve);
                for (int it = 0; it < m_iterations; ++it)
                    solver.solve(bodies, true, motion());
            } else {
                if (member == 0)
                    solver.beginSubstep(); // read only by the solve sweeps, after the warm start's barriers
                barrier();
                sweep([&](size_t begin, size_t end) { solver.warmStartBatchRange(bodies, begin, end); });
                for (int it = 0; it < m_iterations; ++it) {
                    const ContactSolver::Motion m = motion();
                    sweep([&](size_t begin, size_t end) { solver.solveBatchRange(bodies, true, begin, end, m); });
                    if (member == 0)
                        solver.countSweep();
                }
            }
            timer(Stage::IntegratePositions);
            // The solver's velocities move the bodies; then the solver gets each body's motion since the step began
            // and its inverse inertia at the pose just reached, for the relax sweep and the next substep's. (Kept from
            // the step's start, a box spun about its long diagonal between two corner contacts gained 19 % of its
            // energy in 10 s at 5 rad/s: the sweeps' impulses turned it in the metric of a pose it had left.)
            if (edgeOwed) {
                integratePositionsOf(scratch.innerIds);
                awaitCut();
                integratePositionsOf(scratch.edgeIds);
            } else {
                integratePositionsOf(mine);
            }
            moved = true;
            barrier();
            timer(Stage::Relax);
            for (int it = 0; it < m_tuning.relaxIterations; ++it) {
                const ContactSolver::Motion m = motion();
                if (members == 1) {
                    solver.solve(bodies, false, m);
                    continue;
                }
                sweep([&](size_t begin, size_t end) { solver.solveBatchRange(bodies, false, begin, end, m); });
                if (member == 0)
                    solver.countSweep();
            }
            // No barrier here: until the next one, each member touches only its own bodies.
            if (edgeOwed) {
                fromSolver(scratch.innerIds);
                if (s + 1 < substeps) {
                    integrateVelocitiesOf(scratch.innerIds);
                    innerAhead = true;
                }
                awaitCut();
                fromSolver(scratch.edgeIds);
            } else {
                fromSolver(mine);
            }
            t.reset();
        }
    };
    if (members > 1)
        m_team->run(job);
    else
        job(0);
    solveTimer.reset();

    if (m_solverSettings.restitution) {
        std::optional<StageTimer> t;
        if (timed)
            t.emplace(m_profile, Stage::Restitution);
        toSolver(allLocal);
        // The energies of its bound at the step end's poses, which the sweeps' inverse inertias may not be (see
        // kSolverInertiaDrift). Solver body k + 1 is local body k; entry 0 does not move.
        solver.applyRestitution(bodies, [&](uint32_t body) {
            return rotation && body > 0 ? local.worldInverseInertia(body - 1) : Mat3(0.0);
        });
        fromSolver(allLocal);
    }
    std::optional<StageTimer> storeTimer;
    if (timed)
        storeTimer.emplace(m_profile, Stage::StoreImpulses);
    // Each body alone, so a team shares the bodies out. (By one thread, 0.07 ms a step of the 5,050-cube pyramid's
    // serial work on two threads, 2026-12-01.)
    shareOut(parallelFor, group.size(),
             [&](size_t first, size_t last) { local.scatterMotionRange(m_state, group, first, last); });
    solver.storeImpulses(scratch.manifolds, parallelFor);
    for (uint32_t i : group)
        solverIndex[i] = 0;
    scratch.rows += solver.counters();
    scratch.islandsCutTotal += scratch.islandsCut;
    scratch.partImbalanceTotal += scratch.partImbalance;
}

void World::continuousCollision() {
    // Fast bodies are swept by conservative advancement on the signed distance, against the anchors and against
    // dynamic bodies, and moved back to their first time of impact, where next step's speculative contact stops
    // them. A dynamic body is swept against only where the two came closer than the pair's speculative margin
    // covers (World::pairMargin() caps it at the bodies' size): a 10 cm steel cube at 30 m/s went through a
    // free-standing 5 cm wall in 7 of 10 starts without touching it. The margin covers the piles of 1,000 boxes,
    // whose frames this leaves as they were; in ramps.obj a few cubes that meet fast and spinning are caught (about
    // 0.1 more hits a step). A body that is not fast is held at its pose after the solve; two fast bodies move
    // together along their paths, and both go back to the pair's time of impact.
    // Two passes: the times are found first, reading the poses only, each body alone (the team shares the bodies
    // out with the same results), then the bodies are moved.
    const Real target = 0.25 * m_tuning.speculativeDistance;
    const Real fraction = m_tuning.ccdFraction;
    // Body k's motion over the step: its centre's travel, and its turn times its radius. No point of it got farther
    // than |travel| + turn.
    struct Motion {
        Vec3 travel{0.0};
        Real turn = 0.0;
        Real sweep() const { return glm::length(travel) + turn; }
    };
    const auto motionOf = [&](uint32_t k) {
        if (!m_state.isMoving(k))
            return Motion{};
        const Real angle =
            2.0 *
            std::acos(std::clamp(std::abs(glm::dot(m_stepStartOrientation[k], m_state.orientation[k])), 0.0, 1.0));
        return Motion{m_state.position[k] - m_stepStartPosition[k], angle * m_radius[k]};
    };
    const auto isFast = [&](uint32_t k, Real sweep) { return sweep > fraction * m_minExtent[k]; };
    // Body k's centre of mass at the fraction t of the step, on its straight path, and its pose there.
    const auto centreAt = [&](uint32_t k, Real t) {
        return m_stepStartPosition[k] + (m_state.position[k] - m_stepStartPosition[k]) * t;
    };
    const auto poseOf = [&](uint32_t k, Real t) {
        const Quat shapeQ =
            glm::slerp(m_stepStartOrientation[k], m_state.orientation[k], t) * m_state.info[k].shapeFromPrincipal;
        return Transform::fromQuat(centreAt(k, t) - shapeQ * m_state.info[k].comInShape, shapeQ);
    };
    // The first t below `limit` at which a at poseA(t) comes within `target` of b at poseB(t), by conservative
    // advancement (Mirtich 1996): from a distance d along the normal n between them, no point of a closes in on b
    // faster than (travel . n) + turn per unit of t, where travel is a's travel less b's over the step and turn the
    // two bodies' turns times their radii, so t can advance by d over that. `limit` if they do not meet. Bounded by
    // the whole sweep instead, as until 2026-12-08, a body sliding fast along a wall while it closed in slowly took
    // more than the 40 iterations to reach it and was let through: a tetrahedron 2 cm across at 50 m/s, 15 degrees
    // off the plane of a 1 mm steel wall, went through it.
    const auto advance = [&](const Shape& shapeA, const auto& poseA, const Shape& shapeB, const auto& poseB,
                             const Vec3& travel, Real turn, Real limit, Real stopAt, Real closeAt,
                             PenetrationResult* startedClose) {
        // Already closer than closeAt at the start: not swept (and *startedClose, if given, gets how close).
        PenetrationResult r = signedDistance(shapeA, poseA(0.0), shapeB, poseB(0.0));
        if (r.separation < closeAt) {
            if (startedClose)
                *startedClose = r;
            return limit;
        }
        Real t = 0.0;
        for (int iteration = 0; iteration < 40 && t < limit; ++iteration) {
            if (iteration > 0) // the first is the distance at the start, just taken
                r = signedDistance(shapeA, poseA(t), shapeB, poseB(t));
            if (r.separation < stopAt)
                return t;
            // The distance of two convex shapes is convex in a straight translation, so while nothing turns, moving
            // apart along n they never meet.
            const Real closing = std::max(glm::dot(travel, r.normal), 0.0) + turn;
            if (!(closing > 0.0))
                return limit;
            t += (r.separation - 0.5 * stopAt) / closing;
        }
        // No contact before `limit`, or none found in the iterations: left to the solver. (Sent back to where the
        // iterations had got, still apart, a thin stick spinning at 90 rad/s in a pile was sent back 30 times in 120
        // frames, each time among neighbours that had moved on, and a 2 g stick left the pile at 17 m/s.)
        return limit;
    };
    // A body's core: a ball of ccdCoreFraction of its thinnest size about its centre of mass, on the straight path of
    // that centre.
    const auto coreOf = [&](uint32_t k) {
        Shape core;
        core.kind = ShapeKind::Sphere;
        core.radius = m_tuning.ccdCoreFraction * m_minExtent[k];
        return core;
    };
    const auto corePoseOf = [&](uint32_t k, Real t) { return Transform::fromQuat(centreAt(k, t), identityQuat()); };
    // The first t below `limit` at which a (on poseA) and b (on poseB) meet; where they began the step close, the
    // speculative contact and the solver own the pair, but their points are those the narrowphase found at the step
    // start, and a body that turns, or that the blow turns, can bring others through within the step. So the cores
    // are swept then (Box2D v3's fallback when the time of impact is 0): a's core against b, and b's against a when
    // b moves, and the two go back to where a core comes within half its radius (at most `target`) of the other
    // body, so that no centre of mass goes through. An 8 x 1 x 1 cm rod at 200 m/s spinning at 1,000 rad/s went
    // through a 2 mm steel wall, and a tetrahedron 4 cm across at 50 m/s through a free-standing 2 mm wooden one,
    // which it set pivoting about its nose (2026-12-08). motionB is b's (zero where b stays at poseB).
    const auto firstContact = [&](uint32_t a, const auto& poseA, const Motion& motionA, uint32_t b, const auto& poseB,
                                  const Motion& motionB, Real limit) {
        PenetrationResult start;
        start.separation = std::numeric_limits<Real>::max();
        const Vec3 travel = motionA.travel - motionB.travel;
        Real t = advance(m_shapes[a], poseA, m_shapes[b], poseB, travel, motionA.turn + motionB.turn, limit, target,
                         2.0 * target, &start);
        if (!(start.separation < 2.0 * target))
            return t;
        // Only where the two close in along the normal by more than the ccdFraction of a body's thinnest size, so
        // that a thin card sliding fast over the floor and sinking a little stays the solver's, however near the floor
        // its centre is. A core is swept from wherever it is apart.
        const Real approach = glm::dot(travel, start.normal);
        if (approach > m_tuning.ccdFraction * m_minExtent[a]) {
            const Shape coreA = coreOf(a);
            const Real stopA = std::min(target, 0.5 * coreA.radius);
            t = advance(
                coreA, [&](Real u) { return corePoseOf(a, u); }, m_shapes[b], poseB, travel, motionB.turn, limit, stopA,
                stopA, nullptr);
        }
        if (motionB.sweep() > 0.0 && approach > m_tuning.ccdFraction * m_minExtent[b]) {
            const Shape coreB = coreOf(b);
            const Real stopB = std::min(target, 0.5 * coreB.radius);
            t = std::min(t, advance(
                                m_shapes[a], poseA, coreB, [&](Real u) { return corePoseOf(b, u); }, travel,
                                motionA.turn, limit, stopB, stopB, nullptr));
        }
        return t;
    };
    struct Hit {
        uint32_t body;
        Real toi;
    };
    struct MemberWork {
        uint64_t bodies = 0;
        std::vector<Hit> hits;
    };
    const auto sweepBody = [&](uint32_t i, MemberWork& work) {
        const Motion motion = motionOf(i);
        const Real sweep = motion.sweep();
        if (!isFast(i, sweep))
            return;
        ++work.bodies;
        const auto pose = [&](Real t) { return poseOf(i, t); };
        Aabb swept = m_shapes[i].worldBounds(pose(0.0));
        const Aabb endBox = m_shapes[i].worldBounds(pose(1.0));
        swept.min = glm::min(swept.min, endBox.min);
        swept.max = glm::max(swept.max, endBox.max);
        Real toi = 1.0;
        const DynamicTree& anchors = m_broadPhase.tree(ProxyKind::Static);
        anchors.query(swept, [&](int32_t proxy) {
            const uint32_t j = anchors.userId(proxy);
            const Transform xfB = transform(j);
            toi = std::min(toi, firstContact(
                                    i, pose, motion, j, [&](Real) { return xfB; }, Motion{}, toi));
            return true;
        });
        // A dynamic body j needs a sweep when the two came closer than the pair's speculative contact covered,
        // spec + max(size i, size j) (World::pairMargin()); they came at most sweep + sweep j closer. Where j is not
        // fast (sweep j <= f size j, f the ccdFraction, at most 1) that needs sweep > spec + (1 - f) size i; where
        // it is, one of the two swept more than (spec + its size) / 2, and that one finds the other. Below both, the
        // tree is not asked. The tree holds fat boxes, so most candidates are told apart by their own box after the
        // solve first.
        const Real spec = m_tuning.speculativeDistance;
        if (fraction <= 1.0 &&
            !(sweep > std::min(spec + (1.0 - fraction) * m_minExtent[i], 0.5 * (spec + m_minExtent[i])))) {
            if (toi < 1.0)
                work.hits.push_back({i, toi});
            return;
        }
        const Aabb reach{swept.min - Vec3(target), swept.max + Vec3(target)};
        const DynamicTree& dynamic = m_broadPhase.tree(ProxyKind::Dynamic);
        dynamic.query(reach, [&](int32_t proxy) {
            const uint32_t j = dynamic.userId(proxy);
            if (j == i)
                return true;
            const Motion other = motionOf(j);
            const bool fast = isFast(j, other.sweep());
            const Transform xfB = fast ? Transform{} : transform(j);
            if (!fast && !reach.overlaps(m_shapes[j].worldBounds(xfB)))
                return true;
            if (glm::length(motion.travel - other.travel) + motion.turn + other.turn <=
                spec + std::max(m_minExtent[i], m_minExtent[j]))
                return true;
            if (!fast) {
                toi = std::min(toi, firstContact(
                                        i, pose, motion, j, [&](Real) { return xfB; }, Motion{}, toi));
                return true;
            }
            // Both fast: the pair's time, the same from either side (the lower body first, over the whole step),
            // is the time of both.
            const uint32_t a = std::min(i, j), b = std::max(i, j);
            const Motion& motionA = a == i ? motion : other;
            const Motion& motionB = a == i ? other : motion;
            const Real t = firstContact(
                a, [&](Real u) { return poseOf(a, u); }, motionA, b, [&](Real u) { return poseOf(b, u); }, motionB,
                1.0);
            if (t < 1.0) {
                toi = std::min(toi, t);
                work.hits.push_back({j, t});
            }
            return true;
        });
        if (toi < 1.0)
            work.hits.push_back({i, toi});
    };
    // The members claim the bodies in chunks as they go. Split in even halves, the sweeps gained nothing from the
    // second thread in ramps.obj's first 120 frames (0.07 ms a step on one thread and on two); claimed in chunks of
    // 32, 0.04 ms on two (2026-11-27): the bodies that need a sweep are few and come in clusters. A team of two takes
    // them from the two ends of the body list, as refreshTransforms() shares the bodies out in halves, so that each
    // member mostly reads the start poses it recorded there. (Taken in turns from the front, over ramps.obj's first
    // 120 frames with the cores 340-380 ns apart, CCD took 6.8 ms against 6.2, the refresh after it 7.8 against 7.2;
    // medians of six runs of a build with timers, 2026-12-05.)
    const size_t n = m_state.size();
    const int members = m_team && n >= kMinBodiesForTeam ? m_team->size() : 1;
    std::vector<MemberWork> work(static_cast<size_t>(members));
    constexpr size_t kChunk = 32;
    std::atomic<size_t> claimed{0};
    const auto job = [&](int member) {
        ThreadTeam::forEachClaimedChunk(claimed, n, kChunk, member, members, [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i)
                if (m_state.isMoving(static_cast<uint32_t>(i)))
                    sweepBody(static_cast<uint32_t>(i), work[static_cast<size_t>(member)]);
        });
    };
    if (members > 1)
        m_team->run(job);
    else
        job(0);
    // Each body goes back to the earliest of its times (a minimum, so the order of the hits does not matter).
    std::vector<std::pair<uint32_t, Real>>& moved = m_ccdMoves;
    moved.clear();
    for (const MemberWork& w : work) {
        m_profile.count(Counter::CcdBodies, w.bodies);
        for (const Hit& hit : w.hits)
            moved.emplace_back(hit.body, hit.toi);
    }
    std::sort(moved.begin(), moved.end());
    uint64_t hits = 0;
    for (size_t k = 0; k < moved.size(); ++k) {
        if (k > 0 && moved[k].first == moved[k - 1].first)
            continue; // sorted by time within a body: the first is the earliest
        const uint32_t i = moved[k].first;
        const Real toi = moved[k].second;
        m_state.position[i] = m_stepStartPosition[i] + (m_state.position[i] - m_stepStartPosition[i]) * toi;
        const Quat before = m_state.orientation[i];
        m_state.orientation[i] = glm::normalize(glm::slerp(m_stepStartOrientation[i], m_state.orientation[i], toi));
        keepSpinEnergy(i, before);
        ++hits;
    }
    m_profile.count(Counter::CcdHits, hits);
}

void World::updateSleep() {
    const Real dt = 1.0 / m_fps;
    const uint32_t n = m_state.size();
    // Each awake body's sleep clock alone, so a team shares the bodies out with the same results (on two threads
    // this was a serial stretch of every step).
    const auto clocks = [&](size_t begin, size_t end) {
        for (uint32_t i = static_cast<uint32_t>(begin); i < end; ++i) {
            if (m_state.isStatic(i) || !m_state.isAwake(i))
                continue;
            // How far any point of the body has got from where it was when its sleep clock started, bounded by
            // the centre's displacement plus radius times the rotation angle (Jolt's sleep test, with one sphere
            // for all the body's points). The clock runs while that stays within the distance a body moving at
            // sleepSpeed covers in timeToSleep, and restarts from the current pose once it does not.
            const Quat turn = m_state.orientation[i] * glm::conjugate(m_sleepAnchorOrientation[i]);
            const Real angle = 2.0 * std::atan2(glm::length(Vec3(turn.x, turn.y, turn.z)), std::abs(turn.w));
            const Real moved = glm::length(m_state.position[i] - m_sleepAnchorPosition[i]) + m_radius[i] * angle;
            if (moved < m_tuning.sleepSpeed * m_tuning.timeToSleep)
                m_sleepTime[i] += dt;
            else
                restartSleepClock(i);
        }
    };
    if (m_team && n >= kMinBodiesForTeam)
        teamParallelFor()(n, clocks);
    else
        clocks(0, n);
    std::vector<Real>& islandMin = m_islandSleepTime;
    islandMin.assign(n, std::numeric_limits<Real>::max());
    for (uint32_t i = 0; i < n; ++i)
        if (!m_state.isStatic(i))
            islandMin[m_island[i]] = std::min(islandMin[m_island[i]], m_state.isAwake(i) ? m_sleepTime[i] : 1e30);
    for (uint32_t i = 0; i < n; ++i) {
        if (m_state.isStatic(i) || !m_state.isAwake(i) || islandMin[m_island[i]] < m_tuning.timeToSleep)
            continue;
        m_state.flags[i] &= static_cast<uint8_t>(~kBodyAwake);
        m_state.linearVelocity[i] = Vec3(0.0);
        m_state.angularVelocity[i] = Vec3(0.0);
    }
}

uint64_t World::stateHash() const {
    uint64_t hash = 1469598103934665603ull;
    const auto mix = [&](Real value) {
        uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        hash = (hash ^ bits) * 1099511628211ull;
    };
    for (size_t i = 0; i < bodyCount(); ++i) {
        const Vec3 c = centerOfMass(i);
        const Quat q = shapeOrientation(i);
        for (const Real value : {c.x, c.y, c.z, q.w, q.x, q.y, q.z})
            mix(value);
    }
    return hash;
}

FrameDiagnostics World::diagnostics() const {
    FrameDiagnostics d;
    for (uint32_t i = 0; i < m_state.size(); ++i) {
        if (m_state.isStatic(i))
            continue;
        d.kineticEnergy += m_state.kineticEnergy(i);
        d.potentialEnergy -= m_state.info[i].mass * glm::dot(m_gravity, m_state.position[i]);
        d.awakeBodies += m_state.isAwake(i) ? 1 : 0;
    }
    for (uint32_t slot : m_touchingContacts) {
        const Contact& c = m_contactPool[slot];
        for (int k = 0; k < c.manifold.pointCount; ++k) {
            d.maxPenetration = std::max(d.maxPenetration, -c.manifold.points[k].separation);
            d.contactPoints += c.manifold.points[k].separation <= 0.0 ? 1 : 0;
        }
    }
    return d;
}

std::vector<Manifold> World::manifolds() const {
    std::vector<Manifold> out;
    for (uint32_t slot : m_touchingContacts)
        out.push_back(m_contactPool[slot].manifold);
    return out;
}

} // namespace rl
