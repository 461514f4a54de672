#include "sw/run/bullet_worlds.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "models/common/user_text.h"
#include "sw/bullet/board_broadphase.h"
#include "sw/bullet/board_link.h"
#include "sw/bullet/bullet_world.h"
#include "sw/bullet/scenes.h"
#include "sw/run/bullet_report.h"
#include "sw/run/machine_info.h"
#include "sw/run/machine_speed.h"
#include "sw/run/run_checks.h"
#include "sw/run/run_frames.h"
#include "sw/timing/speed_probe.h"

namespace cdvp {

namespace {

// A software step with a speed probe before and after it: the slower in `slower`.
StepTimes probed_step(BulletWorld& world, SpeedProbe& probe, double& slower) {
    const double before = probe.time_ns();
    const StepTimes step = world.step();
    slower = std::max(before, probe.time_ns());
    return step;
}

// The two worlds, stepped frame by frame: the board's world runs each frame
// on the platform through its broad phase; the software world beside it is
// timed in the thread's CPU time (BulletTimes), every disturbed step timed
// again afterwards on a fresh world stepped up to it.
class BulletWorldsSource : public FrameSource {
public:
    BulletWorldsSource(SceneSpec spec, BroadphaseKind software, double factor, uint64_t frames, uint64_t warmup)
        : spec_(std::move(spec)), software_(software), factor_(factor), frames_(frames),
          proxies_(scene_layout(spec_).proxies), times_(warmup) {
        ids_.resize(proxies_);
        std::iota(ids_.begin(), ids_.end(), uint64_t{0});  // the board's order is the world's
    }

    void attach(FramePlatform& platform) override {
        link_.emplace(platform, proxies_);
        board_world_ = make_scene_world(spec_, BroadphaseKind::kBoard, &*link_);
        software_world_ = make_scene_world(spec_, software_);
        load_start_ = load_average();
    }
    bool drives_platform() const override { return true; }

    std::optional<Frame> next() override {
        if (frame_ >= frames_) return std::nullopt;
        Frame frame;
        frame.number = frame_++;
        frame.ids = ids_;
        faulted_ = false;
        try {
            board_step_ = board_world_->step();
        } catch (const BoardFrameFault&) {
            faulted_ = true;  // the run ends on this frame: driven_result says why
            return frame;
        }
        double slower = 0;
        const StepTimes step = probed_step(*software_world_, probe_, slower);
        disturbed_[0].push_back(step.disturbed);
        probes_[0].push_back(slower);
        software_s_ += step.step_ns * 1e-9;
        const BoardFrameStats& board = broadphase().last_frame();
        times_.add({frame.number, board.proxies, board.board_pairs, board_world_->contact_points(), board.phases.total_ns,
                    (board_step_.aabbs_ns + board.bookkeeping_ns) * factor_, step.broadphase_share_ns() * factor_,
                    step.step_ns * factor_});
        return frame;
    }
    const FrameResult* driven_result(FrameFault& fault, double& simulate_ns) override {
        if (faulted_) {
            fault = link_->last_fault();
            return nullptr;
        }
        simulate_ns = broadphase().last_frame().simulate_ns;
        return link_->last_result();
    }
    const std::vector<FloatBox>* float_boxes() const override { return &broadphase().last_boxes(); }

    void rewind() override { throw std::logic_error("Bullet's worlds are stepped once; their software world repeats itself"); }
    std::size_t frame_count() const override { return static_cast<std::size_t>(frames_); }
    std::size_t max_objects() const override { return proxies_; }
    std::optional<uint64_t> last_frame() const override {
        return frames_ > 0 ? std::optional<uint64_t>(frames_ - 1) : std::nullopt;
    }
    bool has_frame(uint64_t number) const override { return number < frames_; }
    std::string describe() const override { return cdvp::describe(spec_); }

    // After the frames: the software world's later runs (--repeat) from the
    // scene's start, and every disturbed step timed again; the native seconds it took.
    double finish_software(uint32_t runs, uint32_t tries, double probe_reference_ns, bool pinned) {
        double seconds = software_s_;
        // The later runs step a fresh software world from the same start: the
        // board's times are simulated, the same every run.
        for (uint32_t run = 2; run <= runs; ++run) {
            software_world_.reset();  // its memory is not the fresh world's to reuse
            software_world_ = make_scene_world(spec_, software_);
            times_.start_software_run();
            disturbed_.emplace_back();
            probes_.emplace_back();
            for (uint64_t frame = 0; frame < frames_; ++frame) {
                double slower = 0;
                const StepTimes step = probed_step(*software_world_, probe_, slower);
                probes_.back().push_back(slower);
                seconds += step.step_ns * 1e-9;
                times_.add_software(step.broadphase_share_ns() * factor_, step.step_ns * factor_);
                disturbed_.back().push_back(step.disturbed);
            }
        }
        software_world_.reset();
        const auto retime_start = std::chrono::steady_clock::now();
        TimingQuality quality = retime(tries, probe_reference_ns);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - retime_start).count();
        quality.load_start = load_start_;
        quality.load_end = load_average();
        times_.set_quality(quality, tries, pinned);
        return seconds;
    }

    const BulletTimes& times() const { return times_; }
    const SceneSpec& spec() const { return spec_; }
    BroadphaseKind software() const { return software_; }

private:
    const BoardBroadphase& broadphase() const { return dynamic_cast<const BoardBroadphase&>(board_world_->broadphase()); }

    // Each software step after the warm-up that a pre-emption, a move to
    // another CPU or a slowed CPU disturbed is timed again: a fresh world
    // stepped untimed up to it (Bullet's worlds are deterministic), up to
    // `tries` passes. The quality of the software world's timing.
    TimingQuality retime(uint32_t tries, double probe_reference_ns) {
        const std::size_t first = frames_ > times_.warmup_frames() ? times_.warmup_frames() : 0;
        TimingQuality quality;
        std::vector<double> all;
        for (const std::vector<double>& run : probes_) {
            all.insert(all.end(), run.begin() + static_cast<std::ptrdiff_t>(first), run.end());
        }
        quality.probe_ns = cdvp::probe_reference_ns(probe_reference_ns, all);
        const double limit = quality.probe_ns * (1 + kProbeTolerance);
        for (std::size_t run = 0; run < disturbed_.size(); ++run) {
            for (std::size_t k = first; k < frames_; ++k) {
                if (disturbed_[run][k] || probes_[run][k] <= limit) continue;
                disturbed_[run][k] = true;
                ++quality.frames_slowed;
            }
        }
        for (uint32_t pass = 0; pass < tries; ++pass) {
            if (!retime_pass(first, limit, quality)) break;
        }
        for (const std::vector<bool>& flags : disturbed_) {
            for (std::size_t k = first; k < flags.size(); ++k) {
                ++quality.frames_timed;
                quality.never_clean += flags[k] ? 1 : 0;
            }
        }
        quality.frames_disturbed = quality.frames_retimed + quality.never_clean;
        quality.runs = static_cast<uint32_t>(disturbed_.size());
        quality.repeat_spread = repeat_spread_of(times_.figures(&BulletFrame::software_step_host_ns).run_means);
        return quality;
    }

    // One pass over the runs with a step still disturbed; false when none was.
    bool retime_pass(std::size_t first, double limit, TimingQuality& quality) {
        bool any = false;
        for (std::size_t run = 0; run < disturbed_.size(); ++run) {
            std::size_t last = frames_;
            for (std::size_t k = first; k < frames_; ++k) {
                if (disturbed_[run][k]) last = k;
            }
            if (last == frames_) continue;
            any = true;
            const std::unique_ptr<BulletWorld> world = make_scene_world(spec_, software_);
            for (std::size_t k = 0; k <= last; ++k) {
                if (k < first || !disturbed_[run][k]) {
                    world->step();
                    continue;
                }
                double slower = 0;
                const StepTimes step = probed_step(*world, probe_, slower);
                ++quality.tries;
                if (step.disturbed || slower > limit) continue;
                times_.replace_software(run, k, step.broadphase_share_ns() * factor_, step.step_ns * factor_);
                disturbed_[run][k] = false;
                ++quality.frames_retimed;
            }
        }
        return any;
    }

    SceneSpec spec_;
    BroadphaseKind software_;
    double factor_;  // Bullet's times are whole worlds: the host's overall factor
    uint64_t frames_;
    uint32_t proxies_;
    std::vector<uint64_t> ids_;
    std::optional<PlatformLink> link_;
    std::unique_ptr<BulletWorld> board_world_, software_world_;
    StepTimes board_step_;
    bool faulted_ = false;
    uint64_t frame_ = 0;
    BulletTimes times_;
    std::vector<std::vector<bool>> disturbed_{1};  // the software world's steps, [run][frame]
    std::vector<std::vector<double>> probes_{1};   // the slower speed probe beside each
    SpeedProbe probe_;
    double software_s_ = 0;
    std::array<double, 3> load_start_{};
};

// The observer's part of a Bullet run: the software world finished after the
// frames, the report's "bullet" section and the summary's table.
class BulletSection : public ForwardingObserver {
public:
    BulletSection(RunObserver& next, BulletWorldsSource& source, const RunSetup& setup)
        : ForwardingObserver(next), source_(source), setup_(setup) {}

    nlohmann::json sections(RunWallTimes& wall) override {
        const RunSettings& run = setup_.values.settings().run;
        wall.baselines_s += source_.finish_software(run.repeat, run.retime_tries, setup_.host.probe_reference_ns,
                                                    run.pinned_cpu().has_value());
        nlohmann::json sections = ForwardingObserver::sections(wall);
        sections["bullet"] = source_.times().section(source_.spec(), source_.software());
        return sections;
    }
    std::string summary(const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall,
                        const LevelChoice* choice) override {
        return ForwardingObserver::summary(run, totals, wall, choice) +
               source_.times().table(source_.software(), run.host, setup_.host.describe(), run.has_report);
    }

private:
    BulletWorldsSource& source_;
    const RunSetup& setup_;
};

RunSetup bullet_setup(const RunSpec& spec, const BulletWorlds& worlds) {
    const SettingNames& names = *spec.settings.names;
    if (worlds.name.empty()) throw InputError(names.input("scene") + ": expected one of " + bullet_scene_list());
    if (const std::optional<std::string> refused = bullet_scene_refusal(worlds.name)) {
        throw InputError(names.input("scene") + ": " + *refused);
    }
    RunSetup setup;
    // The settings' own checks, as cdvp run and cdvp settings make them.
    static_cast<BoardSetup&>(setup) = checked_board_setup(spec.settings, worlds.name);
    setup.level = model_level(setup.values, spec.outputs.waves.has_value());
    if (setup.level == ModelLevel::kAnalytic) {
        throw InputError(setup.values.where(declared_setting("run.fidelity")) +
                         " analytic: cdvp bullet runs Bullet's world on the platform's engines; expected cycle or fast");
    }
    if (setup.values.settings().board.box_banks > 1) {
        throw InputError(setup.values.where(declared_setting("board.box_banks")) +
                         ": two box banks pipeline frames, but a Bullet world steps on each frame's pairs, so its next "
                         "frame is not known ahead; expected 1 (cdvp record, then cdvp run --trace, pipelines its frames)");
    }
    setup.platform.fidelity = engine_of(setup.level, setup.values.settings().run.lockstep);
    setup.trace_window = vcd_window(spec.outputs.waves ? spec.outputs.waves->frames : std::nullopt, names);
    // Bullet's times are whole worlds, not the reference workload's
    // baselines: they all take setup.host's overall factor.
    if (worlds.software != "simple" && worlds.software != "sap" && worlds.software != "dbvt") {
        throw InputError(names.input("software") + ": expected simple, sap or dbvt, got '" + excerpt(worlds.software) + "'");
    }
    return setup;
}

}  // namespace

RunOutcome run_bullet_worlds(const RunSpec& spec, RunObserver& observer) {
    const auto& worlds = std::get<BulletWorlds>(*spec.frames);
    RunSetup setup = bullet_setup(spec, worlds);
    // Outputs next (the level says what the waveforms hold): a path that
    // cannot be written, or that names an input or another output, is
    // refused before any work.
    RunFiles files;
    open_run_files(spec, setup.level, files);
    const SettingValues& values = setup.values;
    const SceneSpec scene = bullet_scene_spec(worlds.name, values);
    const uint64_t frames = values.settings().scene.frames;
    if (frames == 0) throw InputError(values.where(declared_setting("scene.frames")) + ": expected at least 1 frame to step, got 0");
    const FrameOrigin origin{"", worlds.name};
    RunBudgets budgets(values, setup.platform, budget_shape(spec, setup), origin);
    setup.clock_warning = check_scene_fits(origin, values, scene_layout(scene).proxies, frames, budgets);
    if (setup.clock_warning) observer.note("warning: " + *setup.clock_warning);
    check_trace_window(setup.trace_window, frames - 1, describe(scene), values.names());
    setup.platform.pair_budget = budgets.pair_budget();
    pin_to_setting_cpu(values);
    BulletWorldsSource source(scene, broadphase_kind(worlds.software), setup.host.overall, frames,
                              values.settings().run.warmup);
    BulletSection section(observer, source, setup);
    const RunContext context;
    FrameRun run{spec, source, setup, files, budgets, section, context, nullptr};
    return run_frames(run);
}

}  // namespace cdvp
