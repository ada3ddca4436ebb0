// Whole-file writes that either fully replace the target or leave it untouched (temporary file, fsync, rename).
// Every exporter writes through here, so a failed or cancelled export never leaves half a file behind.
#pragma once

#include "common/Result.h"

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace rl {

// Streams into a temporary file next to the target; commit() makes it the target in one rename. Destroying an
// uncommitted writer removes the temporary file. Large outputs stream through a fixed buffer, never one string.
class AtomicFileWriter {
public:
    explicit AtomicFileWriter(std::string path);
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    // Creates the temporary file. Errors name the target file and say why (missing directory, permission...).
    Status open();
    // Valid after a successful open(). Write errors are remembered and reported by commit().
    std::ostream& stream();
    // Flushes, fsyncs and renames over the target; afterwards the writer is closed.
    Status commit();
    // Removes the temporary file and leaves the target as it was.
    void discard();

    const std::string& path() const { return m_path; }

private:
    struct Impl;
    std::string m_path;
    std::unique_ptr<Impl> m_impl;
};

// The writer streams the content and returns an Error to abandon the write; the target is then left as it was.
Status writeFileAtomically(const std::string& path, const std::function<Status(std::ostream&)>& writer);
Status writeFileAtomically(const std::string& path, std::string_view contents);

} // namespace rl
