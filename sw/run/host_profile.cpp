#include "sw/run/host_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "models/common/user_directories.h"
#include "models/common/user_text.h"
#include "platform/settings/preset_json.h"
#include "sw/output/digest.h"
#include "sw/run/reference_workload.h"
#include "sw/run/report_provenance.h"

namespace cdvp {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "cdvp host profile";
// 2: times are the thread's CPU time, runs repeat until they agree (calibration section).
constexpr int kFormatVersion = 2;
constexpr const char* kWhat = "a host profile (cdvp calibrate writes one)";

json workload_json(uint32_t repeat) {
    namespace w = reference_workload;
    return {{"version", w::kVersion}, {"scene", w::kScene},   {"seed", w::kSeed},       {"frames", w::kFrames},
            {"warmup", w::kWarmup},   {"objects", w::objects()}, {"baselines", w::baselines()}, {"repeat", repeat}};
}

// The fields of one profile file, read with every refusal naming the file
// and the field ("PATH: reference.sap.reference_native_ns: ...").
class ProfileFields {
public:
    ProfileFields(std::string path, const json& root) : path_(std::move(path)), root_(root) {}

    const json& at(const std::string& dotted) const {
        const json* node = &root_;
        std::size_t start = 0;
        while (true) {
            const std::size_t dot = dotted.find('.', start);
            const std::string key = dotted.substr(start, dot - start);
            if (!node->is_object() || !node->contains(key)) fail(dotted, "missing");
            node = &(*node)[key];
            if (dot == std::string::npos) return *node;
            start = dot + 1;
        }
    }
    std::string text(const std::string& field) const {
        const json& value = at(field);
        if (!value.is_string()) fail(field, "expected a string");
        return value.get<std::string>();
    }
    double number(const std::string& field, double lo, double hi) const {
        const json& value = at(field);
        if (!value.is_number() || !(value.get<double>() >= lo && value.get<double>() <= hi)) {
            fail(field, "expected a number from " + shown(lo) + " to " + shown(hi) + ", got " + excerpt(value.dump()));
        }
        return value.get<double>();
    }
    // A field of the reference workload: the profile must have timed this one.
    void same(const std::string& field, const json& expected) const {
        const json& value = at(field);
        if (value != expected) {
            fail(field, "a profile of another reference workload (" + excerpt(value.dump()) + ", this cdvp times " +
                            excerpt(expected.dump()) + "): run cdvp calibrate again");
        }
    }
    [[noreturn]] void fail(const std::string& field, const std::string& why) const {
        throw InputError(path_ + ": " + field + ": " + why);
    }

private:
    static std::string shown(double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", value);
        return text;
    }
    std::string path_;
    const json& root_;
};

std::array<double, 3> read_load(const ProfileFields& fields, const std::string& field) {
    const json& value = fields.at(field);
    std::array<double, 3> load{};
    if (!value.is_array() || value.size() != 3) fields.fail(field, "expected the 1, 5 and 15 minute load averages");
    for (std::size_t k = 0; k < 3; ++k) {
        if (!value[k].is_number() || !(value[k].get<double>() >= 0)) {
            fields.fail(field, "expected the 1, 5 and 15 minute load averages");
        }
        load[k] = value[k].get<double>();
    }
    return load;
}

}  // namespace

double ReferenceTiming::spread() const {
    if (kept_means_native_ns.empty()) return 0;
    const auto [lo, hi] = std::minmax_element(kept_means_native_ns.begin(), kept_means_native_ns.end());
    return *lo > 0 ? *hi / *lo - 1 : 0;
}

std::string host_profile_json(const HostProfile& p) {
    json reference = json::object();
    for (const auto& [name, baseline] : p.reference) {
        json sizes = json::array();
        for (const ReferenceTiming& t : baseline.sizes) {
            sizes.push_back({{"objects", t.objects},
                             {"mean_native_ns", t.mean_native_ns},
                             {"run_means_native_ns", t.run_means_native_ns},
                             {"kept_means_native_ns", t.kept_means_native_ns},
                             {"spread", t.spread()}});
        }
        reference[name] = {{"reference_native_ns", baseline.reference_native_ns}, {"sizes", sizes}};
    }
    const json profile = {
        {"format", kFormat},
        {"format_version", kFormatVersion},
        {"created", p.created},
        {"machine",
         {{"cpu_model", p.machine.cpu_model},
          {"cpu_mhz", p.machine.cpu_mhz},
          {"cores_online", p.machine.cores_online},
          {"cores_allowed", p.machine.cores_allowed},
          {"kernel", p.machine.kernel}}},
        {"build",
         {{"cdvp_version", p.build.version},
          {"git_commit", p.build.git_commit},
          {"compiler", p.build.compiler},
          {"build_type", p.build.build_type},
          {"flags", p.build.flags}}},
        {"load_average", {{"start", load_json(p.load_average_start)}, {"end", load_json(p.load_average_end)}}},
        {"workload", workload_json(p.repeat)},
        {"calibration",
         {{"clock", "thread CPU time"},
          {"runs", p.runs},
          {"seconds", p.seconds},
          {"spread", p.spread},
          {"target_spread", p.target_spread},
          {"disturbed_frames", p.disturbed_frames},
          {"probe_native_ns", p.probe_native_ns},
          {"quality", p.poor() ? "poor" : "good"}}},
        {"reference", reference},
        {"factors", p.factors}};
    return profile.dump(2) + '\n';
}

HostProfile read_host_profile(const std::string& path) { return parse_host_profile(path, read_small_file(path, kWhat)); }

HostProfile parse_host_profile(const std::string& path, const std::string& text) {
    const json root = parse_preset(path, text, kWhat);
    const ProfileFields fields(path, root);
    if (fields.text("format") != kFormat) fields.fail("format", std::string("expected \"") + kFormat + "\"");
    if (fields.at("format_version") != kFormatVersion) {
        fields.fail("format_version", "expected " + std::to_string(kFormatVersion) +
                                          " (a profile of another cdvp version: run cdvp calibrate again)");
    }
    HostProfile p;
    p.sha256 = sha256_hex(text);
    p.repeat = static_cast<uint32_t>(fields.number("workload.repeat", 1, 1000));
    json expected = workload_json(p.repeat);
    if (fields.at("workload.version") == reference_workload::kFirstVersion) {
        // Before sap_mt joined: the other baselines' times still hold.
        expected["version"] = reference_workload::kFirstVersion;
        expected["baselines"] = reference_workload::first_version_baselines();
    }
    for (const auto& [key, value] : expected.items()) fields.same("workload." + key, value);
    p.created = fields.text("created");
    p.runs = static_cast<uint32_t>(fields.number("calibration.runs", p.repeat, 1e6));
    p.spread = fields.number("calibration.spread", 0, 1e6);
    p.target_spread = fields.number("calibration.target_spread", 0, 1);
    p.probe_native_ns = fields.number("calibration.probe_native_ns", 0, 1e9);
    p.load_average_start = read_load(fields, "load_average.start");
    p.load_average_end = read_load(fields, "load_average.end");
    p.machine.cpu_model = fields.text("machine.cpu_model");
    p.machine.cpu_mhz = fields.number("machine.cpu_mhz", 0, 1e6);
    p.build.compiler = fields.text("build.compiler");
    p.build.flags = fields.text("build.flags");
    for (const std::string& name : expected["baselines"].get<std::vector<std::string>>()) {
        BaselineReference& baseline = p.reference[name];
        const std::string field = "reference." + name + ".reference_native_ns";
        baseline.reference_native_ns = fields.number(field, 0, 1e12);
        if (baseline.reference_native_ns <= 0) fields.fail(field, "expected a positive time, got 0");
        const json& sizes = fields.at("reference." + name + ".sizes");
        if (!sizes.is_array()) fields.fail("reference." + name + ".sizes", "expected a list");
        for (std::size_t k = 0; k < sizes.size(); ++k) {
            const std::string at = "reference." + name + ".sizes." + std::to_string(k);
            const json& size = sizes[k];
            const auto number = [&](const char* key, double lo, double hi) {
                if (!size.is_object() || !size.contains(key)) fields.fail(at + "." + key, "missing");
                const json& value = size[key];
                if (!value.is_number() || !(value.get<double>() >= lo && value.get<double>() <= hi)) {
                    fields.fail(at + "." + key, "expected a number from " + std::to_string(lo) + " to " + std::to_string(hi));
                }
                return value.get<double>();
            };
            ReferenceTiming t;
            t.objects = static_cast<uint64_t>(number("objects", 1, 1e9));
            t.mean_native_ns = number("mean_native_ns", 0, 1e12);
            if (!size.contains("kept_means_native_ns") || !size["kept_means_native_ns"].is_array()) {
                fields.fail(at + ".kept_means_native_ns", "expected a list of times");
            }
            for (const json& mean : size["kept_means_native_ns"]) {
                if (!mean.is_number() || !(mean.get<double>() >= 0)) fields.fail(at + ".kept_means_native_ns", "expected a list of times");
                t.kept_means_native_ns.push_back(mean.get<double>());
            }
            baseline.sizes.push_back(std::move(t));
        }
    }
    return p;
}

std::string default_host_profile_path() {
    const std::string config = user_base_directory("XDG_CONFIG_HOME", ".config");
    return config.empty() ? config : config + "/cdvp/host-profile.json";
}

}  // namespace cdvp
