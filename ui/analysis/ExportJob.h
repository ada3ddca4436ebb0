// What File > Export writes and the code that writes it, apart from any widget: the same core writers as
// `rigidlab-cli bake` and `export` (io/BakeFile, io/CsvWriter), with progress and cancellation, always through an
// atomic file so that a failed or cancelled export leaves the target as it was.
#pragma once

#include "common/Result.h"

#include <QString>

#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace rl {

class Bake;

struct ExportRequest {
    enum class Format { Bake, Csv };
    Format format = Format::Csv;
    QString path;
    // CSV only (a .bake always holds every body and frame, as the original project's reader expects).
    std::vector<size_t> bodies; // empty: every body
    size_t firstFrame = 0;
    size_t lastFrame = std::numeric_limits<size_t>::max(); // clamped to the bake's last frame
};

// Writes the export on the calling thread. `progress` gets (done, total) now and then (total is the number of
// frames for CSV and of lines for .bake) and returns false to cancel; a cancelled export is an Error whose message
// is "export cancelled", and the target file is then untouched.
Status runExport(const Bake& bake, const ExportRequest& request,
                 const std::function<bool(size_t, size_t)>& progress = {});

} // namespace rl
