// The RTL's signals a waveform viewer shows first, by the names Verilator's
// VCD gives them (the top's ports in the model's scope "board", its signals
// in board.collision_board_top), grouped by block as the clocked engine's are.
// The VCD holds every signal of the design; these open the save file.
#pragma once

#include <vector>

#include "models/common/wave_list.h"
#include "models/rtl_engine/rtl_variant.h"

namespace cdvp {

std::vector<TracedSignal> rtl_waves(const RtlVariant& variant);

}  // namespace cdvp
