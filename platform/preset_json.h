// A board preset's JSON text, parsed strictly: invalid JSON reported with
// line and column, a key given twice refused, and no control character in
// any key or string (escaped or raw), so that preset text reaches messages,
// the summary and the report as printable text.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace cdvp {

// Throws InputError "PATH: ..." naming the position or the key; text nesting
// deeper than kMaxNesting (models/common/nesting_limit.h) is refused as 'what'
// ("a board preset") before it is parsed.
nlohmann::json parse_preset(const std::string& path, const std::string& text, const std::string& what);

// A small hand-written file's text (a preset, a config file): a regular file
// of at most 1 MiB, or InputError "PATH: ... not WHAT".
// A pinned path's text is given without reading the file (PinnedFiles).
std::string read_small_file(const std::string& path, const std::string& what);

// Small input files a caller has read and digested once and whose readers in
// this process must see that text: a sweep pins its presets, config files and
// host profiles, so that every point it runs in process reads what the
// manifest's digest covers (a file changed meanwhile stops the sweep after
// the point, as before). While a PinnedFiles lives, read_small_file gives a
// pinned path's text. One at a time; not for threads.
class PinnedFiles {
public:
    PinnedFiles();  // throws std::logic_error while another lives
    ~PinnedFiles();
    PinnedFiles(const PinnedFiles&) = delete;
    PinnedFiles& operator=(const PinnedFiles&) = delete;

    void pin(const std::string& path, std::string text);
    // The living pins' text for `path`, or null.
    static const std::string* find(const std::string& path);

private:
    std::map<std::string, std::string> texts_;
};

}  // namespace cdvp
