#include "sw/run/json_fields.h"

#include <cmath>
#include <cstdio>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

using nlohmann::json;

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace

std::string json_found(const json& value) { return value.is_discarded() ? "nothing" : excerpt(value.dump()); }

const json& json_field(const json& object, const std::string& key) {
    static const json kMissing(json::value_t::discarded);
    if (!object.is_object()) return kMissing;
    const auto at = object.find(key);
    return at == object.end() ? kMissing : *at;
}

uint64_t json_count(const json& value, const std::string& where, uint64_t min, uint64_t max) {
    // Only a whole number written without a sign, point or exponent is a
    // count: -5 and 5.0 are not, whatever a cast would make of them.
    if (value.is_number_unsigned() && value.get<uint64_t>() >= min && value.get<uint64_t>() <= max) {
        return value.get<uint64_t>();
    }
    throw InputError(where + ": expected a count from " + std::to_string(min) + " to " + std::to_string(max) +
                     ", got " + json_found(value));
}

double json_amount(const json& value, const std::string& where, const std::string& what, double max,
                   const std::string& unit) {
    if (value.is_number() && std::isfinite(value.get<double>()) && value.get<double>() >= 0 &&
        value.get<double>() <= max) {
        return value.get<double>();
    }
    const std::string range = max == std::numeric_limits<double>::max() ? " of 0 or more"
                                                                          : " from 0 to " + number_text(max) + unit;
    throw InputError(where + ": expected " + what + range + ", got " + json_found(value));
}

}  // namespace cdvp
