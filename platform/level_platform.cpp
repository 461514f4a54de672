#include "platform/level_platform.h"

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

std::string LevelChoice::words(const std::string& max_error) const {
    const uint64_t frames = analytic_frames + fast_frames;
    char line[400];
    std::snprintf(line, sizeof line, "auto: analytic level on %llu of %llu %sframes (%llu exact by bound)",
                  static_cast<unsigned long long>(analytic_frames), static_cast<unsigned long long>(frames),
                  pipelined ? "pipelined " : "", static_cast<unsigned long long>(bounded_frames));
    std::string text = line;
    if (measured) {
        std::snprintf(line, sizeof line, "; measured on frame %llu against the fast engine: %s off by %.3g%%, %s %s %g%%",
                      static_cast<unsigned long long>(measured_frame), measured_phase, measured_error_percent,
                      measured_error_percent <= max_error_percent ? "within" : "beyond", max_error.c_str(),
                      max_error_percent);
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
    if (pipelined) choice["pipelined"] = true;
    if (measured) {
        choice["measured_frame"] = measured_frame;
        choice["measured_error_percent"] = measured_error_percent;
        choice["measured_phase"] = measured_phase;
    }
    return choice;
}

LevelPlatform::LevelPlatform(ModelLevel level, const PlatformConfig& config, uint32_t capacity,
                             const std::string& trace_base, double max_error_percent)
    : auto_(level == ModelLevel::kAuto) {
    choice_.pipelined = auto_ && config.board.box_banks > 1;
    if (level == ModelLevel::kAnalytic || auto_) analytic_ = std::make_unique<AnalyticPlatform>(config, capacity);
    if (level != ModelLevel::kAnalytic) board_ = std::make_unique<VirtualBoard>("platform", config, capacity, trace_base);
    choice_.max_error_percent = max_error_percent;
}

const FrameResult* LevelPlatform::try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) {
    if (auto_) return run_auto(boxes, number, fault);
    return board_ ? board_->try_run_frame(boxes, number, fault) : analytic_->try_run_frame(boxes, number, fault);
}

const FrameResult* LevelPlatform::run_auto(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) {
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
    measure(estimate, exact->phases, number);
    ++choice_.fast_frames;
    return exact;
}

void LevelPlatform::measure(const FramePhases& estimate, const FramePhases& exact, uint64_t number) {
    choice_.measured = true;
    choice_.measured_frame = number;
    const double scale = std::max(exact.total_ns, 1e-9);
    for (const PhaseField& phase : kPhaseFields) {
        // Below a femtosecond is the two levels' summing order, not an error.
        const double difference = std::abs(estimate.*phase.field - exact.*phase.field);
        const double error = difference < 1e-6 ? 0.0 : 100.0 * difference / scale;
        if (error >= choice_.measured_error_percent) {
            choice_.measured_error_percent = error;
            choice_.measured_phase = phase.name;
        }
    }
    decided_ = choice_.measured_error_percent <= choice_.max_error_percent ? Decided::kAnalytic : Decided::kFast;
}

const FrameResult* LevelPlatform::try_submit_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                                 FrameFault& fault) {
    const uint64_t finishing = in_flight_number_;  // the frame a result now is
    in_flight_number_ = number;
    if (!auto_ || decided_ != Decided::kNot) {
        return counted(analytic_chosen() ? analytic_->try_submit_frame(boxes, number, fault)
                                         : board_->try_submit_frame(boxes, number, fault));
    }
    // Auto, both until a frame finishes: that one is measured (pipelined
    // frames have no bound); the level not chosen keeps its last frame unread.
    FrameFault analytic_fault;
    const FrameResult* estimated = analytic_->try_submit_frame(boxes, number, analytic_fault);
    const std::optional<FramePhases> estimate = estimated ? std::optional<FramePhases>(estimated->phases) : std::nullopt;
    return measure_pipelined(estimate, board_->try_submit_frame(boxes, number, fault), finishing);
}

const FrameResult* LevelPlatform::try_finish_frames(FrameFault& fault) {
    if (!auto_ || decided_ != Decided::kNot) {
        return counted(analytic_chosen() ? analytic_->try_finish_frames(fault) : board_->try_finish_frames(fault));
    }
    FrameFault analytic_fault;
    const FrameResult* estimated = analytic_->try_finish_frames(analytic_fault);
    const std::optional<FramePhases> estimate = estimated ? std::optional<FramePhases>(estimated->phases) : std::nullopt;
    return measure_pipelined(estimate, board_->try_finish_frames(fault), in_flight_number_);
}

const FrameResult* LevelPlatform::counted(const FrameResult* result) {
    if (auto_ && result != nullptr) ++(analytic_chosen() ? choice_.analytic_frames : choice_.fast_frames);
    return result;
}

const FrameResult* LevelPlatform::measure_pipelined(const std::optional<FramePhases>& estimate, const FrameResult* exact,
                                                  uint64_t number) {
    if (exact == nullptr) return nullptr;  // nothing finished yet, or a fault
    if (estimate) {
        measure(*estimate, exact->phases, number);
    } else {
        decided_ = Decided::kFast;  // the analytic level gave no frame where the engine did
    }
    ++choice_.fast_frames;
    return exact;
}

}  // namespace cdvp
