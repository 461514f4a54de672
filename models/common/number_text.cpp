#include "models/common/number_text.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

std::string show(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

}  // namespace

std::string show_number(double value) {
    // The magnitude first: converting a double beyond int64_t's range (or NaN) is undefined.
    if (std::abs(value) < 1e15 && value == static_cast<double>(static_cast<int64_t>(value))) {
        return std::to_string(static_cast<int64_t>(value));
    }
    return show(value);
}

std::pair<std::string, std::string> distinct_figures(double a, double b, int decimals) {
    const auto fixed = [](double value, int places) {
        char text[400];
        std::snprintf(text, sizeof text, "%.*f", places, value);
        return std::string(text);
    };
    int places = decimals;
    while (a != b && places < 12 && fixed(a, places) == fixed(b, places)) ++places;
    return {fixed(a, places), fixed(b, places)};
}

std::string describe_range(double min, double max) { return show_number(min) + " to " + show_number(max); }

std::string describe_range(uint64_t min, uint64_t max) { return std::to_string(min) + " to " + std::to_string(max); }

uint64_t parse_integer_text(const std::string& text, uint64_t min, uint64_t max) {
    const auto refuse = [&] {
        throw std::invalid_argument("expected an integer from " + describe_range(min, max) + ", got '" + excerpt(text) + "'");
    };
    // Digits only: no sign, no blanks, no fraction or exponent.
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) refuse();
    errno = 0;
    const unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
    if (errno == ERANGE || value < min || value > max) refuse();
    return value;
}

double parse_real_text(const std::string& text, double min, double max) {
    const auto refuse = [&] {
        throw std::invalid_argument("expected a number from " + describe_range(min, max) + ", got '" + excerpt(text) + "'");
    };
    // strtod skips leading blanks and reads "nan", "inf" and hex: a decimal
    // number starts with a digit, a sign or a point.
    if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) refuse();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(value) || value < min || value > max) refuse();
    return value;
}

}  // namespace cdvp
