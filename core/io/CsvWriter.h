// CSV export of a bake (DESIGN.md §5): one row per body per frame, frame-major, centre of mass, rotation since
// frame 0 and velocities in world space, names quoted per RFC 4180.
#pragma once

#include "bake/Bake.h"
#include "common/Result.h"

#include <cstddef>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rl {

inline constexpr std::string_view kCsvHeader = "frame,time,body,name,anchor,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";

struct CsvOptions {
    std::vector<size_t> bodies; // rows for these body indices, in this order; empty means every body
    size_t firstFrame = 0;      // inclusive range of frames; lastFrame is clamped to the last frame of the bake
    size_t lastFrame = std::numeric_limits<size_t>::max();
    // Called after each frame's rows with (frames written, frames in the range); returning false cancels the export
    // with an Error, and writeCsvFile then leaves the target as it was.
    std::function<bool(size_t, size_t)> progress;
    // Threads that format the rows (the bytes are the same for any count); progress is called on the caller's thread.
    int threads = 1;
};

// A field as RFC 4180 wants it: unchanged, or in double quotes with inner quotes doubled when it contains a comma,
// a quote, CR or LF.
std::string csvField(std::string_view text);

// Rows end with LF. Numbers are shortest round-trip (floats as stored, time as a double). A bake read from a .bake
// file has no velocities: those six fields are left empty rather than filled with made-up zeros. A body index out
// of range or an empty frame range is an Error, and then nothing is written.
Status writeCsv(const Bake& bake, std::ostream& out, const CsvOptions& options = {});
// Atomic: on any error the target is left as it was.
Status writeCsvFile(const Bake& bake, const std::string& path, const CsvOptions& options = {});

} // namespace rl
