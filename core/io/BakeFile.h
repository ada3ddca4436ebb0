// Reading and writing .bake files (DESIGN.md §4): ours (header, OBJ text, '!', frame-major id x y z qw qx qy qz)
// and the original project's (no header, object-major id x y z, %g numbers, CRLF, 200 steps per second).
#pragma once

#include "bake/Bake.h"
#include "common/Result.h"

#include <ostream>
#include <string>
#include <string_view>

namespace rl {

inline constexpr int kBakeFormatVersion = 2;
// The original project recorded one line per body per simulation step at 200 steps per second; its files have no
// header to say so.
inline constexpr double kLegacyBakeFps = 200.0;

// Streams the bake in our format; numbers are shortest round-trip floats. Positions are vertex means. The reader
// wants at least one body and one frame, so a Baker refuses an empty scene rather than writing such a file. The
// numbers are formatted on `threads` threads (writeBlocksInOrder()); the bytes are the same for any count.
void writeBake(const Bake& bake, std::ostream& out, int threads = 1);
// Atomic: a failed write leaves an existing file untouched.
Status writeBakeFile(const Bake& bake, const std::string& path, int threads = 1);

// The original project's flavour: optionally the OBJ part and '!', then object-major `id x y z` with %g numbers
// and CRLF line ends. Rotations are lost, as they were in the original.
void writeLegacyBake(const Bake& bake, std::ostream& out, bool includeObjText = true);
Status writeLegacyBakeFile(const Bake& bake, const std::string& path, bool includeObjText = true);

enum class BakeLineOrder { FrameMajor, ObjectMajor, Other };

struct BakeFileInfo {
    int version = 0; // 0 for the original project's header-less files
    int columns = 0; // numeric columns read per line after the id: 3 or 7
    BakeLineOrder order = BakeLineOrder::FrameMajor;
};

// Reads either flavour. A line's frame is how many earlier lines had the same id, so frame-major, object-major
// and any other per-body-chronological order all load; `info` says which order was found. Lines starting with
// '#' and blank lines are skipped, CR before LF is dropped, columns beyond those used are ignored. Positions are
// the vertex means; body offsets are 0 and velocities unknown. Names and anchors come from the OBJ part when it parses
// and has one object per body. Errors name the file and the line: bad id, short line, non-numeric value, inconsistent
// frame counts, a truncated or empty file, a newer version.
Result<Bake> readBake(std::string_view text, const std::string& fileName, BakeFileInfo* info = nullptr);
Result<Bake> readBakeFile(const std::string& path, BakeFileInfo* info = nullptr);

} // namespace rl
