// Reading and writing .rlscene files (DESIGN.md §6): a versioned JSON form of rl::Scene that round-trips exactly.
// Every error names the file, the line and column, the body or section, and the key.
#pragma once

#include "common/Result.h"
#include "io/Json.h"
#include "scene/Scene.h"

#include <string>
#include <string_view>

namespace rl {

inline constexpr std::string_view kSceneFormatName = "rigidlab-scene";
inline constexpr int kSceneFormatVersion = 1;

// Parses .rlscene text. `path` names the file in errors, becomes Scene::sourcePath, and is where relative "obj"
// shape paths start from; the referenced OBJ objects are loaded (vertices and triangles) so that the scene is
// complete. Unknown keys, wrong types and invalid values (negative density or mass, zero half extents, fps <= 0,
// substeps < 1, a non-unit orientation, an unknown material...) are errors, as is a newer format version.
Result<Scene> readSceneJson(std::string_view text, const std::string& path);
Result<Scene> readSceneFile(const std::string& path);

// The document as JSON, for writers and `info --json`-style tools that embed it.
JsonValue sceneToJson(const Scene& scene);

// Writes every setting explicitly and each body's optional values only when set, so write -> read gives an equal
// Scene (doubles included). A Mesh body that names an OBJ object is written as {"obj", "object"}; a Mesh body
// without one (an OBJ import) is written as {"mesh": {"vertices", "triangles"}}, an extension of the §6 contract
// so that nothing is lost. Only the fields that belong to the shape's type are written.
std::string writeSceneJson(const Scene& scene);

// Atomic. Non-finite numbers, which JSON cannot hold, are an Error naming the body instead of a broken file.
Status writeSceneFile(const Scene& scene, const std::string& path);

} // namespace rl
