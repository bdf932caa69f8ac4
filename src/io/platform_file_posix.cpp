// The file seam on POSIX (Linux, and the BSDs and macOS in principle): open/write/fsync/rename.
#include "io/platform_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "verve/error.hpp"

namespace verve::io::platform {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int error) {
    throw Error(ErrorCode::Io, what + " '" + path + "': " + std::strerror(error));
}

class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    ~Descriptor() { close(); }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return fd_; }
    int close() {
        const int rc = fd_ >= 0 ? ::close(fd_) : 0;
        fd_ = -1;
        return rc;
    }

private:
    int fd_;
};

void writeAll(int fd, const std::string& data, const std::string& path) {
    const char* p = data.data();
    std::size_t left = data.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot write", path, errno);
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
}

// Makes a rename durable. A file system that does not support fsync on a directory (EINVAL,
// ENOTSUP) and a folder that cannot be opened for reading (write and search permission only) are
// not errors: there is nothing more to do. Any other failure is (the disk may not have it).
void syncDirectory(const std::string& directory) {
    const std::string name = directory.empty() ? "." : directory;
    const Descriptor fd(::open(name.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (fd.get() < 0) return;
    if (::fsync(fd.get()) == 0) return;
    const int error = errno;
    if (error == EINVAL || error == ENOTSUP || error == EOPNOTSUPP || error == EROFS) return;
    fail("the save is in place, but cannot flush its folder", name, error);
}

// The replaced file's permission bits and owner, so a save over a private file stays private.
void takeModeAndOwner(int fd, const std::string& replacing, const std::string& path) {
    struct stat old;
    if (replacing.empty() || ::stat(replacing.c_str(), &old) != 0 || !S_ISREG(old.st_mode)) return;
    struct stat now;
    if (::fstat(fd, &now) != 0) fail("cannot read", path, errno);
    mode_t mode = old.st_mode & 0777;  // not set-id or sticky bits: a save is data
    if ((now.st_uid != old.st_uid || now.st_gid != old.st_gid) && ::fchown(fd, old.st_uid, old.st_gid) != 0) {
        mode &= 0700;  // owned by someone else now: no one but the owner may read it
    }
    if (::fchmod(fd, mode) != 0) fail("cannot set the permissions of", path, errno);
}

}  // namespace

const char* pathSeparators() { return "/"; }

std::string followLinks(const std::string& path) {
    std::string current = path;
    for (int hop = 0; hop < 40; ++hop) {  // 40: Linux's own limit on links in a path
        struct stat st;
        if (::lstat(current.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return current;
        std::string target(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 4096) + 1, '\0');
        const ssize_t n = ::readlink(current.c_str(), &target[0], target.size());
        if (n < 0) fail("cannot read the link", current, errno);
        target.resize(static_cast<std::size_t>(n));
        if (target.empty()) return current;
        current = target.front() == '/' ? target : joinPath(splitPath(current).directory, target);
    }
    fail("cannot follow the links of", path, ELOOP);
}

bool writeNewFile(const std::string& path, const std::string& data, const std::string& replacing) {
    // A new target gets the umask's permissions, as any file the game makes; a replaced one's are
    // taken before a byte is written, so the data is never more exposed than the old file was.
    Descriptor fd(::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666));
    if (fd.get() < 0) {
        if (errno == EEXIST) return false;
        fail("cannot create", path, errno);
    }
    try {
        takeModeAndOwner(fd.get(), replacing, path);
        writeAll(fd.get(), data, path);
        if (::fsync(fd.get()) != 0) fail("cannot flush", path, errno);
        if (fd.close() != 0) fail("cannot close", path, errno);
    } catch (...) {
        fd.close();
        ::unlink(path.c_str());
        throw;
    }
    return true;
}

void replaceFile(const std::string& from, const std::string& to) {
    if (::rename(from.c_str(), to.c_str()) != 0) fail("cannot replace", to, errno);
    syncDirectory(splitPath(to).directory);
}

void removeFile(const std::string& path) noexcept { ::unlink(path.c_str()); }

std::vector<std::string> listDirectory(const std::string& directory) {
    std::vector<std::string> names;
    DIR* dir = ::opendir(directory.empty() ? "." : directory.c_str());
    if (dir == nullptr) return names;
    while (const dirent* entry = ::readdir(dir)) names.emplace_back(entry->d_name);
    ::closedir(dir);
    return names;
}

std::uint64_t currentProcessId() { return static_cast<std::uint64_t>(::getpid()); }

// Not cached: a process may move to another PID namespace (unshare, then fork) after a save.
std::string placeTag() {
    std::string place;
    char host[256] = {};
    if (::gethostname(host, sizeof host - 1) == 0) place = host;
    char ns[64] = {};
    const ssize_t n = ::readlink("/proc/self/ns/pid", ns, sizeof ns - 1);  // Linux: "pid:[4026531836]"
    if (n > 0) place += std::string("/") + std::string(ns, static_cast<std::size_t>(n));
    std::uint32_t hash = 2166136261u;
    for (const unsigned char c : place) hash = (hash ^ c) * 16777619u;
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(hash));
    return std::string(hex);
}

bool processIsRunning(std::uint64_t pid) {
    if (pid == 0 || pid > static_cast<std::uint64_t>(INT32_MAX)) return true;  // not a pid: leave it alone
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
}

std::string readRegularFile(const std::string& path, std::uint64_t maxBytes) {
    // Checked before opening, so a device is never opened, and again on the open file (it may
    // have been swapped); O_NONBLOCK keeps a FIFO swapped in between from blocking the open.
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) fail("cannot open", path, errno);
    if (!S_ISREG(st.st_mode)) refuseNonRegular(path);
    const Descriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY));
    if (fd.get() < 0) fail("cannot open", path, errno);
    if (::fstat(fd.get(), &st) != 0) fail("cannot read", path, errno);
    if (!S_ISREG(st.st_mode)) refuseNonRegular(path);
    if (static_cast<std::uint64_t>(st.st_size) > maxBytes) refuseTooLarge(path, maxBytes);

    std::string data;
    data.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot read", path, errno);
        }
        if (n == 0) return data;
        if (data.size() + static_cast<std::uint64_t>(n) > maxBytes) refuseTooLarge(path, maxBytes);  // it grew
        data.append(buffer, static_cast<std::size_t>(n));
    }
}

}  // namespace verve::io::platform
