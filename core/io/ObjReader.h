// Our own Wavefront OBJ reader: objects, vertices exactly as written, fan-triangulated faces, usemtl names.
// It reports bad input as an Error with file and line, never throws, and is fuzzed (tests/fuzz/fuzz_obj.cpp).
#pragma once

#include "common/Result.h"
#include "math/Types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rl {

// One body of an OBJ file: an `o` block, or a `g` group when the file has no `o` lines, or the whole file.
struct ObjObject {
    std::string name;
    std::string material;                           // `usemtl` name active at the object's first face, or empty
    std::vector<Vec3> vertices;                     // distinct vertices the faces use, in first-use order
    std::vector<uint32_t> fileVertexIndices;        // for each local vertex, its 0-based index among the file's `v`
    std::vector<std::array<uint32_t, 3>> triangles; // local indices; N-gons fan-triangulated from their first corner
    Vec3 vertexMean{0.0}; // plain average of `vertices`: the object's position in .bake files (DESIGN.md §4)
    int firstLine = 0;    // 1-based line of the statement that started the object (0 for the implicit one)
};

struct ObjFile {
    std::vector<ObjObject> objects; // in file order; objects without faces are left out
    size_t vertexCount = 0;         // `v` statements in the whole file
};

// Limits that keep hostile input bounded. A logical line (after joining backslash continuations) longer than
// kObjMaxLineLength is an error: real exporters write lines of a few hundred bytes at most, even for large N-gons.
inline constexpr size_t kObjMaxLineLength = 1 << 16;

// Parses OBJ text. fileNameForErrors is what error messages call the file, e.g. "scene.obj:42: ...". The
// implicit object (faces before any `o`/`g`) is named after the stem of fileNameForErrors.
Result<ObjFile> readObj(std::string_view text, const std::string& fileNameForErrors);

// Reads the file at path and parses it. A missing or unreadable file is an Error naming the path.
// When text is not null it receives the file's bytes verbatim (kept for .bake files).
Result<ObjFile> readObjFile(const std::string& path, std::string* text = nullptr);

// Reads a whole file into memory; shared by the importers. An Error names the path when it cannot be read.
Result<std::string> readFileBytes(const std::string& path);

// The stem of a path: "dir/scene.obj" -> "scene". Used for bodies that have no name of their own.
std::string fileStem(std::string_view path);

} // namespace rl
