// Whole-file reads and crash-safe whole-file writes.
#pragma once
#include <string>

namespace verve::io {

// Writes `data` to a new temporary file in the target's directory, flushes it to disk (fsync),
// renames it over `path` and syncs the directory. A crash at any moment leaves either the old
// file or the new one at `path`, never a mix. On error the temporary file is removed and the
// old file is untouched; throws Error(Io) naming the path and the system's reason.
void writeFileAtomically(const std::string& path, const std::string& data);

// Throws Error(Io) if the file cannot be opened or read.
std::string readWholeFile(const std::string& path);

}  // namespace verve::io
