#include "models/common/nesting_limit.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "models/common/user_text.h"
#include "models/common/json_strings.h"

namespace cdvp {

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& text, std::size_t offset, const std::string& what,
                         const char* containers) {
    const std::string limit = std::to_string(kMaxNesting);
    throw InputError(text_position(path, text, offset) + ": nesting deeper than " + limit + " levels; " + what +
                     " nests " + containers + " at most " + limit + " deep");
}

// The offset of the bracket that opens level kMaxNesting + 1, if any.
std::optional<std::size_t> too_deep_json(const std::string& text) {
    JsonStrings strings;
    int depth = 0;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (strings.inside(c)) continue;
        if (c == '{' || c == '[') {
            if (++depth > kMaxNesting) return k;
        } else if ((c == '}' || c == ']') && depth > 0) {
            --depth;
        }
    }
    return std::nullopt;
}

void append_utf8(std::string& out, uint32_t code) {
    if (code < 0x80) {
        out += static_cast<char>(code);
    } else if (code < 0x800) {
        out += static_cast<char>(0xc0 | code >> 6);
        out += static_cast<char>(0x80 | (code & 0x3f));
    } else if (code < 0x10000) {
        out += static_cast<char>(0xe0 | code >> 12);
        out += static_cast<char>(0x80 | (code >> 6 & 0x3f));
        out += static_cast<char>(0x80 | (code & 0x3f));
    } else {
        out += static_cast<char>(0xf0 | (code >> 18 & 0x07));
        out += static_cast<char>(0x80 | (code >> 12 & 0x3f));
        out += static_cast<char>(0x80 | (code >> 6 & 0x3f));
        out += static_cast<char>(0x80 | (code & 0x3f));
    }
}

// Reads TOML text as toml++ will, but only as far as nesting goes: table
// headers, dotted keys, inline tables and arrays, stepping over strings and
// comments so that brackets inside them do not count. It validates
// nothing: what it does not understand it steps over, for toml::parse to
// refuse afterwards.
class TomlNesting {
public:
    explicit TomlNesting(const std::string& text) : text_(text) {}

    // The offset of the key part or bracket that goes past kMaxNesting, if any.
    std::optional<std::size_t> too_deep() {
        while (!too_deep_ && pos_ < text_.size()) step();
        return too_deep_;
    }

private:
    struct KeyPart {
        std::size_t offset;
        std::string name;  // as toml++ compares keys: quotes removed, escapes decoded
    };
    struct Open {  // an array or inline table not yet closed
        bool inline_table;
        int depth;
    };
    // A table that headers name, in a tree of them: only arrays of tables
    // are kept (and the tables on their paths), since an array of tables
    // nests its current element one level below it.
    struct HeaderTable {
        std::map<std::string, std::size_t> children;  // indices into headers_
        bool array_of_tables = false;
    };

    bool at(char c) const { return pos_ < text_.size() && text_[pos_] == c; }
    bool at(const char* token) const { return text_.compare(pos_, std::char_traits<char>::length(token), token) == 0; }
    static bool is_bare(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    }
    static bool starts_key(char c) { return is_bare(c) || c == '"' || c == '\''; }
    static bool ends_scalar(char c) { return c == ',' || c == ']' || c == '}' || c == '#' || c == '\r' || c == '\n'; }

    // Spaces, tabs and comments; newlines too inside an array or inline table.
    void skip_blank(bool newlines) {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == ' ' || c == '\t' || (newlines && (c == '\n' || c == '\r'))) {
                ++pos_;
            } else if (c == '#') {
                while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
            } else {
                return;
            }
        }
    }

    void step() {
        skip_blank(!open_.empty());
        if (pos_ >= text_.size()) return;
        const char c = text_[pos_];
        if (open_.empty()) {  // the start of a line of the document
            if (c == '[') {
                header();
            } else if (starts_key(c)) {
                key_value(table_depth_);
            } else {
                ++pos_;
            }
        } else if (open_.back().inline_table) {
            if (starts_key(c)) {
                key_value(open_.back().depth);
            } else {
                if (c == '}') open_.pop_back();
                ++pos_;
            }
        } else if (c == ']' || c == ',') {
            if (c == ']') open_.pop_back();
            ++pos_;
        } else {
            value(open_.back().depth);
        }
    }

    // [a.b.c] or [[a.b.c]]: the table (or the array's new element) below
    // every part, one level further for each array of tables on the way.
    void header() {
        ++pos_;
        const bool array = at('[');
        if (array) ++pos_;
        const std::vector<KeyPart> parts = read_key();
        std::optional<std::size_t> node = 0;  // the document's table; none once off the known paths
        int depth = 1;
        for (std::size_t k = 0; k < parts.size(); ++k) {
            const bool last = k + 1 == parts.size();
            std::optional<std::size_t> child;
            if (node) {
                const auto found = headers_[*node].children.find(parts[k].name);
                if (found != headers_[*node].children.end()) child = found->second;
            }
            if (!child && array) {  // an array of tables keeps its path
                headers_.emplace_back();
                child = headers_.size() - 1;
                if (node) headers_[*node].children[parts[k].name] = *child;
            }
            depth += 1 + ((array && last) || (child && headers_[*child].array_of_tables) ? 1 : 0);
            if (depth > kMaxNesting) {
                too_deep_ = parts[k].offset;
                return;
            }
            node = child;
        }
        if (array && node) {
            headers_[*node].array_of_tables = true;
            headers_[*node].children.clear();  // a new element holds none of the last one's arrays
        }
        table_depth_ = depth;
        skip_blank(false);
        for (int k = 0; k < (array ? 2 : 1) && at(']'); ++k) ++pos_;
    }

    // KEY = VALUE in a table at 'depth': a dotted key's parts before its last are tables.
    void key_value(int depth) {
        const std::vector<KeyPart> parts = read_key();
        for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
            if (++depth > kMaxNesting) {
                too_deep_ = parts[k].offset;
                return;
            }
        }
        skip_blank(false);
        if (!at('=')) return;
        ++pos_;
        skip_blank(false);
        value(depth);
    }

    // A value held at 'depth': an array or inline table opens the next level.
    void value(int depth) {
        if (pos_ >= text_.size() || text_[pos_] == '\n' || text_[pos_] == '\r') return;
        const char c = text_[pos_];
        if (c == '[' || c == '{') {
            if (depth + 1 > kMaxNesting) {
                too_deep_ = pos_;
                return;
            }
            open_.push_back({c == '{', depth + 1});
            ++pos_;
        } else if (c == '"' || c == '\'') {
            skip_string();
        } else {  // a number, date, boolean or something toml::parse refuses
            do ++pos_;
            while (pos_ < text_.size() && !ends_scalar(text_[pos_]));
        }
    }

    // "...", '...', """...""" or '''...''' (which may span lines).
    void skip_string() {
        const char quote = text_[pos_];
        const std::string triple(3, quote);
        const bool multiline = at(triple.c_str());
        pos_ += multiline ? 3 : 1;
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '\\' && quote == '"') {
                pos_ = std::min(pos_ + 2, text_.size());
            } else if (!multiline && c == '\n') {
                return;  // unterminated
            } else if (c == quote && !multiline) {
                ++pos_;
                return;
            } else if (c == quote && at(triple.c_str())) {
                pos_ += 3;
                for (int k = 0; k < 2 && at(quote); ++k) ++pos_;  // """a""""" ends in two quotes of the string
                return;
            } else {
                ++pos_;
            }
        }
    }

    // The parts of a key, a.b."c.d" (three): no more than can be within the
    // limit and one more, so that a key of a million parts costs no memory.
    std::vector<KeyPart> read_key() {
        std::vector<KeyPart> parts;
        while (parts.size() < static_cast<std::size_t>(kMaxNesting) + 2) {
            skip_blank(false);
            if (pos_ >= text_.size() || !starts_key(text_[pos_])) break;
            KeyPart part{pos_, {}};
            if (at('"')) {
                part.name = read_basic_key();
            } else if (at('\'')) {
                const std::size_t end = std::min(text_.find_first_of("'\n", pos_ + 1), text_.size());
                part.name = text_.substr(pos_ + 1, end - pos_ - 1);
                pos_ = end < text_.size() && text_[end] == '\'' ? end + 1 : end;
            } else {
                while (pos_ < text_.size() && is_bare(text_[pos_])) part.name += text_[pos_++];
            }
            parts.push_back(std::move(part));
            skip_blank(false);
            if (!at('.')) break;
            ++pos_;
        }
        return parts;
    }

    // A "quoted" key part, its escapes decoded (\u0061 is the key a).
    std::string read_basic_key() {
        static const std::map<char, char> kEscapes = {{'b', '\b'}, {'t', '\t'}, {'n', '\n'},  {'f', '\f'},
                                                      {'r', '\r'}, {'"', '"'},  {'\\', '\\'}, {'e', '\x1b'}};
        std::string name;
        ++pos_;
        while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') {
            if (text_[pos_] != '\\' || pos_ + 1 >= text_.size()) {
                name += text_[pos_++];
                continue;
            }
            const char escape = text_[pos_ + 1];
            pos_ += 2;
            const std::size_t digits = escape == 'u' ? 4 : escape == 'U' ? 8 : 0;
            if (digits > 0 && pos_ + digits <= text_.size()) {
                const std::string hex = text_.substr(pos_, digits);
                if (hex.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos) {
                    append_utf8(name, static_cast<uint32_t>(std::stoul(hex, nullptr, 16)));
                    pos_ += digits;
                    continue;
                }
            }
            const auto known = kEscapes.find(escape);
            name += known == kEscapes.end() ? escape : known->second;
        }
        if (at('"')) ++pos_;
        return name;
    }

    const std::string& text_;
    std::size_t pos_ = 0;
    std::optional<std::size_t> too_deep_;
    int table_depth_ = 1;  // the last header's table; the document's own is level 1
    std::vector<Open> open_;
    std::vector<HeaderTable> headers_{1};  // [0]: the document's table
};

}  // namespace

void check_json_nesting(const std::string& path, const std::string& text, const std::string& what) {
    if (const std::optional<std::size_t> offset = too_deep_json(text)) {
        refuse(path, text, *offset, what, "objects and arrays");
    }
}

void check_toml_nesting(const std::string& path, const std::string& text, const std::string& what) {
    if (const std::optional<std::size_t> offset = TomlNesting(text).too_deep()) {
        refuse(path, text, *offset, what, "tables and arrays");
    }
}

std::string text_position(const std::string& path, const std::string& text, std::size_t offset) {
    const std::size_t end = std::min(offset, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t k = 0; k < end; ++k) {
        if (text[k] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return path + ":" + std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace cdvp
