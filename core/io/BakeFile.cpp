#include "io/BakeFile.h"

#include "io/AtomicFile.h"
#include "io/NumberFormat.h"
#include "io/ObjReader.h"
#include "io/OrderedBlocks.h"
#include "scene/BodyDef.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>

namespace rl {

namespace {

constexpr std::string_view kHeaderTag = "# rigidlab-bake";
constexpr std::string_view kColumns8 = "id,x,y,z,qw,qx,qy,qz";
constexpr std::string_view kColumns4 = "id,x,y,z";

// Walks the text line by line, dropping the CR of CRLF, counting 1-based line numbers.
class LineCursor {
public:
    explicit LineCursor(std::string_view text, size_t start = 0, int line = 0)
        : m_text(text), m_pos(start), m_line(line) {}

    bool next(std::string_view& line) {
        if (m_pos >= m_text.size())
            return false;
        m_start = m_pos;
        size_t end = m_text.find('\n', m_pos);
        if (end == std::string_view::npos)
            end = m_text.size();
        line = m_text.substr(m_pos, end - m_pos);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        m_pos = std::min(end + 1, m_text.size());
        ++m_line;
        return true;
    }

    size_t lineStart() const { return m_start; } // offset of the line last returned
    size_t position() const { return m_pos; }    // offset of the next line
    int lineNumber() const { return m_line; }    // number of the line last returned

private:
    std::string_view m_text;
    size_t m_pos;
    size_t m_start = 0;
    int m_line;
};

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && isBlank(s.front()))
        s.remove_prefix(1);
    while (!s.empty() && isBlank(s.back()))
        s.remove_suffix(1);
    return s;
}

// Splits on blanks into at most out.size() tokens; returns how many tokens the line has in total.
size_t splitTokens(std::string_view line, std::array<std::string_view, 8>& out) {
    size_t count = 0;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isBlank(line[i]))
            ++i;
        if (i >= line.size())
            break;
        const size_t start = i;
        while (i < line.size() && !isBlank(line[i]))
            ++i;
        if (count < out.size())
            out[count] = line.substr(start, i - start);
        ++count;
    }
    return count;
}

std::string quoted(std::string_view s) {
    constexpr size_t kMaxShown = 40; // hostile lines can be megabytes long; show enough to recognise the value
    return "'" + std::string(s.substr(0, kMaxShown)) + (s.size() > kMaxShown ? "...'" : "'");
}

struct Header {
    int version = 0;
    double fps = kLegacyBakeFps;
    int64_t frames = -1;
    int64_t bodies = -1;
    int columns = 0;   // values per line including the id
    int64_t start = 0; // the frame at which the simulation started (start=, written when above 0)
};

Result<Header> parseHeader(std::string_view line, const std::string& fileName) {
    auto fail = [&](std::string message) { return Error{fileName, 1, {}, std::move(message)}; };
    Header h;
    std::string_view rest = trim(line.substr(kHeaderTag.size()));
    size_t pos = 0;
    bool first = true;
    while (pos < rest.size()) {
        size_t end = rest.find_first_of(" \t", pos);
        if (end == std::string_view::npos)
            end = rest.size();
        const std::string_view token = rest.substr(pos, end - pos);
        pos = end + 1;
        if (token.empty())
            continue;
        if (first) {
            first = false;
            const std::optional<int64_t> v = parseInt(token);
            if (!v || *v < 1)
                return fail("bad format version " + quoted(token));
            if (*v > kBakeFormatVersion)
                return fail("written by a newer RigidLab: format version " + std::to_string(*v) +
                            ", this build reads up to " + std::to_string(kBakeFormatVersion));
            h.version = static_cast<int>(*v);
            continue;
        }
        const size_t eq = token.find('=');
        const std::string_view key = token.substr(0, eq);
        const std::string_view value = eq == std::string_view::npos ? std::string_view() : token.substr(eq + 1);
        if (key == "fps") {
            const std::optional<double> v = parseDouble(value);
            if (!v || *v <= 0.0)
                return fail("bad fps " + quoted(value) + " in the header");
            h.fps = *v;
        } else if (key == "frames" || key == "bodies") {
            const std::optional<int64_t> v = parseInt(value);
            if (!v || *v < 0 || *v > INT32_MAX)
                return fail("bad " + std::string(key) + " " + quoted(value) + " in the header");
            (key == "frames" ? h.frames : h.bodies) = *v;
        } else if (key == "start") {
            const std::optional<int64_t> v = parseInt(value);
            if (!v || *v < 0 || *v > INT32_MAX)
                return fail("bad start " + quoted(value) + " in the header");
            h.start = *v;
        } else if (key == "columns") {
            if (value == kColumns8)
                h.columns = 8;
            else if (value == kColumns4)
                h.columns = 4;
            else
                return fail("unsupported columns " + quoted(value) + " (expected " + std::string(kColumns8) + ")");
        }
        // Other keys are ignored: later versions may add information that older readers can do without.
    }
    if (first)
        return fail("header without a format version");
    if (h.frames < 0 || h.bodies < 0)
        return fail("header lacks frames= or bodies=");
    if (h.columns == 0)
        h.columns = 8;
    return h;
}

void appendLegacyNumber(std::string& out, float value) {
    // %g without printf: printf follows the C locale, which a Qt application sets from the environment, and a
    // German desktop would then write decimal commas.
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, 6);
    if (ec == std::errc())
        out.append(buffer, end);
    else
        out += '0';
}

} // namespace

void writeBake(const Bake& bake, std::ostream& out, int threads) {
    std::string text = std::string(kHeaderTag) + " " + std::to_string(kBakeFormatVersion) +
                       " fps=" + formatDouble(bake.fps()) + " frames=" + std::to_string(bake.frameCount()) +
                       " bodies=" + std::to_string(bake.bodyCount()) + " columns=" + std::string(kColumns8);
    // Readers ignore keys they do not know, so start= costs older builds nothing; it is left out at 0.
    if (bake.simulationStart() > 0)
        text += " start=" + std::to_string(bake.simulationStart());
    text += '\n';
    out << text;
    const std::string& obj = bake.sceneObjText();
    out << obj;
    if (!obj.empty() && obj.back() != '\n')
        out << '\n';
    out << "!\n";
    // A buffer per block of frames keeps memory flat however long the bake is; the blocks are formatted on
    // `threads` threads and written in order.
    const size_t perBlock = framesPerBlock(bake.bodyCount());
    const size_t blocks = (bake.frameCount() + perBlock - 1) / perBlock;
    writeBlocksInOrder(
        blocks, threads,
        [&](size_t block, std::string& lines) {
            const size_t last = std::min(bake.frameCount(), (block + 1) * perBlock);
            for (size_t f = block * perBlock; f < last; ++f)
                for (size_t b = 0; b < bake.bodyCount(); ++b) {
                    const glm::vec3 mean(bake.vertexMean(f, b));
                    const glm::quat& q = bake.rotation(f, b);
                    lines += std::to_string(b);
                    for (float v : {mean.x, mean.y, mean.z, q.w, q.x, q.y, q.z}) {
                        lines += ' ';
                        appendFloat(lines, v);
                    }
                    lines += '\n';
                }
        },
        [&](const std::string& lines) {
            out.write(lines.data(), static_cast<std::streamsize>(lines.size()));
            return true;
        });
}

Status writeBakeFile(const Bake& bake, const std::string& path, int threads) {
    return writeFileAtomically(path, [&](std::ostream& out) -> Status {
        writeBake(bake, out, threads);
        return Ok{};
    });
}

void writeLegacyBake(const Bake& bake, std::ostream& out, bool includeObjText) {
    const std::string& obj = bake.sceneObjText();
    if (includeObjText && !obj.empty()) {
        out << obj;
        if (obj.back() != '\n')
            out << "\r\n";
        out << "!\r\n";
    }
    std::string text;
    for (size_t b = 0; b < bake.bodyCount(); ++b) {
        text.clear();
        for (size_t f = 0; f < bake.frameCount(); ++f) {
            const glm::vec3 mean(bake.vertexMean(f, b));
            text += std::to_string(b);
            for (float v : {mean.x, mean.y, mean.z}) {
                text += ' ';
                appendLegacyNumber(text, v);
            }
            text += "\r\n";
        }
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
}

Status writeLegacyBakeFile(const Bake& bake, const std::string& path, bool includeObjText) {
    return writeFileAtomically(path, [&](std::ostream& out) -> Status {
        writeLegacyBake(bake, out, includeObjText);
        return Ok{};
    });
}

Result<Bake> readBake(std::string_view text, const std::string& fileName, BakeFileInfo* info) {
    auto fail = [&](int line, std::string message) { return Error{fileName, line, {}, std::move(message)}; };
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
        return fail(0, "empty file: no header and no frames");

    // Header (ours) or none (the original project's).
    Header header;
    LineCursor cursor(text);
    std::string_view line;
    size_t bodyStart = 0; // where the OBJ part (if any) begins
    int bodyStartLine = 0;
    cursor.next(line);
    if (line.substr(0, kHeaderTag.size()) == kHeaderTag) {
        Result<Header> h = parseHeader(line, fileName);
        if (!h)
            return h.error();
        header = *h;
        bodyStart = cursor.position();
        bodyStartLine = 1;
    }

    // The OBJ part ends at a line that is just '!'. Without such a line the file is frames only.
    size_t dataStart = bodyStart;
    int dataStartLine = bodyStartLine;
    std::string_view objText;
    {
        LineCursor scan(text, bodyStart, bodyStartLine);
        while (scan.next(line)) {
            if (trim(line) == "!") {
                objText = text.substr(bodyStart, scan.lineStart() - bodyStart);
                dataStart = scan.position();
                dataStartLine = scan.lineNumber();
                break;
            }
        }
    }

    // Frame lines. The column count comes from the header, or from the first line of a header-less file.
    int columns = header.columns;
    std::vector<uint32_t> ids;
    std::vector<float> values; // (columns - 1) per line
    std::vector<int> lineNumbers;
    {
        // Sized once from the line count: growing by doubling would briefly hold twice the frames of a large bake.
        const size_t lines = static_cast<size_t>(std::count(text.begin() + dataStart, text.end(), '\n')) + 1;
        ids.reserve(lines);
        lineNumbers.reserve(lines);
        values.reserve(lines * static_cast<size_t>(columns > 0 ? columns - 1 : 7));
    }
    int64_t maxId = -1;
    LineCursor data(text, dataStart, dataStartLine);
    while (data.next(line)) {
        const std::string_view t = trim(line);
        if (t.empty() || t.front() == '#')
            continue;
        const int lineNo = data.lineNumber();
        std::array<std::string_view, 8> tokens;
        const size_t count = splitTokens(t, tokens);
        if (columns == 0)
            columns = count >= 8 ? 8 : 4;
        if (count < static_cast<size_t>(columns))
            return fail(lineNo, "short line: expected " + std::to_string(columns) + " values (" +
                                    std::string(columns == 8 ? kColumns8 : kColumns4) + "), found " +
                                    std::to_string(count));
        const std::optional<int64_t> id = parseInt(tokens[0]);
        if (!id || *id < 0 || *id > INT32_MAX || (header.version > 0 && *id >= header.bodies))
            return fail(lineNo,
                        "bad id " + quoted(tokens[0]) +
                            (header.version > 0 ? " (the header says " + std::to_string(header.bodies) + " bodies)"
                                                : std::string()));
        for (int c = 1; c < columns; ++c) {
            const std::optional<float> v = parseFloat(tokens[static_cast<size_t>(c)]);
            if (!v)
                return fail(lineNo, "not a finite number: " + quoted(tokens[static_cast<size_t>(c)]) + " in column " +
                                        std::to_string(c + 1));
            values.push_back(*v);
        }
        ids.push_back(static_cast<uint32_t>(*id));
        lineNumbers.push_back(lineNo);
        maxId = std::max(maxId, *id);
    }
    const int lastLine = data.lineNumber();

    // Bodies and frames. Every id from 0 up must have the same number of lines.
    const size_t records = ids.size();
    // Our writer ends every line, so a missing final line end means the file was cut, maybe inside a number.
    if (header.version > 0 && records > 0 && text.back() != '\n')
        return fail(lastLine, "truncated file: the last line is incomplete");
    if (header.version > 0) {
        // Checked before anything is sized from the header, so a hostile header cannot make us allocate.
        const uint64_t expected = static_cast<uint64_t>(header.frames) * static_cast<uint64_t>(header.bodies);
        // Both at least 1: a bake has frame 0, and a bake without bodies has nothing to replay (and would let a
        // header of two billion empty frames cost minutes).
        if (header.frames == 0 || header.bodies == 0)
            return fail(1, "the header says " + std::to_string(header.frames) + " frames of " +
                               std::to_string(header.bodies) + " bodies; a bake has at least one of each");
        if (expected != records)
            return fail(lastLine, "the header says " + std::to_string(header.frames) + " frames of " +
                                      std::to_string(header.bodies) + " bodies (" + std::to_string(expected) +
                                      " lines), found " + std::to_string(records) +
                                      (records < expected ? " lines (truncated file?)" : " lines"));
    }
    if (records == 0 && header.version == 0)
        return fail(lastLine, "no frames: the file has no id x y z lines");
    if (maxId >= 0 && static_cast<size_t>(maxId) >= records) {
        const size_t at =
            static_cast<size_t>(std::find(ids.begin(), ids.end(), static_cast<uint32_t>(maxId)) - ids.begin());
        return fail(lineNumbers[at], "bad id " + std::to_string(maxId) + ": ids must run from 0 without gaps");
    }
    const size_t bodyCount = header.version > 0 ? static_cast<size_t>(header.bodies) : static_cast<size_t>(maxId + 1);
    std::vector<uint32_t> counts(bodyCount, 0);
    std::vector<int> lastLineOf(bodyCount, 0);
    for (size_t i = 0; i < records; ++i) {
        ++counts[ids[i]];
        lastLineOf[ids[i]] = lineNumbers[i];
    }
    const size_t frameCount = header.version > 0 ? static_cast<size_t>(header.frames) : (bodyCount ? counts[0] : 0);
    for (size_t b = 0; b < bodyCount; ++b) {
        if (counts[b] == 0 && frameCount > 0)
            return fail(lastLine,
                        "body " + std::to_string(b) + " has no lines" +
                            (header.version > 0 ? " (truncated file?)" : " (ids must run from 0 without gaps)"));
        if (counts[b] != frameCount)
            return fail(header.version > 0 ? lastLine : lastLineOf[b],
                        "inconsistent frame counts: body " + std::to_string(b) + " has " + std::to_string(counts[b]) +
                            " frames, " +
                            (header.version > 0 ? "the header says " + std::to_string(frameCount)
                                                : "body 0 has " + std::to_string(frameCount)) +
                            (counts[b] < frameCount ? " (truncated file?)" : ""));
    }

    std::vector<BakeBodyInfo> infos(bodyCount);
    // Names and anchors as the importer sees the OBJ part. The frames stand on their own, so an OBJ part that does
    // not parse, or has another number of objects, only costs the names.
    if (!objText.empty()) {
        const Result<ObjFile> obj = readObj(objText, fileName);
        if (obj && obj->objects.size() == bodyCount)
            for (size_t b = 0; b < bodyCount; ++b) {
                infos[b].name = obj->objects[b].name;
                infos[b].anchor = isAnchorName(infos[b].name);
            }
    }
    Bake bake(std::move(infos), header.fps);
    if (header.start > 0 && header.start < header.frames)
        bake.setSimulationStart(static_cast<size_t>(header.start));
    bake.setSceneObjText(std::string(objText));
    bake.setHasVelocities(false);
    bake.reserveFrames(frameCount);
    for (size_t f = 0; f < frameCount; ++f)
        bake.addFrame();

    bool objectMajor = true, frameMajor = true;
    std::fill(counts.begin(), counts.end(), 0u);
    const size_t stride = static_cast<size_t>(columns - 1);
    size_t previousFrame = 0;
    for (size_t i = 0; i < records; ++i) {
        const uint32_t b = ids[i];
        const size_t f = counts[b]++;
        if (i > 0) {
            objectMajor = objectMajor && b >= ids[i - 1];
            frameMajor = frameMajor && f >= previousFrame;
        }
        previousFrame = f;
        const float* v = &values[i * stride];
        BakeBodyState s;
        s.position = glm::vec3(v[0], v[1], v[2]);
        if (columns == 8)
            s.rotation = glm::quat(v[3], v[4], v[5], v[6]);
        bake.setState(f, b, s);
    }
    if (info) {
        info->version = header.version;
        info->columns = columns - 1;
        info->order = frameMajor    ? BakeLineOrder::FrameMajor
                      : objectMajor ? BakeLineOrder::ObjectMajor
                                    : BakeLineOrder::Other;
    }
    return bake;
}

Result<Bake> readBakeFile(const std::string& path, BakeFileInfo* info) {
    Result<std::string> text = readFileBytes(path);
    if (!text)
        return text.error();
    return readBake(*text, path, info);
}

} // namespace rl
