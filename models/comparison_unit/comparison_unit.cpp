#include "models/comparison_unit/comparison_unit.h"

#include <stdexcept>
#include <string>

namespace cdvp {

ComparisonUnit::ComparisonUnit(uint32_t lanes, const ComparisonUnitConfig& config, NumberFormat format)
    : lanes_(lanes),
      latency_(config.latency_cycles),
      format_(format),
      mask_(format.word_mask()),
      is_float_(format.is_float()) {
    if (lanes == 0 || lanes > kMaxLanes) {
        throw std::invalid_argument("the comparison unit supports 1 to " + std::to_string(kMaxLanes) +
                                    " lanes, not " + std::to_string(lanes));
    }
}

bool ComparisonUnit::lane_hit(NumberFormat format, const uint32_t* a, const uint32_t* b) {
    if (format.is_float()) {
        float fa[kCoordinates], fb[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            fa[c] = as_float(a[c]);
            fb[c] = as_float(b[c]);
        }
        return lane_hit(fa, fb);
    }
    const uint32_t mask = format.word_mask();
    uint32_t wa[kCoordinates], wb[kCoordinates];
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        wa[c] = a[c] & mask;
        wb[c] = b[c] & mask;
    }
    return lane_hit(wa, wb);
}

}  // namespace cdvp
