// A board preset's JSON text, parsed strictly: invalid JSON reported with
// line and column, a key given twice refused, and no control character in
// any key or string (escaped or raw), so that preset text reaches messages,
// the summary and the report as printable text.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "models/common/pinned_files.h"

namespace cdvp {

// Throws InputError "PATH: ..." naming the position or the key; text nesting
// deeper than kMaxNesting (models/common/nesting_limit.h) is refused as 'what'
// ("a board preset") before it is parsed.
nlohmann::json parse_preset(const std::string& path, const std::string& text, const std::string& what);

// A small hand-written file's text (a preset, a config file): a regular file
// of at most 1 MiB, or InputError "PATH: ... not WHAT".
// A pinned path's text is given without reading the file (PinnedFiles).
std::string read_small_file(const std::string& path, const std::string& what);

}  // namespace cdvp
