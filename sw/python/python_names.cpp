#include "sw/python/python_names.h"

#include <algorithm>
#include <set>

#include "platform/settings/settings.h"

namespace cdvp {

namespace {

std::string indexed(const Setting& setting) { return "settings['" + setting.name + "']"; }

// A value as Python spells it: numbers bare, yes and no as True and False, words quoted.
std::string python_value(const Setting& setting, const std::string& value) {
    if (is_yes_no(setting)) return value == "yes" ? "True" : "False";
    const bool number = setting.type == SettingType::kCount || setting.type == SettingType::kReal;
    return number ? value : "'" + value + "'";
}

}  // namespace

std::string keyword_of(const Setting& setting) {
    std::string keyword = setting.flag;
    std::replace(keyword.begin(), keyword.end(), '-', '_');
    return keyword;
}

const Setting* setting_of_keyword(const std::string& keyword) {
    if (keyword.empty()) return nullptr;
    for (const Setting& s : settings_table()) {
        if (keyword_of(s) == keyword) return &s;
    }
    return nullptr;
}

bool is_yes_no(const Setting& setting) {
    return setting.type == SettingType::kChoice && setting.choices.size() == 2 &&
           std::set<std::string>(setting.choices.begin(), setting.choices.end()) == std::set<std::string>{"no", "yes"};
}

std::string PythonNames::given(const Setting& setting) const {
    return setting.flag.empty() ? indexed(setting) : keyword_of(setting) + "=";
}
std::string PythonNames::overridden(const Setting& setting) const { return indexed(setting); }
std::string PythonNames::named(const Setting& setting) const { return given(setting); }
std::string PythonNames::given_value(const Setting& setting, const std::string& value) const {
    return (setting.flag.empty() ? indexed(setting) + "=" : keyword_of(setting) + "=") + python_value(setting, value);
}
std::string PythonNames::overridden_value(const Setting& setting, const std::string& value) const {
    return indexed(setting) + "=" + python_value(setting, value);
}
std::string PythonNames::setting_to(const Setting& setting, const std::string& value) const {
    if (setting.flag.empty()) return "settings={'" + setting.name + "': " + python_value(setting, value) + "}";
    return keyword_of(setting) + "=" + python_value(setting, value);
}
std::string PythonNames::given_origin(const Setting& setting) const {
    return setting.flag.empty() ? "keyword settings" : "keyword " + keyword_of(setting);
}
std::string PythonNames::overridden_origin(const Setting&) const { return "keyword settings"; }
std::string PythonNames::input(const std::string& key) const {
    if (key == "override") return "settings";
    if (key == "pairs-out") return "pairs=";
    std::string keyword = key;
    std::replace(keyword.begin(), keyword.end(), '-', '_');
    return keyword + "=";
}

std::shared_ptr<const SettingNames> python_names() {
    static const std::shared_ptr<const SettingNames> names = std::make_shared<PythonNames>();
    return names;
}

}  // namespace cdvp
