// libFuzzer target: the config file loader (platform/settings/config_file.h), JSON
// and TOML.
//
// The first byte chooses the format: 'T' TOML, 'J' JSON, any other byte by
// its low bit, so that mutations reach both. The rest is written to an
// in-memory file (memfd) that the loader opens through a symbolic link named
// fuzz.toml or fuzz.json, since the name's ending picks the format. Invariants,
// each a crash when broken:
//  - no sanitizer report, no exception other than cdvp::InputError;
//  - a rejection is one line that starts with the file's path;
//  - an accepted file names each setting at most once, as a config file's
//    value of the right type within the setting's range, and applies as a
//    layer of settings refusing only with InputError; accepted JSON holds no
//    NUL byte (nlohmann takes one for the end of the input);
//  - the nesting limit is exact: for text the library parses by itself,
//    refused for depth exactly when it nests deeper than kMaxNesting.
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "models/common/user_text.h"
#include "platform/settings/config_file.h"
#include "models/common/nesting_limit.h"
#include "platform/settings/setting_values.h"

namespace {

// Refusals for depth are checked against the library's own tree only this
// small: toml::parse recurses once a level, and past the limit a large input
// could nest deep enough to overflow the fuzzer's stack.
constexpr std::size_t kExactnessBytes = 8192;

int config_fd = -1;
std::string directory;

[[noreturn]] void violated(const std::string& what) {
    std::fprintf(stderr, "config_fuzzer: invariant violated: %s\n", what.c_str());
    std::abort();
}

void write_config(const uint8_t* data, std::size_t size) {
    if (ftruncate(config_fd, 0) != 0) violated(std::string("ftruncate: ") + std::strerror(errno));
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = pwrite(config_fd, data + done, size - done, static_cast<off_t>(done));
        if (n <= 0) violated(std::string("pwrite: ") + std::strerror(errno));
        done += static_cast<std::size_t>(n);
    }
}

void remove_links() {
    for (const char* name : {"/fuzz.json", "/fuzz.toml"}) unlink((directory + name).c_str());
    rmdir(directory.c_str());
}

// A refusal: one line, "PATH: ..." or "PATH:LINE..." (the command line
// escapes other control characters as it prints it).
void check_refusal(const std::string& path, const std::string& message) {
    if (message.compare(0, path.size() + 1, path + ":") != 0) {
        violated("error message does not start with the file's path: " + cdvp::printable(message));
    }
    if (message.find_first_of("\r\n") != std::string::npos) {
        violated("error message is not one line: " + cdvp::printable(message));
    }
}

// Whether 'message' is the refusal for depth, "PATH:LINE:COLUMN: nesting deeper ...".
bool refused_for_depth(const std::string& path, const std::string& message, bool toml) {
    std::size_t k = path.size();
    for (int number = 0; number < 2; ++number) {
        if (k >= message.size() || message[k] != ':') return false;
        const std::size_t digits = ++k;
        while (k < message.size() && message[k] >= '0' && message[k] <= '9') ++k;
        if (k == digits) return false;
    }
    const std::string limit = std::to_string(cdvp::kMaxNesting);
    return message.substr(k) == ": nesting deeper than " + limit + " levels; a config file nests " +
                                    (toml ? "tables" : "objects") + " and arrays at most " + limit + " deep";
}

// Levels of containers at and below 'node', counted no further than one past
// the limit, so that this check's own recursion stays shallow.
int json_depth(const nlohmann::json& node, int level = 1) {
    if (!node.is_structured()) return level - 1;
    int deepest = level;
    if (level > cdvp::kMaxNesting) return deepest;
    for (const auto& child : node) deepest = std::max(deepest, json_depth(child, level + 1));
    return deepest;
}

int toml_depth(const toml::node& node, int level = 1) {
    if (!node.is_table() && !node.is_array()) return level - 1;
    int deepest = level;
    if (level > cdvp::kMaxNesting) return deepest;
    if (const toml::table* table = node.as_table()) {
        for (const auto& [key, child] : *table) deepest = std::max(deepest, toml_depth(child, level + 1));
    } else {
        for (const toml::node& child : *node.as_array()) deepest = std::max(deepest, toml_depth(child, level + 1));
    }
    return deepest;
}

// How deep the library's own parse of 'text' nests, if it parses.
std::optional<int> library_depth(const std::string& text, bool toml) {
    if (toml) {
        try {
            return toml_depth(toml::parse(text));
        } catch (const toml::parse_error&) {
            return std::nullopt;
        }
    }
    if (text.find('\0') != std::string::npos) return std::nullopt;  // nlohmann would parse up to it only
    const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
    if (root.is_discarded()) return std::nullopt;
    return json_depth(root);
}

void check_nesting_limit(const std::string& text, bool toml, bool refused) {
    if (refused && text.size() > kExactnessBytes) return;
    const std::optional<int> depth = library_depth(text, toml);
    if (!depth) return;
    if (refused != (*depth > cdvp::kMaxNesting)) {
        violated(std::string(toml ? "TOML" : "JSON") + " nesting " + std::to_string(*depth) + " levels deep " +
                 (refused ? "refused" : "not refused") + " for depth");
    }
}

[[noreturn]] void bad_value(const cdvp::Setting& s, const cdvp::SettingValue& value, const std::string& what) {
    violated("accepted " + s.name + " = " + cdvp::printable(cdvp::to_text(value)) + ": " + what);
}

// The value is one the setting's own reading gives: its type, in range.
void check_value(const cdvp::Setting& s, const cdvp::SettingValue& value) {
    switch (s.type) {
        case cdvp::SettingType::kCount: {
            const uint64_t* count = std::get_if<uint64_t>(&value);
            if (count == nullptr) bad_value(s, value, "expected a count");
            if (*count < s.count_min || *count > s.count_max) bad_value(s, value, "outside " + s.range_text());
            break;
        }
        case cdvp::SettingType::kReal: {
            const double* real = std::get_if<double>(&value);
            if (real == nullptr) bad_value(s, value, "expected a real number");
            if (!(*real >= s.min && *real <= s.max)) bad_value(s, value, "outside " + s.range_text());
            break;
        }
        case cdvp::SettingType::kChoice:
        case cdvp::SettingType::kText: {
            const std::string* text = std::get_if<std::string>(&value);
            if (text == nullptr) bad_value(s, value, "expected a string");
            try {
                if (s.from_string(*text) != value) bad_value(s, value, "reads back differently");
            } catch (const std::invalid_argument& e) {
                bad_value(s, value, std::string("the setting refuses it: ") + e.what());
            }
            break;
        }
    }
}

void check_accepted(const std::string& path, const std::string& text, const std::vector<cdvp::Assignment>& values,
                    bool toml) {
    // nlohmann takes a NUL byte for the end of the input; what follows must not be ignored.
    if (!toml && text.find('\0') != std::string::npos) violated("accepted JSON holding a NUL byte");
    std::set<const cdvp::Setting*> named;
    for (const cdvp::Assignment& a : values) {
        if (a.setting == nullptr || cdvp::find_setting(a.setting->name) != a.setting) {
            violated("accepted assignment of no setting of the table");
        }
        if (!named.insert(a.setting).second) violated("accepted " + a.setting->name + " twice");
        if (a.origin.kind != cdvp::SettingOrigin::Kind::kConfig || a.origin.file != path ||
            (toml ? a.origin.line < 1 : a.origin.line != 0)) {
            violated("accepted " + a.setting->name + " with another origin than config " + path);
        }
        check_value(*a.setting, a.value);
    }
    try {
        cdvp::SettingValues layered;
        layered.apply(values);
        layered.check_board();
    } catch (const cdvp::InputError& e) {
        const std::string message = e.what();
        if (message.find_first_of("\r\n") != std::string::npos) violated("error message is not one line: " + message);
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    config_fd = memfd_create("config", MFD_CLOEXEC);
    if (config_fd < 0) violated(std::string("memfd_create: ") + std::strerror(errno));
    char pattern[] = "/tmp/cdvp-config-fuzzer-XXXXXX";
    if (mkdtemp(pattern) == nullptr) violated(std::string("mkdtemp: ") + std::strerror(errno));
    directory = pattern;
    const std::string target = "/proc/self/fd/" + std::to_string(config_fd);
    for (const char* name : {"/fuzz.json", "/fuzz.toml"}) {
        if (symlink(target.c_str(), (directory + name).c_str()) != 0) {
            violated(std::string("symlink: ") + std::strerror(errno));
        }
    }
    std::atexit(remove_links);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const bool toml = data[0] == 'T' || (data[0] != 'J' && (data[0] & 1) != 0);
    const std::string path = directory + (toml ? "/fuzz.toml" : "/fuzz.json");
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    write_config(data + 1, size - 1);
    std::vector<cdvp::Assignment> values;
    try {
        values = cdvp::read_config_file(path);
    } catch (const cdvp::InputError& e) {
        check_refusal(path, e.what());
        check_nesting_limit(text, toml, refused_for_depth(path, e.what(), toml));
        return 0;
    }
    check_nesting_limit(text, toml, false);
    check_accepted(path, text, values, toml);
    return 0;
}
