// Loading a .bake for playback and export: the frames from the file, plus what the scene in its OBJ part tells
// about each body (anchor flag, centre of mass), so that CSV exports report centres of mass as DESIGN.md §5 asks.
#pragma once

#include "bake/Bake.h"
#include "common/Result.h"
#include "io/BakeFile.h"
#include "scene/Scene.h"

#include <string>

namespace rl {

struct LoadedBake {
    Bake bake;
    BakeFileInfo info;
    Scene scene;          // the bodies of the OBJ part (empty when the file has none)
    bool centred = false; // positions were moved from vertex means to centres of mass using that scene
};

// Reads either flavour of .bake. When the OBJ part holds one object per body, each body's centre of mass is
// computed from its hull and the stored vertex means are re-based onto it (the vertex means stay exactly where
// they were). Otherwise positions remain vertex means. Errors name the file and the line or object.
Result<LoadedBake> loadBake(const std::string& path);

} // namespace rl
