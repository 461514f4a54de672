// Integer arithmetic the models share.
#pragma once

#include <cstdint>

namespace cdvp {

// ceil(a / b) for b > 0: the cycles, beats or blocks a count of b each needs.
constexpr uint64_t ceil_div(uint64_t a, uint64_t b) { return (a + b - 1) / b; }

}  // namespace cdvp
