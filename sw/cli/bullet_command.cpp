#include "sw/cli/bullet_command.h"

#include <optional>
#include <string>

#include "models/common/user_text.h"
#include "sw/cli/command_observer.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/run_command.h"
#include "sw/run/run.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kBulletUsage =
    "Usage: cdvp bullet --scene NAME [--objects N] [--frames F] [--seed S] [--board B] [options]\n"
    "\n"
    "Steps a Bullet scene (btDiscreteDynamicsWorld) with the virtual board as its broad phase and, in\n"
    "lockstep, the same scene on one of Bullet's broad phases. Per frame: the board's modelled time,\n"
    "Bullet's broad-phase time (AABB update and pair search) and whole step time, the broad phase's\n"
    "share of the step and its Amdahl bound (the most any broad-phase accelerator can speed the step\n"
    "up), and the speed-ups the board gives. Software times are the thread's CPU time x the host factor\n"
    "(from the host profile, as for cdvp run: docs/timing.md); a step a pre-emption or a move to another\n"
    "CPU disturbed is stepped again on a fresh world and timed again (--retime-tries). The summary gives\n"
    "each time's mean over the frames after the warm-up, which the speed-ups compare, with p50, p99 and\n"
    "the maximum, and whether the software's timing came clean.\n"
    "Settings come in layers, each over the last, as for cdvp run: defaults < --board preset\n"
    "< --config FILE < -c NAME=VALUE < the dedicated flags below; the board is checked against its\n"
    "device as cdvp run checks it (--memory auto moves the boxes to SSRAM tiles past the block RAMs).\n"
    "The report is cdvp run's, with a 'bullet' section for the Bullet worlds' times (docs/bullet.md).\n"
    "Options are spelt in full (no abbreviations); numbers show their range and default";

struct BulletOptions {
    std::string scene;
    SettingLayersText layers;
    std::string software = "dbvt";
    std::string report, vcd, vcd_frames, vcd_format = "vcd";
    bool quiet = false;
};

// Every setting means to a Bullet world on the board what it means to a run,
// but the trace's size limit: no trace is read.
bool applies_to_bullet(const Setting& s) { return s.name != "run.max_trace_size"; }

po::options_description bullet_options(BulletOptions& o) {
    po::options_description scene("Scene");
    const std::string scenes = bullet_scene_help() + "; each is built around its own number of bodies (" +
                               bullet_scene_defaults() + ") unless --objects says otherwise";
    scene.add_options()("scene", po::value(&o.scene)->value_name("NAME"), scenes.c_str());
    add_setting_flags(scene, {"scene"}, o.layers.flags);
    po::options_description board("Board");
    add_board_option(board, o.layers.board_name);
    add_setting_flags(board, {"board"}, o.layers.flags);
    po::options_description host("Host and software");
    host.add_options()
        ("software", po::value(&o.software)->value_name("simple|sap|dbvt")->default_value(o.software),
         "Bullet's broad phase to compare with: btSimpleBroadphase, btAxisSweep3, btDbvtBroadphase");
    add_setting_flags(host, {"host", "driver", "run"}, o.layers.flags, false, applies_to_bullet);
    po::options_description budgets("Budgets (checked before the work, and the pairs as they are found; docs/numerics.md)");
    add_setting_flags(budgets, {"run"}, o.layers.flags, true, applies_to_bullet);
    po::options_description output("Output (written only if the whole run succeeds)");
    output.add_options()
        ("report", po::value(&o.report)->value_name("FILE"),
         "JSON report: cdvp run's (every setting with where it came from, the board's phases and cycles a "
         "frame, the summary) and a 'bullet' section (the worlds' times, share, Amdahl bound, gains)");
    add_wave_options(output, o.vcd, o.vcd_frames, o.vcd_format);
    output.add_options()("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors");
    po::options_description all = scene;
    all.add(board).add(settings_options(o.layers)).add(host).add(budgets).add(output);
    return all;
}

// cdvp bullet's options as the run layer takes them.
RunSpec bullet_spec(const BulletOptions& o, const po::variables_map& vm, int argc, char** argv) {
    RunSpec spec;
    spec.settings = setting_layers_of(o.layers, vm);
    spec.frames = BulletWorlds{vm.count("scene") ? o.scene : std::string(), o.software};
    spec.outputs.report = vm.count("report") ? std::optional<std::string>(o.report) : std::nullopt;
    if (vm.count("vcd")) {
        spec.outputs.waves = WaveRequest{o.vcd, vm.count("vcd-frames") ? std::optional(o.vcd_frames) : std::nullopt,
                                         vm.count("vcd-format") ? std::optional(o.vcd_format) : std::nullopt};
    } else if (vm.count("vcd-format")) {
        throw InputError("--vcd-format: the format of --vcd; give --vcd too");
    } else if (vm.count("vcd-frames")) {
        throw InputError("--vcd-frames: traces a window of frames into --vcd; give --vcd too");
    }
    spec.outputs.summary = !o.quiet;
    spec.command_line = report_command_line(argc, argv);
    return spec;
}

}  // namespace

int bullet_command(int argc, char** argv) {
    BulletOptions o;
    const po::options_description options = bullet_options(o);
    return run_command_line("cdvp bullet", argc, argv, kBulletUsage, options, [&](const po::variables_map& vm) {
        const RunSpec spec = bullet_spec(o, vm, argc, argv);
        CommandObserver observer("cdvp bullet", ProgressMode::kNone);
        return command_status("cdvp bullet", run(spec, observer));
    });
}

}  // namespace cdvp
