#include "sw/run/reference_workload.h"

#include "sw/baselines/broad_phase.h"

namespace cdvp::reference_workload {

const std::vector<uint64_t>& objects() {
    static const std::vector<uint64_t> sizes{100, 500, 2000};
    return sizes;
}

const std::vector<std::string>& baselines() {
    static const std::vector<std::string> names = broad_phase_names();
    return names;
}

const std::vector<std::string>& first_version_baselines() {
    static const std::vector<std::string> names = single_thread_broad_phase_names();
    return names;
}

}  // namespace cdvp::reference_workload
