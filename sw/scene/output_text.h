// Text from users (file names, keys, values) inside one-line messages.
#pragma once

#include <string>

namespace cdvp {

// 'text' safe to print on one line: control characters (a newline in a file
// name, say) become escapes such as \n, \t and \x1b; everything else is kept.
inline std::string printable(const std::string& text) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n') {
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

}  // namespace cdvp
