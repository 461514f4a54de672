// The effective settings of a run and where each came from. Layers apply in
// order, each over the last: defaults < board preset < config file <
// NAME=VALUE overrides < values given typed. Every refusal names where the
// failing value came from: the preset or config file and key, or the
// override or given value as the face that took it names it (SettingNames:
// "--m" and "-c board.m" on the command line).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "platform/settings/setting_names.h"
#include "platform/settings/settings.h"

namespace cdvp {

struct SettingOrigin {
    // kOverride: NAME=VALUE text (-c); kGiven: a typed value (a flag, a keyword).
    enum class Kind { kDefault, kPreset, kConfig, kOverride, kGiven };
    Kind kind = Kind::kDefault;
    std::string file;  // a preset's or config file's path
    int line = 0;      // in a config file; 0: not known
};

// One layer's value for one setting.
struct Assignment {
    const Setting* setting = nullptr;
    SettingValue value;
    SettingOrigin origin;
};

class SettingValues {
public:
    // names: how messages and the report name a setting (the face's words).
    explicit SettingValues(std::shared_ptr<const SettingNames> names = dotted_setting_names());

    // Applies one layer: its bus.type first, then the rest. A bus.* setting
    // the bus in effect has no such key for is refused naming the bus type.
    // Throws InputError.
    void apply(const std::vector<Assignment>& layer);

    const Settings& settings() const { return settings_; }
    const SettingNames& names() const { return *names_; }
    const std::shared_ptr<const SettingNames>& shared_names() const { return names_; }
    const SettingOrigin& origin(const Setting& setting) const;
    // As the report gives the origin: "default", "preset PATH", "config
    // FILE:LINE", and for an override or a given value the face's words
    // ("-c", "flag --m").
    std::string origin_words(const Setting& setting) const;
    bool is_default(const Setting& setting) const { return origin(setting).kind == SettingOrigin::Kind::kDefault; }
    // The settings in effect: every one but the bus keys of another bus.
    std::vector<const Setting*> effective() const;

    // How a refusal names the setting: "PATH: board.fifo_depth", "FILE:3:
    // board.m", and a given, overridden or default value in the face's words
    // ("--fifo-depth", "-c board.m").
    std::string where(const Setting& setting) const;
    // Where a value came from, inside a sentence: "--objects", "the default of
    // --objects", "PATH: board.clock_mhz", "-c scene.objects" (the command line's words).
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
    std::shared_ptr<const SettingNames> names_;
    Settings settings_;
    std::map<std::string, SettingOrigin> origins_;
};

// A value as the report and `cdvp settings --json` give it: a number or a string.
nlohmann::json to_json(const SettingValue& value);

}  // namespace cdvp
