#include "sw/run/run_frames.h"

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "platform/level_platform.h"
#include "sw/run/exit_codes.h"
#include "sw/run/format_reference.h"
#include "sw/run/machine_info.h"
#include "sw/run/run_memo.h"
#include "sw/bullet/scenes.h"
#include "platform/fault_injection.h"
#include "sw/scene/conversion.h"
#include "sw/scene/pairs_csv.h"

namespace cdvp {

void open_run_files(const RunSpec& spec, ModelLevel level, RunFiles& out) {
    const SettingNames& names = *spec.settings.names;
    if (const auto* trace = spec.frames ? std::get_if<TraceFrames>(&*spec.frames) : nullptr) {
        out.files.add_input(names.input("trace"), trace->path);
    }
    add_setting_inputs(out.files, spec.settings);
    std::optional<std::size_t> pairs, report;
    if (spec.outputs.pairs_csv) pairs = out.files.add_output(names.input("pairs-out"), *spec.outputs.pairs_csv);
    if (spec.outputs.report) report = out.files.add_output(names.input("report"), *spec.outputs.report);
    open_with_waves_and_summary(out.files, out.waves, spec.outputs, names, level);
    if (pairs) out.pairs = &out.files.file(*pairs);
    if (report) out.report = &out.files.file(*report);
}

BudgetShape budget_shape(const RunSpec& spec, const RunSetup& setup) {
    BudgetShape shape;
    shape.trace = std::holds_alternative<TraceFrames>(*spec.frames);
    if (std::holds_alternative<BulletWorlds>(*spec.frames)) {
        shape.bullet_worlds = 2;  // the board's world and the software's beside it
    } else if (const auto* scene = std::get_if<SceneFrames>(&*spec.frames)) {
        shape.bullet_worlds = is_bullet_scene(scene->name) ? 1 : 0;
    }
    shape.clocked = setup.level == ModelLevel::kCycle;
    shape.pairs_out = spec.outputs.pairs_csv.has_value();
    shape.baselines = setup.baselines.names();
    shape.repeat = shape.baselines.empty() ? 1 : setup.values.settings().run.repeat;
    shape.board = setup.platform.board;
    return shape;
}

namespace {

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

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A run's frames, one after another: each simulated (or taken from a source
// that drives the platform itself), checked, written, timed against the
// baselines and fed back to the application.
class FrameLoop {
public:
    explicit FrameLoop(FrameRun& r)
        : r_(r),
          time_baselines_(!r.setup.baselines.empty() && !(r.shared != nullptr && r.shared->loaded())),
          description_(describe_run(r.setup, static_cast<uint32_t>(r.source.max_objects()), r.budgets)),
          totals_(r.setup.values.settings().run.warmup) {}

    RunOutcome run() {
        prepare();
        if (const std::optional<RunOutcome> ended = frames()) return *ended;
        finish_baselines();
        return finish();
    }

private:
    // The description, the platform, and each output's start.
    void prepare() {
        const Settings& settings = r_.setup.values.settings();
        describe_device_fit(description_, settings);
        energy_.emplace(settings, description_.device_fit ? description_.device_fit->resources : BoardResources{});
        totals_.set_host_power(energy_->host_w());
        totals_.set_timing_warning(r_.setup.clock_warning.value_or(""));
        description_.source = r_.source.describe();
        description_.command_line = r_.spec.command_line;
        description_.has_report = r_.files.report != nullptr;
        description_.baseline_names = r_.setup.baselines.names();
        for (const FaultSpec& spec : r_.setup.platform.faults) description_.inject.push_back(to_string(spec));
        platform_.emplace(r_.setup.level, r_.setup.platform, description_.capacity, r_.files.waves.trace_base(),
                          settings.run.max_error_percent);
        description_.bus = platform_->bus_timing().describe();
        if (VirtualBoard* board = platform_->board()) {
            board->set_trace_window(r_.setup.trace_window.first, r_.setup.trace_window.second);
        }
        r_.source.attach(*platform_);
        if (r_.files.pairs) write_pairs_header(r_.files.pairs->stream());
        // Every output is written a frame at a time: memory stays flat however long the run.
        if (r_.files.report) {
            report_.emplace(r_.files.report->stream());
            report_->begin(description_);
        }
        if (r_.context.report != nullptr) in_memory_.emplace(*r_.context.report);
        reference_.emplace(description_.config.format, r_.setup.platform.driver.ns_per_pair, r_.budgets.pair_budget(),
                           r_.context.memo != nullptr ? r_.context.memo->pairs : nullptr);
        // The later runs of the baselines (--repeat) count as frames too.
        total_frames_ = r_.source.frame_count() * (time_baselines_ ? settings.run.repeat : 1);
    }

    // Every frame: an outcome when the run must end early.
    std::optional<RunOutcome> frames() {
        // Pipelined (two box banks), a frame's result comes with the next
        // frame's submission; the frame in flight when a fault came is the one named.
        std::optional<Frame> in_flight;
        std::vector<FloatBox> in_flight_boxes;
        while (std::optional<Frame> frame = r_.source.next()) {
            // Converted here, unless the source keeps its frames converted (a
            // pipelined frame's boxes are kept with it: a copy of its own).
            const std::vector<FloatBox>* kept = platform_->pipelined() ? nullptr : r_.source.float_boxes();
            std::vector<FloatBox> converted = kept != nullptr ? std::vector<FloatBox>{} : to_float_boxes(frame->boxes);
            const std::vector<FloatBox>& boxes = kept != nullptr ? *kept : converted;
            FrameFault fault;
            double sim_ns = 0;
            const FrameResult* result = simulate(boxes, frame->number, fault, sim_ns);
            if (!platform_->pipelined()) {
                if (std::optional<RunOutcome> ended = take(*frame, boxes, result, fault, sim_ns)) return ended;
                continue;
            }
            if (in_flight || fault) {
                if (std::optional<RunOutcome> ended = take(in_flight ? *in_flight : *frame,
                                                           in_flight ? in_flight_boxes : boxes, result, fault, sim_ns)) {
                    return ended;
                }
            }
            in_flight = std::move(frame);
            in_flight_boxes = std::move(converted);
        }
        if (!in_flight) return std::nullopt;
        FrameFault fault;
        const auto start = std::chrono::steady_clock::now();
        const FrameResult* result = platform_->try_finish_frames(fault);
        const double sim_ns = seconds_since(start) * 1e9;
        wall_.simulator_s += sim_ns * 1e-9;
        return take(*in_flight, in_flight_boxes, result, fault, sim_ns);
    }

    // The frame on the platform, or its result from a source that ran it there.
    const FrameResult* simulate(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault, double& sim_ns) {
        if (r_.source.drives_platform()) {
            const FrameResult* result = r_.source.driven_result(fault, sim_ns);
            wall_.simulator_s += sim_ns * 1e-9;
            return result;
        }
        const auto start = std::chrono::steady_clock::now();
        const FrameResult* result = platform_->pipelined() ? platform_->try_submit_frame(boxes, number, fault)
                                                           : platform_->try_run_frame(boxes, number, fault);
        sim_ns = seconds_since(start) * 1e9;
        wall_.simulator_s += sim_ns * 1e-9;
        return result;
    }

    // One frame's result: checked against the reference, written, timed
    // against the baselines and fed to the application. An outcome when the
    // run must end.
    std::optional<RunOutcome> take(const Frame& frame, const std::vector<FloatBox>& boxes, const FrameResult* result,
                                   const FrameFault& fault, double sim_ns) {
        if (result == nullptr) {
            if (fault.kind == FrameFault::Kind::kPairBudget) {
                return RunOutcome{true, kExitBadInput, r_.budgets.pair_budget_refusal(frame.number, fault.pairs_found)};
            }
            return RunOutcome{true, fault.kind == FrameFault::Kind::kDevice ? kExitDeviceFault : kExitBadInput,
                              "frame " + std::to_string(frame.number) + ": " + printable(fault.message)};
        }
        const FormatReference::Check check = within_budget(
            r_.budgets, frame.number, [&] { return reference_->check(boxes, result->pairs, result->phases); });
        if (check.missing) {
            return RunOutcome{true, kExitDeviceFault,
                              "frame " + std::to_string(frame.number) + ": " +
                                  lost_pair_message(description_.config.format, frame, *check.missing)};
        }
        const PairList& kept = reference_->kept(check, result->pairs);
        if (r_.files.pairs) write_frame_pairs(r_.files.pairs->stream(), frame.number, to_id_pairs(frame, result->pairs));
        FrameStats stats{frame.number, boxes.size(), result->pairs.size(),
                         description_.config.swept_slots(boxes.size(), result->phases.compute_cycles,
                                                         result->phases.stall_cycles),
                         0, result->phases, {}, sim_ns, check.extra, {}};
        stats.load_wait_slots = load_wait_slots(description_, boxes.size());
        stats.energy = energy_->frame(result->phases);
        if (time_baselines_) {
            const auto start = std::chrono::steady_clock::now();
            stats.baselines = within_budget(r_.budgets, frame.number, [&] {
                return r_.setup.baselines.time_frame(boxes, sorted(kept), frame.number);
            });
            wall_.baselines_s += seconds_since(start);
        } else if (r_.shared != nullptr && r_.shared->loaded()) {
            stats.baselines = r_.shared->frame(static_cast<std::size_t>(totals_.frames()), r_.setup.host);
        }
        if (report_) report_->frame(stats);
        if (in_memory_) in_memory_->frame(stats);
        totals_.add(stats);
        // The application gets the pairs the host keeps once it has dropped the extra ones.
        r_.source.feed(kept);
        r_.observer.frame_done(totals_.frames(), total_frames_);
        return std::nullopt;
    }

    // The later runs of the baselines (--repeat), the frames timed again,
    // and the timing shared with the other points of a sweep.
    void finish_baselines() {
        if (!time_baselines_) {
            if (r_.shared != nullptr && r_.shared->loaded()) r_.shared->complete(totals_);
            return;
        }
        std::size_t done = totals_.frames();
        const auto start = std::chrono::steady_clock::now();
        BaselineTimer& baselines = r_.setup.baselines;
        baselines.repeat(r_.source, r_.setup.values.settings().run.repeat, totals_,
                         [&] { r_.observer.frame_done(++done, total_frames_); });
        baselines.retime(r_.source, totals_);
        std::map<std::string, TimingQuality> quality = baselines.quality(totals_);
        for (auto& [name, q] : quality) q.load_start = description_.load_average_start;
        totals_.set_timing_quality(std::move(quality), baselines.max_tries());
        totals_.set_retimed(baselines.retimed());
        wall_.baselines_s += seconds_since(start);
        if (r_.shared != nullptr) r_.shared->publish(totals_, baselines.max_tries());
    }

    // The waveforms, the report's end, the summary, and the commit.
    RunOutcome finish() {
        if (VirtualBoard* board = platform_->board()) {
            board->close_trace();
            if (const std::optional<std::string> failed = r_.files.waves.finish(*board)) {
                return RunOutcome{true, kExitSystem, *failed};
            }
        }
        nlohmann::json sections = r_.observer.sections(wall_);
        if (sections.is_null()) sections = nlohmann::json::object();
        if (const LevelChoice* choice = platform_->choice()) sections["fidelity_choice"] = choice->to_json();
        if (report_) report_->end(totals_, r_.setup.host, &sections);
        if (in_memory_) in_memory_->end(totals_, r_.setup.host);
        if (r_.spec.outputs.summary) {
            r_.files.files.set_standard_output(r_.observer.summary(description_, totals_, wall_, platform_->choice()));
        }
        // Reported by value, not thrown: see OutputFile::try_finish.
        if (const std::optional<OutputFailure> failure = r_.files.files.try_commit()) {
            return RunOutcome{true, failure->system() ? kExitSystem : kExitBadInput, printable(failure->message)};
        }
        const bool software = !r_.setup.baselines.empty() || std::holds_alternative<BulletWorlds>(*r_.spec.frames);
        if (const std::string note = software ? uncalibrated_note(r_.setup.host) : ""; !note.empty()) {
            r_.observer.note(note);
        }
        return RunOutcome{};
    }

    FrameRun& r_;
    const bool time_baselines_;
    RunDescription description_;
    std::optional<BoardEnergy> energy_;  // each frame's energy, from the settings and the device fit
    RunTotals totals_;
    RunWallTimes wall_;  // the simulator's own, and the software's beside it
    std::optional<LevelPlatform> platform_;
    std::optional<ReportWriter> report_;
    std::optional<MemoryReport> in_memory_;
    std::optional<FormatReference> reference_;
    std::size_t total_frames_ = 0;
};

}  // namespace

RunOutcome run_frames(FrameRun& run) { return FrameLoop(run).run(); }

}  // namespace cdvp
