#include "sw/cli/settings_command.h"

#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "platform/setting_values.h"
#include "sw/cli/run_command.h"

namespace cdvp {

namespace {

constexpr const char* kHelp =
    "Usage: cdvp settings [--json | --markdown]\n"
    "\n"
    "Lists every setting of cdvp run: name, type, unit, default, range or choices, dedicated flag,\n"
    "help and the source or assumption behind the default. Set one with -c NAME=VALUE, a config\n"
    "file (--config FILE), a board preset, or its dedicated flag (docs/settings.md).\n"
    "--json prints a JSON array of objects with keys name, type, unit, default, min, max, choices,\n"
    "flag, help and source; --markdown the table of docs/settings.md.\n";

const char* type_name(SettingType type) {
    switch (type) {
        case SettingType::kCount: return "integer";
        case SettingType::kReal: return "number";
        case SettingType::kChoice: return "choice";
        case SettingType::kText: return "string";
    }
    return "string";
}

// The help, with the bus a bus key applies to.
std::string help_of(const Setting& s) {
    return s.buses == kNoBus ? s.help : s.help + " (" + s.bus_types() + " bus)";
}

// The default; a key of both buses has one for each.
std::string default_text(const Setting& s) {
    if (s.buses != kAnyBus) return to_text(s.default_value());
    Settings pcie;
    pcie.bus_type = "pcie";
    return to_text(s.default_value()) + " (pci), " + to_text(s.get(pcie)) + " (pcie)";
}

nlohmann::json settings_json() {
    nlohmann::json all = nlohmann::json::array();
    for (const Setting& s : settings_table()) {
        const bool count = s.type == SettingType::kCount, real = s.type == SettingType::kReal;
        nlohmann::json min = count ? nlohmann::json(s.count_min) : real ? nlohmann::json(s.min) : nlohmann::json();
        nlohmann::json max = count ? nlohmann::json(s.count_max) : real ? nlohmann::json(s.max) : nlohmann::json();
        all.push_back({{"name", s.name},
                       {"type", type_name(s.type)},
                       {"unit", s.unit},
                       {"default", to_json(s.default_value())},
                       {"min", min},
                       {"max", max},
                       {"choices", s.choices},
                       {"flag", s.flag.empty() ? nlohmann::json() : nlohmann::json("--" + s.flag)},
                       {"help", help_of(s)},
                       {"source", s.source}});
    }
    return all;
}

std::string settings_text() {
    std::ostringstream out;
    for (const Setting& s : settings_table()) {
        out << s.name << "  (" << type_name(s.type) << (s.unit.empty() ? "" : ", " + s.unit);
        if (!s.range_text().empty()) out << "; " << s.range_text();
        out << "; default " << default_text(s) << (s.flag.empty() ? "" : "; --" + s.flag) << ")\n"
            << "    " << help_of(s) << "\n    default: " << s.source << "\n";
    }
    return out.str();
}

std::string cell(const std::string& text) {
    std::string out;
    for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string settings_markdown() {
    std::ostringstream out;
    out << "| name | type | unit | default | range | flag | help | source of the default |\n"
        << "|---|---|---|---|---|---|---|---|\n";
    for (const Setting& s : settings_table()) {
        out << "| `" << s.name << "` | " << type_name(s.type) << " | " << cell(s.unit) << " | "
            << cell(default_text(s)) << " | " << cell(s.range_text()) << " | "
            << (s.flag.empty() ? "" : "`--" + s.flag + "`") << " | " << cell(help_of(s)) << " | " << cell(s.source)
            << " |\n";
    }
    return out.str();
}

}  // namespace

int settings_command(int argc, char** argv) {
    if (argc > 2) {
        std::cerr << "cdvp settings: unexpected argument '" << excerpt(argv[2]) << "' (see cdvp settings --help)\n";
        return kExitBadInput;
    }
    const std::string mode = argc == 2 ? argv[1] : "";
    if (mode == "--help" || mode == "-h") return print_to_stdout("cdvp settings", kHelp);
    if (mode == "--json") return print_to_stdout("cdvp settings", settings_json().dump(2) + "\n");
    if (mode == "--markdown") return print_to_stdout("cdvp settings", settings_markdown());
    if (!mode.empty()) {
        std::cerr << "cdvp settings: unknown option '" << excerpt(mode) << "'; expected --json or --markdown\n";
        return kExitBadInput;
    }
    return print_to_stdout("cdvp settings", settings_text());
}

}  // namespace cdvp
