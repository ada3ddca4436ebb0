// Import of every mesh format assimp reads (glTF/GLB, FBX, PLY, STL, DAE, 3DS, OBJ ...) into the OBJ reader's
// per-object structure, with vertices in the file's world coordinates (Y-up, metres) and duplicates merged.
#pragma once

#include "common/Result.h"
#include "io/ObjReader.h"

#include <string>

namespace rl {

// Reads the file at path with assimp. Bodies are the nodes that hold triangle meshes, in depth-first file order.
//
// What assimp is allowed to do, and what we do ourselves, so that vertices stay as the file wrote them:
// - only aiProcess_Triangulate (and the read-only validation step) runs: no welding, no normal generation,
//   no pre-transforming or re-centring;
// - node transforms are applied here, in double precision, so vertices end in the file's world coordinates;
// - FBX: the scene's declared axes (UpAxis, FrontAxis, CoordAxis with signs) are converted to Y-up, and its
//   UnitScaleFactor (centimetres per file unit) to metres. Blender's FBX exporter writes centimetre transforms
//   (x100) with UnitScaleFactor 1, so a Blender cube of 2 m comes out as 2 m;
// - exact duplicate positions within a body are merged (assimp's OBJ, glTF and STL readers copy a vertex for
//   every face corner or normal), so vertices and vertexMean count each position once, as the OBJ reader counts
//   each `v` once. JoinIdenticalVertices is not used: it compares normals and UVs too, and it would not merge
//   the split corners of a flat-shaded cube;
// - COLLADA: assimp itself turns a Z_UP file to Y-up and applies its <unit>; names are the name attributes;
// - a mirroring transform (negative determinant) reverses the triangles' winding so that they stay outward.
//
// Names: the node name. STL and PLY hold no object names: a single body is named after the file stem, and
// unnamed ones get "<stem>.001", "<stem>.002" ... Material: the name of the body's first mesh's material.
// In the result, fileVertexIndices holds for each vertex the first mesh vertex (counted over the body's meshes)
// that produced it, and firstLine is 0. Every assimp failure or exception becomes an Error naming the file.
Result<ObjFile> importWithAssimp(const std::string& path);

// True when assimp has an importer for the extension ("glb", ".fbx", case-insensitive).
bool assimpReadsExtension(const std::string& extension);

} // namespace rl
