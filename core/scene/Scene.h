// A scene definition: world settings, materials and bodies, plus where it came from.
// This is the document the editor edits and the World is built from; it owns no runtime state.
#pragma once

#include "scene/BodyDef.h"
#include "scene/MaterialDef.h"
#include "scene/WorldSettings.h"

#include <string>
#include <vector>

namespace rl {

struct Scene {
    WorldSettings world;
    std::vector<MaterialDef> materials; // scene materials; they shadow presets of the same name
    std::vector<BodyDef> bodies;

    std::string sourcePath;    // file the scene was read from, if any
    std::string sourceObjText; // the source OBJ text verbatim, when the scene came from one OBJ file

    // Scene material first, then preset, case-insensitive; nullopt when the name is unknown.
    std::optional<MaterialDef> findMaterial(std::string_view name) const;

    // The body's material with its per-body overrides applied (unknown material names fall back to Default).
    MaterialDef effectiveMaterial(const BodyDef& body) const;

    bool operator==(const Scene&) const = default;
};

} // namespace rl
