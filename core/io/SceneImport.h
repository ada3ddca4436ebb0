// Turning model files into scenes (DESIGN.md §3) and scenes back into OBJ text for .bake files (DESIGN.md §4).
// .obj goes through our own OBJ reader, every other mesh format through assimp.
#pragma once

#include "common/Result.h"
#include "io/ObjReader.h"
#include "scene/Scene.h"

#include <string>

namespace rl {

// One Mesh body per object, in order: vertices in file coordinates, position 0, identity orientation, anchor by
// the anchor rule, material = the preset whose name matches the object's material case-insensitively (in the
// preset's own spelling), else "Default". Only the bodies are filled in; the caller sets the source fields.
Scene sceneFromObjects(const ObjFile& file);

// Reads a scene file, choosing the reader by extension (case-insensitive): .rlscene -> readSceneFile
// (io/SceneJson.h), .obj -> readObjFile (and the text is kept verbatim in Scene::sourceObjText), any extension
// assimp reads -> importWithAssimp. Scene::sourcePath is the path given.
Result<Scene> importScene(const std::string& path);

// Icosphere subdivision used when a sphere is written as a mesh: 2 gives 162 vertices and 320 triangles that
// enclose 96.6% of the sphere's volume (tst_sceneimport measures it), enough for previews and the original tools.
inline constexpr int kSphereObjSubdivisions = 2;

// Writes the scene as OBJ text: per body `o <name>`, `usemtl <material>`, its vertices placed in the world by
// position and orientation, and its triangles. Boxes become 8 vertices and 12 triangles, spheres an icosphere,
// hulls the convex hull of their points, meshes their vertices and triangles (a mesh that only names an OBJ
// object is read from that file, relative to the scene's sourcePath). Numbers are written shortest round-trip.
// Errors name the body: a hull with fewer than 3 non-collinear points, a mesh without vertices or with a
// triangle index out of range, non-finite numbers. For a scene read from one OBJ file, .bake writers use
// Scene::sourceObjText instead (DESIGN.md §4); this is for every other scene.
Result<std::string> sceneToObjText(const Scene& scene);

} // namespace rl
