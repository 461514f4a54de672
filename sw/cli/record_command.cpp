// `cdvp record`: a Bullet scene's broad-phase AABBs, frame by frame, as a trace.
#include <iostream>
#include <optional>
#include <vector>

#include "models/common/user_text.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/run_command.h"
#include "sw/scene/output_set.h"
#include "sw/scene/trace_csv.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kUsage =
    "Usage: cdvp record --scene NAME [--objects N] [--frames F] [--seed S] --out TRACE.csv [-q]\n"
    "\n"
    "Steps a Bullet scene (on btDbvtBroadphase) and writes, for each frame, the AABBs Bullet's broad\n"
    "phase was given in that step: one box per collision object, ids in the world's order, frames\n"
    "numbered from 0. The trace replays with 'cdvp run --trace TRACE.csv'.";

struct RecordOptions {
    SceneOptions scene;
    std::string out;
    bool quiet = false;
};

int record(const RecordOptions& o, const po::variables_map& vm) {
    const SceneSpec spec = scene_spec(o.scene, vm);
    if (vm.count("out") == 0) throw InputError("--out: expected the trace file to write");
    OutputSet files;
    const std::size_t trace = files.add_output("--out", o.out);
    files.open();
    auto world = make_scene_world(spec, BroadphaseKind::kDbvt);
    // Whole frames are kept until the end: a trace is written in one go.
    std::vector<Frame> frames;
    for (uint64_t frame = 0; frame < o.scene.frames; ++frame) {
        world->step();
        frames.push_back(world->aabbs(frame));  // the AABBs this step's broad phase saw
    }
    write_trace_csv(files.file(trace).stream(), frames);
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp record", *failure);
    if (!o.quiet) {
        std::cout << "recorded " << frames.size() << " frames of " << frames.back().boxes.size() << " boxes ("
                  << spec.name << ") to " << printable(o.out) << '\n';
    }
    return kExitDone;
}

}  // namespace

int record_command(int argc, char** argv) {
    RecordOptions o;
    po::options_description options = scene_options(o.scene);
    po::options_description output("Output");
    output.add_options()
        ("out", po::value(&o.out)->value_name("TRACE.csv"), "the trace to write (written only if the run succeeds)")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors");
    options.add(output);
    return run_command_line("cdvp record", argc, argv, kUsage, options,
                            [&o](const po::variables_map& vm) { return record(o, vm); });
}

}  // namespace cdvp
