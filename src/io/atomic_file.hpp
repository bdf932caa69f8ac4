// Whole-file reads and crash-safe whole-file writes, over the platform seam (platform_file.hpp).
#pragma once
#include <cstdint>
#include <string>

namespace verve::io {

// The largest file loadAgent reads (1 GiB, docs/c-api.md): a larger file, /dev/zero or a file
// that keeps growing is refused instead of being read until memory runs out.
constexpr std::uint64_t kMaxSaveFileBytes = std::uint64_t{1} << 30;

// Writes `data` to a new temporary file next to the target, flushes it to disk, and replaces
// `path` with it in one atomic step. A crash at any moment leaves either the old file or the new
// one at `path`, never a mix. A symbolic link at `path` is followed: the file it points to is
// replaced, keeping its permissions and owner (POSIX; Windows: attributes and ACL). Temporary
// files left by killed saves of the same target from this machine and PID namespace are
// removed (the temporary name carries that place, platform::placeTag). On error the
// temporary file is removed and the old file is untouched; throws Error(Io) naming the path and
// the system's reason.
void writeFileAtomically(const std::string& path, const std::string& data);

// Reads a whole regular file of at most kMaxSaveFileBytes; throws Error(Io) if it cannot be
// opened or read, is not a regular file (a device, FIFO, directory) or is larger.
std::string readWholeFile(const std::string& path);

}  // namespace verve::io
