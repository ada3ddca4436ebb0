#include "io/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace rl {

namespace {

std::string errnoText(int err) {
    return std::strerror(err);
}

Error fileError(const std::string& path, std::string message) {
    return Error{path, 0, {}, std::move(message)};
}

std::string directoryOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string baseNameOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A stream buffer over a POSIX descriptor: std::ofstream cannot be fsynced, and the rename is only safe once the
// data is on disk. The first failing write is remembered; later writes are dropped.
class FdStreamBuf : public std::streambuf {
public:
    explicit FdStreamBuf(int fd) : m_fd(fd), m_buffer(kBufferSize) {
        setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    }

    int error() const { return m_error; }

protected:
    int_type overflow(int_type ch) override {
        if (!flushBuffer())
            return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }

    int sync() override { return flushBuffer() ? 0 : -1; }

private:
    static constexpr size_t kBufferSize = size_t(1) << 16;

    bool flushBuffer() {
        const char* data = pbase();
        size_t left = static_cast<size_t>(pptr() - pbase());
        while (left > 0 && m_error == 0) {
            const ssize_t n = ::write(m_fd, data, left);
            if (n < 0) {
                if (errno == EINTR)
                    continue;
                m_error = errno;
                break;
            }
            data += n;
            left -= static_cast<size_t>(n);
        }
        setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
        return m_error == 0;
    }

    int m_fd;
    int m_error = 0;
    std::vector<char> m_buffer;
};

} // namespace

struct AtomicFileWriter::Impl {
    int fd = -1;
    std::string tempPath;
    std::string targetPath; // the path given, or the file a symbolic link there points to
    FdStreamBuf buffer;
    std::ostream stream;

    Impl(int descriptor, std::string temp, std::string target)
        : fd(descriptor), tempPath(std::move(temp)), targetPath(std::move(target)), buffer(descriptor),
          stream(&buffer) {}
};

AtomicFileWriter::AtomicFileWriter(std::string path) : m_path(std::move(path)) {}

AtomicFileWriter::~AtomicFileWriter() {
    discard();
}

Status AtomicFileWriter::open() {
    discard();
    if (m_path.empty() || m_path.back() == '/')
        return fileError(m_path, "not a file name");
    // Writing through a symbolic link replaces the file it points to and keeps the link, as editors do. A dangling
    // link is replaced itself.
    std::string target = m_path;
    struct stat linkInfo {};
    if (::lstat(m_path.c_str(), &linkInfo) == 0 && S_ISLNK(linkInfo.st_mode)) {
        std::error_code ec;
        const std::filesystem::path resolved = std::filesystem::canonical(m_path, ec);
        if (!ec)
            target = resolved.string();
    }
    const std::string dir = directoryOf(target);
    struct stat dirInfo {};
    if (::stat(dir.c_str(), &dirInfo) != 0)
        return fileError(m_path, "cannot write: directory '" + dir + "': " + errnoText(errno));
    if (!S_ISDIR(dirInfo.st_mode))
        return fileError(m_path, "cannot write: '" + dir + "' is not a directory");

    // The temporary file lives in the target's directory so that rename() never crosses file systems. A process-wide
    // counter plus the pid keeps concurrent writers apart; O_EXCL guarantees we never reuse someone else's file.
    static std::atomic<unsigned> counter{0};
    const std::string prefix = (dir == "." && target.find('/') == std::string::npos ? std::string() : dir + "/") + "." +
                               baseNameOf(target) + ".tmp-" + std::to_string(::getpid()) + "-";
    constexpr int kAttempts = 64;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        std::string temp = prefix + std::to_string(counter.fetch_add(1));
        // 0666 and the umask give the permissions a newly created file would have had.
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) {
            if (errno == EEXIST || errno == EINTR)
                continue;
            return fileError(m_path, "cannot create a temporary file in '" + dir + "': " + errnoText(errno));
        }
        // Replacing a file keeps its permissions, as an editor's save would.
        struct stat old {};
        if (::stat(target.c_str(), &old) == 0 && S_ISREG(old.st_mode))
            ::fchmod(fd, old.st_mode & 07777);
        m_impl = std::make_unique<Impl>(fd, std::move(temp), std::move(target));
        return Ok{};
    }
    return fileError(m_path, "cannot create a temporary file in '" + dir + "': too many attempts");
}

std::ostream& AtomicFileWriter::stream() {
    return m_impl->stream;
}

Status AtomicFileWriter::commit() {
    if (!m_impl)
        return fileError(m_path, "cannot commit: the file was not opened");
    m_impl->stream.flush();
    int err = m_impl->buffer.error();
    if (err == 0 && !m_impl->stream)
        err = EIO;
    if (err == 0 && ::fsync(m_impl->fd) != 0)
        err = errno;
    if (::close(m_impl->fd) != 0 && err == 0)
        err = errno;
    m_impl->fd = -1;
    if (err != 0) {
        discard();
        return fileError(m_path, "cannot write: " + errnoText(err));
    }
    if (::rename(m_impl->tempPath.c_str(), m_impl->targetPath.c_str()) != 0) {
        err = errno;
        discard();
        return fileError(m_path, "cannot replace the file: " + errnoText(err));
    }
    // Make the rename itself durable; failing to sync a directory does not undo a completed write.
    const int dirFd = ::open(directoryOf(m_impl->targetPath).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirFd >= 0) {
        ::fsync(dirFd);
        ::close(dirFd);
    }
    m_impl.reset();
    return Ok{};
}

void AtomicFileWriter::discard() {
    if (!m_impl)
        return;
    if (m_impl->fd >= 0)
        ::close(m_impl->fd);
    ::unlink(m_impl->tempPath.c_str());
    m_impl.reset();
}

Status writeFileAtomically(const std::string& path, const std::function<Status(std::ostream&)>& writer) {
    AtomicFileWriter file(path);
    if (Status s = file.open(); !s)
        return s;
    if (Status s = writer(file.stream()); !s) {
        file.discard();
        Error e = s.error();
        if (e.file.empty())
            e.file = path;
        return e;
    }
    return file.commit();
}

Status writeFileAtomically(const std::string& path, std::string_view contents) {
    return writeFileAtomically(path, [contents](std::ostream& out) -> Status {
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        return Ok{};
    });
}

} // namespace rl
