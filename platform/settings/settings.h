// Every setting of a run declared once, in the spirit of VCML properties and
// SystemC CCI parameters: dotted name, type, unit, default, range or choices,
// help, the source or assumption behind the default, and the member of
// Settings it binds to. Board presets, config files, -c overrides, the
// dedicated flags of `cdvp run`, the report's config and `cdvp settings` all
// derive from settings_table() (settings.cpp); nothing else names a setting.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "models/board_spec/board_config.h"
#include "models/pci/bus_timing.h"
#include "models/pci/pcie_tlp_link.h"
#include "platform/settings/setting_choices.h"
#include "platform/driver/board_driver.h"

namespace cdvp {

struct HostConfig {
    std::string name = "this machine";
    // Native software time x speed_factor = time on the modelled host, when
    // no host profile calibrates this machine (sw/run/host_factor.h).
    double speed_factor = 1.0;
    // The modelled host's mean frame time on cdvp calibrate's reference
    // workload, per baseline (the geometric mean over its scenes; 0: not
    // stated, the factor is speed_factor). A host profile's times of the same
    // workload on this machine turn them into factors.
    double reference_sap_host_ns = 0;
    double reference_dbvt_host_ns = 0;
    double reference_brute_host_ns = 0;
    double reference_soa_host_ns = 0;
    double reference_sap_mt_host_ns = 0;  // sap_mt on one thread
    // The host's cores: a multi-threaded baseline runs on no more of them
    // than this machine has (run.threads 0); 0: not stated, this machine's.
    uint32_t cores = 0;
    std::string profile;  // the host profile to read; empty: the default location
};

struct SceneSettings {
    uint64_t objects = 500;
    // sw/timing's kDefaultWarmupFrames + kMinMeasuredFrames: the fewest whose
    // means the run does not flag as resting on too few (a test holds them equal).
    uint64_t frames = 12;
    uint64_t seed = 1;
    double moving_fraction = 1.0;  // SpheresConfig::moving_fraction
    // The scene families' own (sw/scene: PileConfig, HeavyConfig,
    // PlanarConfig, BrownianConfig; a test holds the defaults equal).
    uint64_t pile_clusters = 3;
    double heavy_size_ratio = 100.0;
    double heavy_large_fraction = 0.01;
    double planar_aspect = 1.0;
    double brownian_jump = 1.0;
};

struct RunSettings {
    // run.pin_cpu as a CPU number; nothing for "none".
    std::optional<uint32_t> pinned_cpu() const;
    ModelLevel fidelity = ModelLevel::kFast;
    double quantum_ns = 0.0;
    double max_error_percent = 1.0;  // run.fidelity auto's bound
    uint64_t warmup = 2;  // sw/timing's kDefaultWarmupFrames (a test holds them equal)
    uint32_t repeat = 1;
    uint32_t threads = 0;  // a multi-threaded baseline's; 0: this machine's cores
    uint32_t retime_tries = 3;      // sw/timing's kDefaultRetimeTries (a test holds them equal)
    std::string pin_cpu = "none";   // or a CPU number: see pinned_cpu()
    bool ignore_capacity = false;
    bool ignore_timing = false;  // a clock beyond the estimated Fmax warns instead of refusing
    bool lockstep = false;  // run.fidelity rtl: the clocked engine compared after every edge
    // Budgets, checked before any work (sw/run/run_budgets.h). 0: derived
    // (from this machine's memory; from the memory budget).
    uint64_t max_memory_mib = 0;
    uint64_t max_pairs = 0;
    uint64_t max_trace_mib = 16384;
};

// The FPGA the board is built on, and what it holds (a preset's device
// section). family names the synthesis results that cost the board
// (models/resources); kNone: no device, nothing is bounded.
struct DeviceSettings {
    std::string name = "none";
    DeviceFamily family = DeviceFamily::kNone;
    uint64_t luts = 0;            // 0: unbounded
    uint64_t flip_flops = 0;      // 0: unbounded
    uint32_t block_rams = 0;      // 18-Kbit block RAMs; 0: unbounded
    // Off-chip SSRAM beside the FPGA: banks, words a bank (36-bit, one float
    // a word), read pipeline latency; one access a clock a bank. 0 banks: none.
    uint32_t ssram_banks = 6;
    uint64_t ssram_words = 524288;
    uint32_t ssram_latency_cycles = 2;
};

// What the board, its bus and its host draw (models/energy; docs/energy.md):
// the presets give each figure with its source; 0 without a preset.
struct PowerSettings {
    double static_w = 0;              // device.static_w
    double clb_uw_per_mhz = 0;        // device.clb_uw_per_mhz
    double luts_per_clb = 8;          // device.luts_per_clb
    double flip_flops_per_clb = 8;    // device.flip_flops_per_clb
    double block_ram_uw_per_mhz = 0;  // device.block_ram_uw_per_mhz
    double io_pj_per_toggle = 0;      // device.io_pj_per_toggle
    double toggle_percent = 12.5;     // device.toggle_percent: the user's, XPE's default
    double bus_w = 0;                 // bus.active_w
    double host_w = 0;                // host.package_w
    double host_idle_w = 0;           // host.idle_w
};

// Where the board keeps its boxes (platform/memory_plan.h resolves it).
struct MemorySettings {
    BoxMemory memory = BoxMemory::kAuto;
    uint64_t tile_boxes = 0;      // 0: the largest tile whose buffers fit the device
};

// Everything a run is configured by. Each member's initializer is its
// setting's default (the table reads it from a default Settings).
struct Settings {
    BoardConfig board;
    MemorySettings memory;
    DeviceSettings device;
    PowerSettings power;
    BusType bus_type = BusType::kIdeal;
    BusModel bus_model = BusModel::kFormula;
    PciConfig pci;
    PcieConfig pcie;
    PcieLinkConfig pcie_link;  // the TLP level's parameters (bus.model transaction)
    BusLoad bus_load;          // background traffic (bus.model transaction)
    HostConfig host;
    DriverConfig driver;
    SceneSettings scene;
    RunSettings run;

    // The bus bus_type names at the level bus_model names, built from its settings (null for ideal).
    // Throws std::invalid_argument from the bus model's own rules.
    std::shared_ptr<const BusTiming> make_bus() const;
};

enum class SettingType { kCount, kReal, kChoice, kText };
// Which buses a bus.* setting applies to.
enum BusMask : unsigned { kNoBus = 0, kPciBus = 1, kPcieBus = 2, kAnyBus = 3 };

using SettingValue = std::variant<uint64_t, double, std::string>;

struct Setting {
    std::string name;   // "section.key"
    SettingType type = SettingType::kReal;
    std::string unit;
    uint64_t count_min = 0, count_max = 0;  // kCount
    double min = 0, max = 0;                // kReal
    // kReal held in a float (binary32) on the board: a value other than 0 must
    // be a normal float32 (at least FLT_MIN in size), or the board would hold
    // 0 or a denormal in its place while the report recorded the value given.
    bool float32 = false;
    std::vector<std::string> choices;       // kChoice: the names of its type (setting_choices.h)
    // kText with a grammar: what it accepts (for range_text) and the check,
    // which throws std::invalid_argument "expected ..., got '...'".
    std::string accepts;
    std::function<void(const std::string&)> check;
    std::string flag;        // dedicated flag of `cdvp run` without "--"; empty: none
    std::string value_name;  // the flag's value in --help ("M"); empty: a switch that sets "yes"
    std::string help;
    std::string source;      // the source or assumption behind the default
    unsigned buses = kNoBus;
    bool in_preset = false;  // a board preset must give it
    // Bound members: for bus settings, get_pci/set_pci and get_pcie/set_pcie
    // (whichever apply); otherwise get_pci/set_pci.
    std::function<SettingValue(const Settings&)> get_pci, get_pcie;
    std::function<void(Settings&, const SettingValue&)> set_pci, set_pcie;

    std::string section() const { return name.substr(0, name.find('.')); }
    std::string key() const { return name.substr(name.find('.') + 1); }
    bool applies_to_bus(BusType bus_type) const;
    std::string bus_types() const;  // "pci", "pcie" or "pci or pcie"
    SettingValue get(const Settings& s) const;
    void set(Settings& s, const SettingValue& value) const;
    // The default, on the first bus the setting applies to.
    SettingValue default_value() const;
    // "1 to 32", "dma or pio", "" for text.
    std::string range_text() const;
    // What a user typed (a flag's value, -c): throws std::invalid_argument
    // "expected an integer from 1 to 32, got 'TEXT'".
    SettingValue parse_text(const std::string& text) const;
    // A number or string read from a file: throws std::invalid_argument
    // "expected 1 to 32 cycles, got 40" (got: 'shown', as the file has it).
    SettingValue from_number(double value, const std::string& shown) const;
    SettingValue from_count(uint64_t value) const;
    SettingValue from_string(const std::string& value) const;
};

const std::vector<Setting>& settings_table();
// nullptr if no setting has this name.
const Setting* find_setting(const std::string& name);
// A setting the code names itself: std::logic_error if the table lacks it.
const Setting& declared_setting(const std::string& name);
// The name in 'names' a typo of 'name' was likely meant to be: the nearest
// by edit distance, when within a typo's reach of it (half the characters
// of the name's last dotted part, at least 2) or when it spells the same
// first word ("call_nanoseconds": "call_ns"); otherwise nothing, so that a
// name far from every one gets no suggestion.
std::optional<std::string> nearest_name(const std::string& name, const std::vector<std::string>& names);
std::vector<std::string> setting_names();
// A value as text: integers in full, reals as %g, strings as they are.
std::string to_text(const SettingValue& value);

}  // namespace cdvp
