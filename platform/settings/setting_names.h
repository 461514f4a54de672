// How a face names a setting, and a run's inputs that are no settings, to its
// user. Below the faces a setting is its dotted name ("board.m"); the command
// line says "--m" for a value given by its flag and "-c bus.interrupt_ns" for
// one given as NAME=VALUE; the Python module says "m=" and
// "settings['bus.interrupt_ns']". A face chooses its names once, when it
// layers a run's settings (SettingValues), and every refusal, note and
// report origin below it is worded through them: no layer below the command
// line spells a flag.
#pragma once

#include <memory>
#include <string>

namespace cdvp {

struct Setting;

class SettingNames {
public:
    virtual ~SettingNames() = default;
    // A setting whose value the caller gave typed (a flag, a keyword): "--m", "m=".
    virtual std::string given(const Setting& setting) const;
    // A setting given as NAME=VALUE text: "-c board.m", "settings['board.m']".
    virtual std::string overridden(const Setting& setting) const;
    // A setting as a user would set it (a default's origin, advice): "--m", "-c bus.interrupt_ns".
    virtual std::string named(const Setting& setting) const;
    // The same with its value: "--m 8", "-c board.m=8", "m=8".
    virtual std::string given_value(const Setting& setting, const std::string& value) const;
    virtual std::string overridden_value(const Setting& setting, const std::string& value) const;
    // How to set it to `value`, as advice: "--transfer dma", "--ignore-capacity" (a switch), "transfer='dma'".
    virtual std::string setting_to(const Setting& setting, const std::string& value) const;
    // The report's word for where a given or overridden value came from: "flag --m", "-c".
    virtual std::string given_origin(const Setting& setting) const;
    virtual std::string overridden_origin(const Setting& setting) const;
    // One of a run's inputs that is no setting, by its key ("trace", "scene",
    // "board", "config", "override", "baseline", "inject", "pairs-out",
    // "report", "vcd", "vcd-frames", "vcd-format", "software-timings",
    // "software"): "--trace", "-c", "trace".
    virtual std::string input(const std::string& key) const;
};

// Settings by their dotted names, inputs by their keys: the names below the faces.
std::shared_ptr<const SettingNames> dotted_setting_names();

}  // namespace cdvp
