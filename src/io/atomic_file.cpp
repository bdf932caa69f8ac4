#include "io/atomic_file.hpp"

#if defined(_WIN32)
#error "atomic_file.cpp: only POSIX is implemented (Windows needs MoveFileEx + FlushFileBuffers)"
#endif

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>

#include "verve/error.hpp"

namespace verve::io {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int error) {
    throw Error(ErrorCode::Io, what + " '" + path + "': " + std::strerror(error));
}

std::string directoryOf(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

// Closes the descriptor and, unless released, removes the temporary file on every error path.
class TempFile {
public:
    TempFile(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
    ~TempFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!committed_) ::unlink(path_.c_str());
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;

    int fd() const { return fd_; }
    const std::string& path() const { return path_; }
    int close() {
        const int rc = ::close(fd_);
        fd_ = -1;
        return rc;
    }
    void commit() { committed_ = true; }

private:
    std::string path_;
    int fd_;
    bool committed_ = false;
};

// A name no other saver uses: pid, a process-wide counter and the clock. O_EXCL guards the rest.
TempFile createTemp(const std::string& path) {
    static std::atomic<unsigned long> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        const auto tick = std::chrono::steady_clock::now().time_since_epoch().count();
        const std::string name = path + ".tmp-" + std::to_string(::getpid()) + "-" +
                                 std::to_string(counter.fetch_add(1)) + "-" + std::to_string(tick % 1000000);
        const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return TempFile(name, fd);
        if (errno != EEXIST) fail("cannot create a temporary file next to", path, errno);
    }
    fail("cannot create a temporary file next to", path, EEXIST);
}

void writeAll(const TempFile& file, const std::string& data) {
    const char* p = data.data();
    std::size_t left = data.size();
    while (left > 0) {
        const ssize_t n = ::write(file.fd(), p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot write", file.path(), errno);
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
}

// Makes the rename itself durable. Some file systems refuse fsync on a directory: not an error.
void syncDirectory(const std::string& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& data) {
    if (path.empty()) throw Error(ErrorCode::InvalidArgument, "the path is empty");
    TempFile temp = createTemp(path);
    writeAll(temp, data);
    if (::fsync(temp.fd()) != 0) fail("cannot flush", temp.path(), errno);
    if (temp.close() != 0) fail("cannot close", temp.path(), errno);
    if (::rename(temp.path().c_str(), path.c_str()) != 0) fail("cannot replace", path, errno);
    temp.commit();
    syncDirectory(directoryOf(path));
}

std::string readWholeFile(const std::string& path) {
    if (path.empty()) throw Error(ErrorCode::InvalidArgument, "the path is empty");
    struct Descriptor {
        int fd;
        ~Descriptor() { if (fd >= 0) ::close(fd); }
    } in{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (in.fd < 0) fail("cannot open", path, errno);
    std::string data;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(in.fd, buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot read", path, errno);
        }
        if (n == 0) return data;
        data.append(buffer, static_cast<std::size_t>(n));
    }
}

}  // namespace verve::io
