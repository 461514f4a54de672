// The Python module's names for settings and a run's inputs (SettingNames):
// a setting with a keyword of its own is "m=" (its command-line flag with
// '_' for '-'), any other "settings['bus.interrupt_ns']", and an input that
// is no setting its keyword, "trace=". Every refusal of a run or sweep the
// module builds names what the user typed in Python.
#pragma once

#include <memory>
#include <string>

#include "platform/settings/setting_names.h"

namespace cdvp {

class PythonNames : public SettingNames {
public:
    std::string given(const Setting& setting) const override;
    std::string overridden(const Setting& setting) const override;
    std::string named(const Setting& setting) const override;
    std::string given_value(const Setting& setting, const std::string& value) const override;
    std::string overridden_value(const Setting& setting, const std::string& value) const override;
    std::string setting_to(const Setting& setting, const std::string& value) const override;
    std::string given_origin(const Setting& setting) const override;
    std::string overridden_origin(const Setting& setting) const override;
    std::string input(const std::string& key) const override;
};

std::shared_ptr<const SettingNames> python_names();

// A setting's keyword: its flag with '_' for '-' ("quantum_ns"); empty: none.
std::string keyword_of(const Setting& setting);
// The setting a keyword sets, or null.
const Setting* setting_of_keyword(const std::string& keyword);
// A choice of "no" or "yes" (run.ignore_capacity, run.lockstep): False or True in Python.
bool is_yes_no(const Setting& setting);

}  // namespace cdvp
