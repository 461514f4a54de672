// The effective settings of a run and where each came from. Layers apply in
// order, each over the last: defaults < board preset < config file < -c
// NAME=VALUE < dedicated flags. Every refusal names where the failing value
// came from: the flag, the preset or config file and key, or the -c.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "platform/settings.h"

namespace cdvp {

struct SettingOrigin {
    enum class Kind { kDefault, kPreset, kConfig, kOverride, kFlag };
    Kind kind = Kind::kDefault;
    std::string file;  // a preset's or config file's path
    int line = 0;      // in a config file; 0: not known

    // As the report gives it: "default", "preset PATH", "config FILE:LINE", "-c", "flag --m".
    std::string describe(const Setting& setting) const;
};

// One layer's value for one setting.
struct Assignment {
    const Setting* setting = nullptr;
    SettingValue value;
    SettingOrigin origin;
};

class SettingValues {
public:
    // Applies one layer: its bus.type first, then the rest. A bus.* setting
    // the bus in effect has no such key for is refused naming the bus type.
    // Throws InputError.
    void apply(const std::vector<Assignment>& layer);

    const Settings& settings() const { return settings_; }
    const SettingOrigin& origin(const Setting& setting) const;
    bool is_default(const Setting& setting) const { return origin(setting).kind == SettingOrigin::Kind::kDefault; }
    // The settings in effect: every one but the bus keys of another bus.
    std::vector<const Setting*> effective() const;

    // How a refusal names the setting: "--fifo-depth", "PATH: board.fifo_depth",
    // "FILE:3: board.m", "-c board.m"; a default by its flag if it has one.
    std::string where(const Setting& setting) const;
    // Where a value came from, inside a sentence: "--objects", "the default of
    // --objects", "PATH: board.clock_mhz", "-c scene.objects".
    std::string origin_text(const Setting& setting) const;
    // A value and its origin: "--m 8", "m=8 (the default of --m)", "66 MHz
    // (PATH: board.clock_mhz)", "-c board.m=8".
    std::string value_and_origin(const Setting& setting) const;

    // The board's settings against each other (the FIFO holds one cycle's
    // hits, ...) and the bus model's own rules (PCI is 32 or 64 bits wide,
    // ...): the refusal names where the failing value came from. Throw
    // InputError; bus() returns null for the ideal bus.
    void check_board() const;
    std::shared_ptr<const BusTiming> bus() const;

private:
    // A model's message "KEY: rest" (KEY as BoardConfig or the bus config
    // name it) as a refusal naming where the setting came from.
    [[noreturn]] void refuse_model_message(const std::string& message, const std::string& section,
                                           const std::string& suffix = "") const;
    Settings settings_;
    std::map<std::string, SettingOrigin> origins_;
};

// A value as the report and `cdvp settings --json` give it: a number or a string.
nlohmann::json to_json(const SettingValue& value);

}  // namespace cdvp
