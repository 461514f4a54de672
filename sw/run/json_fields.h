// Numbers of a JSON file cdvp wrote and a user may have edited (a shared
// software timing, a report read back), checked against what they mean
// before anything uses them: a count is a whole number that fits its type, an
// amount (a time, a spread, a load) a finite number from 0 to its bound. A
// bad one is an InputError naming where it is and what was expected, one
// line: "DIR/KEY.json: baselines.sap.timing_quality.frames_timed: expected a
// count from 0 to 18446744073709551615, got -5".
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

namespace cdvp {

// A time of a frame or a probe, in ns, beyond any measured: 1e15 ns, 11.6
// days (a time past it would make host times and sums overflow to inf).
constexpr double kMaxTimeNs = 1e15;

// The field 'key' of 'object'; a missing one is said to be ("got nothing").
const nlohmann::json& json_field(const nlohmann::json& object, const std::string& key);
// What a refusal says was there instead of what was expected: the value's
// JSON (cut to an excerpt), or "nothing" for a missing field.
std::string json_found(const nlohmann::json& value);

// A count from 'min' to the largest T; 'where' names the field.
uint64_t json_count(const nlohmann::json& value, const std::string& where, uint64_t min, uint64_t max);
template <class T>
T json_count(const nlohmann::json& value, const std::string& where, T min = 0) {
    return static_cast<T>(json_count(value, where, min, std::numeric_limits<T>::max()));
}

// A finite number from 0 to 'max', 'what' saying what it is ("a time") and
// 'unit' following the bound (" ns"): "expected a time from 0 to 1e+15 ns",
// or, when 'max' is the largest double, "expected a load average of 0 or more".
double json_amount(const nlohmann::json& value, const std::string& where, const std::string& what,
                   double max = std::numeric_limits<double>::max(), const std::string& unit = "");
// A time in ns (json_amount up to kMaxTimeNs).
inline double json_time_ns(const nlohmann::json& value, const std::string& where) {
    return json_amount(value, where, "a time", kMaxTimeNs, " ns");
}

}  // namespace cdvp
