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
bool writeNewFile(const std::string& path, const std::string& data);

// Replaces `to` by `from` in one atomic step and makes that durable.
void replaceFile(const std::string& from, const std::string& to);

void removeFile(const std::string& path) noexcept;

// The entries of a directory ("" = the current one); empty when it cannot be listed.
std::vector<std::string> listDirectory(const std::string& directory);

std::uint64_t currentProcessId();
// True unless the process is known to be gone (a temporary file it owned is then stale).
bool processIsRunning(std::uint64_t pid);

// Reads a whole regular file. Devices, FIFOs and directories are refused without blocking or
// reading from them, and so is a file of more than maxBytes.
std::string readRegularFile(const std::string& path, std::uint64_t maxBytes);

// The two refusals of readRegularFile, worded once for both platforms (atomic_file.cpp).
[[noreturn]] void refuseNonRegular(const std::string& path);
[[noreturn]] void refuseTooLarge(const std::string& path, std::uint64_t maxBytes);

}  // namespace verve::io::platform
