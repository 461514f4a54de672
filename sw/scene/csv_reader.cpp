#include "sw/scene/csv_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <locale.h>
#include <string>
#include <utility>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "sw/scene/scene.h"

namespace cdvp {

namespace {

bool is_blank_char(char c) {
    return c == ' ' || c == '\t';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_blank_char(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && is_blank_char(s.back())) {
        s.remove_suffix(1);
    }
    return s;
}

}  // namespace

std::string line_too_long(std::size_t max_bytes) {
    const std::string limit = std::to_string(max_bytes);
    return "line longer than " + limit + " bytes; expected at most " + limit + " bytes a line, counting its line end";
}

std::string shorten_found(std::string_view text) { return excerpt(std::string(text)); }

std::string quote_found(std::string_view text) {
    return "'" + shorten_found(text) + "'";
}

std::ifstream open_input(const std::string& path) {
    // A directory opens as a stream that reads nothing, which would be
    // reported as an empty file; name the real problem.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        refuse_input(path, EISDIR, "expected a file");
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        refuse_input(path, errno != 0 ? errno : ENOENT);
    }
    return in;
}

CsvReader::CsvReader(std::istream& in, std::string name)
    : in_(in), name_(std::move(name)) {
    text_.reserve(kMaxLineBytes);
}

// Byte by byte from the stream buffer, so that at most kMaxLineBytes are
// ever held, however long the line is.
bool CsvReader::read_line() {
    constexpr int kEof = std::char_traits<char>::eof();
    std::streambuf* buffer = in_.rdbuf();
    text_.clear();
    std::size_t bytes = 0;  // of this line, line end included
    for (;;) {
        int c = buffer->sbumpc();
        if (c == kEof) {
            if (bytes == 0) {
                return false;
            }
            break;
        }
        if (bytes == 0) {
            ++line_;
        }
        if (++bytes > kMaxLineBytes) {
            fail(line_too_long(kMaxLineBytes));
        }
        if (c == '\n') {
            break;
        }
        if (c == '\r') {
            if (buffer->sgetc() != '\n') {
                check_characters();  // binary input: name the first non-text byte instead
                fail("carriage return not followed by a line feed at column " +
                     std::to_string(text_.size() + 1) +
                     "; expected LF or CRLF line ends");
            }
            continue;  // the LF ends the line on the next byte
        }
        text_.push_back(static_cast<char>(c));
    }
    check_characters();
    return true;
}

void CsvReader::check_characters() const {
    for (std::size_t k = 0; k < text_.size(); ++k) {
        unsigned char c = static_cast<unsigned char>(text_[k]);
        bool control = (c < 0x20 && c != '\t') || c == 0x7f;
        if (!control) {
            continue;
        }
        std::string column = std::to_string(k + 1);
        if (c == 0) {
            fail("NUL byte at column " + column + "; expected a text file");
        }
        char code[8];
        std::snprintf(code, sizeof code, "0x%02x", c);
        fail(std::string("control character ") + code + " at column " + column +
             "; expected printable text");
    }
}

void CsvReader::expect_header(std::string_view header) {
    std::string expected = "expected header '" + std::string(header) + "', found ";
    if (!read_line()) {
        fail_at(1, expected + "end of file");
    }
    // Spreadsheets on Windows save UTF-8 with a byte order mark.
    constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
    std::string_view text = text_;
    if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) {
        text.remove_prefix(kUtf8Bom.size());
    }
    if (text != header) {
        fail(expected + quote_found(text));
    }
}

bool CsvReader::next_row(std::size_t field_count) {
    std::size_t first_blank = 0;
    while (read_line()) {
        if (trim(text_).empty()) {
            if (first_blank == 0) {
                first_blank = line_;
            }
            continue;
        }
        if (first_blank != 0) {
            fail_at(first_blank, "blank line followed by more rows; expected one row "
                                 "per line (blank lines only at the end of the file)");
        }
        fields_.clear();
        std::string_view rest = text_;
        for (;;) {
            std::size_t comma = rest.find(',');
            fields_.push_back(trim(rest.substr(0, comma)));
            if (comma == std::string_view::npos) {
                break;
            }
            rest.remove_prefix(comma + 1);
        }
        if (fields_.size() != field_count) {
            fail("expected " + std::to_string(field_count) +
                 " comma-separated fields, found " + std::to_string(fields_.size()));
        }
        return true;
    }
    return false;
}

uint64_t CsvReader::uint_field(std::size_t i, const char* what) const {
    std::string_view s = fields_[i];
    uint64_t value = 0;
    // from_chars takes digits only: no sign, no space, no fraction, no 0x.
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range) {
        fail(std::string("field '") + what +
             "': expected an integer below 2^64, found " + quote_found(s));
    }
    if (s.empty() || ec != std::errc() || end != s.data() + s.size()) {
        fail(std::string("field '") + what +
             "': expected a non-negative integer, found " + quote_found(s));
    }
    return value;
}

double CsvReader::number_field(std::size_t i, const char* what) const {
    // The "C" locale whatever the process locale is, so '.' is the decimal
    // point everywhere.
    static const locale_t c_locale = newlocale(LC_ALL_MASK, "C", locale_t{});
    std::string_view s = fields_[i];
    number_text_.assign(s);  // strtod needs a NUL-terminated string
    const char* begin = number_text_.c_str();
    char* end = nullptr;
    errno = 0;
    double value = strtod_l(begin, &end, c_locale);
    auto field = [what] { return std::string("field '") + what + "': "; };  // built only on failure
    if (s.empty() || end != begin + number_text_.size()) {
        fail(field() + "expected a decimal number, found " + quote_found(s));
    }
    if (std::isnan(value)) {
        fail(field() + "NaN is not allowed (expected a number or +-inf)");
    }
    if (std::isinf(value) && errno == ERANGE) {
        fail(field() + quote_found(s) +
             " is beyond the double range (about 1.8e308); expected a finite "
             "number in range, or inf / -inf for an unbounded side");
    }
    return value;
}

void CsvReader::fail(const std::string& message) const {
    fail_at(line_, message);
}

void CsvReader::fail_at(std::size_t line, const std::string& message) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + message);
}

}  // namespace cdvp
