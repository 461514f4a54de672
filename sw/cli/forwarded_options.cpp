#include "sw/cli/forwarded_options.h"

#include "models/common/user_text.h"
#include "platform/settings/config_file.h"
#include "platform/settings/settings.h"
#include "sw/cli/run_options.h"
#include "sw/run/run_arguments.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

// The setting a flag sets, or nothing for a flag that is no setting.
const Setting* setting_of_flag(const std::string& flag) {
    for (const Setting& s : settings_table()) {
        if (!s.flag.empty() && s.flag == flag) return &s;
    }
    return nullptr;
}

ForwardedOption forwarded(const po::option& option) {
    ForwardedOption f;
    f.typed = option.original_tokens.empty() ? option.string_key : option.original_tokens.front();
    f.value = option.value.empty() ? std::string() : option.value.front();
    if (option.string_key == "-c") {
        f.key = parse_override(f.value, "-c").setting->name;  // a bad name or value refused here
        f.words = {"-c", f.value};  // NAME=VALUE starts with a letter: never an option
        return f;
    }
    const Setting* s = setting_of_flag(option.string_key);
    f.key = s != nullptr ? s->name : option.string_key;
    f.words = {option.value.empty() ? "--" + option.string_key : "--" + option.string_key + "=" + f.value};
    return f;
}

}  // namespace

void apply_forwarded(const ForwardedOption& option, RunSpec& spec) {
    if (option.words.size() == 2 && option.words[0] == "-c") {
        spec.settings.overrides.push_back(option.value);
        return;
    }
    const Setting* s = find_setting(option.key);
    const bool is_switch = s != nullptr && s->value_name.empty();
    set_input(spec, option.key, is_switch ? "yes" : option.value, true);
}

std::set<std::string> run_option_names() {
    RunOptions unused;
    const po::options_description run = run_options_description(unused);
    std::set<std::string> names;
    for (const auto& option : run.options()) {
        if (!option->long_name().empty()) names.insert(option->long_name());
    }
    return names;
}

ParsedCommandLine parse_with_run_options(int argc, char** argv, const po::options_description& own,
                                         const std::string& program) {
    RunOptions unused;
    const po::options_description run = run_options_description(unused);
    po::options_description all = own;
    for (const auto& option : run.options()) {
        if (own.find_nothrow(option->long_name().empty() ? option->format_name() : option->long_name(), false) ==
            nullptr) {
            all.add(option);
        }
    }
    ParsedCommandLine line;
    po::parsed_options parsed(&all);
    try {
        parsed = po::command_line_parser(argc, argv)
                     .options(all)
                     .style(po::command_line_style::default_style & ~po::command_line_style::allow_guessing)
                     .run();
        po::store(parsed, line.values);  // checks every value of a setting's flag, and options given twice
    } catch (po::error& e) {
        throw InputError(option_error_text(e, program));
    }
    for (const std::string& stray : po::collect_unrecognized(parsed.options, po::include_positional)) {
        throw InputError("unexpected argument '" + excerpt(stray) + "'");
    }
    for (const po::option& option : parsed.options) {
        if (own.find_nothrow(option.string_key, false) != nullptr) {
            line.own.push_back(option);
        } else {
            line.forwarded.push_back(forwarded(option));
        }
    }
    return line;
}

}  // namespace cdvp
