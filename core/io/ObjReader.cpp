#include "io/ObjReader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <system_error>

namespace rl {

namespace {

// Files larger than this are refused before reading: no scene this program can simulate comes near it, and it
// keeps a wrong path (a disk image, a video) from exhausting memory.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 30;

// How much of the file the text/binary sniffing looks at, and how many suspicious bytes it tolerates there:
// a text OBJ has none, but a stray DOS end-of-file mark or a few Latin-1 names must not make it "binary".
constexpr size_t kSniffBytes = 1 << 16;
constexpr size_t kSuspiciousPerThousand = 50;

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && isBlank(s.front()))
        s.remove_prefix(1);
    while (!s.empty() && isBlank(s.back()))
        s.remove_suffix(1);
    return s;
}

// Splits off the next whitespace-separated token; returns an empty view at the end of the line.
std::string_view nextToken(std::string_view& rest) {
    while (!rest.empty() && isBlank(rest.front()))
        rest.remove_prefix(1);
    size_t n = 0;
    while (n < rest.size() && !isBlank(rest[n]))
        ++n;
    std::string_view token = rest.substr(0, n);
    rest.remove_prefix(n);
    return token;
}

// Length of a valid UTF-8 sequence starting at p (1..4), or 0 when the bytes there are not valid UTF-8.
size_t utf8SequenceLength(const unsigned char* p, size_t available) {
    unsigned char c = p[0];
    size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || n > available)
        return 0;
    for (size_t i = 1; i < n; ++i)
        if ((p[i] & 0xC0) != 0x80)
            return 0;
    return n;
}

// A binary file (a renamed .stl, a .glb, random bytes) must be refused with that reason instead of a confusing
// parse error deep inside it. NUL never occurs in text; otherwise a text file has almost no control bytes and
// almost no invalid UTF-8.
std::optional<std::string> binaryReason(std::string_view text) {
    if (const void* nul = std::memchr(text.data(), '\0', text.size()))
        return "binary file (NUL byte at offset " + std::to_string(static_cast<const char*>(nul) - text.data()) +
               "); an OBJ file is text";
    const size_t n = std::min(text.size(), kSniffBytes);
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    size_t suspicious = 0;
    for (size_t i = 0; i < n;) {
        unsigned char c = bytes[i];
        if ((c < 0x20 && !isBlank(static_cast<char>(c)) && c != '\n') || c == 0x7F) {
            ++suspicious;
            ++i;
            continue;
        }
        size_t len = utf8SequenceLength(bytes + i, n - i);
        if (len == 0) {
            ++suspicious;
            len = 1;
        }
        i += len;
    }
    if (suspicious * 1000 > n * kSuspiciousPerThousand)
        return "binary file (" + std::to_string(suspicious) + " of the first " + std::to_string(n) +
               " bytes are not text); an OBJ file is text";
    return std::nullopt;
}

// Shortens a token for an error message so that a hostile 60 kB token does not become a 60 kB message.
std::string quoted(std::string_view token) {
    constexpr size_t kShown = 32;
    std::string out = "'";
    out += token.substr(0, kShown);
    if (token.size() > kShown)
        out += "...";
    out += "'";
    return out;
}

enum class NumberStatus { Ok, Garbled, NotFinite };

NumberStatus parseReal(std::string_view token, Real& out) {
    // from_chars does not take a leading '+', which some exporters write.
    if (token.size() > 1 && token.front() == '+' && token[1] != '-' && token[1] != '+')
        token.remove_prefix(1);
    if (token.empty())
        return NumberStatus::Garbled;
    const char* end = token.data() + token.size();
    auto [ptr, ec] = std::from_chars(token.data(), end, out, std::chars_format::general);
    if (ec == std::errc::result_out_of_range)
        return NumberStatus::NotFinite; // 1e999: written as a number, but no finite double holds it
    if (ec != std::errc() || ptr != end)
        return NumberStatus::Garbled;
    return std::isfinite(out) ? NumberStatus::Ok : NumberStatus::NotFinite;
}

bool isInteger(std::string_view s) {
    if (!s.empty() && (s.front() == '-' || s.front() == '+'))
        s.remove_prefix(1);
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

struct FaceRecord {
    int line = 0;
    uint32_t objectKey = 0; // `o` block (1-based, 0 = before the first `o`)
    uint32_t groupKey = 0;  // `g` name (1-based, 0 = before the first `g`)
    uint32_t materialKey = 0;
    size_t first = 0; // range in Parser::m_corners
    size_t count = 0;
};

class Parser {
public:
    Parser(std::string_view text, const std::string& fileName)
        : m_text(text), m_fileName(fileName), m_stem(fileStem(fileName)) {
        m_materials.emplace_back(); // key 0: no usemtl yet
    }

    Result<ObjFile> run() {
        if (m_text.find_first_not_of(" \t\r\n\v\f") == std::string_view::npos)
            return fail(0, "file is empty");
        if (auto reason = binaryReason(m_text))
            return fail(0, *reason);

        size_t pos = 0;
        int lineNumber = 0;
        std::string joined; // only used when a line continues with a backslash
        while (pos < m_text.size()) {
            const int startLine = lineNumber + 1;
            joined.clear();
            bool continued = false;
            std::string_view logical;
            for (;;) {
                size_t nl = m_text.find('\n', pos);
                size_t end = nl == std::string_view::npos ? m_text.size() : nl;
                std::string_view physical = m_text.substr(pos, end - pos);
                pos = nl == std::string_view::npos ? m_text.size() : nl + 1;
                ++lineNumber;
                if (!physical.empty() && physical.back() == '\r')
                    physical.remove_suffix(1);
                if (physical.size() + joined.size() > kObjMaxLineLength)
                    return fail(startLine, "line is longer than " + std::to_string(kObjMaxLineLength) + " bytes");
                const bool more = !physical.empty() && physical.back() == '\\' && pos < m_text.size();
                if (!more && !continued) {
                    logical = physical;
                    break;
                }
                continued = true;
                if (more) {
                    physical.remove_suffix(1);
                    joined.append(physical);
                    joined.push_back(' ');
                    continue;
                }
                joined.append(physical);
                logical = joined;
                break;
            }
            if (auto error = statement(logical, startLine))
                return std::move(*error);
        }
        return finish();
    }

private:
    Error fail(int line, std::string message) const { return Error{m_fileName, line, {}, std::move(message)}; }

    std::optional<Error> statement(std::string_view line, int lineNumber) {
        std::string_view rest = line;
        std::string_view keyword = nextToken(rest);
        if (keyword.empty() || keyword.front() == '#')
            return std::nullopt;
        if (keyword == "v")
            return vertex(rest, lineNumber);
        if (keyword == "f")
            return face(rest, lineNumber);
        if (keyword == "o") {
            m_objectNames.push_back(nameOrStem(rest));
            m_objectLines.push_back(lineNumber);
            m_objectKey = static_cast<uint32_t>(m_objectNames.size());
            return std::nullopt;
        }
        if (keyword == "g") {
            // Groups with the same name are one group, as in the OBJ specification.
            std::string name = nameOrStem(rest);
            auto it = std::find(m_groupNames.begin(), m_groupNames.end(), name);
            if (it == m_groupNames.end()) {
                m_groupNames.push_back(std::move(name));
                m_groupLines.push_back(lineNumber);
                it = m_groupNames.end() - 1;
            }
            m_groupKey = static_cast<uint32_t>(it - m_groupNames.begin()) + 1;
            return std::nullopt;
        }
        if (keyword == "usemtl") {
            std::string name(trim(rest));
            auto it = std::find(m_materials.begin(), m_materials.end(), name);
            if (it == m_materials.end()) {
                m_materials.push_back(std::move(name));
                it = m_materials.end() - 1;
            }
            m_materialKey = static_cast<uint32_t>(it - m_materials.begin());
            return std::nullopt;
        }
        // vt, vn, vp, mtllib, s, l, p, curves and anything unknown do not change the bodies: skipped.
        return std::nullopt;
    }

    std::string nameOrStem(std::string_view rest) const {
        std::string_view name = trim(rest);
        return name.empty() ? m_stem : std::string(name);
    }

    std::optional<Error> vertex(std::string_view rest, int lineNumber) {
        Real xyz[3] = {0.0, 0.0, 0.0};
        int count = 0;
        for (std::string_view token = nextToken(rest); !token.empty() && token.front() != '#';
             token = nextToken(rest)) {
            Real value = 0.0;
            NumberStatus status = parseReal(token, value);
            if (status == NumberStatus::Garbled)
                return fail(lineNumber, "bad number " + quoted(token) + " in vertex");
            // Only x, y and z are used: a w weight or vertex colours after them are read and dropped.
            if (count < 3) {
                if (status == NumberStatus::NotFinite)
                    return fail(lineNumber, "vertex coordinate " + quoted(token) + " is not a finite number");
                xyz[count] = value;
            }
            ++count;
        }
        if (count < 3)
            return fail(lineNumber, "vertex has " + std::to_string(count) + " coordinate" + (count == 1 ? "" : "s") +
                                        "; it needs x, y and z");
        m_vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
        return std::nullopt;
    }

    std::optional<Error> face(std::string_view rest, int lineNumber) {
        FaceRecord record;
        record.line = lineNumber;
        record.objectKey = m_objectKey;
        record.groupKey = m_groupKey;
        record.materialKey = m_materialKey;
        record.first = m_corners.size();
        for (std::string_view token = nextToken(rest); !token.empty() && token.front() != '#';
             token = nextToken(rest)) {
            // v, v/vt, v//vn or v/vt/vn: texture and normal indices are checked for shape only, then dropped.
            std::string_view parts[3];
            int partCount = 0;
            size_t start = 0;
            for (;;) {
                size_t slash = token.find('/', start);
                if (partCount == 3)
                    return fail(lineNumber, "bad face vertex " + quoted(token));
                parts[partCount++] = token.substr(start, slash == std::string_view::npos ? slash : slash - start);
                if (slash == std::string_view::npos)
                    break;
                start = slash + 1;
            }
            if (!isInteger(parts[0]) || (partCount > 1 && !parts[1].empty() && !isInteger(parts[1])) ||
                (partCount > 2 && !isInteger(parts[2])))
                return fail(lineNumber, "bad face vertex " + quoted(token));
            int64_t index = 0;
            std::string_view digits = parts[0].front() == '+' ? parts[0].substr(1) : parts[0];
            auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
            const int64_t defined = static_cast<int64_t>(m_vertices.size());
            auto range = [defined] {
                return defined == 0 ? std::string("(no vertex defined yet)") : "(1.." + std::to_string(defined) + ")";
            };
            if (ec != std::errc() || ptr != digits.data() + digits.size())
                return fail(lineNumber, "face index " + quoted(parts[0]) + " out of range " + range());
            if (index == 0)
                return fail(lineNumber, "face index 0 is invalid: OBJ indices start at 1");
            // Negative indices count back from the last vertex defined so far.
            const int64_t resolved = index > 0 ? index - 1 : defined + index;
            if (resolved < 0 || resolved >= defined)
                return fail(lineNumber, "face index " + std::to_string(index) + " out of range " + range());
            m_corners.push_back(static_cast<uint32_t>(resolved));
        }
        record.count = m_corners.size() - record.first;
        if (record.count < 3)
            return fail(lineNumber, "face has " + std::to_string(record.count) + " vert" +
                                        (record.count == 1 ? "ex" : "ices") + "; it needs at least 3");
        m_faces.push_back(record);
        return std::nullopt;
    }

    Result<ObjFile> finish() {
        // Bodies are the `o` blocks; without any `o`, the `g` groups; without either, the whole file.
        const bool byObject = !m_objectNames.empty();
        const bool byGroup = !byObject && !m_groupNames.empty();
        const size_t keyCount = 1 + (byObject ? m_objectNames.size() : byGroup ? m_groupNames.size() : 0);
        std::vector<std::vector<uint32_t>> facesOf(keyCount);
        for (size_t i = 0; i < m_faces.size(); ++i) {
            const FaceRecord& f = m_faces[i];
            facesOf[byObject ? f.objectKey : byGroup ? f.groupKey : 0].push_back(static_cast<uint32_t>(i));
        }

        ObjFile file;
        file.vertexCount = m_vertices.size();
        constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
        std::vector<uint32_t> localOf(m_vertices.size(), kUnused);
        for (size_t key = 0; key < keyCount; ++key) {
            if (facesOf[key].empty())
                continue;
            ObjObject object;
            if (key == 0) {
                object.name = m_stem;
            } else {
                object.name = byObject ? m_objectNames[key - 1] : m_groupNames[key - 1];
                object.firstLine = byObject ? m_objectLines[key - 1] : m_groupLines[key - 1];
            }
            object.material = m_materials[m_faces[facesOf[key].front()].materialKey];
            auto local = [&](uint32_t global) {
                if (localOf[global] == kUnused) {
                    localOf[global] = static_cast<uint32_t>(object.vertices.size());
                    object.vertices.push_back(m_vertices[global]);
                    object.fileVertexIndices.push_back(global);
                }
                return localOf[global];
            };
            for (uint32_t faceIndex : facesOf[key]) {
                const FaceRecord& f = m_faces[faceIndex];
                const uint32_t* c = m_corners.data() + f.first;
                // Fan from the first corner; convex N-gons (what exporters write) triangulate correctly this way.
                const uint32_t a = local(c[0]);
                uint32_t b = local(c[1]);
                for (size_t i = 2; i < f.count; ++i) {
                    const uint32_t d = local(c[i]);
                    object.triangles.push_back({a, b, d});
                    b = d;
                }
            }
            Vec3 sum(0.0);
            for (const Vec3& v : object.vertices)
                sum += v;
            object.vertexMean = sum / static_cast<Real>(object.vertices.size());
            for (uint32_t global : object.fileVertexIndices)
                localOf[global] = kUnused;
            file.objects.push_back(std::move(object));
        }
        if (file.objects.empty())
            return fail(0, "no faces: the file has no object to import");
        return file;
    }

    std::string_view m_text;
    const std::string& m_fileName;
    std::string m_stem;

    std::vector<Vec3> m_vertices;
    std::vector<uint32_t> m_corners;
    std::vector<FaceRecord> m_faces;
    std::vector<std::string> m_objectNames;
    std::vector<int> m_objectLines;
    std::vector<std::string> m_groupNames;
    std::vector<int> m_groupLines;
    std::vector<std::string> m_materials;
    uint32_t m_objectKey = 0;
    uint32_t m_groupKey = 0;
    uint32_t m_materialKey = 0;
};

} // namespace

std::string fileStem(std::string_view path) {
    size_t slash = path.find_last_of("/\\");
    std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
    size_t dot = name.rfind('.');
    if (dot != std::string_view::npos && dot > 0)
        name = name.substr(0, dot);
    return std::string(name);
}

Result<std::string> readFileBytes(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        return Error{path, 0, {}, "file not found"};
    if (fs::is_directory(status))
        return Error{path, 0, {}, "is a directory, not a file"};
    // A device or a pipe (/dev/zero, a FIFO) could be read forever; scenes are regular files.
    if (!fs::is_regular_file(status))
        return Error{path, 0, {}, "is not a regular file"};
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > kMaxFileBytes)
        return Error{path, 0, {}, "file is larger than " + std::to_string(kMaxFileBytes >> 20) + " MiB"};
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Error{path, 0, {}, "cannot open the file for reading"};
    std::string bytes;
    if (!ec)
        bytes.reserve(static_cast<size_t>(size));
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad())
        return Error{path, 0, {}, "read error"};
    return bytes;
}

Result<ObjFile> readObj(std::string_view text, const std::string& fileNameForErrors) {
    return Parser(text, fileNameForErrors).run();
}

Result<ObjFile> readObjFile(const std::string& path, std::string* text) {
    Result<std::string> bytes = readFileBytes(path);
    if (!bytes)
        return bytes.error();
    Result<ObjFile> file = readObj(*bytes, path);
    if (file && text)
        *text = std::move(*bytes);
    return file;
}

} // namespace rl
