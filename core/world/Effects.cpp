#include "world/Effects.h"

#include <algorithm>

namespace rl {

std::string ActiveEffects::toString() const {
    std::string out;
    for (int i = 0; i < kEffectCount; ++i) {
        if (!on[i])
            continue;
        if (!out.empty())
            out += ',';
        out += effectName(static_cast<Effect>(i));
    }
    return out.empty() ? "none" : out;
}

bool anyPositivePair(CombineRule rule, const std::vector<Real>& values, const std::vector<bool>& dynamic) {
    // A pair combines to a positive value when (Max, Average) either value is positive, or (GeometricMean, Min,
    // Multiply) both are. Count positives among all bodies and among dynamic ones.
    size_t positives = 0, dynamicPositives = 0, dynamicCount = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        const bool p = values[i] > 0.0;
        positives += p ? 1 : 0;
        dynamicPositives += (p && dynamic[i]) ? 1 : 0;
        dynamicCount += dynamic[i] ? 1 : 0;
    }
    if (dynamicCount == 0 || values.size() < 2)
        return false;
    switch (rule) {
    case CombineRule::Max:
    case CombineRule::Average:
        // Some pair with a dynamic body has a positive member: either a positive dynamic body (with any partner)
        // or a positive body of any kind next to some other dynamic body.
        return dynamicPositives > 0 || (positives > 0 && dynamicCount > 0);
    case CombineRule::GeometricMean:
    case CombineRule::Min:
    case CombineRule::Multiply:
        return dynamicPositives > 0 && positives >= 2;
    }
    return true;
}

EffectsDecision decideEffects(const Scene& scene, const EffectsSetting& setting, const SceneFacts& facts) {
    EffectsDecision d;
    auto decide = [&](Effect e, bool autoValue, std::string reason) {
        const EffectMode mode = setting.mode(e);
        const int i = static_cast<int>(e);
        if (mode == EffectMode::Auto) {
            d.effects.on[i] = autoValue;
            d.reasons[i] = "auto: " + reason;
        } else {
            d.effects.on[i] = mode == EffectMode::On;
            d.reasons[i] = mode == EffectMode::On ? "forced on" : "forced off";
        }
    };
    const bool gravity = facts.anyDynamic && glm::length(scene.world.gravity) > 0.0;
    decide(Effect::Gravity, gravity,
           gravity ? "dynamic bodies and non-zero gravity" : "no dynamic body or zero gravity");
    const bool friction = facts.frictionPairs;
    decide(Effect::Friction, friction,
           friction ? "some pair has friction above zero" : "every pair's combined friction is zero");
    // Rotation is needed when something can start or keep a spin. (Friction can spin a sphere.)
    const bool rotation = facts.anyDynamic && (facts.anyNonSphereDynamic || facts.anySpinning ||
                                               (friction && setting.mode(Effect::Friction) != EffectMode::Off));
    decide(Effect::Rotation, rotation,
           rotation ? "bodies can rotate" : "only frictionless, non-spinning spheres (rotation cannot change)");
    decide(Effect::Restitution, facts.restitutionPairs,
           facts.restitutionPairs ? "some pair has restitution above zero"
                                  : "every pair's combined restitution is zero");
    const bool damping = scene.world.linearDamping > 0.0 || scene.world.angularDamping > 0.0;
    decide(Effect::Damping, damping, damping ? "damping is set" : "no damping is set");
    const bool sleeping = gravity && facts.anyAnchor;
    decide(Effect::Sleeping, sleeping,
           sleeping ? "bodies can come to rest on anchors" : "nothing to come to rest on (no gravity or no anchor)");
    decide(Effect::Ccd, facts.fastBodies,
           facts.fastBodies ? "some body may move more than half its size in one frame"
                            : "no body moves fast relative to its size");
    return d;
}

} // namespace rl
