#include "sw/run/reference_workload.h"

namespace cdvp::reference_workload {

const std::vector<uint64_t>& objects() {
    static const std::vector<uint64_t> sizes{100, 500, 2000};
    return sizes;
}

// Named here, not taken from broad_phase_names(): a baseline added later
// leaves the workload, and every profile and preset stated for it, as it was.
const std::vector<std::string>& baselines() {
    static const std::vector<std::string> names{"sap", "dbvt", "brute", "soa", "sap_mt"};
    return names;
}

const std::vector<std::string>& first_version_baselines() {
    static const std::vector<std::string> names{"sap", "dbvt", "brute", "soa"};
    return names;
}

}  // namespace cdvp::reference_workload
