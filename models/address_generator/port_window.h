// One address-generator cycle's addresses, as the seed's datapath drives
// them: port 0 on box `row`, ports 1..valid_lanes on boxes first_column,
// first_column + 1, ... (the untiled generator, the tiled schedule and the
// clocked pipeline all issue these).
#pragma once

#include <cstdint>

namespace cdvp {

struct PortWindow {
    uint32_t row = 0;
    uint32_t first_column = 0;
    uint32_t valid_lanes = 0;  // lanes 1..valid_lanes are valid
};

}  // namespace cdvp
