// What a run runs its frames on, by its level (run.fidelity): the SystemC
// platform with the clocked, fast or RTL engine, the analytic level (no
// kernel), or auto, which takes the analytic level wherever its error is
// bounded or measured within run.max_error_percent and the fast engine
// (exact) elsewhere. It is the FramePlatform a run sees whatever the level.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "platform/analytic_platform.h"
#include "platform/frame_platform.h"
#include "platform/virtual_board.h"
#include "platform/settings/setting_choices.h"

namespace cdvp {

// Auto, frame by frame: a frame the analytic level is exact on by
// bound (AnalyticPlatform::exact_by_bound) is timed by it; until a frame
// needs measuring, that is all. The first frame that does runs on both: if
// the analytic level's largest phase error on it, in percent of the fast
// engine's frame time, is within run.max_error_percent, the analytic level times the
// rest of the run, else the fast engine does. That frame's result is the
// fast engine's.
struct LevelChoice {
    double max_error_percent = 1.0;
    uint64_t analytic_frames = 0, bounded_frames = 0, fast_frames = 0;
    bool measured = false;
    uint64_t measured_frame = 0;
    double measured_error_percent = 0;
    const char* measured_phase = "";
    bool pipelined = false;  // two box banks: measured on the first frame to finish
    // "auto: analytic level on 18 of 20 frames ...", for the summary; max_error:
    // how the face names run.max_error_percent ("--max-error").
    std::string words(const std::string& max_error) const;
    nlohmann::json to_json() const;   // the report's "fidelity_choice"
};

class LevelPlatform : public FramePlatform {
public:
    // trace_base: where the SystemC platform writes its waveforms (empty: none).
    LevelPlatform(ModelLevel level, const PlatformConfig& config, uint32_t capacity, const std::string& trace_base,
                  double max_error_percent);
    const FrameResult* try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) override;
    // Frames pipelined on a board with two box banks: VirtualBoard's, or the
    // analytic level's (AnalyticPipeline); under auto both until the first
    // frame finishes and is measured, then the one chosen.
    bool pipelined() const override { return board_ ? board_->pipelined() : analytic_->pipelined(); }
    const FrameResult* try_submit_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) override;
    const FrameResult* try_finish_frames(FrameFault& fault) override;
    const BusTiming& bus_timing() const override { return board_ ? board_->bus_timing() : analytic_->bus_timing(); }
    // The SystemC platform, or null at the analytic level (which has no waveforms).
    VirtualBoard* board() { return board_.get(); }
    // Under --fidelity auto, what was chosen and why; else null.
    const LevelChoice* choice() const { return auto_ ? &choice_ : nullptr; }

private:
    const FrameResult* run_auto(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault);
    // Pipelined frames go to the analytic level: it is the run's level, or auto chose it.
    bool analytic_chosen() const { return board_ == nullptr || decided_ == Decided::kAnalytic; }
    // A pipelined result, counted under auto for the level that gave it.
    const FrameResult* counted(const FrameResult* result);
    // Under auto, pipelined: the fast engine's result for a frame (null: none
    // finished), the analytic level's phases for it measured against it and
    // the level chosen.
    const FrameResult* measure_pipelined(const std::optional<FramePhases>& estimate, const FrameResult* exact,
                                         uint64_t number);
    // The analytic level's largest phase error on frame `number`, in percent
    // of the exact total, and which phase; decides the level by it.
    void measure(const FramePhases& estimate, const FramePhases& exact, uint64_t number);
    uint64_t in_flight_number_ = 0;  // pipelined: the frame submitted last

    std::unique_ptr<VirtualBoard> board_;
    std::unique_ptr<AnalyticPlatform> analytic_;
    bool auto_ = false;
    enum class Decided : uint8_t { kNot, kAnalytic, kFast } decided_ = Decided::kNot;
    LevelChoice choice_;
};

}  // namespace cdvp
