#include "platform/device_fit.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/common/number_text.h"
#include "models/common/user_text.h"
#include "models/resources/whole_board_timing.h"
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
        const BlockRamGeometry geometry = board.block_ram_geometry(capacity);
        const auto memories = static_cast<double>(geometry.block_rams());
        costs.push_back(board.grid_board() ? grid_board_resources(table, device, board.format.name(), m, memories)
                                           : board_resources(table, device, board.format.name(), m, memories));
        costs.back().memory_geometry = geometry;
    }
    if (kept.size() == kKept) {
        kept.erase(order.front());
        order.pop_front();
    }
    order.push_back(key);
    return kept.emplace(std::move(key), std::move(costs)).first->second;
}

// The grade a device name ends in ("XC2V6000-4": 4), or 0.
uint32_t named_grade(const std::string& name) {
    const std::size_t dash = name.rfind('-');
    if (dash == std::string::npos || dash + 1 == name.size() || dash + 4 < name.size()) return 0;
    for (std::size_t k = dash + 1; k < name.size(); ++k) {
        if (name[k] < '0' || name[k] > '9') return 0;
    }
    return static_cast<uint32_t>(std::strtoul(name.c_str() + dash + 1, nullptr, 10));
}

// "98.5 MHz", "10.15 ns": a figure with its unit, to the decimals it is known to.
std::string with_unit(double value, int decimals, const char* unit) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f %s", decimals, value, unit);
    return text;
}
std::string megahertz(double mhz) { return with_unit(mhz, 1, "MHz"); }
std::string nanoseconds(double ns) { return with_unit(ns, 2, "ns"); }

// The bits a box index takes on a board of `capacity` boxes (at least 1).
uint32_t address_bits_for(uint64_t capacity) {
    uint32_t bits = 1;
    while (bits < 64 && (uint64_t{1} << bits) < capacity) ++bits;
    return bits;
}

BoardTiming timing_of(const Settings& settings, uint64_t capacity, uint32_t grade, FifoMemory fifo_memory) {
    const BoardConfig board = planned_board(settings, capacity);
    TimedBoard timed;
    timed.family = name_of(settings.device.family);
    timed.speed_grade = grade;
    timed.format = board.format.name();
    timed.m = board.m;
    timed.compare_latency = board.compare.latency_cycles;
    timed.fifo_memory = fifo_memory;
    timed.address_bits = address_bits_for(capacity);
    timed.tiled = board.tiles.tiled();
    timed.grid = board.grid_board();
    return board_timing(TimingTable::stored(), WholeBoardTable::stored(), timed);
}

}  // namespace

SpeedGrade speed_grade_of(const DeviceSettings& device) {
    const std::string family = name_of(device.family);
    const std::vector<uint32_t> grades = TimingTable::stored().speed_grades(family);
    if (grades.empty()) throw std::invalid_argument("no timing for the " + family + " family");
    const uint32_t named = named_grade(device.name);
    if (named == 0) return {grades.front(), false};
    if (std::find(grades.begin(), grades.end(), named) == grades.end()) {
        std::string known;
        for (std::size_t k = 0; k < grades.size(); ++k) {
            known += (k == 0 ? "-" : k + 1 == grades.size() ? " or -" : ", -") + std::to_string(grades[k]);
        }
        throw std::invalid_argument("speed grade -" + std::to_string(named) + " of " + excerpt(device.name) +
                                    ": the " + family + " timing has " + known);
    }
    return {named, true};
}

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
    fit.speed_grade = speed_grade_of(d);
    fit.timing = timing_of(settings, capacity, fit.speed_grade.grade, fit.resources.pair_fifo_memory);
    fit.clock_mhz = settings.board.clock_mhz;
    return fit;
}

std::optional<std::string> check_clock(const SettingValues& values, uint64_t capacity) {
    const Settings& settings = values.settings();
    if (!has_device_family(settings)) return std::nullopt;
    SpeedGrade grade;
    try {
        grade = speed_grade_of(settings.device);
    } catch (const std::invalid_argument& e) {
        throw InputError(values.where(*find_setting("device.name")) + ": " + e.what());
    }
    // Where the pair FIFO lives (block RAM, or LUTs when the boxes leave it
    // none) picks its row and the whole board's: the fit's costs decide it.
    const DeviceFit fit = fit_on_device(settings, capacity);
    const BoardTiming& timing = fit.timing;
    const double clock = settings.board.clock_mhz, fmax = timing.fmax_mhz();
    if (clock <= fmax) return std::nullopt;
    const PieceTiming& limit = timing.limiting();
    const auto [clock_text, fmax_text] = distinct_figures(clock, fmax, 1);
    const std::string line = values.where(*find_setting("board.clock_mhz")) + ": " + clock_text +
                             " MHz is beyond the " + fmax_text + " MHz the board reaches on the " +
                             excerpt(settings.device.name) + " (speed grade -" + std::to_string(grade.grade) +
                             (grade.named ? "" : ", the family's slowest") + "): its " + limit.piece + " takes " +
                             nanoseconds(limit.path.ns) + " a cycle (synthesis timing for " +
                             name_of(settings.device.family) + ")";
    const std::string ignore = values.names().setting_to(*find_setting("run.ignore_timing"), "yes");
    if (!settings.run.ignore_timing) throw InputError(line + "; " + ignore + " runs it anyway");
    return line + "; running it anyway (" + ignore + ")";
}

nlohmann::json timing_json(const DeviceFit& fit) {
    const BoardTiming& timing = fit.timing;
    nlohmann::json pieces = nlohmann::json::object();
    nlohmann::json awaiting = nlohmann::json::array();
    for (const auto* list : {&timing.pieces, &timing.awaiting_pipelining}) {
        for (const PieceTiming& piece : *list) {
            const PathDelay& p = piece.path;
            pieces[piece.key] = {{"piece", piece.piece},
                                 {"path_ns", p.ns},
                                 {"fmax_mhz", p.fmax_mhz()},
                                 {"luts", p.luts},
                                 {"carry_cells", p.carry_cells},
                                 {"wide_muxes", p.wide_muxes},
                                 {"from", p.from},
                                 {"to", p.to}};
            if (list == &timing.awaiting_pipelining) awaiting.push_back(piece.key);
        }
    }
    nlohmann::json json = {
        {"speed_grade", fit.speed_grade.grade},
        {"speed_grade_from", fit.speed_grade.named ? "device name" : "the family's slowest (not in the name)"},
        {"fmax_mhz", timing.fmax_mhz()},
        {"limited_by", timing.limiting().piece},
        {"fmax_from", timing.whole_board_missing.empty()
                          ? "every piece and the whole board as one design"
                          : "the pieces alone: " + timing.whole_board_missing},
        {"as_written_fmax_mhz", timing.slowest().path.fmax_mhz()},
        {"as_written_limited_by", timing.slowest().piece},
        {"clock_mhz", fit.clock_mhz},
        {"meets_clock", fit.clock_mhz <= timing.fmax_mhz()},
        {"pieces", pieces}};
    // Only while kGridPiecesAwaitPipelining leaves pieces out of the Fmax.
    if (!awaiting.empty()) json["awaiting_pipelining"] = awaiting;
    return json;
}

std::string timing_summary(const DeviceFit& fit) {
    const PieceTiming& limit = fit.timing.limiting();
    const PieceTiming& slowest = fit.timing.slowest();
    const auto [fmax_text, clock_text] = distinct_figures(fit.timing.fmax_mhz(), fit.clock_mhz, 1);
    std::string text = "Fmax about " + fmax_text + " MHz at speed grade -" + std::to_string(fit.speed_grade.grade) +
                       " (its " + limit.piece + ", " + nanoseconds(limit.path.ns) + ")";
    if (fit.clock_mhz > fit.timing.fmax_mhz()) text += ", below the " + clock_text + " MHz clock";
    if (!fit.timing.whole_board_missing.empty()) text += "; from the pieces alone: " + fit.timing.whole_board_missing;
    if (&slowest != &limit) text += "; its " + slowest.piece + " as written: " + megahertz(slowest.path.fmax_mhz());
    return text;
}

}  // namespace cdvp
