// The settings table: every setting of a run, declared once (settings.h).
// Each default is the bound member's initializer; 'source' says where it
// comes from.
#include "platform/settings/settings.h"

#include <optional>
#include <stdexcept>
#include <type_traits>

#include "models/control_registers/control_registers.h"

namespace cdvp {

namespace {

// A CPU number as run.pin_cpu takes it: decimal digits, below 1024 (CPU_SETSIZE).
std::optional<uint32_t> parse_cpu_number(const std::string& text) {
    if (text.empty() || text.size() > 4) return std::nullopt;
    uint32_t value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + static_cast<uint32_t>(c - '0');
    }
    if (value >= 1024) return std::nullopt;
    return value;
}

using Getter = std::function<SettingValue(const Settings&)>;
using Setter = std::function<void(Settings&, const SettingValue&)>;
struct Binding {
    Getter get;
    Setter set;
    bool float32 = false;  // the member is a float
};

// Follows a path of member pointers: reach(s, &Settings::board, &BoardConfig::m) is s.board.m.
template <class Object, class Member, class... Rest>
decltype(auto) reach(Object& object, Member member, Rest... rest) {
    if constexpr (sizeof...(Rest) == 0) {
        return (object.*member);
    } else {
        return reach(object.*member, rest...);
    }
}

// A choice's value from its name, which Setting::from_string has checked
// (a name it has not is a caller's error).
template <class T>
T choice_value(const std::string& name) {
    if (const std::optional<T> value = parse_choice<T>(name)) return *value;
    throw std::logic_error("a choice set to a name it has not: '" + name + "'");
}

// A setting bound to the member at the end of 'path'; a choice (a type with
// Choices, setting_choices.h) by its names.
template <class... Path>
Binding member(Path... path) {
    return {[=](const Settings& s) -> SettingValue {
                const auto& field = reach(s, path...);
                using T = std::decay_t<decltype(field)>;
                if constexpr (has_choices<T>::value) return std::string(name_of(field));
                else if constexpr (std::is_same_v<T, std::string>) return field;
                else if constexpr (std::is_floating_point_v<T>) return static_cast<double>(field);
                else return static_cast<uint64_t>(field);
            },
            [=](Settings& s, const SettingValue& value) {
                auto& field = reach(s, path...);
                using T = std::decay_t<decltype(field)>;
                if constexpr (has_choices<T>::value) field = choice_value<T>(std::get<std::string>(value));
                else if constexpr (std::is_same_v<T, std::string>) field = std::get<std::string>(value);
                else if constexpr (std::is_floating_point_v<T>) field = static_cast<T>(std::get<double>(value));
                else field = static_cast<T>(std::get<uint64_t>(value));
            },
            std::is_same_v<std::decay_t<decltype(reach(std::declval<const Settings&>(), path...))>, float>};
}

Setting base(const char* name, SettingType type, const char* unit, Binding b, const char* help, const char* source) {
    Setting s;
    s.name = name;
    s.type = type;
    s.unit = unit;
    s.get_pci = std::move(b.get);
    s.set_pci = std::move(b.set);
    s.float32 = b.float32;
    s.help = help;
    s.source = source;
    return s;
}
Setting count(const char* name, const char* unit, uint64_t lo, uint64_t hi, Binding b, const char* help,
              const char* source) {
    Setting s = base(name, SettingType::kCount, unit, std::move(b), help, source);
    s.count_min = lo;
    s.count_max = hi;
    return s;
}
Setting real(const char* name, const char* unit, double lo, double hi, Binding b, const char* help, const char* source) {
    Setting s = base(name, SettingType::kReal, unit, std::move(b), help, source);
    s.min = lo;
    s.max = hi;
    return s;
}
// A choice among the names of T (setting_choices.h), bound to a member of type T.
template <class T>
Setting choice(const char* name, Binding b, const char* help, const char* source) {
    Setting s = base(name, SettingType::kChoice, "", std::move(b), help, source);
    s.choices = choice_names<T>();
    return s;
}
Setting text(const char* name, Binding b, const char* help, const char* source) {
    return base(name, SettingType::kText, "", std::move(b), help, source);
}
// A text setting that only `check` accepts (it throws std::invalid_argument).
Setting checked_text(const char* name, const char* accepts, std::function<void(const std::string&)> check, Binding b,
                     const char* help, const char* source) {
    Setting s = text(name, std::move(b), help, source);
    s.accepts = accepts;
    s.check = std::move(check);
    return s;
}
// The board's number format, bound by name (NumberFormat::parse checks it).
Binding number_format() {
    return {[](const Settings& s) -> SettingValue { return s.board.format.name(); },
            [](Settings& s, const SettingValue& value) { s.board.format = NumberFormat::parse(std::get<std::string>(value)); }};
}
// A dedicated flag of `cdvp run` sets it (--flag VALUE_NAME).
Setting flag(Setting s, const char* name, const char* value_name) {
    s.flag = name;
    s.value_name = value_name;
    return s;
}
// A dedicated switch of `cdvp run` (--flag alone) that sets a no|yes choice to yes.
Setting switch_flag(Setting s, const char* name) {
    s.flag = name;
    return s;
}
// Every board preset gives it.
Setting preset(Setting s) {
    s.in_preset = true;
    return s;
}
// A key of the bus section for PCI only, PCIe only, or both (the PCIe member bound by 'pcie').
Setting pci(Setting s) {
    s.buses = kPciBus;
    return preset(std::move(s));
}
Setting pcie(Setting s) {
    s.buses = kPcieBus;
    s.get_pcie = std::move(s.get_pci);
    s.set_pcie = std::move(s.set_pci);
    s.get_pci = nullptr;
    s.set_pci = nullptr;
    return preset(std::move(s));
}
Setting both_buses(Setting s, Binding pcie) {
    s.buses = kAnyBus;
    s.get_pcie = std::move(pcie.get);
    s.set_pcie = std::move(pcie.set);
    return preset(std::move(s));
}
// A bus key that is the user's choice, never a preset's: of both buses, bound
// to one member of Settings, or of PCIe only.
Setting user_bus(Setting s) {
    s.buses = kAnyBus;
    s.get_pcie = s.get_pci;
    s.set_pcie = s.set_pci;
    return s;
}
Setting user_pcie(Setting s) {
    s = pcie(std::move(s));
    s.in_preset = false;
    return s;
}

using S = Settings;
using B = BoardConfig;
using G = GridConfig;
using C = PciConfig;
using E = PcieConfig;
using L = LocalBusConfig;
using D = DriverConfig;
using T = PcieLinkConfig;
using W = BusLoad;

constexpr const char* kPaperPci = "PCI 2.2 rules and the paper's host (platform/boards/adm-xrc-ii.json)";
constexpr const char* kPcieWhatIf = "PCIe 3.0 and stated assumptions (platform/boards/pcie-gen3-x8.json)";
constexpr const char* kNoLoad = "no load: the formula's idle bus (docs/bus_models.md)";

std::vector<Setting> board_settings() {
    return {
        flag(count("board.m", "", 1, BoardConfig::kMaxM, member(&S::board, &B::m),
                   "parallelism: 2m-port memories, 2m-1 comparison lanes",
                   "the user's choice (never a preset's); the paper's XC2V6000 fits m = 24 at 500 objects"),
             "m", "M"),
        flag(checked_text("board.format", "float32 or fixed8 to fixed32",
                          [](const std::string& text) { NumberFormat::parse(text); }, number_format(),
                          "comparator and coordinate number format: float32, or K-bit fixed point over each frame's "
                          "bounds (fewer LUTs a lane; extra pairs, never a lost one)",
                          "the paper's board compares float32"),
             "format", "FORMAT"),
        flag(preset(real("board.clock_mhz", "MHz", 1, 1000, member(&S::board, &B::clock_mhz), "board clock in MHz",
                         "assumption: the design runs at the ADM-XRC-II's local bus clock, up to 66 MHz (Alpha Data "
                         "SDK)")),
             "clock-mhz", "F"),
        flag(preset(count("board.compare_latency_cycles", "cycles", 0, 64,
                          member(&S::board, &B::compare, &ComparisonUnitConfig::latency_cycles),
                          "float compare pipeline depth in cycles",
                          "assumption: top of the 0-2 cycles plausible for a Virtex-II -4 float compare core")),
             "compare-latency", "C"),
        flag(preset(count("board.fifo_depth", "pairs", 1, 1u << 20,
                          member(&S::board, &B::collector, &PairCollectorConfig::fifo_depth),
                          "pair FIFO depth in pairs (at least 2m-1)", "assumption: one 512-deep block-RAM FIFO")),
             "fifo-depth", "P"),
        flag(preset(count("board.drain_per_cycle", "pairs a cycle", 1, 64,
                          member(&S::board, &B::collector, &PairCollectorConfig::drain_per_cycle),
                          "pairs moved from FIFO to pair buffer a cycle",
                          "assumption: one 64-bit pair write a cycle into on-board memory")),
             "drain-rate", "R"),
        flag(preset(count("board.pair_buffer_depth", "pairs", 1, address_map::kMaxBufferedPairs,
                          member(&S::board, &B::collector, &PairCollectorConfig::buffer_depth),
                          "pair buffer depth in pairs before the host drains it",
                          "assumption: one 2 MiB ZBT SSRAM bank of 64-bit entries (the ADM-XRC-II has six)")),
             "pair-buffer", "P"),
        flag(count("board.box_banks", "banks", 1, BoardConfig::kMaxBoxBanks, member(&S::board, &B::box_banks),
                   "banks of box memory: 2 double-buffers the coordinate memories and the pair buffer, and the "
                   "driver pipelines frames (frame k+1 uploads while frame k sweeps, frame k's pairs read back "
                   "while frame k+1 sweeps; a trace's frames, known ahead; twice the box memory)",
                   "1: the paper's board has one bank (docs/communication.md)"),
             "box-banks", "B"),
        flag(choice<BoxMemory>("board.memory", member(&S::memory, &MemorySettings::memory),
                    "where the boxes live: block_ram, ssram (off-chip, swept in tiles; docs/tiles.md) or auto "
                    "(block RAM while the boxes fit it or --ignore-capacity is given, else SSRAM)",
                    "auto: the paper's board keeps its boxes in block RAM up to about 500"),
             "memory", "M"),
        flag(count("board.tile_boxes", "boxes", 0, address_map::kMaxObjects,
                   member(&S::memory, &MemorySettings::tile_boxes),
                   "boxes a tile when SSRAM serves; 0: the largest whose buffers fit the device's block RAMs",
                   "0: as large as the device allows (fewer tiles, fewer loads)"),
             "tile-boxes", "T"),
        flag(choice<BoardAlgorithm>("board.algorithm", member(&S::board, &B::algorithm),
                                    "what computes a sweep: all_pairs (the seed's board: every pair through the "
                                    "2m-1 lanes) or grid (boxes binned into a uniform grid's cell lists in SSRAM, "
                                    "the lanes run inside each cell; docs/grid_board.md)",
                                    "all_pairs: the paper's board"),
             "algorithm", "all_pairs|grid"),
        count("board.grid.dims", "cells a side", 0, GridConfig::kMaxDims, member(&S::board, &B::grid, &G::dims),
              "grid board: cells a side (dims^3 cells); 0: at each START the largest g with 16 g^3 <= N, about "
              "sixteen boxes a cell",
              "0: sixteen boxes a cell took the fewest sweep cycles on the spheres scene at 10^4 and 10^5 boxes on "
              "both presets (docs/grid_board.md, Choosing the grid)"),
        real("board.grid.cell_size", "coordinate units", 0, 1e30, member(&S::board, &B::grid, &G::cell_size),
             "grid board: the edge of a cubic cell in the board's coordinates (scene units in float32, codes in "
             "fixedK), from the frame's least bounds; 0: the grid fitted to each frame's bounds",
             "0: fitted, so the grid covers the scene whatever its scale"),
        count("board.grid.cell_capacity", "boxes", GridConfig::kMinCellCapacity, GridConfig::kMaxCellCapacity,
              member(&S::board, &B::grid, &G::cell_capacity),
              "grid board: boxes a cell list and the cell buffer hold; a box meeting a full cell is swept against "
              "every box instead (counted as overflow)",
              "512: one 512 x 36 block RAM deep, the seed's board's own limit"),
        count("board.grid.max_span", "cells", 1, GridConfig::kMaxSpan, member(&S::board, &B::grid, &G::max_span),
              "grid board: cells a binned box may cover; a box covering more is swept against every box",
              "8: up to 2 x 2 x 2 cells, so the binning passes take at most 8 slots a box"),
    };
}

constexpr const char* kSsramSource =
    "the ADM-XRC-II's six ZBT SSRAM banks (Alpha Data); 512K x 36 a bank is an assumption (not confirmed)";

std::vector<Setting> device_settings() {
    using V = DeviceSettings;
    return {
        preset(text("device.name", member(&S::device, &V::name), "the FPGA the board is built on",
                    "none without a preset; adm-xrc-ii.json: the XC2V6000")),
        preset(choice<DeviceFamily>("device.family", member(&S::device, &V::family),
                      "the FPGA family whose synthesis results cost the board (models/resources/synthesis.csv): "
                      "xc2v (Virtex-II), xcup (UltraScale+); none: resources not modelled",
                      "none without a preset")),
        preset(count("device.luts", "LUTs", 0, 100'000'000, member(&S::device, &V::luts),
                     "the FPGA's look-up tables (4-input on xc2v, 6-input on xcup); 0: unbounded",
                     "none without a preset; Xilinx DS031: the XC2V6000 has 33,792 slices of two 4-input LUTs")),
        preset(count("device.flip_flops", "flip-flops", 0, 100'000'000, member(&S::device, &V::flip_flops),
                     "the FPGA's flip-flops; 0: unbounded",
                     "none without a preset; Xilinx DS031: two a slice on the XC2V6000")),
        preset(count("device.block_rams", "block RAMs", 0, 100000, member(&S::device, &V::block_rams),
                     "the FPGA's 18-Kbit block RAMs, which bound m for N boxes (0: unbounded)",
                     "none without a preset; Xilinx DS031: the XC2V6000 has 144")),
        preset(count("device.ssram_banks", "banks", 0, 64, member(&S::device, &V::ssram_banks),
                     "independent off-chip SSRAM banks, one access a clock each; a tile loads a box a cycle "
                     "with six (one per coordinate), ceil(6/banks) cycles with fewer; 0: no off-chip memory",
                     kSsramSource)),
        preset(count("device.ssram_words", "words", 0, 1ull << 32, member(&S::device, &V::ssram_words),
                     "words of 36 bits a bank (one coordinate a word): a board in SSRAM holds this many boxes with "
                     "six banks", kSsramSource)),
        preset(count("device.ssram_latency_cycles", "cycles", 0, 64, member(&S::device, &V::ssram_latency_cycles),
                     "SSRAM read pipeline: address to data, in board cycles", "pipelined ZBT SSRAM: 2 cycles")),
    };
}

// What the device, its bus and its host draw: the energy model's coefficients (docs/energy.md).
std::vector<Setting> power_settings() {
    using P = PowerSettings;
    constexpr const char* kNoPreset = "0 without a preset (no energy counted); the presets state theirs";
    return {
        preset(real("device.static_w", "W", 0, 1000, member(&S::power, &P::static_w),
                    "the device's quiescent power, drawn for the whole frame", kNoPreset)),
        preset(real("device.clb_uw_per_mhz", "uW/MHz", 0, 1000, member(&S::power, &P::clb_uw_per_mhz),
                    "dynamic power of one CLB in use, at XPE's default 12.5% toggle rate (logic, routing and "
                    "clock while the lanes compare)",
                    "0 without a preset; Virtex-II: 5.9 uW/MHz for typical designs (Shang, Kaviani, Bathala, FPGA "
                    "2002)")),
        preset(real("device.luts_per_clb", "LUTs", 1, 64, member(&S::power, &P::luts_per_clb),
                    "LUTs a CLB holds (the board's CLBs: the larger of its LUTs' and flip-flops' share)",
                    "8: four slices of two on Virtex-II (DS031), one slice of eight on UltraScale+ (UG574)")),
        preset(real("device.flip_flops_per_clb", "flip-flops", 1, 64, member(&S::power, &P::flip_flops_per_clb),
                    "flip-flops a CLB holds", "8 on Virtex-II (DS031), 16 on UltraScale+ (UG574)")),
        preset(real("device.block_ram_uw_per_mhz", "uW/MHz", 0, 10000, member(&S::power, &P::block_ram_uw_per_mhz),
                    "dynamic power of one 18-Kbit block RAM accessed every cycle", kNoPreset)),
        preset(real("device.io_pj_per_toggle", "pJ", 0, 10000, member(&S::power, &P::io_pj_per_toggle),
                    "energy of one output pin's transition (1/2 C V^2 of its load)", kNoPreset)),
        real("device.toggle_percent", "%", 0, 100, member(&S::power, &P::toggle_percent),
             "transitions a clock of the board's logic and pins, in percent (the published CLB power is read at "
             "12.5%)",
             "12.5%: Xilinx Power Estimator's default toggle rate"),
        both_buses(real("bus.active_w", "W", 0, 1000, member(&S::power, &P::bus_w),
                        "the bus and its bridges while they move boxes, commands or pairs", kNoPreset),
                   member(&S::power, &P::bus_w)),
        preset(real("host.package_w", "W", 0, 10000, member(&S::power, &P::host_w),
                    "the host CPU package's power while it works or waits on a frame (its TDP: an upper bound)",
                    kNoPreset)),
        preset(real("host.idle_w", "W", 0, 10000, member(&S::power, &P::host_idle_w),
                    "the host CPU package's power while its cores sleep on the board's interrupt (run.wait irq: the "
                    "sweep and the interrupt's delivery); 0: not stated, host.package_w through the wait too",
                    "0 without a preset; the present-day presets state theirs (docs/energy.md)")),
    };
}

std::vector<Setting> bus_settings() {
    return {
        preset(choice<BusType>("bus.type", member(&S::bus_type),
                      "the host bus: ideal (untimed, the board alone), pci or pcie; bus.* keys of one type are "
                      "refused on the other",
                      "ideal without a preset: only the board's compute time")),
        pci(count("bus.width_bits", "bits", 32, 64, member(&S::pci, &C::width_bits), "PCI data width (32 or 64)",
                  kPaperPci)),
        pci(real("bus.clock_mhz", "MHz", 1, 133, member(&S::pci, &C::clock_mhz), "PCI clock", kPaperPci)),
        pci(count("bus.arbitration_clocks", "clocks", 0, 255, member(&S::pci, &C::arbitration_clocks),
                  "REQ# to GNT# on an idle bus", "assumption (PCI 2.2 leaves it to the arbiter)")),
        pci(count("bus.address_phase_clocks", "clocks", 1, 2, member(&S::pci, &C::address_phase_clocks),
                  "address phases a transaction", "PCI 2.2: one for 32-bit addresses")),
        pci(count("bus.board_read_latency_clocks", "clocks", 0, 16, member(&S::pci, &C::board_read_latency_clocks),
                  "bridge as target: address to first data of a read",
                  "assumption within PCI 2.2's 16-clock target initial latency")),
        pci(count("bus.board_write_latency_clocks", "clocks", 0, 16, member(&S::pci, &C::board_write_latency_clocks),
                  "bridge as target: a posted write's DEVSEL and TRDY", "PCI 2.2: medium DEVSEL")),
        pci(count("bus.host_read_latency_clocks", "clocks", 0, 16, member(&S::pci, &C::host_read_latency_clocks),
                  "host bridge as target of a DMA read of host memory",
                  "assumption within PCI 2.2's 16-clock limit")),
        pci(count("bus.host_write_latency_clocks", "clocks", 0, 16, member(&S::pci, &C::host_write_latency_clocks),
                  "host bridge as target of a DMA write (posted)", "PCI 2.2: medium DEVSEL")),
        pci(count("bus.wait_states", "clocks", 0, 8, member(&S::pci, &C::wait_states),
                  "wait states per data phase after the first", "assumption (PCI 2.2 allows up to 8)")),
        pci(count("bus.turnaround_clocks", "clocks", 0, 8, member(&S::pci, &C::turnaround_clocks),
                  "idle clocks between transactions", "PCI 2.2: one")),
        pci(count("bus.latency_timer_clocks", "clocks", 0, 255, member(&S::pci, &C::latency_timer_clocks),
                  "a master's tenure ends when its latency timer expires",
                  "assumption: a common BIOS default")),
        pci(count("bus.dma_read_burst_bytes", "bytes", 4, 4096, member(&S::pci, &C::dma_read_burst_bytes),
                  "bridge DMA read burst", "PCI9656 DMA read bursts seen as 16 quadwords (reference notes)")),
        pci(count("bus.dma_write_burst_bytes", "bytes", 4, 4096, member(&S::pci, &C::dma_write_burst_bytes),
                  "bridge DMA write burst", "PCI9656 DMA write bursts seen as 32 quadwords (reference notes)")),
        pci(real("bus.host_pio_overhead_ns", "ns", 0, 1e6, member(&S::pci, &C::host_pio_overhead_ns),
                 "CPU to host bridge and back, beyond the PCI cycles of a PIO access",
                 "assumption: puts a PIO read at ~0.6 us, inside the era's 0.5-1 us")),
        both_buses(real("bus.interrupt_ns", "ns", 0, 1e6, member(&S::pci, &C::interrupt_ns),
                        "interrupt delivery plus handler entry",
                        "PCI: middle of the era's 5-20 us (assumption); PCIe: an MSI (assumption)"),
                   member(&S::pcie, &E::interrupt_ns)),
        both_buses(count("bus.local_bus_width_bits", "bits", 8, 1024, member(&S::pci, &C::local_bus, &L::width_bits),
                         "the board's local bus between bridge and FPGA: DMA cannot outrun it",
                         "PLX PCI9656: 32 bits (PCIe: the card's fabric datapath, assumption)"),
                   member(&S::pcie, &E::local_bus, &L::width_bits)),
        both_buses(real("bus.local_bus_clock_mhz", "MHz", 1, 1000, member(&S::pci, &C::local_bus, &L::clock_mhz),
                        "the board's local bus clock",
                        "ADM-XRC-II: programmable up to 66 MHz (PCIe: the card's fabric, assumption)"),
                   member(&S::pcie, &E::local_bus, &L::clock_mhz)),
        pcie(real("bus.gigatransfers_per_s", "GT/s", 1, 64, member(&S::pcie, &E::gigatransfers_per_s),
                  "PCIe link rate per lane", kPcieWhatIf)),
        pcie(count("bus.lanes", "lanes", 1, 32, member(&S::pcie, &E::lanes), "PCIe link width", kPcieWhatIf)),
        pcie(real("bus.encoding_efficiency", "(fraction)", 0.5, 1, member(&S::pcie, &E::encoding_efficiency),
                  "line-code efficiency", "PCIe 3.0: 128b/130b")),
        pcie(count("bus.max_payload_bytes", "bytes", 128, 4096, member(&S::pcie, &E::max_payload_bytes),
                   "largest write payload a packet", kPcieWhatIf)),
        pcie(count("bus.max_read_request_bytes", "bytes", 128, 4096, member(&S::pcie, &E::max_read_request_bytes),
                   "largest read request", kPcieWhatIf)),
        pcie(count("bus.tlp_overhead_bytes", "bytes", 0, 256, member(&S::pcie, &E::tlp_overhead_bytes),
                   "framing, sequence number, header, LCRC and DLLP share a packet", kPcieWhatIf)),
        pcie(real("bus.read_round_trip_ns", "ns", 0, 1e6, member(&S::pcie, &E::read_round_trip_ns),
                  "a non-posted read: request to completion", kPcieWhatIf)),
        pcie(real("bus.posted_write_ns", "ns", 0, 1e6, member(&S::pcie, &E::posted_write_ns),
                  "CPU cost of one posted MMIO write", kPcieWhatIf)),
    };
}

// The transaction level (bus.model transaction): its background traffic and
// the PCIe TLP level's parameters; none changes the formula.
std::vector<Setting> bus_model_settings() {
    return {
        // Of every bus, the ideal one included: it costs nothing at either level,
        // so a study may give --bus-model whatever the board's bus.
        flag(choice<BusModel>("bus.model", member(&S::bus_model),
                              "how the bus is timed: formula (closed form, an idle bus) or transaction "
                              "(PCI tenures or PCIe TLPs against background traffic; slower to set up); "
                              "the ideal bus costs nothing at either",
                              "formula: the fast level; docs/bus_models.md measures its error"),
             "bus-model", "formula|transaction"),
        user_bus(real("bus.load_bytes_per_s", "B/s", 0, 1e12, member(&S::bus_load, &W::bytes_per_s),
                      "background traffic of another bus master (a NIC, a disk controller); transaction level only",
                      kNoLoad)),
        user_bus(count("bus.load_burst_bytes", "bytes", 4, 65536, member(&S::bus_load, &W::burst_bytes),
                       "bytes the background master moves a request", "assumption: a disk controller's 512-byte sector")),
        user_bus(choice<Direction>("bus.load_direction", member(&S::bus_load, &W::direction),
                                   "the background master writes (to_host) or reads (to_board) host memory",
                                   "to_host: a NIC receiving or a disk reading into memory")),
        user_bus(choice<LoadArrivals>("bus.load_arrivals", member(&S::bus_load, &W::arrivals),
                                      "background bursts evenly spaced, or seeded exponential gaps (Poisson)",
                                      "periodic: every start phase sampled once")),
        user_bus(count("bus.load_seed", "", 0, UINT64_MAX, member(&S::bus_load, &W::seed),
                       "the seed of random background arrivals", "any fixed seed")),
        user_pcie(count("bus.tlp_header_bytes", "bytes", 12, 16, member(&S::pcie_link, &T::tlp_header_bytes),
                        "a request's header: 12 (3 DW, 32-bit addresses) or 16 (4 DW, 64-bit)",
                        "PCIe: 64-bit host addresses need 4 DW")),
        user_pcie(count("bus.read_completion_boundary_bytes", "bytes", 64, 128,
                        member(&S::pcie_link, &T::read_completion_boundary_bytes),
                        "the completer splits read completions at addresses aligned to it (64 or 128)",
                        "a Xilinx VC709 reference design: 64 (REFERENCE.md)")),
        user_pcie(count("bus.posted_header_credits", "credits", 1, 4096, member(&S::pcie_link, &T::posted_header_credits),
                        "the root complex's posted-request header credits (DMA writes)", "assumption")),
        user_pcie(count("bus.posted_data_credits", "16-byte credits", 1, 65536,
                        member(&S::pcie_link, &T::posted_data_credits),
                        "the root complex's posted data credits (at least one max payload)",
                        "assumption: 16 KiB, more than the credit-return time at the link rate")),
        user_pcie(count("bus.completion_header_credits", "credits", 1, 4096,
                        member(&S::pcie_link, &T::completion_header_credits),
                        "completions the board's read buffer holds (it issues a read only with room for all of them)",
                        "assumption")),
        user_pcie(count("bus.completion_data_credits", "16-byte credits", 1, 65536,
                        member(&S::pcie_link, &T::completion_data_credits),
                        "the board's read buffer (at least one read request)", "assumption: 16 KiB")),
        user_pcie(real("bus.credit_return_ns", "ns", 0, 1e6, member(&S::pcie_link, &T::credit_return_ns),
                       "a TLP consumed to its credits back at the sender (an UpdateFC DLLP)", "assumption")),
        user_pcie(real("bus.bit_error_rate", "(per bit)", 0, 1e-4, member(&S::pcie_link, &T::bit_error_rate),
                       "bit errors on the wire: a corrupt TLP is NAKed and replayed (deterministic draws)",
                       "0: PCIe requires better than 1e-12")),
        user_pcie(real("bus.replay_timer_ns", "ns", 0, 1e6, member(&S::pcie_link, &T::replay_timer_ns),
                       "the replay when the NAK itself is lost", "assumption")),
        user_pcie(count("bus.error_seed", "", 0, UINT64_MAX, member(&S::pcie_link, &T::error_seed),
                        "the seed of the bit-error draws", "any fixed seed")),
    };
}

// The modelled host's time on the reference workload for one baseline (a
// preset gives it; docs/timing.md derives the shipped presets' values).
Setting reference_time(const char* name, double HostConfig::*time) {
    return preset(real(name, "ns", 0, 1e12, member(&S::host, time),
                       "the modelled host's mean frame time on cdvp calibrate's reference workload (the geometric "
                       "mean over its scenes) for the baseline in the name; 0: not stated",
                       "0 without a preset; the presets: their host's factor x the project's reference machine "
                       "(docs/timing.md)"));
}

std::vector<Setting> host_and_run_settings() {
    return {
        preset(text("host.name", member(&S::host, &HostConfig::name), "the modelled host, as the summary names it",
                    "this machine without a preset")),
        flag(preset(real("host.speed_factor", "x", 0.001, 1000, member(&S::host, &HostConfig::speed_factor),
                         "host-speed factor: native software time x F = time on the modelled host; given, it "
                         "overrides a host profile",
                         "1 without a preset; adm-xrc-ii.json derives 4 for a Pentium 4 1.8 GHz")),
             "host-factor", "F"),
        flag(text("host.profile", member(&S::host, &HostConfig::profile),
                  "host profile from cdvp calibrate: with the preset's reference timings it gives this machine's "
                  "host factors (default: host-profile.json in $XDG_CONFIG_HOME/cdvp, else in ~/.config/cdvp, when "
                  "there)",
                  "none: the default location; without a profile, the preset's speed_factor (docs/timing.md)"),
             "host-profile", "FILE"),
        reference_time("host.reference_sap_host_ns", &HostConfig::reference_sap_host_ns),
        reference_time("host.reference_dbvt_host_ns", &HostConfig::reference_dbvt_host_ns),
        reference_time("host.reference_brute_host_ns", &HostConfig::reference_brute_host_ns),
        reference_time("host.reference_soa_host_ns", &HostConfig::reference_soa_host_ns),
        reference_time("host.reference_sap_mt_host_ns", &HostConfig::reference_sap_mt_host_ns),
        preset(count("host.cores", "cores", 0, 4096, member(&S::host, &HostConfig::cores),
                     "the modelled host's cores: a multi-threaded baseline (sap_mt) runs on as many threads as "
                     "this machine and the host both have, unless run.threads says; 0: not stated",
                     "0 without a preset; the presets: their host's data sheet")),
        preset(real("host.ns_per_box", "ns", 0, 1e6, member(&S::driver, &D::ns_per_box),
                    "driver CPU work packing a box", "0 without a preset; assumption: about 45 P4 cycles")),
        preset(real("host.ns_per_pair", "ns", 0, 1e6, member(&S::driver, &D::ns_per_pair),
                    "driver CPU work unpacking a pair", "0 without a preset; assumption: about 10 P4 cycles")),
        preset(real("host.call_ns", "ns", 0, 1e6, member(&S::driver, &D::call_ns),
                    "one call into the kernel driver per board operation",
                    "0 without a preset; assumption: a kernel call of 2002")),
        real("driver.poll_gap_ns", "ns", 0, 1e6, member(&S::driver, &D::poll_gap_ns),
             "CPU time between two status polls (run.wait poll)", "assumption: back-to-back reads"),
        real("driver.timeout_factor", "x", 1, 1000, member(&S::driver, &D::timeout_factor),
             "a wait gives up after this x its worst-case time plus driver.timeout_floor_ns",
             "assumption: twice the worst case"),
        real("driver.timeout_floor_ns", "ns", 1000, 1e9, member(&S::driver, &D::timeout_floor_ns),
             "added to every wait's bound", "assumption: 100 us"),
        flag(choice<UploadMode>("driver.upload", member(&S::driver, &D::upload),
                                "how boxes reach the board: all six arrays each frame; only the boxes whose words "
                                "changed, as 28-byte records (index and six words) of the board's delta stream; or "
                                "per frame whichever the bus formula says is quicker",
                                "the paper's driver uploads every box (docs/communication.md)"),
             "upload", "full|delta|auto"),
        flag(choice<PairFormat>("driver.pair_format", member(&S::driver, &D::pair_format),
                                "how the pair buffer reads back: 8 bytes a pair; per row its index, count and "
                                "partners (4 bytes a pair, 8 a row); or a bitmap of the rows the pairs span "
                                "(N/8 bytes a row, sweeps of up to 11,584 boxes)",
                                "the paper's board returns a list of pairs (docs/communication.md)"),
             "pair-format", "list|counted|bitmap"),
        flag(choice<InterruptPolicy>("driver.interrupts", member(&S::driver, &D::interrupts),
                                     "with --wait irq, which completions interrupt: every DMA's and the board's, or "
                                     "only the board's (the DMA completions polled)",
                                     "the paper's driver takes every interrupt"),
             "interrupts", "every|board"),
        real("driver.poll_backoff", "x", 1, 16, member(&S::driver, &D::poll_backoff),
             "polling back-off: each gap between two polls is this x the one before (from driver.poll_gap_ns, or a "
             "board period), up to driver.poll_gap_max_ns; 1: a constant gap",
             "assumption: a constant gap"),
        real("driver.poll_gap_max_ns", "ns", 0, 1e9, member(&S::driver, &D::poll_gap_max_ns),
             "the largest gap between two polls under back-off", "assumption: 100 us, a tenth of a 1 ms frame"),
        flag(count("scene.objects", "objects", 0, address_map::kMaxObjects, member(&S::scene, &SceneSettings::objects),
                   "objects in a generated scene: its spheres or boxes (pile releases its boxes over the frames), "
                   "or the bodies a Bullet scene is built around (a Bullet scene's default is its own: cdvp bullet "
                   "--help)",
                   "the paper's largest scene"),
             "objects", "N"),
        flag(count("scene.frames", "frames", 0, 1'000'000'000, member(&S::scene, &SceneSettings::frames),
                   "frames of a generated scene",
                   "12: the 2 warm-up frames (run.warmup) and the 10 after them that a mean should rest on at least "
                   "(fewer are flagged: one disturbed frame moves a mean of 10 by a tenth of its excess; docs/timing.md)"),
             "frames", "F"),
        flag(count("scene.seed", "", 0, UINT64_MAX, member(&S::scene, &SceneSettings::seed),
                   "a generated scene's random seed (same seed, same scene)", "any fixed seed"),
             "seed", "S"),
        flag(real("scene.moving_fraction", "", 0, 1, member(&S::scene, &SceneSettings::moving_fraction),
                  "the share of a spheres scene's spheres that move; the rest are static bodies the moving ones "
                  "bounce off (a physics scene's level geometry)",
                  "1: every sphere moves, as in the paper"),
             "moving", "F"),
        count("scene.pile.clusters", "clusters", 1, 1'048'576, member(&S::scene, &SceneSettings::pile_clusters),
              "scene pile: the footprints its boxes fall onto and pile up on, box k onto cluster k mod clusters "
              "(each about four layers deep)",
              "assumption: a few heaps, as a spawner or a collapse drops them"),
        real("scene.heavy.size_ratio", "x", 1, 10000, member(&S::scene, &SceneSettings::heavy_size_ratio),
             "scene heavy: a large box's longest extent over a small box's mean extent (it is 0.75 to 1 x this x 1.5 "
             "units): the level's static slabs, walls and ramps against its debris",
             "assumption: a level's static geometry a hundred times its debris"),
        real("scene.heavy.large_fraction", "", 0, 1, member(&S::scene, &SceneSettings::heavy_large_fraction),
             "scene heavy: the share of its boxes that are large and static, spread evenly over the ids; the rest "
             "are small debris drifting at up to 1 unit/s",
             "assumption: one box in a hundred is level geometry"),
        real("scene.planar.aspect", "x", 1, 10000, member(&S::scene, &SceneSettings::planar_aspect),
             "scene planar: its floor's length (x) over its width (y); 1 a square floor, more a corridor; the floor's "
             "area grows with the objects so they cover a quarter of it",
             "assumption: a square floor"),
        real("scene.brownian.jump", "x span", 0, 1, member(&S::scene, &SceneSettings::brownian_jump),
             "scene brownian: each frame, each box jumps along each axis by a uniform step of up to this x the room "
             "its centre has along that axis (mirrored at the walls); 1: positions all but redrawn every frame",
             "assumption: no frame-to-frame coherence at all"),
        flag(choice<Transfer>("run.transfer", member(&S::driver, &D::transfer),
                    "how the driver moves boxes and pairs: bridge DMA or programmed I/O",
                    "the paper's driver uses the bridge's DMA"),
             "transfer", "dma|pio"),
        flag(choice<WaitMode>("run.wait", member(&S::driver, &D::wait),
                    "how the driver waits for the board: interrupt or polling", "the paper's driver takes interrupts"),
             "wait", "irq|poll"),
        flag(choice<ModelLevel>("run.fidelity", member(&S::run, &RunSettings::fidelity),
                    "the modelling level: fast computes pairs and cycles from the schedule, cycle clocks the datapath "
                    "edge by edge (the same pairs, cycles and times; --vcd needs cycle or rtl, and picks cycle when "
                    "the fidelity is not given); rtl clocks the board's Verilog under Verilator, the reference the "
                    "others answer to (a parameter set not built in, cdvp rtl-variants, is compiled on first use and cached: docs/rtl.md); analytic finds the same pairs and times the frame from closed forms "
                    "without the SystemC kernel (FIFO stalls estimated, the host quantum not modelled); auto takes "
                    "the analytic level where its error is bounded or measured within --max-error, fast elsewhere",
                    "fast: exact, faster (docs/fast_engine.md); rtl: docs/rtl.md; analytic: docs/analytic.md"),
             "fidelity", "rtl|cycle|fast|analytic|auto"),
        flag(real("run.max_error_percent", "%", 0, 100, member(&S::run, &RunSettings::max_error_percent),
                  "--fidelity auto: the largest error of any phase, in percent of the frame time, the analytic level "
                  "may have where it is measured against the fast engine",
                  "1%: below the spread of the paper's own measurements (assumption)"),
             "max-error", "E"),
        flag(real("run.quantum_ns", "ns", 0, 1e9, member(&S::run, &RunSettings::quantum_ns),
                  "host CPU quantum in ns: how far the CPU runs ahead of the board and bus before it synchronises "
                  "(0: at every access, exact; larger is faster and loosely timed)",
                  "0: exact"),
             "quantum-ns", "Q"),
        flag(count("run.warmup", "frames", 0, 1'000'000'000, member(&S::run, &RunSettings::warmup),
                   "frames at the start of each run left out of the timing statistics (allocation, first insertion)",
                   "Bullet's incremental broad phases build their structures in the first frames (docs/timing.md)"),
             "warmup", "W"),
        flag(count("run.repeat", "runs", 1, 1000, member(&S::run, &RunSettings::repeat),
                   "time the baselines over the frames R times, fresh instances each run; each figure is the median "
                   "of the runs' means (the board's simulated times are deterministic and simulated once)",
                   "one run"),
             "repeat", "R"),
        flag(count("run.threads", "threads", 0, 1024, member(&S::run, &RunSettings::threads),
                   "threads of a multi-threaded baseline (sap_mt), timed by the wall clock since they run side by "
                   "side; 0: this machine's cores, at most the modelled host's (host.cores)",
                   "0: every core of this machine (docs/timing.md)"),
             "threads", "N"),
        flag(count("run.retime_tries", "tries", 0, 100, member(&S::run, &RunSettings::retime_tries),
                   "how often a baseline frame disturbed while timed (an involuntary context switch, a move to "
                   "another CPU) is timed again, on fresh instances stepped through the frames before it; a frame "
                   "still disturbed after them marks the timing disturbed; 0: never",
                   "three: a pre-empted frame of a few hundred microseconds comes clean on the first try beside one "
                   "busy loop (docs/timing.md)"),
             "retime-tries", "T"),
        flag(checked_text("run.pin_cpu", "none or a CPU number this process may run on",
                          [](const std::string& value) {
                              if (value != "none" && !parse_cpu_number(value)) {
                                  throw std::invalid_argument("expected none or a CPU number (0 to 1023)");
                              }
                          },
                          member(&S::run, &RunSettings::pin_cpu),
                          "pin the run (simulator and baselines) to one CPU before any frame; none: the scheduler "
                          "places it",
                          "none: CPU time already leaves out time spent waiting for a CPU (docs/timing.md)"),
             "pin-cpu", "N"),
        switch_flag(choice<bool>("run.ignore_capacity", member(&S::run, &RunSettings::ignore_capacity),
                           "run a board that does not fit its device (device.*) anyway, to explore what a larger "
                           "device would give",
                           "no: a board that does not fit is refused naming the resource"),
                    "ignore-capacity"),
        switch_flag(choice<bool>("run.ignore_timing", member(&S::run, &RunSettings::ignore_timing),
                           "run a board clock beyond the Fmax estimated for its device (device.* and the "
                           "synthesis timing tables: every piece and the whole board as one design) anyway, to "
                           "explore a faster design; the summary, the report and a sweep's row carry the warning",
                           "no: a clock beyond the estimate is refused naming the piece or path that limits it "
                           "(docs/resources.md)"),
                    "ignore-timing"),
        switch_flag(choice<bool>("run.lockstep", member(&S::run, &RunSettings::lockstep),
                           "--fidelity rtl: clock the clocked engine beside the RTL and compare them after every edge "
                           "(addresses, lane hits, FIFO level, pairs, registers, state); the run stops at the first "
                           "difference, naming the cycle and the signal",
                           "no: the RTL alone (docs/rtl.md)"),
                    "lockstep"),
        flag(count("run.max_memory", "MiB", 0, uint64_t{1} << 30, member(&S::run, &RunSettings::max_memory_mib),
                   "memory budget: a run whose estimate (boxes, board model, engine, pairs, baselines, frames) "
                   "exceeds it is refused before any work; 0: half of this machine's memory, or of a cgroup's "
                   "memory limit or RLIMIT_AS when lower",
                   "half: the rest for the system, the page cache and other work (assumption)"),
             "max-memory", "MiB"),
        flag(count("run.max_pairs", "pairs", 0, uint64_t{1} << 43, member(&S::run, &RunSettings::max_pairs),
                   "the most pairs a frame may hold, refused where they are found; 0: as many as the memory budget "
                   "leaves room for, at the bytes a pair costs on its way through the run",
                   "0: derived from run.max_memory (docs/numerics.md)"),
             "max-pairs", "P"),
        flag(count("run.max_trace_size", "MiB", 1, uint64_t{1} << 20, member(&S::run, &RunSettings::max_trace_mib),
                   "the largest trace, a file or a pipe (a pipe is copied to $TMPDIR as it is read)",
                   "assumption: room for 65,536 boxes x 2,000 frames at full precision (about 110 bytes a box)"),
             "max-trace-size", "MiB"),
    };
}

}  // namespace

const std::vector<Setting>& settings_table() {
    static const std::vector<Setting> table = [] {
        std::vector<Setting> all = board_settings();
        for (auto* group : {device_settings, power_settings, bus_settings, bus_model_settings, host_and_run_settings}) {
            for (Setting& s : group()) all.push_back(std::move(s));
        }
        return all;
    }();
    return table;
}

std::optional<uint32_t> RunSettings::pinned_cpu() const { return parse_cpu_number(pin_cpu); }

}  // namespace cdvp
