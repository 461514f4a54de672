#include "sw/run/reference_workload.h"

namespace cdvp::reference_workload {

const std::vector<uint64_t>& objects() {
    static const std::vector<uint64_t> sizes{100, 500, 2000};
    return sizes;
}

// Fixed by the version, not by the baselines cdvp has: a baseline added
// since takes a profile's overall factor (sw/run/host_factor.h).
const std::vector<std::string>& baselines() {
    static const std::vector<std::string> names{"sap", "dbvt", "brute", "soa", "sap_mt"};
    return names;
}

const std::vector<std::string>& first_version_baselines() {
    static const std::vector<std::string> names{"sap", "dbvt", "brute", "soa"};
    return names;
}

}  // namespace cdvp::reference_workload
