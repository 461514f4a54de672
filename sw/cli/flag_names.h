// The command line's names for settings and a run's inputs (SettingNames):
// a setting given by its dedicated flag is "--m", one given as -c NAME=VALUE
// is "-c board.m", and every other input is its long option, "--trace"
// (an override's, "override", is "-c").
#pragma once

#include <memory>

#include "platform/settings/setting_names.h"

namespace cdvp {

class FlagNames : public SettingNames {
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

std::shared_ptr<const SettingNames> flag_names();

}  // namespace cdvp
