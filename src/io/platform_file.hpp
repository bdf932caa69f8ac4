// The platform seam of src/io: the few file operations that differ between POSIX and Windows.
// platform_file_posix.cpp and platform_file_win32.cpp implement it (CMake compiles one of them);
// nothing else in Verve touches the operating system's file API. Paths are UTF-8 (Windows converts
// them to UTF-16). Failures throw Error(Io) naming the path and the system's reason.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace verve::io::platform {

// The characters that separate folders in a path, the preferred one first: "/" or "\\/".
const char* pathSeparators();

// Path arithmetic over pathSeparators(), the same for both platforms (atomic_file.cpp).
struct PathParts {
    std::string directory;  // "" for the current directory
    std::string name;
};
PathParts splitPath(const std::string& path);
std::string joinPath(const std::string& directory, const std::string& name);

// The file that saving to `path` must replace: symbolic links are followed, so a save writes
// through a link to the file it points to (POSIX; on Windows `path` itself).
std::string followLinks(const std::string& path);

// Creates `path` (never an existing file), writes `data`, flushes it to the disk and closes it.
// Returns false, changing nothing, when the name is taken; on other failures removes the new file.
// POSIX: when `replacing` exists, the new file takes its permission bits and owner (a private
// save stays private); if the owner cannot be given (not root), group and others lose access.
// Windows: replaceFile keeps the replaced file's attributes and ACL instead.
bool writeNewFile(const std::string& path, const std::string& data, const std::string& replacing);

// Replaces `to` by `from` in one atomic step and makes that durable: POSIX renames, then flushes
// the folder (a folder that cannot be flushed for another reason than the file system's not
// supporting it is Error(Io), the new file in place); Windows uses ReplaceFileW (MoveFileExW with
// MOVEFILE_WRITE_THROUGH for a new target), retried for a while on a sharing violation (a
// reader, an antivirus or an indexer holding the file).
void replaceFile(const std::string& from, const std::string& to);

void removeFile(const std::string& path) noexcept;

// The entries of a directory ("" = the current one); empty when it cannot be listed.
std::vector<std::string> listDirectory(const std::string& directory);

std::uint64_t currentProcessId();
// True unless the process is known to be gone (a temporary file it owned is then stale). Only
// meaningful for a pid of this place (placeTag).
bool processIsRunning(std::uint64_t pid);
// Eight hex digits naming where process ids mean what they mean here: the machine (its host
// name) and, on Linux, the PID namespace (a container). Temporary files carry it, and a save
// removes only the stale ones of its own place: another machine's or container's pids cannot be
// checked from here.
std::string placeTag();

// Reads a whole regular file. Devices, FIFOs and directories are refused without blocking or
// reading from them, and so is a file of more than maxBytes.
std::string readRegularFile(const std::string& path, std::uint64_t maxBytes);

// The two refusals of readRegularFile, worded once for both platforms (atomic_file.cpp).
[[noreturn]] void refuseNonRegular(const std::string& path);
[[noreturn]] void refuseTooLarge(const std::string& path, std::uint64_t maxBytes);

}  // namespace verve::io::platform
