#include "platform/settings/settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "models/common/number_text.h"
#include "models/common/user_text.h"
#include "models/pci/pci_transaction_bus.h"

namespace cdvp {

namespace {

std::string join(const std::vector<std::string>& words, const std::string& last) {
    std::string text;
    for (std::size_t k = 0; k < words.size(); ++k) {
        text += (k == 0 ? "" : k + 1 == words.size() ? last : ", ") + words[k];
    }
    return text;
}

// The most a master can move on the bus, each way: PCI's width x clock, a
// PCIe link's lanes x transfer rate after the line code. Background traffic
// beyond it is no load the bus could carry (and the transaction level would
// simulate every one of its bursts).
double peak_bytes_per_s(const Settings& s, std::string& how) {
    if (s.bus_type == BusType::kPci) {
        how = std::to_string(s.pci.width_bits) + " bits at " + show_number(s.pci.clock_mhz) + " MHz";
        return s.pci.width_bits / 8.0 * s.pci.clock_mhz * 1e6;
    }
    how = std::to_string(s.pcie.lanes) + " lanes at " + show_number(s.pcie.gigatransfers_per_s) + " GT/s after the line code";
    return s.pcie.gigatransfers_per_s * 1e9 * s.pcie.lanes * s.pcie.encoding_efficiency / 8.0;
}

}  // namespace

std::shared_ptr<const BusTiming> Settings::make_bus() const {
    if (bus_type != BusType::kIdeal && bus_model == BusModel::kFormula && bus_load.active()) {
        throw std::invalid_argument("bus.load_bytes_per_s: expected 0 with bus.model formula (it times an idle bus; "
                                    "give --bus-model transaction)");
    }
    if (bus_type != BusType::kIdeal) {
        std::string how;
        const double peak = peak_bytes_per_s(*this, how);
        if (bus_load.bytes_per_s > peak) {
            char times[32];
            std::snprintf(times, sizeof times, "%.3g", bus_load.bytes_per_s / peak);
            throw std::invalid_argument("bus.load_bytes_per_s: expected at most the bus's peak of " +
                                        show_number(std::floor(peak)) + " B/s (" + how + "), got " +
                                        show_number(bus_load.bytes_per_s) + ", " + times + " x it");
        }
    }
    const bool detailed = bus_model == BusModel::kTransaction;
    switch (bus_type) {
        case BusType::kPci:
            if (detailed) return std::make_shared<PciTransactionTiming>(pci, bus_load);
            return std::make_shared<PciTiming>(pci);
        case BusType::kPcie:
            if (detailed) return std::make_shared<PcieTlpTiming>(pcie, pcie_link, bus_load);
            return std::make_shared<PcieTiming>(pcie);
        case BusType::kIdeal: break;
    }
    return nullptr;
}

bool Setting::applies_to_bus(BusType bus_type) const {
    if (buses == kNoBus) return true;
    return (bus_type == BusType::kPci && (buses & kPciBus) != 0) || (bus_type == BusType::kPcie && (buses & kPcieBus) != 0);
}

std::string Setting::bus_types() const {
    return buses == kAnyBus ? "pci or pcie" : buses == kPcieBus ? "pcie" : "pci";
}

// A key of both buses binds the member of the bus in effect; a key of one
// bus always binds that bus's member.
SettingValue Setting::get(const Settings& s) const {
    return (s.bus_type == BusType::kPcie && get_pcie) || !get_pci ? get_pcie(s) : get_pci(s);
}

void Setting::set(Settings& s, const SettingValue& value) const {
    if ((s.bus_type == BusType::kPcie && set_pcie) || !set_pci) {
        set_pcie(s, value);
    } else {
        set_pci(s, value);
    }
}

SettingValue Setting::default_value() const {
    Settings defaults;
    if (buses != kNoBus) defaults.bus_type = (buses & kPciBus) != 0 ? BusType::kPci : BusType::kPcie;
    return get(defaults);
}

std::string Setting::range_text() const {
    switch (type) {
        case SettingType::kCount: return describe_range(count_min, count_max);
        case SettingType::kReal: return describe_range(min, max);
        case SettingType::kChoice: return join(choices, " or ");
        case SettingType::kText: return accepts;
    }
    return "";
}

namespace {

// A real setting's value as the board holds it: one held in a float must be
// 0 or a normal float32 (FLT_MIN up), or the board would hold 0 or a denormal.
double held_value(const Setting& s, double value, const std::string& shown) {
    if (!s.float32 || value == 0 || std::abs(value) >= std::numeric_limits<float>::min()) return value;
    const double least = std::max(s.min, static_cast<double>(std::numeric_limits<float>::min()));
    throw std::invalid_argument("expected " + (s.min <= 0 ? std::string("0 or ") : std::string()) +
                                show_number(least) + " to " + show_number(s.max) + (s.unit.empty() ? "" : " " + s.unit) +
                                " (the board holds it as a float32, whose least normal value is about 1.2e-38), got " +
                                shown);
}

}  // namespace

SettingValue Setting::parse_text(const std::string& text) const {
    switch (type) {
        case SettingType::kCount: return parse_integer_text(text, count_min, count_max);
        case SettingType::kReal: return held_value(*this, parse_real_text(text, min, max), "'" + excerpt(text) + "'");
        case SettingType::kChoice:
        case SettingType::kText: return from_string(text);
    }
    return text;
}

SettingValue Setting::from_number(double value, const std::string& shown) const {
    const std::string unit_text = unit.empty() ? "" : " " + unit;
    if (type == SettingType::kChoice || type == SettingType::kText) {
        throw std::invalid_argument("expected " + (type == SettingType::kText ? std::string("a non-empty string")
                                                                               : range_text()) + ", got " + shown);
    }
    const double lo = type == SettingType::kCount ? static_cast<double>(count_min) : min;
    const double hi = type == SettingType::kCount ? static_cast<double>(count_max) : max;
    if (!(value >= lo && value <= hi)) {
        throw std::invalid_argument("expected " + show_number(lo) + " to " + show_number(hi) + unit_text + ", got " +
                                    shown);
    }
    if (type == SettingType::kReal) return held_value(*this, value, shown);
    if (value != std::floor(value)) throw std::invalid_argument("expected a whole number of" + unit_text + ", got " + shown);
    return static_cast<uint64_t>(value);
}

SettingValue Setting::from_count(uint64_t value) const {
    if (type != SettingType::kCount) return from_number(static_cast<double>(value), std::to_string(value));
    if (value < count_min || value > count_max) {
        throw std::invalid_argument("expected " + describe_range(count_min, count_max) +
                                    (unit.empty() ? "" : " " + unit) + ", got " + std::to_string(value));
    }
    return value;
}

SettingValue Setting::from_string(const std::string& value) const {
    if (type == SettingType::kChoice) {
        if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
            throw std::invalid_argument("expected " + range_text() + ", got '" + excerpt(value) + "'");
        }
        return value;
    }
    if (type == SettingType::kText) {
        if (check) {
            check(value);
        } else if (value.empty()) {
            throw std::invalid_argument("expected a non-empty string");
        }
        return value;
    }
    throw std::invalid_argument("expected a number from " + range_text() + (unit.empty() ? "" : " " + unit) +
                                ", got '" + excerpt(value) + "'");
}

const Setting* find_setting(const std::string& name) {
    for (const Setting& s : settings_table()) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

const Setting& declared_setting(const std::string& name) {
    if (const Setting* s = find_setting(name)) return *s;
    throw std::logic_error("no setting '" + name + "' is declared");
}

std::vector<std::string> setting_names() {
    std::vector<std::string> names;
    for (const Setting& s : settings_table()) names.push_back(s.name);
    return names;
}

std::optional<std::string> nearest_name(const std::string& name, const std::vector<std::string>& names) {
    if (names.empty()) return std::nullopt;
    const std::string& nearest = *std::min_element(names.begin(), names.end(), [&](const std::string& x, const std::string& y) {
        return edit_distance(name, x) < edit_distance(name, y);
    });
    const auto last_part = [](const std::string& text) { return text.substr(text.rfind('.') + 1); };
    const std::string own = last_part(name), theirs = last_part(nearest);
    if (edit_distance(name, nearest) <= std::max<std::size_t>(2, own.size() / 2)) return nearest;
    const std::size_t word = own.find('_');
    if (word != std::string::npos && word >= 3 && theirs.compare(0, word + 1, own, 0, word + 1) == 0 &&
        name.size() - own.size() == nearest.size() - theirs.size() &&
        name.compare(0, name.size() - own.size(), nearest, 0, nearest.size() - theirs.size()) == 0) {
        return nearest;
    }
    return std::nullopt;
}

std::string to_text(const SettingValue& value) {
    if (const auto* count = std::get_if<uint64_t>(&value)) return std::to_string(*count);
    if (const auto* real = std::get_if<double>(&value)) return show_number(*real);
    return std::get<std::string>(value);
}

}  // namespace cdvp
