#include "sw/run/report_summary.h"

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "sw/run/best_software.h"
#include "sw/run/json_fields.h"

namespace cdvp {

const std::array<const char*, ReportSummary::kPhases> ReportSummary::kPhaseKeys = {
    "upload_ns", "start_ns", "compute_ns", "irq_ns", "readback_ns", "driver_ns", "total_ns"};

namespace {

// mean_KEY, p50_KEY, p99_KEY and max_KEY: flat, like the phases' mean_ keys beside them.
void put_spread(nlohmann::json& json, const std::string& key, const Spread& s) {
    json["mean_" + key] = s.mean;
    json["p50_" + key] = s.p50;
    json["p99_" + key] = s.p99;
    json["max_" + key] = s.max;
}

// Reads one key, naming it and the report when it is missing or of another type.
class Reader {
public:
    Reader(const nlohmann::json& json, std::string where) : json_(json), where_(std::move(where)) {}

    template <class T>
    T get(const std::string& key) const {
        const auto at = json_.find(key);
        if (at == json_.end()) throw InputError(where_ + ": no " + key + " (expected a report of cdvp run)");
        try {
            return at->get<T>();
        } catch (const nlohmann::json::exception&) {
            throw InputError(where_ + ": " + key + " is " + at->type_name() + " (expected a report of cdvp run)");
        }
    }
    Spread spread(const std::string& key) const {
        Spread s;
        s.mean = get<double>("mean_" + key);
        s.p50 = get<double>("p50_" + key);
        s.p99 = get<double>("p99_" + key);
        s.max = get<double>("max_" + key);
        return s;
    }
    Reader in(const std::string& key) const {
        const auto at = json_.find(key);
        if (at == json_.end() || !at->is_object()) {
            throw InputError(where_ + ": no " + key + " section (expected a report of cdvp run)");
        }
        return Reader(*at, where_ + ": " + key);
    }
    const nlohmann::json& json() const { return json_; }

private:
    const nlohmann::json& json_;
    std::string where_;
};

// The board's energy keys, each a flat mean_ figure like the phases'.
std::array<std::pair<const char*, double>, 6> energy_figures(const ReportSummary& s) {
    return {{{"mean_energy_j", s.mean_energy.total_j()},
             {"mean_energy_static_j", s.mean_energy.static_j},
             {"mean_energy_dynamic_j", s.mean_energy.dynamic_j},
             {"mean_energy_bus_j", s.mean_energy.bus_j},
             {"mean_energy_host_j", s.mean_energy.host_j},
             {"mean_energy_per_pair_j", s.mean_energy_per_pair_j}}};
}

}  // namespace

nlohmann::json to_json(const TimingQuality& q) {
    return {{"verdict", q.verdict()},
            {"frames_timed", q.frames_timed},
            {"frames_disturbed", q.frames_disturbed},
            {"frames_retimed", q.frames_retimed},
            {"frames_slowed", q.frames_slowed},
            {"probe_native_ns", q.probe_ns},
            {"tries", q.tries},
            {"never_clean", q.never_clean},
            {"runs", q.runs},
            {"repeat_spread", q.repeat_spread},
            {"load_average_start", q.load_start},
            {"load_average_end", q.load_end}};
}

TimingQuality timing_quality_from_json(const nlohmann::json& json, const std::string& where) {
    if (!json.is_object()) throw InputError(where + ": expected an object (a timing quality cdvp wrote)");
    const auto field = [&](const std::string& key) -> const nlohmann::json& { return json_field(json, key); };
    const auto count = [&](const std::string& key) { return json_count<uint64_t>(field(key), where + "." + key); };
    const auto loads = [&](const std::string& key) {
        const nlohmann::json& value = field(key);
        if (!value.is_array() || value.size() != 3) {
            throw InputError(where + "." + key + ": expected the 1, 5 and 15 minute load averages, got " +
                             json_found(value));
        }
        std::array<double, 3> out{};
        for (std::size_t k = 0; k < 3; ++k) {
            out[k] = json_amount(value[k], where + "." + key + "[" + std::to_string(k) + "]", "a load average");
        }
        return out;
    };
    TimingQuality q;
    q.frames_timed = count("frames_timed");
    q.frames_disturbed = count("frames_disturbed");
    q.frames_retimed = count("frames_retimed");
    q.frames_slowed = count("frames_slowed");
    q.probe_ns = json_time_ns(field("probe_native_ns"), where + ".probe_native_ns");
    q.tries = count("tries");
    q.never_clean = count("never_clean");
    q.runs = json_count<uint32_t>(field("runs"), where + ".runs", 1);
    q.repeat_spread = json_amount(field("repeat_spread"), where + ".repeat_spread", "a spread");
    q.load_start = loads("load_average_start");
    q.load_end = loads("load_average_end");
    return q;
}

nlohmann::json to_json(const ReportSummary& s) {
    nlohmann::json baselines = nlohmann::json::object();
    for (const auto& [name, b] : s.baselines) {
        nlohmann::json& json = baselines[name];
        put_spread(json, "native_ns", b.native_ns);
        put_spread(json, "wall_native_ns", b.wall_native_ns);
        put_spread(json, "host_ns", b.host_ns);
        json["run_means_native_ns"] = b.run_means_native_ns;
        json["host_factor"] = b.host_factor;
        json["speedup"] = b.speedup;
        json["energy_j"] = b.energy_j;
        json["energy_per_pair_j"] = b.energy_per_pair_j;
        json["energy_ratio"] = b.energy_ratio;
        // The software's energy rests on the stated package power; this
        // machine's own, where RAPL can be read, is beside it.
        json["energy_source"] = b.native_energy_j >= 0 ? "rapl" : "stated";
        if (b.native_energy_j >= 0) json["native_energy_j"] = b.native_energy_j;
        json["timing_quality"] = to_json(b.quality);
        json["retimed"] = b.retimed;
        if (!b.timing.empty()) json["timing"] = b.timing;
    }
    nlohmann::json json = {{"frames", s.frames},
                           {"warmup_frames", s.warmup_frames},
                           {"frames_in_means", s.frames_in_means},
                           {"too_few_frames", s.too_few_frames},
                           {"baselines", baselines},
                           {"timing_quality", to_json(s.timing_quality)},
                           {"retime_tries", s.retime_tries},
                           {"pairs", s.pairs},
                           {"load_average_end", s.load_average_end},
                           {"reference_pairs", s.extra.reference_pairs},
                           {"extra_pairs", s.extra.extra_pairs},
                           {"extra_share", s.extra.share()},
                           {"extra_readback_ns", s.extra.extra_readback_ns},
                           {"extra_driver_ns", s.extra.extra_driver_ns}};
    if (!s.best_software.empty()) json["best_software"] = s.best_software;
    if (!s.timing_warning.empty()) json["timing_warning"] = s.timing_warning;
    put_spread(json, "total_ns", s.total_ns);
    put_spread(json, "latency_ns", s.latency_ns);
    put_spread(json, "sim_wall_native_ns", s.sim_wall_native_ns);
    // After the spread: mean_total_ns is the phases' mean, summed as they are.
    for (std::size_t k = 0; k < ReportSummary::kPhases; ++k) {
        json[std::string("mean_") + ReportSummary::kPhaseKeys[k]] = s.mean_phase_ns[k];
    }
    for (const auto& [key, value] : energy_figures(s)) json[key] = value;
    json["host_package_w"] = s.host_package_w;
    return json;
}

ReportSummary summary_from_json(const nlohmann::json& json, const std::string& source) {
    if (!json.is_object()) throw InputError(source + ": summary is not an object (expected a report of cdvp run)");
    const Reader r(json, source + ": summary");
    ReportSummary s;
    s.frames = r.get<uint64_t>("frames");
    s.warmup_frames = r.get<uint64_t>("warmup_frames");
    s.frames_in_means = r.get<uint64_t>("frames_in_means");
    s.too_few_frames = r.get<bool>("too_few_frames");
    s.pairs = r.get<uint64_t>("pairs");
    s.load_average_end = r.get<std::array<double, 3>>("load_average_end");
    s.extra.reference_pairs = r.get<uint64_t>("reference_pairs");
    s.extra.extra_pairs = r.get<uint64_t>("extra_pairs");
    s.extra.extra_readback_ns = r.get<double>("extra_readback_ns");
    s.extra.extra_driver_ns = r.get<double>("extra_driver_ns");
    s.total_ns = r.spread("total_ns");
    // Reports from before frames were pipelined ran one frame at a time.
    s.latency_ns = json.contains("mean_latency_ns") ? r.spread("latency_ns") : s.total_ns;
    s.sim_wall_native_ns = r.spread("sim_wall_native_ns");
    for (std::size_t k = 0; k < ReportSummary::kPhases; ++k) {
        s.mean_phase_ns[k] = r.get<double>(std::string("mean_") + ReportSummary::kPhaseKeys[k]);
    }
    const Reader baselines = r.in("baselines");
    for (const auto& [name, ignored] : baselines.json().items()) {
        const Reader b = baselines.in(name);
        BaselineSummary& out = s.baselines[name];
        out.native_ns = b.spread("native_ns");
        out.host_ns = b.spread("host_ns");
        out.run_means_native_ns = b.get<std::vector<double>>("run_means_native_ns");
        out.host_factor = b.get<double>("host_factor");
        out.speedup = b.get<double>("speedup");
        // Reports from before CPU time was the estimator have no wall time beside it, nor a quality.
        if (b.json().contains("mean_wall_native_ns")) out.wall_native_ns = b.spread("wall_native_ns");
        if (b.json().contains("timing_quality")) {
            out.quality = timing_quality_from_json(b.json()["timing_quality"],
                                                   source + ": summary: baselines: " + name + ": timing_quality");
        }
        if (b.json().contains("timing")) out.timing = b.get<std::string>("timing");
        // Reports from before energy was modelled have none.
        if (b.json().contains("energy_j")) {
            out.energy_j = b.get<double>("energy_j");
            out.energy_per_pair_j = b.get<double>("energy_per_pair_j");
            out.energy_ratio = b.get<double>("energy_ratio");
        }
        if (b.json().contains("native_energy_j")) out.native_energy_j = b.get<double>("native_energy_j");
        if (b.json().contains("retimed")) out.retimed = b.get<std::vector<std::array<double, 3>>>("retimed");
    }
    // Reports from before the fastest software was named: the fastest of their baselines.
    if (json.contains("best_software")) {
        s.best_software = r.get<std::string>("best_software");
        if (s.baselines.count(s.best_software) == 0) {
            throw InputError(source + ": summary: best_software: '" + excerpt(s.best_software) +
                             "' is none of the summary's baselines");
        }
    } else if (const std::optional<std::string> fastest = fastest_baseline(s)) {
        s.best_software = *fastest;
    }
    if (json.contains("timing_quality")) {
        s.timing_quality = timing_quality_from_json(json["timing_quality"], source + ": summary: timing_quality");
    }
    if (json.contains("retime_tries")) s.retime_tries = r.get<uint32_t>("retime_tries");
    if (json.contains("timing_warning")) s.timing_warning = r.get<std::string>("timing_warning");
    if (json.contains("mean_energy_j")) {
        s.mean_energy.static_j = r.get<double>("mean_energy_static_j");
        s.mean_energy.dynamic_j = r.get<double>("mean_energy_dynamic_j");
        s.mean_energy.bus_j = r.get<double>("mean_energy_bus_j");
        s.mean_energy.host_j = r.get<double>("mean_energy_host_j");
        s.mean_energy_per_pair_j = r.get<double>("mean_energy_per_pair_j");
        s.host_package_w = r.get<double>("host_package_w");
    }
    return s;
}

}  // namespace cdvp
