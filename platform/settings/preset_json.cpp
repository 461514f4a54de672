#include "platform/settings/preset_json.h"

#include <algorithm>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include "models/common/user_text.h"
#include "models/common/input_path.h"
#include "models/common/json_strings.h"
#include "models/common/nesting_limit.h"

namespace cdvp {

namespace {

using nlohmann::json;

bool is_control(unsigned char byte) { return byte < 0x20 || byte == 0x7f; }

// The first control character of 'text' (C0, DEL, or C1 as UTF-8), if any.
std::optional<std::string> first_control(const std::string& text) {
    for (std::size_t k = 0; k < text.size(); ++k) {
        const auto byte = static_cast<unsigned char>(text[k]);
        if (is_control(byte)) return text.substr(k, 1);
        if (byte == 0xc2 && k + 1 < text.size() && static_cast<unsigned char>(text[k + 1]) >= 0x80 &&
            static_cast<unsigned char>(text[k + 1]) <= 0x9f) {
            return text.substr(k, 2);
        }
    }
    return std::nullopt;
}

// Raw control bytes inside strings written as \u00XX escapes, which JSON
// allows, so that the parsed tree names the key that holds them. Outside
// strings the text is kept, so a stray byte stays a syntax error.
std::string escape_raw_controls(const std::string& text) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    bool in_string = false, escaped = false;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (in_string && is_control(byte) && byte != 0x7f) {
            out += std::string("\\u00") + kHex[byte >> 4] + kHex[byte & 15];
            escaped = false;
            continue;
        }
        out += c;
        if (escaped) {
            escaped = false;
        } else if (in_string && c == '\\') {
            escaped = true;
        } else if (c == '"') {
            in_string = !in_string;
        }
    }
    return out;
}

// json::parse, and where the text fails only for raw control bytes inside
// strings, the parse of the text with those escaped; positions in errors are
// always the original text's.
template <class Callback, class Levels>
json parse_naming_controls(const std::string& text, const Callback& check_keys, Levels& levels, std::string& duplicate) {
    try {
        return json::parse(text, check_keys);
    } catch (const json::parse_error&) {
        const std::string escaped = escape_raw_controls(text);
        if (escaped == text) throw;
        levels.clear();
        duplicate.clear();
        try {
            return json::parse(escaped, check_keys);
        } catch (const json::exception&) {
        }
        levels.clear();
        duplicate.clear();
        return json::parse(text, check_keys);  // throws the original error
    }
}

// "KEY.PATH: control character \xNN in a key|string", for the first one found.
std::optional<std::string> control_in(const json& value, const std::string& where) {
    const auto named = [](const std::string& where, const std::string& text, const char* in) {
        return std::optional<std::string>(where + ": control character " + printable(*first_control(text)) + " in " +
                                          in + "; expected printable text");
    };
    if (value.is_string()) {
        const std::string& text = value.get_ref<const std::string&>();
        if (first_control(text)) return named(where.empty() ? "(top level)" : where, text, "a string");
    } else if (value.is_object()) {
        for (const auto& [key, member] : value.items()) {
            const std::string path = where.empty() ? excerpt(key) : where + "." + excerpt(key);
            if (first_control(key)) return named(path, key, "a key");
            if (std::optional<std::string> found = control_in(member, path)) return found;
        }
    } else if (value.is_array()) {
        for (std::size_t k = 0; k < value.size(); ++k) {
            if (std::optional<std::string> found = control_in(value[k], where + "[" + std::to_string(k) + "]")) return found;
        }
    }
    return std::nullopt;
}

// "FILE:LINE:COLUMN" of a byte offset (nlohmann counts from 1).
std::string position(const std::string& path, const std::string& text, std::size_t byte) {
    return text_position(path, text, byte == 0 ? 0 : byte - 1);
}

// nlohmann takes a NUL byte for the end of the input: the offset of one
// outside strings, after which text would be ignored.
std::optional<std::size_t> nul_outside_strings(const std::string& text) {
    JsonStrings strings;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (!strings.inside(text[k]) && text[k] == '\0') return k;
    }
    return std::nullopt;
}

// Parses the preset text, refusing a key given twice in one object (JSON
// leaves that open; nlohmann would keep the last silently).
json parse_strictly(const std::string& path, const std::string& text) {
    struct Level {
        std::set<std::string> keys;
        std::string current;
    };
    std::vector<Level> levels;
    std::string duplicate;
    const json::parser_callback_t check_keys = [&](int, json::parse_event_t event, json& parsed) {
        if (event == json::parse_event_t::object_start) levels.emplace_back();
        if (event == json::parse_event_t::object_end && !levels.empty()) levels.pop_back();
        if (event == json::parse_event_t::key && !levels.empty()) {
            const std::string key = parsed.get<std::string>();
            if (!levels.back().keys.insert(key).second && duplicate.empty()) {
                for (std::size_t k = 0; k + 1 < levels.size(); ++k) duplicate += levels[k].current + ".";
                duplicate += key;
            }
            levels.back().current = key;
        }
        return true;
    };
    json root;
    try {
        root = parse_naming_controls(text, check_keys, levels, duplicate);
    } catch (const json::parse_error& e) {
        std::string what = e.what();
        const std::size_t detail = what.find("syntax error");
        throw InputError(position(path, text, e.byte) + ": invalid JSON: " +
                         (detail == std::string::npos ? what : what.substr(detail)));
    } catch (const json::exception& e) {
        // A number beyond double's range (out_of_range 406) and the like: the
        // library gives no position, so the message names the file alone.
        const std::string what = e.what();
        const std::size_t detail = what.find("] ");
        throw InputError(path + ": invalid JSON: " + (detail == std::string::npos ? what : what.substr(detail + 2)));
    }
    if (const std::optional<std::size_t> nul = nul_outside_strings(text)) {
        throw InputError(text_position(path, text, *nul) +
                         ": invalid JSON: syntax error while parsing value - unexpected NUL byte; expected end of input");
    }
    if (!duplicate.empty()) throw InputError(path + ": " + excerpt(duplicate) + ": key given twice");
    if (!root.is_object()) throw InputError(path + ": expected a JSON object");
    return root;
}

}  // namespace

json parse_preset(const std::string& path, const std::string& text, const std::string& what) {
    check_json_nesting(path, text, what);  // before the walks below, which recurse
    json root = parse_strictly(path, text);
    if (std::optional<std::string> found = control_in(root, "")) throw InputError(path + ": " + *found);
    return root;
}

std::string read_small_file(const std::string& path, const std::string& what) {
    if (const std::string* pinned = PinnedFiles::find(path)) return *pinned;
    constexpr std::size_t kMaxBytes = 1 << 20;  // a hand-written file; anything bigger is not one
    return *read_input_file({path, what, kMaxBytes});
}

}  // namespace cdvp
