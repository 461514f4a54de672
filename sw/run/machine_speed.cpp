#include "sw/run/machine_speed.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "models/common/input_path.h"
#include "models/common/user_directories.h"
#include "sw/output/created_directories.h"
#include "sw/output/text_file.h"
#include "sw/run/machine_info.h"
#include "sw/timing/speed_probe.h"

namespace cdvp {
namespace {

constexpr std::size_t kMaxBytes = 4096;
// A probe is a few microseconds of work: anything outside is no probe's time.
constexpr double kLeastProbeNs = 1, kMostProbeNs = 1e9;

bool probe_time(double ns) { return std::isfinite(ns) && ns >= kLeastProbeNs && ns <= kMostProbeNs; }

}  // namespace

std::string machine_speed_path() {
    const std::string cache = user_base_directory("XDG_CACHE_HOME", ".cache");
    return cache.empty() ? std::string() : cache + "/cdvp/speed-probe.json";
}

double remembered_fast_probe_ns(const std::string& cpu_model) {
    const std::string path = machine_speed_path();
    if (path.empty()) return 0;
    try {
        const std::optional<std::string> text =
            read_input_file({path, "cdvp's record of the machine's speed", kMaxBytes, true});
        if (!text) return 0;
        const nlohmann::json j = nlohmann::json::parse(*text);
        const nlohmann::json& model = j.at("cpu_model");
        const nlohmann::json& ns = j.at("probe_native_ns");
        if (!model.is_string() || model.get<std::string>() != cpu_model || !ns.is_number()) return 0;
        return probe_time(ns.get<double>()) ? ns.get<double>() : 0;
    } catch (const std::exception&) {
        return 0;  // damaged or not ours: written anew by the next run
    }
}

namespace {

// Writes `ns` as the machine's speed unless `kept` (the one kept, 0: none) is as fast.
void keep_unless_slower(const std::string& cpu_model, double ns, double kept) {
    const std::string path = machine_speed_path();
    if (path.empty() || !probe_time(ns) || (kept > 0 && kept <= ns)) return;
    try {
        CreatedDirectories directories;
        directories.create(path.substr(0, path.rfind('/')), "the cache directory");
        directories.keep();
        const nlohmann::json j = {{"cpu_model", cpu_model}, {"probe_native_ns", ns}, {"updated", utc_now()}};
        commit_text_file(path, j.dump(2) + "\n", "cdvp's record of the machine's speed");
    } catch (const std::exception&) {
        // A cache that cannot be written keeps nothing; the run goes on.
    }
}

}  // namespace

void remember_fast_probe_ns(const std::string& cpu_model, double ns) {
    keep_unless_slower(cpu_model, ns, remembered_fast_probe_ns(cpu_model));
}

double probe_reference_ns(double calibrated_ns, const std::vector<double>& probes) {
    if (calibrated_ns > 0) return calibrated_ns;
    const double own = fast_probe_ns(probes);
    if (own <= 0) return 0;
    const std::string cpu = read_machine_info().cpu_model;
    const double kept = remembered_fast_probe_ns(cpu);
    keep_unless_slower(cpu, own, kept);  // the record read once
    return kept > 0 ? std::min(kept, own) : own;
}

}  // namespace cdvp
