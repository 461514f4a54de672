#include "sw/cli/run_platform.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cdvp {

namespace {

struct PhaseField {
    const char* name;
    double FramePhases::*field;
};
constexpr PhaseField kPhaseFields[] = {{"upload", &FramePhases::upload_ns},     {"start", &FramePhases::start_ns},
                                       {"compute", &FramePhases::compute_ns},   {"irq", &FramePhases::irq_ns},
                                       {"readback", &FramePhases::readback_ns}, {"driver", &FramePhases::driver_ns},
                                       {"total", &FramePhases::total_ns}};

}  // namespace

std::string LevelChoice::words() const {
    if (pipelined) {
        return "auto: the fast engine on every frame: two box banks pipeline frames, and auto measures the analytic "
               "level one frame at a time (--fidelity analytic times pipelined frames as an estimate)";
    }
    const uint64_t frames = analytic_frames + fast_frames;
    char line[400];
    std::snprintf(line, sizeof line, "auto: analytic level on %llu of %llu frames (%llu exact by bound)",
                  static_cast<unsigned long long>(analytic_frames), static_cast<unsigned long long>(frames),
                  static_cast<unsigned long long>(bounded_frames));
    std::string text = line;
    if (measured) {
        std::snprintf(line, sizeof line, "; measured on frame %llu against the fast engine: %s off by %.3g%%, %s --max-error %g%%",
                      static_cast<unsigned long long>(measured_frame), measured_phase, measured_error_percent,
                      measured_error_percent <= max_error_percent ? "within" : "beyond", max_error_percent);
        text += line;
    }
    if (fast_frames > (measured ? 1u : 0u)) text += "; the fast engine on the rest";
    return text;
}

nlohmann::json LevelChoice::to_json() const {
    nlohmann::json choice = {{"max_error_percent", max_error_percent},
                             {"analytic_frames", analytic_frames},
                             {"exact_by_bound_frames", bounded_frames},
                             {"fast_frames", fast_frames}};
    if (pipelined) choice["reason"] = "two box banks: auto measures the analytic level one frame at a time";
    if (measured) {
        choice["measured_frame"] = measured_frame;
        choice["measured_error_percent"] = measured_error_percent;
        choice["measured_phase"] = measured_phase;
    }
    return choice;
}

RunPlatform::RunPlatform(const BoardSetup& setup, uint32_t capacity, const std::string& trace_base)
    : auto_(setup.level == ModelLevel::kAuto) {
    // Auto measures the analytic level a frame at a time: pipelined frames run on the fast engine.
    choice_.pipelined = auto_ && setup.platform.board.box_banks > 1;
    if (choice_.pipelined) decided_ = Decided::kFast;
    if (setup.level == ModelLevel::kAnalytic || (auto_ && !choice_.pipelined)) {
        analytic_ = std::make_unique<AnalyticPlatform>(setup.platform, capacity);
    }
    if (setup.level != ModelLevel::kAnalytic) {
        board_ = std::make_unique<VirtualBoard>("platform", setup.platform, capacity, trace_base);
    }
    choice_.max_error_percent = setup.values.settings().run.max_error_percent;
}

const FrameResult* RunPlatform::try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) {
    if (auto_) return run_auto(boxes, number, fault);
    return board_ ? board_->try_run_frame(boxes, number, fault) : analytic_->try_run_frame(boxes, number, fault);
}

const FrameResult* RunPlatform::run_auto(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) {
    if (decided_ == Decided::kFast) {
        ++choice_.fast_frames;
        return board_->try_run_frame(boxes, number, fault);
    }
    const FrameResult* analytic = analytic_->try_run_frame(boxes, number, fault);
    if (analytic == nullptr) return nullptr;
    const bool bounded = analytic_->exact_by_bound(*analytic);
    if (bounded || decided_ == Decided::kAnalytic) {
        ++choice_.analytic_frames;
        choice_.bounded_frames += bounded ? 1 : 0;
        return analytic;
    }
    const FramePhases estimate = analytic->phases;
    const FrameResult* exact = board_->try_run_frame(boxes, number, fault);
    if (exact == nullptr) return nullptr;
    choice_.measured = true;
    choice_.measured_frame = number;
    const double scale = std::max(exact->phases.total_ns, 1e-9);
    for (const PhaseField& phase : kPhaseFields) {
        // Below a femtosecond is the two levels' summing order, not an error.
        const double difference = std::abs(estimate.*phase.field - exact->phases.*phase.field);
        const double error = difference < 1e-6 ? 0.0 : 100.0 * difference / scale;
        if (error >= choice_.measured_error_percent) {
            choice_.measured_error_percent = error;
            choice_.measured_phase = phase.name;
        }
    }
    decided_ = choice_.measured_error_percent <= choice_.max_error_percent ? Decided::kAnalytic : Decided::kFast;
    ++choice_.fast_frames;
    return exact;
}

}  // namespace cdvp
