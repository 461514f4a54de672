// Line-oriented reader shared by the trace and pairs CSV parsers, so both
// formats report errors the same way ("NAME:LINE: message", one line).
//
// Framing, the same for both formats: lines end in LF or CRLF (the last line
// may lack its line end); a line holds at most kMaxLineBytes bytes counting
// its line end, and no more than that is ever buffered, so a file without
// line ends (/dev/zero, a binary) fails on line 1 after 4 KiB. Line 1 may
// start with a UTF-8 byte order mark. A CR not followed by LF (old Mac line
// ends), a NUL byte or another control character other than tab is refused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace cdvp {

// The longest line a CSV input may hold, counting its LF or CRLF.
constexpr std::size_t kMaxLineBytes = 4096;

// The refusal of a line past `max_bytes`, after "NAME:LINE: ": one text for
// the reader and for an input read under limits (sw/scene/input_spool.h).
std::string line_too_long(std::size_t max_bytes);

// 'text' cut to ~40 characters and with control characters replaced, so an
// error message stays one short line; quote_found adds single quotes.
std::string shorten_found(std::string_view text);
std::string quote_found(std::string_view text);

// Opens 'path' for reading; InputError "PATH: cannot open: <strerror>", or
// "PATH: is a directory; expected a file".
std::ifstream open_input(const std::string& path);

class CsvReader {
public:
    CsvReader(std::istream& in, std::string name);

    // Reads line 1 and checks it equals 'header' (after a UTF-8 BOM).
    void expect_header(std::string_view header);

    // Reads the next data row and splits it into 'field_count' trimmed
    // fields. Returns false at end of input. Blank lines are allowed only at
    // the end of the input.
    bool next_row(std::size_t field_count);

    std::size_t line() const { return line_; }
    std::string_view field(std::size_t i) const { return fields_[i]; }

    // Field i as a decimal integer 0 .. 2^64-1: digits only (no sign, no
    // fraction, no exponent, no hex); 'what' names it in errors.
    uint64_t uint_field(std::size_t i, const char* what) const;
    // Field i as strtod reads it in the "C" locale, any length: decimal or
    // hex (0x1p-3), +-inf/infinity in any case. Refused: NaN, and finite
    // spellings beyond the double range (1e999), which strtod would turn into
    // an infinity the user did not write. Underflow rounds to the nearest
    // double (a denormal or a signed zero), as any other rounding does.
    double number_field(std::size_t i, const char* what) const;

    // Throws InputError "NAME:LINE: message" for the current line.
    [[noreturn]] void fail(const std::string& message) const;
    [[noreturn]] void fail_at(std::size_t line, const std::string& message) const;

private:
    bool read_line();
    void check_characters() const;

    std::istream& in_;
    std::string name_;
    std::size_t line_ = 0;
    std::string text_;
    std::vector<std::string_view> fields_;
    mutable std::string number_text_;  // NUL-terminated copy of a field for strtod
};

}  // namespace cdvp
