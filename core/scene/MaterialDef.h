// Materials: density, friction and restitution, the built-in presets, and how two materials combine at a contact.
#pragma once

#include "math/Types.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rl {

struct MaterialDef {
    std::string name = "Default";
    Real density = 1000.0;  // kg/m^3
    Real friction = 0.5;    // Coulomb coefficient
    Real restitution = 0.0; // 0 = no bounce, 1 = elastic

    bool operator==(const MaterialDef&) const = default;
};

// The original project's presets (DESIGN.md §3): Default, Steel, Wood, Rubber, Ice, Concrete, Plastic.
const std::vector<MaterialDef>& materialPresets();

// Case-insensitive lookup among the presets.
std::optional<MaterialDef> findPreset(std::string_view name);

enum class CombineRule { GeometricMean, Average, Min, Max, Multiply };

// Pair friction is sqrt(ua*ub) and pair restitution max(ea, eb) unless the world settings choose otherwise.
Real combine(CombineRule rule, Real a, Real b);

std::string_view combineRuleName(CombineRule rule);
std::optional<CombineRule> parseCombineRule(std::string_view name);

} // namespace rl
