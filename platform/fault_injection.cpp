#include "platform/fault_injection.h"

#include <charconv>
#include <sstream>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

constexpr uint64_t kMaxCount = 1'000'000;  // more faults per frame than any frame has transactions

std::string valid_kinds() {
    std::string list;
    for (FaultKind kind : kAllFaultKinds) list += std::string(list.empty() ? "" : ", ") + fault_kind_name(kind);
    return list;
}

[[noreturn]] void fail(const std::string& spec, const std::string& what) {
    throw InputError("'" + excerpt(spec) + "': " + what);
}

// A positive decimal integer up to max, all of text.
uint64_t parse_count(const std::string& spec, const std::string& key, const std::string& text, uint64_t min,
                     uint64_t max) {
    uint64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end || value < min || value > max) {
        fail(spec, key + ": expected an integer from " + std::to_string(min) + " to " + std::to_string(max) + ", found '" + excerpt(text) + "'");
    }
    return value;
}

FaultSpec parse_one(const std::string& spec) {
    const std::size_t at = spec.find('@');
    if (at == std::string::npos) fail(spec, "expected KIND@frame=N[,n=K]");
    const std::string kind_text = spec.substr(0, at);
    FaultSpec parsed{FaultKind::kRetry, 0, 1};
    bool has_frame = false;
    bool known = false;
    for (FaultKind kind : kAllFaultKinds) {
        if (kind_text == fault_kind_name(kind)) {
            parsed.kind = kind;
            known = true;
        }
    }
    if (!known) fail(spec, "unknown fault kind '" + excerpt(kind_text) + "'; expected one of: " + valid_kinds());
    bool has_count = false;
    std::stringstream where(spec.substr(at + 1));
    for (std::string item; std::getline(where, item, ',');) {
        const std::size_t eq = item.find('=');
        const std::string key = item.substr(0, eq);
        const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (key == "frame" && !has_frame) {
            parsed.frame = parse_count(spec, key, value, 0, UINT64_MAX);
            has_frame = true;
        } else if (key == "n" && !has_count) {
            parsed.count = static_cast<uint32_t>(parse_count(spec, key, value, 1, kMaxCount));
            has_count = true;
        } else {
            fail(spec, "unexpected '" + excerpt(item) + "'; expected frame=N and optionally n=K, once each");
        }
    }
    if (!has_frame) fail(spec, "expected frame=N after '@'");
    return parsed;
}

}  // namespace

std::vector<FaultSpec> parse_fault_specs(const std::string& text) {
    std::vector<FaultSpec> specs;
    std::string normalised = text;
    for (char& c : normalised) {
        if (c == ';') c = ' ';
    }
    std::istringstream words(normalised);
    for (std::string spec; words >> spec;) specs.push_back(parse_one(spec));
    if (specs.empty()) throw InputError("expected KIND@frame=N[,n=K]; kinds: " + valid_kinds());
    return specs;
}

std::string to_string(const FaultSpec& spec) {
    std::string text = std::string(fault_kind_name(spec.kind)) + "@frame=" + std::to_string(spec.frame);
    if (spec.count != 1) text += ",n=" + std::to_string(spec.count);
    return text;
}

}  // namespace cdvp
