#include "analysis/Preflight.h"

#include "scene/BodyProperties.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rl {

std::string_view preflightKindName(PreflightKind kind) {
    switch (kind) {
    case PreflightKind::TinyBody:
        return "tiny-body";
    case PreflightKind::Tunnelling:
        return "tunnelling";
    case PreflightKind::ConcaveDynamic:
        return "concave-dynamic";
    case PreflightKind::MassRatio:
        return "mass-ratio";
    case PreflightKind::InvalidBody:
        return "invalid-body";
    }
    return "unknown";
}

namespace {

std::string fmt(const char* format, Real value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

struct Box {
    Vec3 lo{std::numeric_limits<Real>::max()};
    Vec3 hi{-std::numeric_limits<Real>::max()};
    void add(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
};

struct BodyInfo {
    bool valid = false;
    Real mass = 0.0;
    Real size = 0.0;      // longest bounding-box edge in shape coordinates
    Real thickness = 0.0; // smallest width
    Box world;            // world bounding box
    Real lowest = 0.0;    // lowest point along "up" (against gravity)
    Real highest = 0.0;
};

BodyInfo measure(const BodyDef& body, const BodyProperties& props, const Vec3& up) {
    BodyInfo info;
    info.valid = true;
    info.mass = props.mass;
    Box local;
    std::vector<Vec3> points;
    if (body.shape.type == ShapeType::Sphere) {
        const Real r = body.shape.radius;
        local.add(Vec3(-r));
        local.add(Vec3(r));
        info.thickness = 2.0 * r;
        info.world.add(body.position - Vec3(r));
        info.world.add(body.position + Vec3(r));
        const Real c = glm::dot(body.position, up);
        info.lowest = c - r;
        info.highest = c + r;
    } else {
        points = props.hull.vertices.empty() ? shapePoints(body.shape) : props.hull.vertices;
        info.lowest = std::numeric_limits<Real>::max();
        info.highest = -std::numeric_limits<Real>::max();
        for (const Vec3& p : points) {
            local.add(p);
            const Vec3 w = shapeToWorld(body, p);
            info.world.add(w);
            info.lowest = std::min(info.lowest, glm::dot(w, up));
            info.highest = std::max(info.highest, glm::dot(w, up));
        }
        // The smallest width of a convex polytope over its face normals: exact for boxes and prisms, an upper bound
        // (within a few per cent for hulls of round shapes) otherwise.
        info.thickness = props.flat ? 0.0 : std::numeric_limits<Real>::max();
        if (!props.flat)
            for (const HullFace& face : props.hull.faces) {
                Real lowestAlong = std::numeric_limits<Real>::max();
                for (const Vec3& v : props.hull.vertices)
                    lowestAlong = std::min(lowestAlong, glm::dot(face.normal, v));
                info.thickness = std::min(info.thickness, face.offset - lowestAlong);
            }
        if (info.thickness == std::numeric_limits<Real>::max())
            info.thickness = 0.0;
    }
    const Vec3 extent = points.empty() && body.shape.type != ShapeType::Sphere ? Vec3(0.0) : local.hi - local.lo;
    info.size = std::max({extent.x, extent.y, extent.z});
    return info;
}

bool touching(const Box& a, const Box& b, Real gap) {
    for (int k = 0; k < 3; ++k)
        if (a.lo[k] > b.hi[k] + gap || b.lo[k] > a.hi[k] + gap)
            return false;
    return true;
}

} // namespace

std::vector<PreflightFinding> runPreflight(const Scene& scene, const PreflightOptions& options) {
    std::vector<PreflightFinding> findings;
    const size_t n = scene.bodies.size();
    const Real g = glm::length(scene.world.gravity);
    const Vec3 up = g > 0.0 ? -scene.world.gravity / g : Vec3(0.0, 1.0, 0.0);
    const Real fps = scene.world.fps > 0.0 ? scene.world.fps : 60.0;
    const bool ccdOff = scene.world.effects.mode(Effect::Ccd) == EffectMode::Off;

    std::vector<BodyInfo> infos(n);
    std::vector<bool> concave(n, false);
    for (size_t i = 0; i < n; ++i) {
        const BodyDef& body = scene.bodies[i];
        Result<BodyProperties> props = computeBodyProperties(scene, body);
        if (!props) {
            PreflightFinding f;
            f.kind = PreflightKind::InvalidBody;
            f.body = i;
            f.message = props.error().toString();
            f.fix = "Fix the body's shape, size or mass in the inspector or in the source file; the bake cannot run "
                    "with it.";
            findings.push_back(std::move(f));
            continue;
        }
        infos[i] = measure(body, *props, up);
        concave[i] = props->concave;
    }

    // The top of the lowest anchor is where falling bodies end up.
    std::optional<Real> landing;
    for (size_t i = 0; i < n; ++i)
        if (scene.bodies[i].anchor && infos[i].valid)
            landing = landing ? std::min(*landing, infos[i].highest) : infos[i].highest;

    for (size_t i = 0; i < n; ++i) {
        const BodyDef& body = scene.bodies[i];
        const BodyInfo& info = infos[i];
        if (body.anchor || !info.valid)
            continue;
        const std::string name = "'" + body.name + "'";

        if (info.size < options.minSize) {
            PreflightFinding f;
            f.kind = PreflightKind::TinyBody;
            f.body = i;
            f.value = info.size;
            f.limit = options.minSize;
            f.message = name + " is " + fmt("%.3g", info.size * 100.0) + " cm across, below " +
                        fmt("%.3g", options.minSize * 100.0) + " cm";
            f.fix = "Coordinates are metres: if the model was made in centimetres, scale it up by 100. Contacts start "
                    "2 cm before bodies touch, so smaller bodies jitter and sink.";
            findings.push_back(std::move(f));
        }

        const Real v0 = glm::length(body.velocity);
        Real speed = v0 + g * options.duration;
        if (landing && g > 0.0) {
            const Real h = std::max(0.0, info.lowest - *landing);
            speed = std::min(speed, std::sqrt(v0 * v0 + 2.0 * g * h));
        }
        const Real perFrame = speed / fps;
        if (info.thickness > 0.0 && perFrame > info.thickness) {
            PreflightFinding f;
            f.kind = PreflightKind::Tunnelling;
            f.body = i;
            f.value = perFrame;
            f.limit = info.thickness;
            f.speed = speed;
            f.suggestedFps = std::ceil(speed / info.thickness);
            f.message = name + " may reach " + fmt("%.3g", speed) + " m/s and move " + fmt("%.3g", perFrame) +
                        " m per frame, more than its thickness of " + fmt("%.3g", info.thickness) + " m";
            f.fix = (ccdOff ? std::string("CCD is switched off for this scene: turn it back on (effects auto or "
                                          "+ccd), or raise the frame rate to at least ")
                            : std::string("CCD sweeps such bodies (effects auto); to be safe without it, raise the "
                                          "frame rate to at least ")) +
                    fmt("%.0f", f.suggestedFps) + " fps or make the body thicker.";
            findings.push_back(std::move(f));
        }

        if (concave[i]) {
            PreflightFinding f;
            f.kind = PreflightKind::ConcaveDynamic;
            f.body = i;
            f.message = name + " is concave; it collides as its convex hull, so its hollows are filled";
            f.fix = "Split it into convex parts in Blender (one object each), make it an anchor, or accept the hull.";
            findings.push_back(std::move(f));
        }
    }

    // Pairs of dynamic bodies that touch at the start: sweep over the bounding boxes sorted by their lower x.
    std::vector<size_t> order;
    for (size_t i = 0; i < n; ++i)
        if (!scene.bodies[i].anchor && infos[i].valid && infos[i].mass > 0.0)
            order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return infos[a].world.lo.x < infos[b].world.lo.x; });
    for (size_t k = 0; k < order.size(); ++k) {
        const size_t a = order[k];
        for (size_t m = k + 1; m < order.size(); ++m) {
            const size_t b = order[m];
            if (infos[b].world.lo.x > infos[a].world.hi.x + options.contactGap)
                break;
            if (!touching(infos[a].world, infos[b].world, options.contactGap))
                continue;
            const size_t light = infos[a].mass <= infos[b].mass ? a : b;
            const size_t heavy = light == a ? b : a;
            const Real ratio = infos[heavy].mass / infos[light].mass;
            if (!(ratio > options.maxMassRatio))
                continue;
            PreflightFinding f;
            f.kind = PreflightKind::MassRatio;
            f.body = light;
            f.other = heavy;
            f.value = ratio;
            f.limit = options.maxMassRatio;
            f.message = "'" + scene.bodies[light].name + "' (" + fmt("%.3g", infos[light].mass) + " kg) touches '" +
                        scene.bodies[heavy].name + "' (" + fmt("%.3g", infos[heavy].mass) + " kg), a mass ratio of " +
                        fmt("%.0f", ratio) + ":1";
            f.fix = "Bring the densities or masses closer (below " + fmt("%.0f", options.maxMassRatio) +
                    ":1), or raise substeps and iterations; otherwise the lighter body may sink or jitter.";
            findings.push_back(std::move(f));
        }
    }

    std::stable_sort(findings.begin(), findings.end(), [](const PreflightFinding& x, const PreflightFinding& y) {
        if (x.body != y.body)
            return x.body < y.body;
        if (x.kind != y.kind)
            return x.kind < y.kind;
        return x.other.value_or(0) < y.other.value_or(0);
    });
    return findings;
}

} // namespace rl
