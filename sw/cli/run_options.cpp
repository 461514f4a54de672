#include "sw/cli/run_options.h"

#include <algorithm>
#include <optional>
#include <sstream>
#include <vector>

#include "models/common/user_text.h"
#include "platform/settings/board_preset.h"
#include "platform/settings/settings.h"
#include "sw/baselines/broad_phase.h"
#include "sw/bullet/scenes.h"
#include "sw/cli/setting_flag.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

// The run's budgets (run.max_*) have a group of their own.
bool is_budget(const Setting& s) { return s.name.rfind("run.max_", 0) == 0; }

}  // namespace

void add_setting_flags(po::options_description& group, const std::vector<std::string>& sections,
                       std::vector<Assignment>& given, bool budgets, const std::function<bool(const Setting&)>& applies) {
    for (const Setting& s : settings_table()) {
        if (s.flag.empty() || std::find(sections.begin(), sections.end(), s.section()) == sections.end()) continue;
        if (is_budget(s) != budgets || (applies && !applies(s))) continue;
        group.add_options()(s.flag.c_str(), new SettingFlag(s, &given), s.help.c_str());
    }
}

void add_board_option(po::options_description& group, std::string& board_name) {
    // The presets as found where they are looked for, so the list is never behind them.
    std::string names;
    for (const std::string& name : board_preset_names()) names += (names.empty() ? "" : ", ") + name;
    const std::string help = "board preset" + (names.empty() ? "" : " (" + names + ")") +
                             " from $CDVP_BOARDS, else share/cdvp/boards of the installed prefix, else the source "
                             "tree's platform/boards; or a .json path; without it: the board alone on an ideal, "
                             "untimed bus";
    group.add_options()("board", po::value(&board_name)->value_name("NAME"), help.c_str());
}

po::options_description settings_options(SettingLayersText& layers) {
    po::options_description settings("Settings (every one: cdvp settings; docs/settings.md)");
    settings.add_options()
        ("config", po::value(&layers.config)->value_name("FILE"),
         "settings file, JSON or (.toml) TOML, over the preset's: {\"board\": {\"m\": 4}} or [board] m = 4")
        (",c", po::value(&layers.overrides)->value_name("NAME=VALUE"),
         "one setting over the config file's (repeatable), e.g. -c bus.interrupt_ns=5000; dedicated flags go over "
         "it");
    return settings;
}

void add_wave_options(po::options_description& group, std::string& vcd, std::string& frames, std::string& format) {
    group.add_options()
        ("vcd", po::value(&vcd)->value_name("FILE"),
         "waveforms of the board, bridge DMA, PCI bus and interrupts, with a GTKWave save file beside it "
         "(FILE minus .vcd or .fst, plus .gtkw: gtkwave -a FILE.gtkw) that groups the signals by block, names "
         "the controller's and DMA engine's states (FILE.controller-states.txt, FILE.dma-states.txt) and opens "
         "on the first traced frame")
        ("vcd-frames", po::value(&frames)->value_name("A:B"),
         "trace only frames A to B (as the run numbers them); the others run untraced, every signal holding")
        ("vcd-format", po::value(&format)->value_name("vcd|fst"),
         "the waveforms' format: vcd (the default), or fst, GTKWave's compressed format, made from the VCD by "
         "vcd2fst (Debian package gtkwave): smaller and faster to open for long windows");
}

po::options_description run_options_description(RunOptions& o) {
    po::options_description input("Input (one of)");
    const std::string scenes = "generated scene: spheres (the paper's application), a kinematic family: pile, heavy, "
                               "planar, brownian (docs/scenes.md), or one of Bullet's scenes as cdvp record records "
                               "them: " + bullet_scene_list() + " (docs/bullet.md)";
    input.add_options()
        ("trace", po::value(&o.trace)->value_name("FILE"), "scene trace CSV (docs/formats.md)")
        ("scene", po::value(&o.scene)->value_name("NAME"), scenes.c_str());
    add_setting_flags(input, {"scene"}, o.layers.flags);
    po::options_description board("Board");
    add_board_option(board, o.layers.board_name);
    add_setting_flags(board, {"board", "bus"}, o.layers.flags);
    // The baselines as the registry names them, so help cannot fall behind it.
    static const std::string baseline_help = [] {
        std::string known;
        for (const std::string& name : broad_phase_names()) known += (known.empty() ? "" : ", ") + name;
        return "software broad phases to time on the same frames, comma-separated: " + known +
               " (a name ending in _mt runs on --threads threads), or best: the candidates an expert would pick "
               "for the frames' size, each timed, the fastest named in the summary and the report "
               "(docs/baselines.md)";
    }();
    po::options_description host("Host, baselines and faults");
    add_setting_flags(host, {"host", "driver", "run"}, o.layers.flags);
    host.add_options()
        ("baseline", po::value(&o.baselines)->value_name("LIST"), baseline_help.c_str())
        ("software-timings", po::value(&o.software_timings)->value_name("DIR"),
         "share the baselines' timing through DIR (cdvp sweep gives every point OUT/software): a timing of this "
         "run's workload there (scene and its settings or the trace's frames, baselines, repeats, warm-up, this "
         "CPU and host profile) is taken, and nothing is timed; else the run times them and adds its timing, "
         "DIR made as mkdir -p if missing (docs/timing.md)")
        ("inject", po::value(&o.inject)->value_name("KIND@frame=N[,n=K]"),
         "inject a bus or board fault into frame N (repeatable): target-abort, master-abort, retry, disconnect, "
         "lost-irq, dma-hang, board-error (docs/faults.md)");
    po::options_description budgets("Budgets (checked before the work, and the pairs as they are found; docs/numerics.md)");
    add_setting_flags(budgets, {"run"}, o.layers.flags, true);
    po::options_description output("Output (written only if the whole run succeeds)");
    output.add_options()
        ("pairs-out", po::value(&o.pairs_out)->value_name("FILE"), "overlapping pairs CSV (frame,a,b)")
        ("report", po::value(&o.report)->value_name("FILE"),
         "JSON report: every setting with where it came from, and per-frame cycles");
    add_wave_options(output, o.vcd, o.vcd_frames, o.vcd_format);
    output.add_options()
        ("progress", po::value(&o.progress)->value_name("auto|lines|none")->default_value("auto"),
         "the frames' progress on stderr: auto (a line kept in place, on a terminal only), lines (a line "
         "about every second with the time left, for logs, scripts and notebooks that capture stderr) or none")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors (no progress either)")
        ("help,h", po::bool_switch(&o.help), "show this help");
    po::options_description all(
        "Usage: cdvp run (--trace FILE | --scene NAME [--objects N] [--frames F] [--seed S]) [options]\n\n"
        "Simulates each frame on the virtual platform and reports its pairs, cycles and time.\n"
        "Settings come in layers, each over the last: defaults < --board preset < --config FILE\n"
        "< -c NAME=VALUE < the dedicated flags below.\n"
        "Options are spelt in full (no abbreviations); numbers show their range and default");
    all.add(input).add(board).add(settings_options(o.layers)).add(host).add(budgets).add(output);
    return all;
}

po::variables_map parse_strictly(int argc, char** argv, const po::options_description& description) {
    const po::parsed_options parsed =
        po::command_line_parser(argc, argv)
            .options(description)
            .style(po::command_line_style::default_style & ~po::command_line_style::allow_guessing)
            .run();
    for (const std::string& stray : po::collect_unrecognized(parsed.options, po::include_positional)) {
        throw InputError("unexpected argument '" + excerpt(stray) + "'");
    }
    po::variables_map vm;
    po::store(parsed, vm);
    po::notify(vm);
    return vm;
}

po::variables_map parse_run_options(int argc, char** argv, RunOptions& options) {
    // Described once a process (a sweep parses a point's options thousands of
    // times a second), bound to one scratch RunOptions that is emptied before
    // each parse and copied out after it.
    static RunOptions scratch;
    static const po::options_description description = run_options_description(scratch);
    scratch = RunOptions{};
    po::variables_map vm = parse_strictly(argc, argv, description);
    options = scratch;
    return vm;
}

namespace {

// The option an unknown one was likely meant to be ("--frames" for
// "--frmaes"), when one lies within a typo's distance of it.
std::optional<std::string> nearest_option(const std::string& typed, const po::options_description& options) {
    if (typed.rfind("--", 0) != 0 || typed.size() < 4) return std::nullopt;
    const std::string name = typed.substr(2, typed.find('=') == std::string::npos ? std::string::npos : typed.find('=') - 2);
    std::vector<std::string> names;
    for (const auto& option : options.options()) {
        if (!option->long_name().empty()) names.push_back(option->long_name());
    }
    const std::optional<std::string> nearest = nearest_name(name, names);
    if (!nearest) return std::nullopt;
    return "--" + *nearest;
}

}  // namespace

std::string option_error_text(po::error& error, const std::string& program, const po::options_description* options) {
    std::string suggestion;
    if (const auto* unknown = dynamic_cast<const po::unknown_option*>(&error); unknown != nullptr && options != nullptr) {
        if (const auto nearest = nearest_option(unknown->get_option_name(), *options)) {
            suggestion = "; did you mean '" + *nearest + "'?";
        }
    }
    if (auto* named = dynamic_cast<po::error_with_option_name*>(&error)) {
        // boost quotes an unknown option as typed: keep a huge one short.
        const std::string name = named->get_option_name();
        if (name.size() > kExcerptBytes) {
            named->set_option_name("");  // boost then quotes the original token
            named->set_original_token(excerpt(name));
        }
    }
    return printable(error.what()) + suggestion + " (see " + program + " --help)";
}

std::string run_options_help() {
    RunOptions defaults;
    std::ostringstream text;
    text << run_options_description(defaults);
    return text.str();
}

}  // namespace cdvp
