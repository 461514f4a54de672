// Bad input from users, and their text (file names, keys, values) inside
// one-line messages. Every layer refuses bad input this way.
#pragma once

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace cdvp {

// Bad user input (a file, a flag). what() is one line: "FILE:LINE: message"
// for file input, so the CLI prints it as is and exits with status 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The operating system failed what the input was fine for: a write on a full
// disk, an I/O error. what() is one line ending in the system's own error
// text; the CLI exits with status 4, and a sweep does not take it for a result.
class SystemError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Whether a failed create, write or sync is the system's doing (a full disk
// or quota, an I/O error, no memory or descriptors) rather than the path's
// (missing, not writable, a directory).
inline bool is_system_failure(int error) {
    switch (error) {
        case ENOSPC: case EDQUOT: case EIO: case EFBIG: case ENOMEM: case ENFILE: case EMFILE: case ENOBUFS:
            return true;
        default:
            return false;
    }
}

// "MESSAGE: <the system's text for 'error'>" as a SystemError or an
// InputError, as is_system_failure() tells.
[[noreturn]] inline void throw_os_error(const std::string& message, int error) {
    const std::string text = message + ": " + std::strerror(error);
    if (is_system_failure(error)) throw SystemError(text);
    throw InputError(text);
}

// 'text' safe to print on one line: control characters (a newline in a file
// name, say) become escapes such as \n, \t and \x1b, and C1 controls in
// UTF-8 \u0085 and the like; everything else is kept.
inline std::string printable(const std::string& text) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        const auto byte = static_cast<unsigned char>(c);
        const auto next = k + 1 < text.size() ? static_cast<unsigned char>(text[k + 1]) : 0;
        if (byte == 0xc2 && next >= 0x80 && next <= 0x9f) {  // a C1 control in UTF-8 (CSI, NEL, ...)
            out += std::string("\\u00") + kHex[next >> 4] + kHex[next & 15];
            ++k;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (byte < 0x20 || byte == 0x7f) {
            out += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
        } else {
            out += c;
        }
    }
    return out;
}

// A user-supplied value (an option's argument, a preset string, a trace
// field) quoted in a message: printable(), cut to its first kExcerptBytes
// bytes followed by "... (N bytes)" when longer, so that a 100 KB value still
// gives a short one-line message. The cut never splits a UTF-8 sequence.
constexpr std::size_t kExcerptBytes = 60;
inline std::string excerpt(const std::string& text) {
    if (text.size() <= kExcerptBytes) return printable(text);
    std::size_t cut = kExcerptBytes;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return printable(text.substr(0, cut)) + "... (" + std::to_string(text.size()) + " bytes)";
}

// Whether a name ends with a suffix (a file's extension, a column's kind).
inline bool ends_with(const std::string& text, const std::string& end) {
    return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// Levenshtein distance: how far a misspelt name is from a valid one, so a
// refusal can suggest the nearest.
inline std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace cdvp
