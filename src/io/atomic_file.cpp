#include "io/atomic_file.hpp"

#include <atomic>
#include <cstdio>

#include "io/platform_file.hpp"
#include "verve/error.hpp"

namespace verve::io {
namespace {

// A file name may have at most 255 bytes (ext4, NTFS in UTF-16 units, most others).
constexpr std::size_t kMaxNameBytes = 255;
// The temporary name's tail after the target's head: ".tmp-" + 8 hex digits (the name's hash) +
// "-" + 8 hex digits (the place, platform::placeTag) + "-" + pid (up to 20 digits) + "-" +
// counter (up to 20 digits).
constexpr std::size_t kMaxTempTail = 5 + 8 + 1 + 8 + 1 + 20 + 1 + 20;

std::uint32_t fnv1a(const std::string& text) {
    std::uint32_t hash = 2166136261u;
    for (const unsigned char c : text) hash = (hash ^ c) * 16777619u;
    return hash;
}

// "<head of name>.tmp-<hash of name>-": what every temporary file of this target starts with.
// The head is cut (at a UTF-8 character boundary) so that a temporary name never exceeds the
// file system's limit even when the target's own name is at it; the hash of the whole name keeps
// apart targets whose names share that head.
std::string temporaryPrefix(const std::string& name) {
    std::size_t keep = name.size() < kMaxNameBytes - kMaxTempTail ? name.size() : kMaxNameBytes - kMaxTempTail;
    while (keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;
    char hash[9];
    std::snprintf(hash, sizeof hash, "%08x", static_cast<unsigned>(fnv1a(name)));
    return name.substr(0, keep) + ".tmp-" + hash + "-";
}

// Removes the temporary files that saves of this target left when their process was killed. A
// file whose owner (the pid in its name) still runs is left alone: it may be a save in progress.
// So is one from another place (machine or PID namespace, platform::placeTag), whose pid means
// nothing here: `prefix` ends with this place's tag.
void removeStaleTemporaries(const std::string& directory, const std::string& prefix) {
    const std::uint64_t self = platform::currentProcessId();
    for (const std::string& name : platform::listDirectory(directory)) {
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        std::uint64_t pid = 0;
        std::size_t i = prefix.size();
        for (; i < name.size() && name[i] >= '0' && name[i] <= '9' && pid < (std::uint64_t{1} << 40); ++i) {
            pid = pid * 10 + static_cast<std::uint64_t>(name[i] - '0');
        }
        if (i == prefix.size() || i == name.size() || name[i] != '-') continue;  // not one of ours
        if (pid != self && !platform::processIsRunning(pid)) platform::removeFile(platform::joinPath(directory, name));
    }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& data) {
    if (path.empty()) throw Error(ErrorCode::InvalidArgument, "the path is empty");
    const std::string target = platform::followLinks(path);
    const platform::PathParts parts = platform::splitPath(target);
    const std::string prefix = temporaryPrefix(parts.name) + platform::placeTag() + "-";
    removeStaleTemporaries(parts.directory, prefix);

    static std::atomic<std::uint64_t> counter{0};  // with the place and pid: no other saver picks the same name
    const std::string ours = prefix + std::to_string(platform::currentProcessId()) + "-";
    std::string temp;
    for (int attempt = 0;; ++attempt) {
        temp = platform::joinPath(parts.directory, ours + std::to_string(counter.fetch_add(1)));
        if (platform::writeNewFile(temp, data, target)) break;
        if (attempt == 100) throw Error(ErrorCode::Io, "cannot create a temporary file next to '" + target + "'");
    }
    try {
        platform::replaceFile(temp, target);
    } catch (...) {
        platform::removeFile(temp);
        throw;
    }
}

std::string readWholeFile(const std::string& path) {
    if (path.empty()) throw Error(ErrorCode::InvalidArgument, "the path is empty");
    return platform::readRegularFile(path, kMaxSaveFileBytes);
}

namespace platform {

PathParts splitPath(const std::string& path) {
    const auto slash = path.find_last_of(pathSeparators());
    if (slash == std::string::npos) return {"", path};
    return {path.substr(0, slash == 0 ? 1 : slash), path.substr(slash + 1)};
}

std::string joinPath(const std::string& directory, const std::string& name) {
    if (directory.empty()) return name;
    const bool separated = std::string(pathSeparators()).find(directory.back()) != std::string::npos;
    return separated ? directory + name : directory + pathSeparators()[0] + name;
}

void refuseNonRegular(const std::string& path) {
    throw Error(ErrorCode::Io, "cannot load '" + path + "': not a regular file (a directory, device or pipe)");
}

void refuseTooLarge(const std::string& path, std::uint64_t maxBytes) {
    throw Error(ErrorCode::Io, "cannot load '" + path + "': larger than the " + std::to_string(maxBytes) +
                                   "-byte limit for a save file");
}

}  // namespace platform
}  // namespace verve::io
