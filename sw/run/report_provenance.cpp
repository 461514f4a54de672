#include "sw/run/report_provenance.h"

#include "sw/run/build_info.h"

namespace cdvp {

nlohmann::json load_json(const std::array<double, 3>& loads) { return nlohmann::json::array({loads[0], loads[1], loads[2]}); }

nlohmann::json provenance_json(const MachineInfo& machine, const std::array<double, 3>& load_start,
                               const HostTiming& host) {
    const BuildInfo& build = build_info();
    nlohmann::json profile = host.basis_name();
    if (host.basis == HostTiming::Basis::kCalibrated) {
        profile = {{"path", host.profile_path}, {"sha256", host.profile_sha256}};
    }
    return {{"cpu_model", machine.cpu_model},
            {"cpu_mhz", machine.cpu_mhz},
            {"cores_online", machine.cores_online},
            {"cores_allowed", machine.cores_allowed},
            // The baselines and the simulator run one after the other on one thread.
            {"threads_timed", 1},
            {"kernel", machine.kernel},
            {"load_average_start", load_json(load_start)},
            {"compiler", build.compiler},
            {"build_type", build.build_type},
            {"build_flags", build.flags},
            {"cdvp_version", build.version},
            {"git_commit", build.git_commit},
            {"host_profile", profile}};
}

nlohmann::json host_calibration_json(const HostTiming& host) {
    nlohmann::json factors = host.factors;
    factors["overall"] = host.overall;
    return {{"basis", host.basis_name()},
            {"host", host.host},
            {"factors", factors},
            {"uncalibrated_factor", host.uncalibrated_factor},
            {"profile_machine", host.profile_machine.empty() ? nlohmann::json(nullptr) : nlohmann::json(host.profile_machine)},
            {"profile_spread", host.profile_spread},
            {"profile_quality", host.basis != HostTiming::Basis::kCalibrated ? nlohmann::json(nullptr)
                                : nlohmann::json(host.profile_poor() ? "poor" : "good")}};
}

}  // namespace cdvp
