// Unique body names in Blender's style: "Cube", then "Cube.001", "Cube.002", ... (the lowest free number).
// Used by Add, Duplicate and the rename checks; names are compared exactly, as the scene stores them.
#pragma once

#include "scene/Scene.h"

#include <set>
#include <string>
#include <string_view>

namespace rl {

// The name without a trailing ".<digits>" ("Cube.001" -> "Cube"; "Cube" and "v1.5a" stay).
std::string baseBodyName(std::string_view name);

// `wanted` when no body (and no name in alsoTaken) has it, else base + ".NNN" with the lowest free number >= 1.
std::string uniqueBodyName(const Scene& scene, std::string_view wanted, const std::set<std::string>& alsoTaken = {});

} // namespace rl
