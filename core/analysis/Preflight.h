// Pre-flight check: what in a scene is likely to simulate badly, found before a bake, each with a suggested fix.
// The editor runs it before every bake; it reads only the scene definition (no World is built).
#pragma once

#include "math/Types.h"
#include "scene/Scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rl {

// What is checked, and how (the numbers are PreflightOptions):
//   TinyBody        a dynamic body whose size is below minSize. Size: the longest edge of the body's bounding box in
//                   shape coordinates (a sphere: its diameter). Contacts are created 2 cm before bodies touch
//                   (WorldTuning::speculativeDistance), so smaller bodies jitter, hover and sink; a model authored in
//                   centimetres but read as metres is the usual cause.
//   Tunnelling      a dynamic body that may move further than its own thickness in one frame, when contacts are
//                   looked for once per frame. Thickness: the body's smallest width (over its hull's face normals; a
//                   sphere: its diameter). Speed: the fastest it can plausibly get, |v0| plus free fall: with an
//                   anchor below, falling from its lowest point to the top of the lowest anchor,
//                   sqrt(|v0|^2 + 2 g h), capped at |v0| + g T; with no anchor, |v0| + g T over the bake duration T.
//                   Flagged when speed / fps > thickness.
//   ConcaveDynamic  a dynamic body whose mesh is not convex: it collides as its convex hull, so hollows are filled.
//   MassRatio       two dynamic bodies that touch or overlap at the start (world bounding boxes closer than
//                   contactGap) with masses more than maxMassRatio apart. The sequential-impulse solver converges
//                   slowly on such pairs, so the light body sinks or jitters under the heavy one; the world spends
//                   extra substeps on islands above 250:1 to hold them (World.cpp), so such scenes also bake slower.
//   InvalidBody     a body the simulation cannot use at all (no volume, bad numbers); the bake would fail.
enum class PreflightKind { TinyBody, Tunnelling, ConcaveDynamic, MassRatio, InvalidBody };
std::string_view preflightKindName(PreflightKind kind); // "tiny-body", "tunnelling", ...

struct PreflightOptions {
    Real minSize = 0.02;       // m, see TinyBody
    Real maxMassRatio = 100.0; // see MassRatio: warns before the world's own 250:1 remedy sets in
    Real duration = 10.0;      // s, the bake's length (the CLI's default)
    Real contactGap = 0.01;    // m: bounding boxes this close count as touching
};

struct PreflightFinding {
    PreflightKind kind = PreflightKind::TinyBody;
    size_t body = 0;
    std::optional<size_t> other; // MassRatio: the other body
    // TinyBody: the size (m). Tunnelling: the distance per frame (m). MassRatio: heavier / lighter. Otherwise 0.
    Real value = 0.0;
    // TinyBody: minSize. Tunnelling: the thickness (m). MassRatio: maxMassRatio. Otherwise 0.
    Real limit = 0.0;
    Real speed = 0.0;        // Tunnelling: the speed used (m/s)
    Real suggestedFps = 0.0; // Tunnelling: the lowest frame rate at which the body moves less than its thickness
    std::string message;     // what was found, naming the body (English; the editor words its own)
    std::string fix;         // what to do about it
};

// Findings in body order, at most one of each kind per body (MassRatio: per pair, listed at the lighter body).
std::vector<PreflightFinding> runPreflight(const Scene& scene, const PreflightOptions& options = {});

} // namespace rl
