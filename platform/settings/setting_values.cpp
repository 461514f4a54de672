#include "platform/settings/setting_values.h"

#include <algorithm>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

std::string file_and_line(const SettingOrigin& origin) {
    return origin.file + (origin.line > 0 ? ":" + std::to_string(origin.line) : "");
}

}  // namespace

SettingValues::SettingValues(std::shared_ptr<const SettingNames> names) : names_(std::move(names)) {}

std::string SettingValues::origin_words(const Setting& setting) const {
    const SettingOrigin& o = origin(setting);
    switch (o.kind) {
        case SettingOrigin::Kind::kDefault: return "default";
        case SettingOrigin::Kind::kPreset: return "preset " + o.file;
        case SettingOrigin::Kind::kConfig: return "config " + file_and_line(o);
        case SettingOrigin::Kind::kOverride: return names_->overridden_origin(setting);
        case SettingOrigin::Kind::kGiven: return names_->given_origin(setting);
    }
    return "default";
}

const SettingOrigin& SettingValues::origin(const Setting& setting) const {
    static const SettingOrigin kDefault;
    const auto it = origins_.find(setting.name);
    return it == origins_.end() ? kDefault : it->second;
}

void SettingValues::apply(const std::vector<Assignment>& layer) {
    std::vector<const Assignment*> ordered;
    for (const Assignment& a : layer) ordered.push_back(&a);
    std::stable_partition(ordered.begin(), ordered.end(),
                          [](const Assignment* a) { return a->setting->name == "bus.type"; });
    for (const Assignment* a : ordered) {
        const Setting& s = *a->setting;
        if (!s.applies_to_bus(settings_.bus_type)) {
            SettingValues at = *this;
            at.origins_[s.name] = a->origin;
            const Setting& type = *find_setting("bus.type");
            const std::string bus_origin = is_default(type) ? "the default" : origin_words(type);
            throw InputError(at.where(s) + ": a setting of a " + s.bus_types() + " bus; the bus is " +
                             name_of(settings_.bus_type) + " (" + bus_origin + ")" +
                             (settings_.bus_type == BusType::kIdeal
                                  ? ": give " + names_->input("board") + " or " + names_->setting_to(type, "pci|pcie")
                                  : ""));
        }
        s.set(settings_, a->value);
        origins_[s.name] = a->origin;
    }
}

std::vector<const Setting*> SettingValues::effective() const {
    std::vector<const Setting*> in_effect;
    for (const Setting& s : settings_table()) {
        if (s.applies_to_bus(settings_.bus_type)) in_effect.push_back(&s);
    }
    return in_effect;
}

std::string SettingValues::where(const Setting& setting) const {
    const SettingOrigin& o = origin(setting);
    switch (o.kind) {
        case SettingOrigin::Kind::kGiven: return names_->given(setting);
        case SettingOrigin::Kind::kPreset:
        case SettingOrigin::Kind::kConfig: return file_and_line(o) + ": " + setting.name;
        case SettingOrigin::Kind::kOverride: return names_->overridden(setting);
        case SettingOrigin::Kind::kDefault: break;
    }
    return names_->named(setting);
}

std::string SettingValues::origin_text(const Setting& setting) const {
    const SettingOrigin& o = origin(setting);
    if (o.kind == SettingOrigin::Kind::kDefault) return "the default of " + names_->named(setting);
    return where(setting);
}

std::string SettingValues::value_and_origin(const Setting& setting) const {
    const std::string value = to_text(setting.get(settings_));
    switch (origin(setting).kind) {
        case SettingOrigin::Kind::kGiven: return names_->given_value(setting, value);
        case SettingOrigin::Kind::kOverride: return names_->overridden_value(setting, value);
        default: break;
    }
    const std::string shown = setting.unit.empty() ? setting.key() + "=" + value : value + " " + setting.unit;
    return shown + " (" + origin_text(setting) + ")";
}

void SettingValues::refuse_model_message(const std::string& message, const std::string& section,
                                         const std::string& suffix) const {
    const std::size_t colon = message.find(':');
    std::string key = colon == std::string::npos ? "" : message.substr(0, colon);
    for (const char* model_prefix : {"pci.", "pcie.", "bus."}) {  // the bus models name their keys "pci.KEY", "bus.KEY"
        if (key.rfind(model_prefix, 0) == 0) key = key.substr(std::string(model_prefix).size());
    }
    if (key == "local_bus") key = "local_bus_*";
    const std::string rest = colon == std::string::npos ? ": " + message : message.substr(colon);
    if (const Setting* s = find_setting(section + "." + key)) throw InputError(where(*s) + rest + suffix);
    // A rule over several keys ("bus.dma_*_burst_bytes"): named from where the bus came from.
    const SettingOrigin& o = origin(*find_setting("bus.type"));
    const std::string file = o.kind == SettingOrigin::Kind::kPreset || o.kind == SettingOrigin::Kind::kConfig
                                 ? file_and_line(o) + ": "
                                 : "";
    throw InputError(file + section + "." + key + rest + suffix);
}

void SettingValues::check_board() const {
    try {
        settings_.board.validate();
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        // The FIFO must hold one cycle's hits, so its check depends on m too.
        const std::string with_m = message.rfind("fifo_depth:", 0) == 0
                                       ? " (with " + value_and_origin(*find_setting("board.m")) + ")"
                                       : "";
        refuse_model_message(message, "board", with_m);
    }
}

std::shared_ptr<const BusTiming> SettingValues::bus() const {
    try {
        return settings_.make_bus();
    } catch (const std::invalid_argument& e) {
        refuse_model_message(e.what(), "bus");
    }
}

nlohmann::json to_json(const SettingValue& value) {
    if (const auto* count = std::get_if<uint64_t>(&value)) return *count;
    if (const auto* real = std::get_if<double>(&value)) return *real;
    return std::get<std::string>(value);
}

}  // namespace cdvp
