#include "sw/cli/sweep_names.h"

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "sw/cli/child_runs.h"

namespace cdvp {

namespace {

// Set by the sweep for each point, or meaningless as an axis.
bool sweep_owned(const std::string& name) {
    for (const char* own : {"report", "pairs-out", "vcd", "vcd-frames", "help", "quiet"}) {
        if (name == own) return true;
    }
    return false;
}

// A child's standard output, or "" when it does not exit 0.
std::string output_of(const std::vector<std::string>& args) {
    ScratchFile out(".out"), err(".err");
    const int status = run_child(args, err.path(), out.path().c_str());
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? slurp(out.path()) : std::string();
}

}  // namespace

std::set<std::string> help_options(const std::string& help) {
    std::set<std::string> names;
    std::istringstream lines(help);
    for (std::string line; std::getline(lines, line);) {
        // An option's line starts with it; its description may name others.
        const std::size_t first = line.find_first_not_of(' ');
        if (first == std::string::npos || line[first] != '-') continue;
        const std::string column = line.substr(0, std::min<std::size_t>(line.size(), 38));
        for (std::size_t at = column.find("--"); at != std::string::npos; at = column.find("--", at + 2)) {
            std::size_t end = at + 2;
            while (end < column.size() && (std::isalnum(static_cast<unsigned char>(column[end])) || column[end] == '-')) ++end;
            const std::string name = column.substr(at + 2, end - at - 2);
            if (!name.empty() && !sweep_owned(name)) names.insert(name);
        }
    }
    return names;
}

void add_settings(const std::string& json, std::set<std::string>& names) {
    for (const auto& setting : nlohmann::json::parse(json)) {
        if (setting.contains("name") && setting["name"].is_string()) names.insert(setting["name"].get<std::string>());
        if (setting.contains("flag") && setting["flag"].is_string()) {
            std::string flag = setting["flag"].get<std::string>();
            flag.erase(0, flag.find_first_not_of('-'));
            if (!flag.empty() && !sweep_owned(flag)) names.insert(flag);
        }
    }
}

AxisNames axis_names(const std::string& run_help, const std::string& cdvp_binary) {
    AxisNames known;
    known.names = help_options(run_help);
    const std::string settings = output_of({cdvp_binary, "settings", "--json"});
    if (!settings.empty()) {
        try {
            add_settings(settings, known.names);
            known.settings_known = true;
        } catch (const nlohmann::json::exception&) {
            // Not the array this expects: the points refuse unknown names instead.
        }
    }
    return known;
}

void check_axis_names(const std::vector<Axis>& axes, const AxisNames& known) {
    for (const Axis& axis : axes) {
        if (known.names.count(axis.name) != 0) continue;
        if (is_setting_name(axis.name) && !known.settings_known) continue;
        const std::string nearest = nearest_name(axis.name, known.names);
        throw InputError("--set " + excerpt(axis.name) + ": no flag of cdvp run or setting has this name" +
                         (nearest.empty() ? std::string() : "; the nearest is '" + nearest + "'") +
                         " (see cdvp run --help)");
    }
}

std::string nearest_name(const std::string& name, const std::set<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = SIZE_MAX;
    for (const std::string& candidate : candidates) {
        const std::size_t d = edit_distance(name, candidate);
        if (d < best_distance) {
            best_distance = d;
            best = candidate;
        }
    }
    return best;
}

}  // namespace cdvp
