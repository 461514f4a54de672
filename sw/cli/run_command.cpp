#include "sw/cli/run_command.h"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <boost/program_options.hpp>

#include "platform/fault_injection.h"
#include "platform/virtual_board.h"
#include "sw/bullet/scenes.h"
#include "sw/cli/baseline_timing.h"
#include "sw/cli/bullet_scene_source.h"
#include "sw/cli/frame_source.h"
#include "sw/cli/run_checks.h"
#include "sw/cli/run_options.h"
#include "sw/cli/run_platform.h"
#include "sw/cli/run_report.h"
#include "sw/cli/run_setup.h"
#include "sw/cli/shared_baselines.h"
#include "sw/cli/wave_outputs.h"
#include "sw/scene/conversion.h"
#include "sw/study/output/output_set.h"
#include "sw/study/output/output_target.h"
#include "models/common/user_text.h"
#include "sw/scene/pairs_csv.h"
#include "sw/cli/format_reference.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

// The run's output files: one transaction (see OutputSet).
struct Outputs {
    OutputSet files;
    OutputFile* pairs = nullptr;
    OutputFile* report = nullptr;
    WaveOutputs waves;  // --vcd: the dump, its GTKWave save file and state names
};

// Declares the inputs and outputs and checks them together before any work.
void open_outputs(const RunOptions& o, const po::variables_map& vm, Outputs& out) {
    if (vm.count("trace")) out.files.add_input("--trace", o.trace);
    add_setting_inputs(out.files, o.layers, vm);
    std::optional<std::size_t> pairs, report;
    if (vm.count("pairs-out")) pairs = out.files.add_output("--pairs-out", o.pairs_out);
    if (vm.count("report")) report = out.files.add_output("--report", o.report);
    open_with_waves_and_summary(out.files, out.waves, vm, o.vcd, o.vcd_format, o.quiet);
    if (pairs) out.pairs = &out.files.file(*pairs);
    if (report) out.report = &out.files.file(*report);
}

std::unique_ptr<FrameSource> open_source(const RunOptions& o, const po::variables_map& vm, const SettingValues& values,
                                         const RunBudgets& budgets, RunMemo* memo) {
    if (vm.count("trace")) return trace_source(o.trace, budgets.trace_limits(), budgets.input_limits());
    const Settings& settings = values.settings();
    if (is_bullet_scene(o.scene)) {
        return bullet_scene_source(bullet_scene_spec(o.scene, values), static_cast<std::size_t>(settings.scene.frames));
    }
    BouncingSpheresConfig spheres;
    spheres.objects = static_cast<std::size_t>(settings.scene.objects);
    spheres.seed = settings.scene.seed;
    spheres.moving_fraction = settings.scene.moving_fraction;
    const auto frames = static_cast<std::size_t>(settings.scene.frames);
    return memo != nullptr ? memo->scenes.spheres(spheres, frames) : spheres_source(spheres, frames);
}

class Progress {
public:
    Progress(std::size_t total, bool enabled) : total_(total), enabled_(enabled && total > 1 && isatty(2)) {}
    void update(std::size_t done) {
        if (!enabled_) return;
        const auto now = std::chrono::steady_clock::now();
        if (done < total_ && now - last_ < std::chrono::milliseconds(200)) return;
        last_ = now;
        std::cerr << "\rcdvp run: frame " << done << "/" << total_ << std::flush;
        if (done == total_) std::cerr << "\r\033[K" << std::flush;
    }

private:
    std::size_t total_;
    bool enabled_;
    std::chrono::steady_clock::time_point last_{};
};

// What the run simulates on: the board, its bus and host from the settings,
// and the software baselines to time beside it.
struct Setup : BoardSetup {
    BaselineTimer baselines;
    std::pair<uint64_t, uint64_t> trace_window{0, UINT64_MAX};  // --vcd-frames
};

// What the analytic level cannot model is refused, not silently ignored.
void check_analytic_run(const Setup& setup, const RunOptions& o) {
    const SettingValues& values = setup.values;
    const std::string level = std::string("the ") + name_of(values.settings().run.fidelity) + " level (" +
                              values.where(*find_setting("run.fidelity")) + ")";
    if (!o.inject.empty()) {
        throw InputError("--inject: " + level + " has no engine to inject faults into; use --fidelity fast or cycle");
    }
    const Setting& quantum = *find_setting("run.quantum_ns");
    if (values.settings().run.quantum_ns != 0) {
        throw InputError(values.where(quantum) + ": " + level +
                         " times a host that synchronises at every access; expected 0 (docs/analytic.md)");
    }
}

Setup make_setup(const RunOptions& o, const po::variables_map& vm) {
    Setup setup;
    static_cast<BoardSetup&>(setup) = board_setup(o.layers, vm, vm.count("scene") ? o.scene : "");
    setup.platform.faults = fault_specs(o.inject, setup.platform.driver);
    setup.level = model_level(setup.values, vm);
    setup.platform.fidelity = engine_of(setup.level, setup.values.settings().run.lockstep);
    if (setup.level == ModelLevel::kAnalytic || setup.level == ModelLevel::kAuto) check_analytic_run(setup, o);
    // Pipelined frames must be known ahead; an application's next frame
    // comes from this frame's pairs.
    if (setup.values.settings().board.box_banks > 1 && vm.count("scene")) {
        throw InputError(setup.values.where(*find_setting("board.box_banks")) + ": two box banks pipeline frames, " +
                         "but --scene " + o.scene + " steps on each frame's pairs, so its next frame is not known " +
                         "ahead; expected --trace (cdvp record writes a Bullet scene's frames to one)");
    }
    setup.trace_window = vcd_window(o.vcd_frames, vm);
    setup.host = resolve_host_timing(setup.values);
    setup.baselines = BaselineTimer(o.baselines, setup.host, setup.values.settings().run.retime_tries);
    const Setting& repeat = *find_setting("run.repeat");
    if (!setup.values.is_default(repeat) && setup.baselines.empty()) {
        throw InputError(setup.values.where(repeat) +
                         ": reruns the software baselines over the frames; give --baseline too");
    }
    return setup;
}

// What the budgets see of the run (its board is planned for each scene).
RunShape run_shape(const po::variables_map& vm, const Setup& setup) {
    RunShape shape;
    shape.trace = vm.count("trace") != 0;
    shape.bullet_worlds = !shape.trace && is_bullet_scene(vm["scene"].as<std::string>()) ? 1 : 0;
    shape.clocked = setup.level == ModelLevel::kCycle;
    shape.pairs_out = vm.count("pairs-out") != 0;
    shape.baselines = setup.baselines.names();
    shape.repeat = shape.baselines.empty() ? 1 : setup.values.settings().run.repeat;
    shape.board = setup.platform.board;
    return shape;
}

// A stage on the host (the float32 reference, a baseline) whose pairs outgrow
// the budget is refused as the board's read-back is.
template <typename Stage>
auto within_budget(const RunBudgets& budgets, uint64_t frame, Stage&& stage) {
    try {
        return stage();
    } catch (const PairBudgetExceeded& e) {
        throw InputError(budgets.pair_budget_refusal(frame, e.found()));
    }
}

int simulate(const RunOptions& o, FrameSource& source, Setup& setup, Outputs& out,
             const std::vector<std::string>& command_line, const RunBudgets& budgets, nlohmann::json* memory_report,
             RunMemo* memo, SharedBaselines* shared) {
    // A shared timing of this workload: the baselines are not run at all.
    const bool time_baselines = !setup.baselines.empty() && !(shared != nullptr && shared->loaded());
    RunConfig run = describe_run(setup, static_cast<uint32_t>(source.max_objects()), budgets);
    if (out.report != nullptr || !o.quiet) describe_device_fit(run, setup.values.settings());
    run.source = source.describe();
    run.command_line = command_line;
    run.has_report = out.report != nullptr;
    run.baseline_names = setup.baselines.names();
    for (const FaultSpec& spec : setup.platform.faults) run.inject.push_back(to_string(spec));
    RunPlatform platform(setup, run.capacity, out.waves.trace_base());
    run.bus = platform.bus_timing().describe();
    if (VirtualBoard* board = platform.board()) board->set_trace_window(setup.trace_window.first, setup.trace_window.second);
    if (out.pairs) write_pairs_header(out.pairs->stream());
    // Every output is written a frame at a time: memory stays flat however
    // long the run.
    std::optional<ReportWriter> report;
    if (out.report) {
        report.emplace(out.report->stream());
        report->begin(run);
    }
    std::optional<MemoryReport> in_memory;
    if (memory_report != nullptr) in_memory.emplace(*memory_report);
    RunTotals totals(setup.values.settings().run.warmup);
    FormatReference reference(run.config.format, setup.platform.driver.ns_per_pair, budgets.pair_budget(),
                              memo != nullptr ? memo->pairs : nullptr);

    // The later runs of the baselines (--repeat) count as frames too.
    const std::size_t baseline_runs = time_baselines ? setup.values.settings().run.repeat : 1;
    Progress progress(source.frame_count() * baseline_runs, !o.quiet);
    RunWallTimes wall;  // the simulator's own, and the baselines' beside it
    const auto seconds_since = [](std::chrono::steady_clock::time_point start) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // One frame's result: checked against the reference, written, timed
    // against the baselines and fed to the application. An exit status
    // when the run must end.
    const auto take_result = [&](const Frame& frame, const std::vector<FloatBox>& boxes, const FrameResult* frame_result,
                                 const FrameFault& fault, double sim_wall_native_ns) -> std::optional<int> {
        if (frame_result == nullptr) {
            std::cerr << "cdvp run: "
                      << (fault.kind == FrameFault::Kind::kPairBudget
                              ? budgets.pair_budget_refusal(frame.number, fault.pairs_found)
                              : "frame " + std::to_string(frame.number) + ": " + printable(fault.message))
                      << '\n';
            return fault.kind == FrameFault::Kind::kDevice ? kExitDeviceFault : kExitBadInput;
        }
        const FrameResult& result = *frame_result;
        const FormatReference::Check check =
            within_budget(budgets, frame.number, [&] { return reference.check(boxes, result.pairs, result.phases); });
        if (check.missing) {
            std::cerr << "cdvp run: frame " << frame.number << ": "
                      << lost_pair_message(run.config.format, frame, *check.missing) << '\n';
            return kExitDeviceFault;
        }
        if (out.pairs) write_frame_pairs(out.pairs->stream(), frame.number, to_id_pairs(frame, result.pairs));
        FrameStats stats{frame.number, boxes.size(), result.pairs.size(),
                         run.config.swept_slots(boxes.size(), result.phases.compute_cycles, result.phases.stall_cycles),
                         0, result.phases, {}, sim_wall_native_ns, check.extra};
        stats.load_wait_slots = load_wait_slots(run, boxes.size());
        if (time_baselines) {
            const auto baselines_start = std::chrono::steady_clock::now();
            stats.baselines = within_budget(budgets, frame.number, [&] {
                return setup.baselines.time_frame(boxes, sorted(reference.kept(check, result.pairs)), frame.number);
            });
            wall.baselines_s += seconds_since(baselines_start);
        } else if (shared != nullptr && shared->loaded()) {
            stats.baselines = shared->frame(static_cast<std::size_t>(totals.frames()), setup.host);
        }
        if (report) report->frame(stats);
        if (in_memory) in_memory->frame(stats);
        totals.add(stats);
        // The application gets the pairs the host keeps once it has dropped the extra ones.
        source.feed(reference.kept(check, result.pairs));
        progress.update(totals.frames());
        return std::nullopt;
    };
    // A simulated fault comes back by value, so the platform is torn down
    // by an ordinary return (see OutputFile::try_finish); the outputs'
    // destructors discard their temporaries. Pipelined (two box banks), a
    // frame's result comes with the next frame's submission; the frame in
    // flight when the fault came is the one named.
    std::optional<Frame> in_flight;
    std::vector<FloatBox> in_flight_boxes;
    while (std::optional<Frame> frame = source.next()) {
        // Converted here, unless the source keeps its frames converted (a
        // pipelined frame's boxes are kept with it: a copy of its own).
        const std::vector<FloatBox>* kept = platform.pipelined() ? nullptr : source.float_boxes();
        std::vector<FloatBox> converted = kept != nullptr ? std::vector<FloatBox>{} : to_float_boxes(frame->boxes);
        const std::vector<FloatBox>& boxes = kept != nullptr ? *kept : converted;
        FrameFault fault;
        const auto sim_start = std::chrono::steady_clock::now();
        const FrameResult* frame_result = platform.pipelined()
                                              ? platform.try_submit_frame(boxes, frame->number, fault)
                                              : platform.try_run_frame(boxes, frame->number, fault);
        const double sim_wall_native_ns = seconds_since(sim_start) * 1e9;
        wall.simulator_s += sim_wall_native_ns * 1e-9;
        if (!platform.pipelined()) {
            if (const std::optional<int> status = take_result(*frame, boxes, frame_result, fault, sim_wall_native_ns)) {
                return *status;
            }
            continue;
        }
        if (in_flight || fault) {
            if (const std::optional<int> status =
                    take_result(in_flight ? *in_flight : *frame, in_flight ? in_flight_boxes : boxes, frame_result,
                                fault, sim_wall_native_ns)) {
                return *status;
            }
        }
        in_flight = std::move(frame);
        in_flight_boxes = std::move(converted);
    }
    if (in_flight) {
        FrameFault fault;
        const auto sim_start = std::chrono::steady_clock::now();
        const FrameResult* frame_result = platform.try_finish_frames(fault);
        const double sim_wall_native_ns = seconds_since(sim_start) * 1e9;
        wall.simulator_s += sim_wall_native_ns * 1e-9;
        if (const std::optional<int> status =
                take_result(*in_flight, in_flight_boxes, frame_result, fault, sim_wall_native_ns)) {
            return *status;
        }
    }
    std::size_t frames_done = totals.frames();
    if (!time_baselines && shared != nullptr && shared->loaded()) shared->complete(totals);
    if (time_baselines) {
        const auto repeats_start = std::chrono::steady_clock::now();
        setup.baselines.repeat(source, setup.values.settings().run.repeat, totals, [&] { progress.update(++frames_done); });
        setup.baselines.retime(source, totals);
        std::map<std::string, TimingQuality> quality = setup.baselines.quality(totals);
        for (auto& [name, q] : quality) q.load_start = run.load_average_start;
        totals.set_timing_quality(std::move(quality), setup.baselines.max_tries());
        totals.set_retimed(setup.baselines.retimed());
        wall.baselines_s += seconds_since(repeats_start);
        if (shared != nullptr) shared->publish(totals, setup.baselines.max_tries());
    }
    if (VirtualBoard* board = platform.board()) {
        board->close_trace();
        if (const std::optional<std::string> failed = out.waves.finish(*board)) {
            std::cerr << "cdvp run: " << *failed << '\n';
            return kExitSystem;
        }
    }

    if (report) {
        const nlohmann::json choice =
            platform.choice() ? nlohmann::json{{"fidelity_choice", platform.choice()->to_json()}} : nlohmann::json::object();
        report->end(totals, setup.host, &choice);
    }
    if (in_memory) in_memory->end(totals, setup.host);
    if (!o.quiet) {
        std::ostringstream summary;
        print_summary(summary, run, totals, wall);
        if (const LevelChoice* choice = platform.choice()) summary << choice->words() << '\n';
        out.files.set_standard_output(summary.str());
    }
    // Reported by value, not thrown: see OutputFile::try_finish.
    if (const std::optional<OutputFailure> failure = out.files.try_commit()) return commit_failed("cdvp run", *failure);
    const std::string note = setup.baselines.empty() ? "" : uncalibrated_note(setup.host);
    if (!o.quiet && !note.empty()) std::cerr << "cdvp run: " << note << '\n';
    return 0;
}

}  // namespace

namespace {

// What run_checked returns, having done nothing, when asked for an analytic
// run only and the settings choose another level.
constexpr int kNotAnalytic = -1;

// The run, with option errors pointing at --help.
// memory_report: the report is kept there (frames and summary), not written;
// memo: pairs and scenes kept across runs.
int run_checked(int argc, char** argv, bool analytic_only = false, nlohmann::json* memory_report = nullptr,
                RunMemo* memo = nullptr) {
    try {
        RunOptions o;
        const po::variables_map vm =
            memo != nullptr ? memo->options.parse(argc, argv, o) : parse_run_options(argc, argv, o);
        check_path_lengths({{"trace", &o.trace}, {"board", &o.layers.board_name}, {"config", &o.layers.config},
                            {"pairs-out", &o.pairs_out}, {"report", &o.report}, {"vcd", &o.vcd}},
                           vm);
        // Outputs first: a path that cannot be written, or that names an
        // input or another output, is refused before any work.
        Outputs out;
        open_outputs(o, vm, out);
        check_source_options(o, vm);
        Setup setup = make_setup(o, vm);
        if (analytic_only && setup.level != ModelLevel::kAnalytic) return kNotAnalytic;
        check_scene_settings(vm, setup.values);
        const FrameOrigin origin = vm.count("trace") ? FrameOrigin{o.trace, ""} : FrameOrigin{"", o.scene};
        RunBudgets budgets(setup.values, setup.platform, run_shape(vm, setup), origin);
        // A generated scene is checked before it is generated (millions of
        // spheres take a while to place), a trace once it is read.
        const SceneSettings& scene = setup.values.settings().scene;
        if (vm.count("scene")) {
            // A Bullet scene's board holds its every collision object.
            const uint64_t boxes = is_bullet_scene(o.scene) ? scene_layout(bullet_scene_spec(o.scene, setup.values)).proxies
                                                            : scene.objects;
            check_scene_fits(origin, setup.values, boxes, scene.frames, budgets);
            const std::optional<uint64_t> last =
                scene.frames > 0 ? std::optional<uint64_t>(scene.frames - 1) : std::nullopt;
            check_inject_frames(setup.platform.faults, last, [](uint64_t) { return true; },
                                "--frames " + std::to_string(scene.frames));
        }
        std::unique_ptr<FrameSource> source = open_source(o, vm, setup.values, budgets, memo);
        check_scene_fits(origin, setup.values, source->max_objects(), source->frame_count(), budgets);
        check_inject_frames(setup.platform.faults, source->last_frame(),
                            [&source](uint64_t n) { return source->has_frame(n); }, source->describe());
        check_trace_window(setup.trace_window, source->last_frame(), source->describe());
        pin_to_setting_cpu(setup.values);
        std::optional<SharedBaselines> shared;
        if (vm.count("software-timings") && !setup.baselines.empty()) {
            if (o.software_timings.empty()) throw InputError("--software-timings: expected a directory, got ''");
            shared.emplace(o.software_timings,
                           software_workload(vm.count("scene") ? o.scene : "", *source, setup.values,
                                             setup.baselines.names(), setup.host),
                           setup.baselines.names(), setup.values.settings().run.repeat, source->frame_count());
        }
        // Every stage that collects a frame's pairs holds the same budget.
        setup.platform.pair_budget = budgets.pair_budget();
        setup.baselines.set_pair_budget(budgets.pair_budget());
        if (memo != nullptr) setup.platform.pair_memo = memo->pairs;
        return simulate(o, *source, setup, out, report_command_line(argc, argv), budgets, memory_report, memo,
                        shared ? &*shared : nullptr);
    } catch (po::error_with_option_name& e) {
        // boost quotes an unknown option as typed: keep a huge one short.
        const std::string name = e.get_option_name();
        if (name.size() > kExcerptBytes) {
            e.set_option_name("");  // boost then quotes the original token
            e.set_original_token(excerpt(name));
        }
        std::cerr << "cdvp run: " << printable(e.what()) << " (see cdvp run --help)\n";
        return kExitBadInput;
    } catch (const po::error& e) {
        std::cerr << "cdvp run: " << printable(e.what()) << " (see cdvp run --help)\n";
        return kExitBadInput;
    }
}

}  // namespace

int run_command(int argc, char** argv) {
    // After "--" every argument is positional, so a "--help" there is a stray word.
    for (int k = 1; k < argc && std::strcmp(argv[k], "--") != 0; ++k) {
        if (std::strcmp(argv[k], "--help") == 0 || std::strcmp(argv[k], "-h") == 0) {
            return print_to_stdout("cdvp run", run_options_help() + '\n');
        }
    }
    return exit_status_of("cdvp run", [&] { return run_checked(argc, argv); });
}

std::optional<int> run_analytic_in_process(const std::vector<std::string>& args, std::string& errors,
                                           nlohmann::json* report, RunMemo* memo) {
    std::vector<std::string> words{"run"};  // as main passes a command its words
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    // The run's one-line error is the caller's, as a child's stderr would be.
    std::ostringstream captured;
    std::streambuf* const previous = std::cerr.rdbuf(captured.rdbuf());
    int status = 0;
    try {
        status = exit_status_of("cdvp run", [&] { return run_checked(static_cast<int>(words.size()), argv.data(), true, report, memo); });
    } catch (...) {
        std::cerr.rdbuf(previous);
        throw;
    }
    std::cerr.rdbuf(previous);
    errors = captured.str();
    if (status == kNotAnalytic) return std::nullopt;
    return status;
}

}  // namespace cdvp
