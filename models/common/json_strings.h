// Which bytes of JSON text lie inside strings, without parsing it, for the
// checks made on the text itself (how deep it nests, where a NUL byte is).
#pragma once

namespace cdvp {

// Fed the text a byte at a time: a quote opens and closes a string, and
// inside one a backslash escapes the byte after it.
class JsonStrings {
public:
    // Whether 'c', the next byte, belongs to a string (its quotes included).
    bool inside(char c) {
        if (!open_) {
            open_ = c == '"';
            return open_;
        }
        if (escaped_) {
            escaped_ = false;
        } else if (c == '\\') {
            escaped_ = true;
        } else if (c == '"') {
            open_ = false;
        }
        return true;
    }

private:
    bool open_ = false, escaped_ = false;
};

}  // namespace cdvp
