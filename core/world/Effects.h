// Which effects a world simulates: decided once per scene from what it contains (auto), or forced on or off.
// A skipped effect costs nothing: the step leaves its stage out entirely.
#pragma once

#include "scene/Scene.h"

#include <array>
#include <string>

namespace rl {

struct ActiveEffects {
    std::array<bool, kEffectCount> on{};
    bool has(Effect e) const { return on[static_cast<int>(e)]; }
    void set(Effect e, bool value) { on[static_cast<int>(e)] = value; }
    // Comma list of the active effects in the order of rl::Effect, or "none".
    std::string toString() const;
    bool operator==(const ActiveEffects&) const = default;
};

// Why each auto decision is made (also shown by the editor next to the effect):
//   gravity      there is a dynamic body and the gravity vector is not zero
//   rotation     some dynamic body can be made to spin: it is not a sphere, or it starts spinning, or friction acts
//   friction     some pair of bodies, one of them dynamic, has a combined friction above zero
//   restitution  some pair of bodies, one of them dynamic, has a combined restitution above zero
//   damping      the world's linear or angular damping is above zero
//   sleeping     gravity acts and there is an anchor to come to rest on
//   ccd          some dynamic body may move more than half its smallest size in one frame: by its initial speed,
//                or by the speed it gains falling the height of the scene under gravity
// explain(e) returns that reason for the scene at hand.
struct EffectsDecision {
    ActiveEffects effects;
    std::array<std::string, kEffectCount> reasons;
};

// fastestFallSpeed and minimumSize come from the body properties; the world computes them (see World::create).
struct SceneFacts {
    bool anyDynamic = false;
    bool anyAnchor = false;
    bool anyNonSphereDynamic = false;
    bool anySpinning = false;
    bool frictionPairs = false;
    bool restitutionPairs = false;
    bool fastBodies = false; // some dynamic body may move more than half its smallest size in a frame
};

EffectsDecision decideEffects(const Scene& scene, const EffectsSetting& setting, const SceneFacts& facts);

// Whether any pair (i dynamic, j != i) combines to a positive value under the rule. O(n).
bool anyPositivePair(CombineRule rule, const std::vector<Real>& values, const std::vector<bool>& dynamic);

} // namespace rl
