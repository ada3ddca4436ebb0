#include "io/CsvWriter.h"

#include "io/AtomicFile.h"
#include "io/NumberFormat.h"
#include "io/OrderedBlocks.h"

#include <algorithm>

namespace rl {

namespace {

Status validate(const Bake& bake, const CsvOptions& options) {
    for (size_t b : options.bodies)
        if (b >= bake.bodyCount())
            return Error{
                {}, 0, {}, "no body " + std::to_string(b) + " (the bake has " + std::to_string(bake.bodyCount()) + ")"};
    if (bake.frameCount() == 0 || options.firstFrame >= bake.frameCount() || options.firstFrame > options.lastFrame)
        return Error{{},
                     0,
                     {},
                     "empty frame range: frames " + std::to_string(options.firstFrame) + " to " +
                         (options.lastFrame == std::numeric_limits<size_t>::max() ? std::string("the end")
                                                                                  : std::to_string(options.lastFrame)) +
                         " of a bake with " + std::to_string(bake.frameCount()) + " frames"};
    return Ok{};
}

void appendVec(std::string& row, const glm::vec3& v) {
    for (int i = 0; i < 3; ++i) {
        row += ',';
        appendFloat(row, v[i]);
    }
}

} // namespace

std::string csvField(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos)
        return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"')
            out += '"';
        out += c;
    }
    out += '"';
    return out;
}

Status writeCsv(const Bake& bake, std::ostream& out, const CsvOptions& options) {
    if (Status s = validate(bake, options); !s)
        return s;
    std::vector<size_t> bodies = options.bodies;
    if (bodies.empty()) {
        bodies.resize(bake.bodyCount());
        for (size_t b = 0; b < bodies.size(); ++b)
            bodies[b] = b;
    }
    // Quoting is per body, not per row.
    std::vector<std::string> names(bake.bodyCount());
    for (size_t b : bodies)
        names[b] = csvField(bake.body(b).name);

    out << kCsvHeader << '\n';
    const size_t first = options.firstFrame;
    const size_t last = std::min(options.lastFrame, bake.frameCount() - 1);
    const size_t frames = last - first + 1;
    // Blocks of frames formatted on options.threads threads, written in order: the same bytes for any count.
    const size_t perBlock = framesPerBlock(bodies.size());
    const size_t blocks = (frames + perBlock - 1) / perBlock;
    size_t done = 0; // frames written
    const bool completed = writeBlocksInOrder(
        blocks, options.threads,
        [&](size_t block, std::string& rows) {
            const size_t end = first + std::min(frames, (block + 1) * perBlock);
            for (size_t f = first + block * perBlock; f < end; ++f) {
                const std::string frame = std::to_string(f) + ',' + formatDouble(bake.frameTime(f)) + ',';
                for (size_t b : bodies) {
                    rows += frame;
                    rows += std::to_string(b);
                    rows += ',';
                    rows += names[b];
                    rows += bake.body(b).anchor ? ",1" : ",0";
                    appendVec(rows, bake.position(f, b));
                    const glm::quat& q = bake.rotation(f, b);
                    for (float v : {q.w, q.x, q.y, q.z}) {
                        rows += ',';
                        appendFloat(rows, v);
                    }
                    if (bake.hasVelocities()) {
                        appendVec(rows, bake.linearVelocity(f, b));
                        appendVec(rows, bake.angularVelocity(f, b));
                    } else {
                        rows += ",,,,,,";
                    }
                    rows += '\n';
                }
            }
        },
        [&](const std::string& rows) {
            out.write(rows.data(), static_cast<std::streamsize>(rows.size()));
            // Progress as before the rows were formatted in blocks: after each frame's rows.
            const size_t end = std::min(frames, done + perBlock);
            if (!options.progress) {
                done = end;
                return true;
            }
            while (done < end)
                if (!options.progress(++done, frames))
                    return false;
            return true;
        });
    if (!completed)
        return Error{{}, 0, {}, "export cancelled"};
    return Ok{};
}

Status writeCsvFile(const Bake& bake, const std::string& path, const CsvOptions& options) {
    // Validate before the temporary file exists, so a bad request touches nothing on disk.
    if (Status s = validate(bake, options); !s) {
        Error e = s.error();
        e.file = path;
        return e;
    }
    return writeFileAtomically(path, [&](std::ostream& out) { return writeCsv(bake, out, options); });
}

} // namespace rl
