// Line-oriented reader shared by the trace and pairs CSV parsers, so both
// formats report errors the same way ("NAME:LINE: message", one line).
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace cdvp {

// 'text' cut to ~40 characters and with control characters replaced, so an
// error message stays one short line; quote_found adds single quotes.
std::string shorten_found(std::string_view text);
std::string quote_found(std::string_view text);

// Opens 'path' for reading; InputError "PATH: cannot open: <strerror>".
std::ifstream open_input(const std::string& path);

class CsvReader {
public:
    CsvReader(std::istream& in, std::string name);

    // Reads line 1 and checks it equals 'header' (after a trailing '\r').
    void expect_header(std::string_view header);

    // Reads the next data row and splits it into 'field_count' trimmed
    // fields. Returns false at end of input. Blank lines are allowed only at
    // the end of the input.
    bool next_row(std::size_t field_count);

    std::size_t line() const { return line_; }
    std::string_view field(std::size_t i) const { return fields_[i]; }

    // Field i as a non-negative decimal integer; 'what' names it in errors.
    uint64_t uint_field(std::size_t i, const char* what) const;
    // Field i as a number strtod reads (including +-inf), NaN rejected.
    double number_field(std::size_t i, const char* what) const;

    // Throws InputError "NAME:LINE: message" for the current line.
    [[noreturn]] void fail(const std::string& message) const;
    [[noreturn]] void fail_at(std::size_t line, const std::string& message) const;

private:
    bool read_line();

    std::istream& in_;
    std::string name_;
    std::size_t line_ = 0;
    std::string text_;
    std::vector<std::string_view> fields_;
};

}  // namespace cdvp
