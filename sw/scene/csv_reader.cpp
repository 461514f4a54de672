#include "sw/scene/csv_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "sw/scene/scene.h"

namespace cdvp {

namespace {

constexpr std::size_t kMaxQuoted = 40;

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

std::string shorten_found(std::string_view text) {
    std::string out;
    std::size_t n = text.size() > kMaxQuoted ? kMaxQuoted - 3 : text.size();
    for (std::size_t i = 0; i < n; ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        out += (c < 0x20 || c == 0x7f) ? '?' : text[i];
    }
    if (n < text.size()) {
        out += "...";
    }
    return out;
}

std::string quote_found(std::string_view text) {
    return "'" + shorten_found(text) + "'";
}

std::ifstream open_input(const std::string& path) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(path + ": cannot open: " +
                         std::strerror(errno != 0 ? errno : ENOENT));
    }
    return in;
}

CsvReader::CsvReader(std::istream& in, std::string name)
    : in_(in), name_(std::move(name)) {}

bool CsvReader::read_line() {
    if (!std::getline(in_, text_)) {
        if (in_.bad()) {
            fail_at(line_ + 1, "read error; expected a readable text file");
        }
        return false;
    }
    ++line_;
    if (!text_.empty() && text_.back() == '\r') {
        text_.pop_back();
    }
    return true;
}

void CsvReader::expect_header(std::string_view header) {
    std::string expected = "expected header '" + std::string(header) + "', found ";
    if (!read_line()) {
        fail_at(1, expected + "end of file");
    }
    if (text_ != header) {
        fail(expected + quote_found(text_));
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
    std::string_view s = fields_[i];
    // strtod needs a NUL-terminated string; a field longer than the buffer
    // is not a sensible number, so it is reported rather than parsed.
    char buf[128];
    bool fits = !s.empty() && s.size() < sizeof buf;
    char* end = buf;
    double value = 0.0;
    if (fits) {
        std::memcpy(buf, s.data(), s.size());
        buf[s.size()] = '\0';
        // Overflow gives +-HUGE_VAL (= +-inf) and underflow a denormal or
        // zero, both wanted; errno is therefore not consulted.
        value = std::strtod(buf, &end);
    }
    if (!fits || end != buf + s.size()) {
        fail(std::string("field '") + what +
             "': expected a decimal number, found " + quote_found(s));
    }
    if (std::isnan(value)) {
        fail(std::string("field '") + what +
             "': NaN is not allowed (expected a number or +-inf)");
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
