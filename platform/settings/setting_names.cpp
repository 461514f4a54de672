#include "platform/settings/setting_names.h"

#include "platform/settings/settings.h"

namespace cdvp {

std::string SettingNames::given(const Setting& setting) const { return setting.name; }
std::string SettingNames::overridden(const Setting& setting) const { return setting.name; }
std::string SettingNames::named(const Setting& setting) const { return setting.name; }
std::string SettingNames::given_value(const Setting& setting, const std::string& value) const {
    return setting.name + "=" + value;
}
std::string SettingNames::overridden_value(const Setting& setting, const std::string& value) const {
    return setting.name + "=" + value;
}
std::string SettingNames::setting_to(const Setting& setting, const std::string& value) const {
    return setting.name + "=" + value;
}
std::string SettingNames::given_origin(const Setting&) const { return "given"; }
std::string SettingNames::overridden_origin(const Setting&) const { return "override"; }
std::string SettingNames::input(const std::string& key) const { return key; }

std::shared_ptr<const SettingNames> dotted_setting_names() {
    static const std::shared_ptr<const SettingNames> names = std::make_shared<SettingNames>();
    return names;
}

}  // namespace cdvp
