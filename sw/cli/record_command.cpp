// `cdvp record`: a scene's boxes, frame by frame, as a trace: Bullet's scenes
// and the generated ones (spheres and the kinematic families).
#include <iostream>
#include <optional>
#include <vector>

#include "models/common/user_text.h"
#include "sw/bullet/scene_recording.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/run_command.h"
#include "sw/cli/run_options.h"
#include "sw/output/output_set.h"
#include "sw/run/generated_source.h"
#include "sw/run/run_checks.h"
#include "sw/run/run_setup.h"
#include "sw/scene/trace_csv.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kRecordUsage =
    "Usage: cdvp record --scene NAME [--objects N] [--frames F] [--seed S]\n"
    "                   [-c scene.KEY=VALUE]... --out TRACE.csv [-q]\n"
    "\n"
    "Writes a scene's boxes, frame by frame, as a trace: ids in the scene's order, frames numbered from 0,\n"
    "the scene's settings (scene.*: cdvp settings) as cdvp run takes them, with the same defaults.\n"
    "A generated scene gives the frames 'cdvp run --scene NAME' simulates with the same settings; the\n"
    "spheres step on each frame's pairs as on a float32 board. A Bullet scene steps on the board's broad\n"
    "phase, a float32 board's pairs found on the host (so the world moves bit for bit as the world of\n"
    "'cdvp bullet' on the board, and as on btSimpleBroadphase), and writes the AABBs Bullet's broad phase\n"
    "was given in each step: one box per collision object.\n"
    "The trace replays with 'cdvp run --trace TRACE.csv' (a frame without boxes writes no rows).";

struct RecordOptions {
    std::string scene;
    SettingLayersText layers;
    std::string out;
    bool quiet = false;
};

std::string recordable_scenes() { return generated_scene_list() + " or one of Bullet's, " + bullet_scene_list(); }

int record(const RecordOptions& o, const po::variables_map& vm) {
    if (vm.count("scene") == 0) throw InputError("--scene: expected " + recordable_scenes());
    const bool bullet = is_bullet_scene(o.scene);
    if (!bullet && !is_generated_scene(o.scene)) {
        throw InputError("--scene: expected " + recordable_scenes() + ", got '" + excerpt(o.scene) + "'");
    }
    const BoardSetup setup = board_setup(setting_layers_of(o.layers, vm), o.scene);
    const SettingValues& values = setup.values;
    for (const Setting* s : values.effective()) {
        if (s->section() != "scene" && !values.is_default(*s)) {
            throw InputError(values.where(*s) + ": cdvp record writes a scene's frames; only its scene.* settings "
                             "go with it (cdvp run takes the rest)");
        }
    }
    std::optional<SceneSpec> spec;
    if (bullet) {
        spec = bullet_scene_spec(o.scene, values);
        try {
            scene_layout(*spec);
        } catch (const std::invalid_argument& e) {
            throw InputError(std::string("--scene: ") + e.what());
        }
    }
    if (vm.count("out") == 0) throw InputError("--out: expected the trace file to write");
    OutputSet files;
    const std::size_t trace = files.add_output("--out", o.out);
    files.open();
    std::ostream& out = files.file(trace).stream();
    write_trace_header(out);
    // Written a frame at a time: memory holds one frame, however long the scene.
    uint64_t frames = 0;
    std::size_t boxes = 0;
    const auto take = [&](const Frame& frame) {
        write_trace_frame(out, frame);
        ++frames;
        boxes = frame.boxes.size();
    };
    if (spec) {
        SceneRecording recording(*spec);
        for (uint64_t frame = 0; frame < values.settings().scene.frames; ++frame) take(recording.next());
    } else {
        play_generated(o.scene, values, take);
    }
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp record", *failure);
    if (!o.quiet) {
        std::cout << "recorded " << frames << " frames of " << boxes << " boxes" << (frames > 1 ? " (the last)" : "")
                  << " (" << o.scene << ") to " << printable(o.out) << '\n';
    }
    return kExitDone;
}

}  // namespace

int record_command(int argc, char** argv) {
    RecordOptions o;
    po::options_description options("Scene");
    const std::string scenes = "the scene: " + recordable_scenes() + " (docs/scenes.md, docs/bullet.md)";
    options.add_options()("scene", po::value(&o.scene)->value_name("NAME"), scenes.c_str());
    add_setting_flags(options, {"scene"}, o.layers.flags);
    options.add(settings_options(o.layers));
    po::options_description output("Output");
    output.add_options()
        ("out", po::value(&o.out)->value_name("TRACE.csv"), "the trace to write (written only if the run succeeds)")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors");
    options.add(output);
    return run_command_line("cdvp record", argc, argv, kRecordUsage, options,
                            [&o](const po::variables_map& vm) { return record(o, vm); });
}

}  // namespace cdvp
