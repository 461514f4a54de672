// `cdvp record`: a Bullet scene's broad-phase AABBs, frame by frame, as a trace.
#include <iostream>
#include <optional>
#include <vector>

#include "models/common/user_text.h"
#include "sw/bullet/scene_recording.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/run_command.h"
#include "sw/output/output_set.h"
#include "sw/scene/trace_csv.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kRecordUsage =
    "Usage: cdvp record --scene NAME [--objects N] [--frames F] [--seed S] --out TRACE.csv [-q]\n"
    "\n"
    "Steps a Bullet scene on the board's broad phase, a float32 board's pairs found on the host (so the\n"
    "world moves bit for bit as the world of 'cdvp bullet' on the board, and as on btSimpleBroadphase),\n"
    "and writes, for each frame, the AABBs Bullet's broad phase was given in that step: one box per\n"
    "collision object, ids in the world's order, frames numbered from 0.\n"
    "The trace replays with 'cdvp run --trace TRACE.csv'; 'cdvp run --scene NAME' simulates the same\n"
    "frames without the file.";

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
    SceneRecording recording(spec);
    // Whole frames are kept until the end: a trace is written in one go.
    std::vector<Frame> frames;
    for (uint64_t frame = 0; frame < o.scene.frames; ++frame) frames.push_back(recording.next());
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
    return run_command_line("cdvp record", argc, argv, kRecordUsage, options,
                            [&o](const po::variables_map& vm) { return record(o, vm); });
}

}  // namespace cdvp
