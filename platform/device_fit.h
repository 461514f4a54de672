// How a board configuration sits on its FPGA (the device.* settings), costed
// by the synthesis-backed resource model (models/resources).
#pragma once

#include <cstdint>

#include "models/resources/resource_model.h"
#include "platform/settings/settings.h"

namespace cdvp {

struct DeviceFit {
    DeviceCapacity device;     // unbounded resources as infinity
    BoardResources resources;  // for the settings' m and number format (lanes, block RAM depth)
    Utilisation use;           // over the device; overflow names the first resource that does not fit
    uint32_t largest_m = 0;    // the largest m (1 to BoardConfig::kMaxM) that fits; 0: none does
};

// Whether a device family is set, so that resources can be costed.
bool has_device_family(const Settings& settings);
// The fit of settings.board on settings.device for boards of 'capacity'
// boxes, in the memory plan_memory picks at each m (block RAM or SSRAM
// tiles); only with has_device_family(settings).
DeviceFit fit_on_device(const Settings& settings, uint64_t capacity);

}  // namespace cdvp
