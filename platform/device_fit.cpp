#include "platform/device_fit.h"

#include <limits>

#include "platform/memory_plan.h"

namespace cdvp {

namespace {

double capacity_or_unbounded(uint64_t value) {
    return value == 0 ? std::numeric_limits<double>::infinity() : static_cast<double>(value);
}

}  // namespace

bool has_device_family(const Settings& settings) { return settings.device.family != DeviceFamily::kNone; }

DeviceFit fit_on_device(const Settings& settings, uint64_t capacity) {
    const DeviceSettings& d = settings.device;
    DeviceFit fit;
    fit.device = {d.name, name_of(d.family), capacity_or_unbounded(d.luts), capacity_or_unbounded(d.flip_flops),
                  capacity_or_unbounded(d.block_rams), ""};
    const SynthesisTable& table = SynthesisTable::stored();
    const auto cost = [&](uint32_t m) {
        Settings at_m = settings;
        at_m.board.m = m;
        const BoardConfig board = planned_board(at_m, capacity);  // block RAM or SSRAM tiles at this m
        // Lanes in the board's format; memories at the format's block RAM depth.
        return board_resources(table, fit.device, board.format.name(), m,
                               static_cast<double>(board.block_rams(capacity)));
    };
    fit.resources = cost(settings.board.m);
    fit.use = utilisation(fit.resources.total(), fit.device);
    for (uint32_t m = 1; m <= BoardConfig::kMaxM; ++m) {
        if (utilisation(cost(m).total(), fit.device).fits()) fit.largest_m = m;
    }
    return fit;
}

}  // namespace cdvp
