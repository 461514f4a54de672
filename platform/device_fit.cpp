#include "platform/device_fit.h"

#include <deque>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "platform/memory_plan.h"

namespace cdvp {

namespace {

double capacity_or_unbounded(uint64_t value) {
    return value == 0 ? std::numeric_limits<double>::infinity() : static_cast<double>(value);
}

// What a fit reads besides m: every setting of the sections plan_memory and
// the fit read (board, device, memory, run) but board.m, and the capacity.
std::string fit_key(const Settings& settings, uint64_t capacity) {
    std::string key = std::to_string(capacity);
    for (const Setting& setting : settings_table()) {
        const std::string& name = setting.name;
        const bool read = name.rfind("board.", 0) == 0 || name.rfind("device.", 0) == 0 ||
                          name.rfind("memory.", 0) == 0 || name.rfind("run.", 0) == 0;
        if (!read || name == "board.m") continue;
        key += '\n';
        key += name;
        key += '=';
        key += to_text(setting.get_pci(settings));
    }
    return key;
}

// The costs at every m, kept for the last few keys: a sweep over m (or
// anything the fit does not read) costs the board once, not 32 times a point.
const std::vector<BoardResources>& costs_by_m(const Settings& settings, uint64_t capacity,
                                              const DeviceCapacity& device) {
    static constexpr std::size_t kKept = 64;
    static std::map<std::string, std::vector<BoardResources>> kept;
    static std::deque<std::string> order;
    std::string key = fit_key(settings, capacity);
    if (const auto at = kept.find(key); at != kept.end()) return at->second;
    const SynthesisTable& table = SynthesisTable::stored();
    std::vector<BoardResources> costs;
    for (uint32_t m = 1; m <= BoardConfig::kMaxM; ++m) {
        Settings at_m = settings;
        at_m.board.m = m;
        const BoardConfig board = planned_board(at_m, capacity);  // block RAM or SSRAM tiles at this m
        // Lanes in the board's format; memories at the format's block RAM depth.
        costs.push_back(board_resources(table, device, board.format.name(), m,
                                        static_cast<double>(board.block_rams(capacity))));
    }
    if (kept.size() == kKept) {
        kept.erase(order.front());
        order.pop_front();
    }
    order.push_back(key);
    return kept.emplace(std::move(key), std::move(costs)).first->second;
}

}  // namespace

bool has_device_family(const Settings& settings) { return settings.device.family != DeviceFamily::kNone; }

DeviceFit fit_on_device(const Settings& settings, uint64_t capacity) {
    const DeviceSettings& d = settings.device;
    DeviceFit fit;
    fit.device = {d.name, name_of(d.family), capacity_or_unbounded(d.luts), capacity_or_unbounded(d.flip_flops),
                  capacity_or_unbounded(d.block_rams), ""};
    const std::vector<BoardResources>& costs = costs_by_m(settings, capacity, fit.device);
    fit.resources = costs.at(settings.board.m - 1);
    fit.use = utilisation(fit.resources.total(), fit.device);
    for (uint32_t m = 1; m <= BoardConfig::kMaxM; ++m) {
        if (utilisation(costs[m - 1].total(), fit.device).fits()) fit.largest_m = m;
    }
    return fit;
}

}  // namespace cdvp
