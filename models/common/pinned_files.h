// Small input files a caller has read and digested once and whose readers in
// this process must see that text: a sweep pins its presets, config files and
// host profiles, so that every point it runs in process reads what the
// manifest's digest covers (a file changed meanwhile stops the sweep after
// the point, as before). While a PinnedFiles lives, read_small_file
// (platform/settings/preset_json.h) gives a pinned path's text. One at a time; not for
// threads.
#pragma once

#include <map>
#include <string>

namespace cdvp {

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
