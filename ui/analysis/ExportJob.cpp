#include "analysis/ExportJob.h"

#include "bake/Bake.h"
#include "io/AtomicFile.h"
#include "io/BakeFile.h"
#include "io/CsvWriter.h"

#include <algorithm>
#include <ostream>
#include <streambuf>
#include <thread>

namespace rl {

namespace {

// writeBake() has no progress hook, but it hands over a block of some 8,192 lines at a time: this buffer passes the
// bytes on, counts the lines that went through, and throws to stop the writer when the user cancels.
class ProgressBuffer : public std::streambuf {
public:
    struct Cancelled {};

    ProgressBuffer(std::ostream& target, size_t totalLines, const std::function<bool(size_t, size_t)>& progress)
        : m_target(target), m_total(totalLines), m_progress(progress) {}

protected:
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        m_target.write(s, n);
        m_lines += static_cast<size_t>(std::count(s, s + n, '\n'));
        if (m_progress && !m_progress(std::min(m_lines, m_total), m_total))
            throw Cancelled{};
        return n;
    }
    int_type overflow(int_type c) override {
        if (traits_type::eq_int_type(c, traits_type::eof()))
            return traits_type::not_eof(c);
        const char ch = traits_type::to_char_type(c);
        xsputn(&ch, 1);
        return c;
    }

private:
    std::ostream& m_target;
    size_t m_lines = 0;
    size_t m_total;
    const std::function<bool(size_t, size_t)>& m_progress;
};

// An export runs while the interface only shows its progress, so every core formats numbers (the file is the same
// for any count).
int exportThreads() {
    return std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 8);
}

} // namespace

Status runExport(const Bake& bake, const ExportRequest& request, const std::function<bool(size_t, size_t)>& progress) {
    const std::string path = request.path.toStdString();
    if (request.format == ExportRequest::Format::Csv) {
        CsvOptions options;
        options.bodies = request.bodies;
        options.firstFrame = request.firstFrame;
        options.lastFrame = request.lastFrame;
        options.progress = progress;
        options.threads = exportThreads();
        return writeCsvFile(bake, path, options);
    }
    if (bake.bodyCount() == 0 || bake.frameCount() == 0)
        return Error{path, 0, {}, "the bake is empty: nothing to export"};
    // Header, the OBJ part, '!', then one line per body per frame.
    const std::string& obj = bake.sceneObjText();
    const size_t objLines =
        static_cast<size_t>(std::count(obj.begin(), obj.end(), '\n')) + (!obj.empty() && obj.back() != '\n' ? 1 : 0);
    const size_t total = 2 + objLines + bake.frameCount() * bake.bodyCount();
    return writeFileAtomically(path, [&](std::ostream& out) -> Status {
        ProgressBuffer buffer(out, total, progress);
        std::ostream counted(&buffer);
        // The stream turns an exception from its buffer into badbit; with badbit in exceptions() it rethrows ours.
        counted.exceptions(std::ios::badbit);
        try {
            writeBake(bake, counted, exportThreads());
        } catch (const ProgressBuffer::Cancelled&) {
            return Error{path, 0, {}, "export cancelled"};
        }
        return Ok{};
    });
}

} // namespace rl
