#include "sw/run/host_factor.h"

#include <cmath>
#include <cstdio>

#include "models/common/input_path.h"
#include "models/common/number_text.h"
#include "models/common/user_text.h"
#include "sw/run/reference_workload.h"
#include "sw/timing/spread.h"

namespace cdvp {

namespace {

std::string factor_text(double factor) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", factor);
    return text;
}

// Whether a profile is there to read; one that cannot be looked at (a link
// loop, a directory it may not search) is refused, not passed over.
bool file_exists(const std::string& path, const std::string& label) {
    if (path.empty()) return false;
    const InputPresence presence = input_presence(path);
    if (presence.kind == InputPresence::Kind::kUnreadable) {
        throw InputError(label + ": " + excerpt(path) + ": cannot open: " + presence.reason);
    }
    return presence.present();
}

// A factor must lie where --host-factor may: a profile (or a preset) whose
// times give one outside it describes no machine, and would print inf or 0
// for every speedup. Refused naming the profile's field, its time, and the
// times that would be in range.
void check_factors(const std::map<std::string, double>& factors, const HostConfig& host, const HostProfile& profile,
                   const std::string& path) {
    const Setting& bound = *find_setting("host.speed_factor");
    for (const auto& [name, factor] : factors) {
        if (name == "overall" || (std::isfinite(factor) && factor >= bound.min && factor <= bound.max)) continue;
        const double modelled = host_reference_ns(host, name);
        throw InputError(path + ": reference." + name + ".reference_native_ns: " +
                         show_number(profile.reference.at(name).reference_native_ns) + " ns gives a host factor of " +
                         (std::isfinite(factor) ? factor_text(factor) : std::string("over 1e308")) + " against " + printable(host.name) + "'s " + show_number(modelled) +
                         " ns (host.reference_" + name + "_host_ns); expected a time from " +
                         show_number(modelled / bound.max) + " to " + show_number(modelled / bound.min) +
                         " ns, a factor of " + describe_range(bound.min, bound.max) + " as host.speed_factor allows");
    }
}

}  // namespace

double HostTiming::factor(const std::string& baseline) const {
    const auto at = factors.find(baseline);
    return at != factors.end() ? at->second : overall;
}

const char* HostTiming::basis_name() const {
    switch (basis) {
        case Basis::kCalibrated: return "calibrated";
        case Basis::kUncalibrated: return "uncalibrated";
        case Basis::kUnstated: return "unstated";
        case Basis::kOverridden: return "overridden";
    }
    return "?";
}

std::string HostTiming::describe() const {
    switch (basis) {
        case Basis::kCalibrated: {
            std::string each;
            for (const auto& [name, f] : factors) each += (each.empty() ? "" : ", ") + name + " x " + factor_text(f);
            return "native x " + factor_text(overall) + " (" + each + "; calibrated by " + printable(profile_path) +
                   ")";
        }
        case Basis::kUncalibrated:
            return "native x " + factor_text(overall) + " (the preset's uncalibrated estimate)";
        case Basis::kUnstated: return "native x " + factor_text(overall);
        case Basis::kOverridden: return "native x " + factor_text(overall) + " (--host-factor)";
    }
    return {};
}

double host_reference_ns(const HostConfig& host, const std::string& baseline) {
    if (baseline == "sap") return host.reference_sap_host_ns;
    if (baseline == "dbvt") return host.reference_dbvt_host_ns;
    if (baseline == "brute") return host.reference_brute_host_ns;
    if (baseline == "soa") return host.reference_soa_host_ns;
    if (baseline == "sap_mt") return host.reference_sap_mt_host_ns;
    return 0;
}

std::map<std::string, double> derive_factors(const HostConfig& host, const HostProfile& profile) {
    std::map<std::string, double> factors;
    std::vector<double> each;
    for (const std::string& name : reference_workload::baselines()) {
        const double modelled = host_reference_ns(host, name);
        const auto measured = profile.reference.find(name);
        if (modelled <= 0 || measured == profile.reference.end() || measured->second.reference_native_ns <= 0) continue;
        factors[name] = modelled / measured->second.reference_native_ns;
        each.push_back(factors[name]);
    }
    if (!factors.empty()) factors["overall"] = geometric_mean(each);
    return factors;
}

HostTiming resolve_host_timing(const HostConfig& host, bool factor_given, const std::string& profile_label) {
    HostTiming timing;
    timing.host = host.name;
    timing.uncalibrated_factor = host.speed_factor;
    timing.overall = host.speed_factor;
    timing.profile_path = host.profile.empty() ? default_host_profile_path() : host.profile;
    bool stated = false;
    for (const std::string& name : reference_workload::baselines()) stated = stated || host_reference_ns(host, name) > 0;
    if (factor_given) {
        timing.basis = HostTiming::Basis::kOverridden;
        return timing;
    }
    // A profile named on the command line must be there; the default one may not be.
    if (!host.profile.empty() && !file_exists(host.profile, profile_label)) {
        throw InputError(profile_label + ": " + excerpt(host.profile) + ": no such file (cdvp calibrate --out " +
                         excerpt(host.profile) + " writes one)");
    }
    // A profile named is read whatever the host states, so a damaged one is never passed over in silence.
    const bool named = !host.profile.empty();
    if (!stated && !named) return timing;
    if (!named && !file_exists(timing.profile_path, "the default host profile")) {
        timing.basis = HostTiming::Basis::kUncalibrated;
        return timing;
    }
    const HostProfile profile = read_host_profile(timing.profile_path);
    if (!stated) return timing;
    timing.basis = HostTiming::Basis::kCalibrated;
    timing.factors = derive_factors(host, profile);
    check_factors(timing.factors, host, profile, timing.profile_path);
    timing.overall = timing.factors.at("overall");
    timing.factors.erase("overall");
    timing.profile_sha256 = profile.sha256;
    timing.profile_machine = profile.machine.cpu_model + ", " + profile.created;
    timing.profile_spread = profile.spread;
    timing.profile_target_spread = profile.target_spread;
    timing.profile_load = profile.load_average_start;
    timing.probe_reference_ns = profile.probe_native_ns;
    return timing;
}

HostTiming resolve_host_timing(const SettingValues& values) {
    const SettingOrigin::Kind origin = values.origin(*find_setting("host.speed_factor")).kind;
    const bool given = origin != SettingOrigin::Kind::kDefault && origin != SettingOrigin::Kind::kPreset;
    return resolve_host_timing(values.settings().host, given, values.where(*find_setting("host.profile")));
}

std::string uncalibrated_note(const HostTiming& timing) {
    if (timing.profile_poor()) {
        const auto [spread, target] = distinct_figures(100 * timing.profile_spread, 100 * timing.profile_target_spread, 1);
        char text[200];
        std::snprintf(text, sizeof text, "its runs stayed %s%% apart, over the %s%% it was asked for, at load %.2f",
                      spread.c_str(), target.c_str(), timing.profile_load[0]);
        return "host factors rest on a poor profile, " + printable(timing.profile_path) + ": " + text +
               " (cdvp calibrate on a quieter machine; docs/timing.md)";
    }
    if (timing.basis != HostTiming::Basis::kUncalibrated) return {};
    return "host factor " + factor_text(timing.overall) + " for " + printable(timing.host) +
           " is the preset's uncalibrated estimate: no host profile" +
           (timing.profile_path.empty() ? std::string() : " at " + printable(timing.profile_path)) +
           " (cdvp calibrate writes one; docs/timing.md)";
}

}  // namespace cdvp
