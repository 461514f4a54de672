#include "sw/cli/help_text.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/settings_command.h"

#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "platform/settings/setting_values.h"
#include "sw/cli/run_command.h"
#include "sw/cli/run_options.h"
#include "sw/run/run_setup.h"

namespace cdvp {

namespace {

constexpr const char* kSettingsHelp =
    "Usage: cdvp settings [--json | --markdown]\n"
    "       cdvp settings [--board NAME] [--config FILE] [-c NAME=VALUE]... [--json]\n"
    "\n"
    "Lists every setting of cdvp run: name, type, unit, default, range or choices, dedicated flag,\n"
    "help and the source or assumption behind the default. Set one with -c NAME=VALUE, a config\n"
    "file (--config FILE), a board preset, or its dedicated flag (docs/settings.md).\n"
    "--json prints a JSON array of objects with keys name, type, unit, default, min, max, choices,\n"
    "flag, help and source; --markdown the table of docs/settings.md.\n"
    "\n"
    "With --board, --config or -c: the settings a run with those layers would use, each with its\n"
    "value and where it came from (the default, the preset file and key, the config file and line,\n"
    "-c), checked by the code cdvp run checks its settings with (all but the checks against a run's\n"
    "frames and outputs; the clock is held to the device's estimated Fmax at scene.objects boxes), so\n"
    "that what run refuses of them settings refuses in the same words; --json prints an array of\n"
    "{name, value, origin}.\n";

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
    pcie.bus_type = BusType::kPcie;
    return to_text(s.default_value()) + " (pci), " + to_text(s.get(pcie)) + " (pcie)";
}

}  // namespace

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

namespace {

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

// Where a value came from, as the resolved listing says it.
std::string origin_of(const SettingValues& values, const Setting& s) {
    const SettingOrigin& origin = values.origin(s);
    switch (origin.kind) {
        case SettingOrigin::Kind::kDefault: return "default";
        case SettingOrigin::Kind::kPreset: return "preset " + origin.file + ": " + s.name;
        case SettingOrigin::Kind::kConfig:
            return "config " + origin.file + (origin.line > 0 ? ":" + std::to_string(origin.line) : "") + ": " + s.name;
        case SettingOrigin::Kind::kOverride: return "-c " + s.name;
        case SettingOrigin::Kind::kGiven: return "--" + s.flag;
    }
    return "default";
}

// The settings the layers give, each with its value and origin.
int resolved_settings(int argc, char** argv) {
    namespace po = boost::program_options;
    SettingLayersText layers;
    bool json = false;
    po::options_description options;
    options.add_options()("board", po::value(&layers.board_name), "")("config", po::value(&layers.config), "")(
        ",c", po::value(&layers.overrides), "")("json", po::bool_switch(&json), "");
    po::variables_map vm;
    try {
        vm = parse_strictly(argc, argv, options);
    } catch (po::error& e) {
        throw InputError(option_error_text(e, "cdvp settings", &options));
    }
    // Exactly cdvp run's checks of its settings; the frames are not named here.
    const BoardSetup setup = checked_board_setup(setting_layers_of(layers, vm), std::nullopt);
    const SettingValues& values = setup.values;
    if (setup.clock_warning) std::cerr << "cdvp settings: warning: " << *setup.clock_warning << "\n";
    nlohmann::json all = nlohmann::json::array();
    std::ostringstream text;
    for (const Setting* s : values.effective()) {
        const std::string value = to_text(s->get(values.settings()));
        const std::string origin = origin_of(values, *s);
        all.push_back({{"name", s->name}, {"value", to_json(s->get(values.settings()))}, {"origin", origin}});
        text << s->name << " = " << printable(value) << "  (" << printable(origin) << ")\n";
    }
    return print_to_stdout("cdvp settings", json ? all.dump(2) + "\n" : text.str());
}

}  // namespace

int settings_command(int argc, char** argv) {
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--board" || arg == "--config" || arg.rfind("-c", 0) == 0 || arg.rfind("--board=", 0) == 0 ||
            arg.rfind("--config=", 0) == 0) {
            return exit_status_of("cdvp settings", [&] { return resolved_settings(argc, argv); });
        }
    }
    if (argc > 2) {
        std::cerr << "cdvp settings: unexpected argument '" << excerpt(argv[2]) << "' (see cdvp settings --help)\n";
        return kExitBadInput;
    }
    const std::string mode = argc == 2 ? argv[1] : "";
    if (mode == "--help" || mode == "-h") return print_help("cdvp settings", kSettingsHelp);
    if (mode == "--json") return print_to_stdout("cdvp settings", settings_json().dump(2) + "\n");
    if (mode == "--markdown") return print_to_stdout("cdvp settings", settings_markdown());
    if (!mode.empty()) {
        std::cerr << "cdvp settings: unknown option '" << excerpt(mode) << "'; expected --json or --markdown\n";
        return kExitBadInput;
    }
    return print_to_stdout("cdvp settings", settings_text());
}

}  // namespace cdvp
