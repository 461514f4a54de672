// The platform a board preset's settings give (platform_config over the
// preset's layer), on the clocked engine the platform tests step by step.
#pragma once

#include <string>

#include "platform/settings/board_preset.h"
#include "platform/platform_settings.h"

namespace cdvp::testing {

inline PlatformConfig preset_platform(const std::string& name) {
    PlatformConfig config = platform_config(load_board_preset(name).applied());
    config.fidelity = Fidelity::kCycle;
    return config;
}

}  // namespace cdvp::testing
