#include "sw/cli/point_options.h"

#include <stdexcept>

namespace po = boost::program_options;

namespace cdvp {

namespace {

// "--NAME=VALUE": NAME, VALUE; false for any other shape.
bool flag_with_value(const std::string& arg, std::string& name, std::string& value) {
    if (arg.rfind("--", 0) != 0) return false;
    const std::size_t equals = arg.find('=');
    if (equals == std::string::npos || equals == 2) return false;
    name = arg.substr(2, equals - 2);
    value = arg.substr(equals + 1);
    return true;
}

const Setting* setting_of_flag(const std::string& flag) {
    for (const Setting& setting : settings_table()) {
        if (setting.flag == flag) return &setting;
    }
    return nullptr;
}

}  // namespace

bool PointOptions::reuse(const std::vector<std::string>& args, RunOptions& options) const {
    if (!parsed_ || args.size() != args_.size()) return false;
    options = options_;
    for (std::size_t k = 0; k < args.size(); ++k) {
        if (args[k] == args_[k]) continue;
        std::string name, value, old_name, old_value;
        if (flag_with_value(args[k], name, value) && flag_with_value(args_[k], old_name, old_value) &&
            name == old_name) {
            if (name == "report") {  // the point's own report: a path, checked when the outputs open
                options.report = value;
                continue;
            }
            // A setting's dedicated flag given once: its value parsed by the setting, as SettingFlag does.
            const Setting* setting = setting_of_flag(name);
            if (setting == nullptr || setting->value_name.empty()) return false;
            Assignment* given = nullptr;
            for (Assignment& a : options.layers.flags) {
                if (a.setting != setting) continue;
                if (given != nullptr) return false;
                given = &a;
            }
            if (given == nullptr) return false;
            try {
                given->value = setting->parse_text(value);
            } catch (const std::invalid_argument&) {
                return false;  // refused: the parser words it
            }
            continue;
        }
        // "-c" "NAME=VALUE": the same NAME, as the j-th -c of the last parse.
        if (k == 0 || args[k - 1] != "-c" || args_[k - 1] != "-c") return false;
        const std::size_t equals = args[k].find('=');
        if (equals == std::string::npos || args[k].compare(0, equals + 1, args_[k], 0, equals + 1) != 0) return false;
        std::size_t j = 0;
        for (std::size_t i = 0; i + 1 < k; ++i) j += args_[i] == "-c";
        if (j >= options.layers.overrides.size() || options.layers.overrides[j] != args_[k]) return false;
        options.layers.overrides[j] = args[k];  // checked where the layers apply (parse_override)
    }
    return true;
}

po::variables_map PointOptions::parse(int argc, char** argv, RunOptions& options) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    RunOptions reused;
    if (reuse(args, reused)) {
        ++reused_;
        options = std::move(reused);
        options_ = options;
        args_ = args;
        return vm_;  // the same options given: what the run asks of vm (which were given) is the same
    }
    po::variables_map vm = parse_run_options(argc, argv, options);
    args_ = args;
    options_ = options;
    vm_ = vm;
    parsed_ = true;
    return vm;
}

}  // namespace cdvp
