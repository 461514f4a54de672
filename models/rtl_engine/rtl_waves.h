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

// The controller's one-hot state by name (1 idle, 2 sweep, 4 drain, 8
// paused, 16 done): the RTL's table "controller", as the platform's
// controller state has one of its own.
const StateNames& rtl_controller_states();

}  // namespace cdvp
