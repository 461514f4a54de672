// The ranges of a sweep's lists, A:B:+S and A:B:xF. A range of whole numbers
// steps in 64-bit integers, exactly, and prints every value in full (an
// integer setting takes 10000000000000000, not 1e+16); any other steps in
// doubles and counts B as reached up to a billionth of a step, so that B's
// own size never adds or loses points. The count is known before a value is
// made, so a range too long is refused at once, with its count.
#include "sw/study/sweep_grid.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

[[noreturn]] void refuse_range(const std::string& label, const std::string& list, const std::string& why) {
    throw InputError(label + ": '" + excerpt(list) + "': " + why);
}

// A finite decimal number, whole string; nothing else (no hex, no inf).
bool parse_number(const std::string& text, double& value) {
    if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string::npos) return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

// The number as a 64-bit integer when it is one: digits as written (no
// rounding through a double), or a whole double within 2^53, where doubles
// are exact ("1e16").
bool whole_number(const std::string& text, double value, int64_t& whole) {
    const std::string digits = !text.empty() && (text[0] == '-' || text[0] == '+') ? text.substr(1) : text;
    if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos) {
        errno = 0;
        char* end = nullptr;
        const long long parsed = std::strtoll(text.c_str(), &end, 10);
        if (errno == ERANGE || end != text.c_str() + text.size()) return false;
        whole = parsed;
        return true;
    }
    constexpr double kExact = 9007199254740992.0;  // 2^53
    if (value != std::floor(value) || std::fabs(value) > kExact) return false;
    whole = static_cast<int64_t>(value);
    return true;
}

std::string format_real(double value) {
    char text[64];
    if (std::fabs(value) < 9.0e15 && value == std::floor(value)) {
        std::snprintf(text, sizeof text, "%.0f", value);
    } else {
        std::snprintf(text, sizeof text, "%.12g", value);
    }
    return text;
}

struct Range {
    std::string list, label;
    std::string from_text, to_text, step_text;
    double from = 0, to = 0, step = 0;
    bool geometric = false;

    void check_count(long double count) const {
        if (count > static_cast<long double>(kMaxAxisValues)) {
            refuse_range(label, list, count_text(count) + " values, more than " + std::to_string(kMaxAxisValues));
        }
    }

    // Whole A and step: exact integer steps, B taken down to a whole number.
    bool integral(std::vector<std::string>& values) const {
        int64_t a = 0, s = 0;
        if (!whole_number(from_text, from, a) || !whole_number(step_text.substr(1), step, s)) return false;
        constexpr double kTop = 9.2e18;  // below INT64_MAX: B beyond it is taken as INT64_MAX
        int64_t b = std::numeric_limits<int64_t>::max();
        if (to < kTop && !whole_number(to_text, to, b)) b = static_cast<int64_t>(std::floor(to));
        if (b < a) refuse_range(label, list, "A is above B");
        if (geometric) {
            for (int64_t value = a;; value *= s) {
                values.push_back(std::to_string(value));
                if (value > b / s) break;  // the next would pass B (or overflow)
            }
            return true;
        }
        // b - a and each a + k s in unsigned arithmetic: exact, since b >= a and every value lies in [a, b].
        const uint64_t steps = (static_cast<uint64_t>(b) - static_cast<uint64_t>(a)) / static_cast<uint64_t>(s);
        check_count(static_cast<long double>(steps) + 1);
        for (uint64_t k = 0; k <= steps; ++k) {
            values.push_back(std::to_string(static_cast<int64_t>(static_cast<uint64_t>(a) + k * static_cast<uint64_t>(s))));
        }
        return true;
    }

    void real(std::vector<std::string>& values) const {
        constexpr double kReach = 1e-9;  // of a step
        // In long double: a count past a double's range is still told.
        const long double steps = geometric ? std::log(static_cast<long double>(to) / from) / std::log(static_cast<long double>(step))
                                            : (static_cast<long double>(to) - from) / step;
        const long double count = std::floor(steps + kReach) + 1;
        check_count(count);
        for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
            const double n = static_cast<double>(k);
            values.push_back(format_real(geometric ? from * std::pow(step, n) : from + step * n));
        }
    }
};

}  // namespace

std::string count_text(long double count) {
    char text[64];
    std::snprintf(text, sizeof text, count < 1e19L ? "%.0Lf" : "%.3Lg", count);
    return text;
}

std::vector<std::string> expand_range(const std::string& list, const std::string& label) {
    const std::size_t first_colon = list.find(':');
    const std::size_t second_colon = first_colon == std::string::npos ? first_colon : list.find(':', first_colon + 1);
    if (second_colon == std::string::npos || list.find(':', second_colon + 1) != std::string::npos) {
        refuse_range(label, list, "expected a,b,c or A:B:xF or A:B:+S");
    }
    Range r{list, label, list.substr(0, first_colon), list.substr(first_colon + 1, second_colon - first_colon - 1),
            list.substr(second_colon + 1)};
    if (!parse_number(r.from_text, r.from) || !parse_number(r.to_text, r.to)) {
        refuse_range(label, list, "expected numbers A and B in A:B:xF or A:B:+S");
    }
    r.geometric = !r.step_text.empty() && r.step_text[0] == 'x';
    if (r.step_text.empty() || (!r.geometric && r.step_text[0] != '+') || !parse_number(r.step_text.substr(1), r.step)) {
        refuse_range(label, list, "expected the step as xF (a factor) or +S (an increment) after A:B:");
    }
    if (r.from > r.to) refuse_range(label, list, "A is above B");
    if (r.geometric && (r.step <= 1 || r.from <= 0)) refuse_range(label, list, "a geometric range needs A > 0 and a factor above 1");
    if (!r.geometric && r.step <= 0) refuse_range(label, list, "an arithmetic range needs an increment above 0");
    std::vector<std::string> values;
    if (!r.integral(values)) r.real(values);
    return values;
}

}  // namespace cdvp
