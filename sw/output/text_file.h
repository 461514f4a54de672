// Whole text files: read at once, and replaced whole (a temporary beside the
// target, synced, then renamed), so that an interrupted command leaves the
// old file or the new one, never a part.
#pragma once

#include <optional>
#include <string>

namespace cdvp {

// The whole file (empty when it cannot be read).
std::string slurp(const std::string& path);
// The whole file, or nothing when it cannot be opened or read (errno tells why).
std::optional<std::string> read_whole_file(const std::string& path);

// Replaces 'path' with 'text' whole: written to a temporary beside it,
// synced, then renamed over it, with the cleanup signals held back meanwhile
// so that an interrupted command leaves the old file or the new one, never a
// part. Throws SystemError (a full disk, an I/O error) or InputError, naming
// 'label' and the path, with the system's own error text.
void commit_text_file(const std::string& path, const std::string& text, const std::string& label);

}  // namespace cdvp
