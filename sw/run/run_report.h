// The JSON report of `cdvp run` and its terminal summary. Both are written
// without keeping the run's frames: the report a frame at a time, the summary
// from running totals and the first few frames, so memory stays flat however
// many frames a run has.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <ostream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "models/board_spec/board_config.h"
#include "platform/device_fit.h"
#include "platform/frame_energy.h"
#include "platform/settings/setting_choices.h"
#include "platform/settings/setting_values.h"
#include "sw/run/format_reference.h"
#include "sw/run/host_factor.h"
#include "sw/run/report_summary.h"
#include "platform/driver/board_driver.h"
#include "sw/timing/frame_samples.h"
#include "sw/timing/timing_quality.h"

namespace cdvp {

// Time names say which clock they are on (docs/timing.md): _native_ns is
// measured on this machine, _host_ns is that times the host factor (the
// modelled host), and a plain _ns is the platform's simulated time.
// A baseline's native_ns is its thread's CPU time, the estimator every
// figure rests on; wall_native_ns is the wall time beside it.
struct BaselineTime {
    double native_ns = 0;       // CPU time, measured natively on this machine
    double wall_native_ns = 0;  // wall time of the same call
    double host_ns = 0;         // native_ns x the baseline's host factor: on the modelled host
    uint64_t involuntary_switches = 0;  // while it was timed (first try)
    bool migrated = false;              // it moved to another CPU while timed
    double probe_native_ns = 0;         // the slower SpeedProbe beside it (sw/timing/speed_probe.h)
    double native_energy_j = -1;        // this machine's package energy over the call (RAPL); < 0: not measured
    double threads_cpu_native_ns = 0;   // a multi-threaded baseline's threads' CPU time together (0: one thread)
};

struct FrameStats {
    uint64_t frame = 0;
    uint64_t objects = 0;
    uint64_t pairs = 0;
    uint64_t sweep_cycles = 0;  // S(N, m), or the tiled schedule's slots
    uint64_t load_wait_slots = 0;  // of those, slots waiting for SSRAM tiles
    FramePhases phases;         // simulated; compute_cycles, stall_cycles, overflow_pauses inside
    std::map<std::string, BaselineTime> baselines;
    double sim_wall_native_ns = 0;  // the simulator's own wall time for the frame (no file I/O, no baselines)
    ExtraPairs extra;           // against the float32 reference (none under float32)
    FrameEnergy energy;         // the board's frame: static, dynamic, bus and host (platform/frame_energy.h)
};

// What the run is: its scene, board, bus, host and driver settings.
struct RunDescription {
    BoardConfig config;
    uint32_t capacity = 0;
    uint32_t block_rams = 0;
    bool ssram = false;        // the boxes live in SSRAM, swept in tiles of config.tiles.boxes
    uint32_t tiles = 0;        // tiles at capacity
    uint64_t load_wait_slots = 0;  // at capacity
    std::string source;
    std::string board = "ideal";  // preset name
    std::string bus;
    std::string host;
    HostTiming host_timing;  // the factors from native to modelled-host time, and what they rest on
    std::array<double, 3> load_average_start{};
    // The settings' typed values (the engine as the platform runs it: --vcd
    // picks the clocked one); the report and the summary print their names.
    Transfer transfer = Transfer::kDma;
    WaitMode wait = WaitMode::kIrq;
    double quantum_ns = 0.0;
    ModelLevel fidelity = ModelLevel::kCycle;
    std::vector<std::string> baseline_names;
    uint32_t baseline_runs = 1;  // --repeat
    std::vector<std::string> inject;  // fault specs, as parsed
    const SettingValues* settings = nullptr;  // every setting in effect and where it came from
    std::optional<DeviceFit> device_fit;      // with a device family: the board's resources on it
    std::vector<std::string> command_line;
    bool has_report = false;  // --report: every frame is there
    // The budgets the run is held to, and its memory estimate before any
    // pair and for each pair of a frame (sw/run/run_budgets.h).
    struct Budgets {
        uint64_t memory_bytes = 0;
        uint64_t pairs = 0;
        uint64_t estimate_bytes = 0;
        uint64_t bytes_per_pair = 0;
    } budgets;
};

// The memory that serves the boxes: sets run.ssram, and the tiles and load
// waits at run.capacity from run.config.
void describe_memory(RunDescription& run, bool ssram);
// Slots a frame of `objects` boxes waits for SSRAM tiles (0 in block RAM).
uint64_t load_wait_slots(const RunDescription& run, uint64_t objects);

// The frames of a run folded as they come: counts and sums for the totals
// and the steady-state means (which leave out the warm-up frames when there
// are more), the per-frame samples behind the medians, and the first rows of
// the summary's table. Memory holds a few numbers a frame, not the frames.
class RunTotals {
public:
    static constexpr std::size_t kRowsShown = 10;
    static constexpr int kPhases = 7;  // upload, start, compute, irq, readback, driver, total

    explicit RunTotals(uint64_t warmup = kDefaultWarmupFrames) : warmup_frames_(warmup) {}
    void add(const FrameStats& frame);
    // A baseline's samples (CPU time, and wall time beside it), for the runs
    // after the first (--repeat) and for frames timed again.
    FrameSamples& baseline_samples(const std::string& name);
    FrameSamples& baseline_wall_samples(const std::string& name);
    // What each baseline's timing can be trusted for (BaselineTimer::quality),
    // and the tries a disturbed frame was given; the summary carries them.
    void set_timing_quality(std::map<std::string, TimingQuality> quality, uint32_t max_tries);
    const std::map<std::string, TimingQuality>& timing_quality() const { return quality_; }
    // Every baseline's samples dropped, for a timing taken from elsewhere
    // (a sweep's shared one), which `timing_id` then names in the summary.
    void clear_baselines();
    // Frames a baseline timed again (BaselineTimer::retime), for the summary.
    void set_retimed(std::map<std::string, std::vector<std::array<double, 3>>> retimed) { retimed_ = std::move(retimed); }
    void set_timing_id(std::string id) { timing_id_ = std::move(id); }
    // The modelled host's package power (host.package_w): the software's
    // energy is it times the baseline's host time.
    void set_host_power(double host_w) { host_w_ = host_w; }
    // The board's clock beyond its estimated Fmax, run under
    // run.ignore_timing (check_clock's line); empty: the clock is met.
    void set_timing_warning(std::string warning) { timing_warning_ = std::move(warning); }
    const std::string& timing_warning() const { return timing_warning_; }
    const std::string& timing_id() const { return timing_id_; }
    uint32_t retime_tries() const { return max_tries_; }

    uint64_t frames() const { return frames_; }
    uint64_t warmup_frames() const { return warmup_frames_; }
    uint64_t frames_in_means() const { return frames_ > warmup_frames_ ? frames_ - warmup_frames_ : frames_; }
    const std::vector<FrameStats>& shown() const { return shown_; }
    uint64_t pairs() const { return pairs_; }
    const ExtraPairs& extra() const { return extra_; }
    uint64_t cycles() const { return cycles_; }
    uint64_t stalls() const { return stalls_; }
    uint64_t last_objects() const { return last_objects_; }
    // Mean of phase k (ReportSummary::kPhaseKeys order) over the frames in the means.
    double mean_phase(int k) const;
    // Means, p50, p99 and maxima over the frames after the warm-up: the
    // board's simulated frame time, the simulator's wall time, each
    // baseline's native time (scale by its host factor for the modelled host).
    TimingFigures board_figures() const { return board_total_.figures(); }
    // Frames pipelined: the frames' latencies, from upload to pairs (the
    // board's figures are then the host's time a frame: the throughput).
    TimingFigures latency_figures() const { return latency_.figures(); }
    TimingFigures sim_wall_figures() const { return sim_wall_.figures(); }
    std::map<std::string, TimingFigures> baseline_figures() const;
    // The report's summary: these figures, each baseline's on the host too.
    ReportSummary summary(const HostTiming& host) const;

private:
    void put_energy(ReportSummary& s) const;
    // Sums over the warm-up frames and over the frames after them, kept
    // apart so the means add the same frames in the same order whatever the count.
    struct Sums {
        double phases[kPhases] = {};
        FrameEnergy energy;
        uint64_t pairs = 0;
        // Each baseline's package energy on this machine (RAPL) and the frames it was measured on.
        std::map<std::string, std::pair<double, uint64_t>> native_energy;
    };
    const Sums& in_means() const { return frames_ > warmup_frames_ ? rest_ : warmup_; }
    uint64_t warmup_frames_;
    uint64_t frames_ = 0, pairs_ = 0, cycles_ = 0, stalls_ = 0, last_objects_ = 0;
    ExtraPairs extra_;
    Sums warmup_, rest_;
    FrameSamples board_total_{warmup_frames_}, sim_wall_{warmup_frames_}, latency_{warmup_frames_};
    std::map<std::string, FrameSamples> baselines_, baselines_wall_;
    std::map<std::string, TimingQuality> quality_;
    uint32_t max_tries_ = 0;
    double host_w_ = 0;
    std::string timing_id_;
    std::string timing_warning_;
    std::map<std::string, std::vector<std::array<double, 3>>> retimed_;
    std::vector<FrameStats> shown_;
};


// The version of the run report's layout (its top-level "format_version"),
// which share/cdvp/schema/run-report.schema.json describes: raised when a
// field is renamed, removed or changes meaning, not when one is added.
constexpr int kReportFormatVersion = 2;

// Writes the report as the run goes: begin() the configuration (with the
// provenance at the start), frame() each frame, end() the summary (with the
// load average at the end) and then, in their order, the keys of `more`: the
// sections of what only the command has (`cdvp bullet`'s "bullet"). The text
// is what nlohmann's dump(2) gives for the whole document, followed by a line
// end, but for the order of those sections.
class ReportWriter {
public:
    explicit ReportWriter(std::ostream& out) : out_(out) {}
    void begin(const RunDescription& run);
    void frame(const FrameStats& frame);
    void end(const RunTotals& totals, const HostTiming& host, const nlohmann::json* more = nullptr);

private:
    std::ostream& out_;
    bool any_frame_ = false;
};

// A report kept in memory, for a compact sweep's point run in process: the
// frames and the summary as ReportWriter writes them, no config.
class MemoryReport {
public:
    explicit MemoryReport(nlohmann::json& out);
    void frame(const FrameStats& frame);
    void end(const RunTotals& totals, const HostTiming& host);

private:
    nlohmann::json& out_;
};

// Where a run's native wall time went: the simulator's own (each frame on
// the platform) and the software baselines timed beside it.
struct RunWallTimes {
    double simulator_s = 0;
    double baselines_s = 0;
};

}  // namespace cdvp
