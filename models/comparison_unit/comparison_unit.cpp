#include "models/comparison_unit/comparison_unit.h"

#include <stdexcept>
#include <string>

namespace cdvp {

ComparisonUnit::ComparisonUnit(uint32_t lanes, const ComparisonUnitConfig& config)
    : lanes_(lanes), latency_(config.latency_cycles) {
    if (lanes == 0 || lanes > kMaxLanes) {
        throw std::invalid_argument("the comparison unit supports 1 to " + std::to_string(kMaxLanes) +
                                    " lanes, not " + std::to_string(lanes));
    }
}

}  // namespace cdvp
