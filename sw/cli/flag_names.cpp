#include "sw/cli/flag_names.h"

#include "platform/settings/settings.h"

namespace cdvp {

std::string FlagNames::given(const Setting& setting) const { return "--" + setting.flag; }
std::string FlagNames::overridden(const Setting& setting) const { return "-c " + setting.name; }
std::string FlagNames::named(const Setting& setting) const {
    return setting.flag.empty() ? setting.name : "--" + setting.flag;
}
std::string FlagNames::given_value(const Setting& setting, const std::string& value) const {
    return "--" + setting.flag + " " + value;
}
std::string FlagNames::overridden_value(const Setting& setting, const std::string& value) const {
    return "-c " + setting.name + "=" + value;
}
std::string FlagNames::setting_to(const Setting& setting, const std::string& value) const {
    if (setting.flag.empty()) return "-c " + setting.name + "=" + value;
    return setting.value_name.empty() ? "--" + setting.flag : "--" + setting.flag + " " + value;
}
std::string FlagNames::given_origin(const Setting& setting) const { return "flag --" + setting.flag; }
std::string FlagNames::overridden_origin(const Setting&) const { return "-c"; }
std::string FlagNames::input(const std::string& key) const { return key == "override" ? "-c" : "--" + key; }

std::shared_ptr<const SettingNames> flag_names() {
    static const std::shared_ptr<const SettingNames> names = std::make_shared<FlagNames>();
    return names;
}

}  // namespace cdvp
