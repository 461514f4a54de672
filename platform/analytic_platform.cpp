#include "platform/analytic_platform.h"

#include <stdexcept>
#include <string>

#include "models/address_generator/sweep_schedule.h"
#include "platform/driver/quantiser.h"

namespace cdvp {

AnalyticBoard analytic_board(const BoardConfig& board) {
    AnalyticBoard analytic;
    // sc_time(1 / MHz, SC_US) at femtosecond resolution: scaled, plus one half, truncated.
    analytic.period_fs = static_cast<SimTime>(1.0 / board.clock_mhz * 1e9 + 0.5);
    analytic.m = board.m;
    analytic.pipeline_latency = board.pipeline_latency();
    analytic.fifo_depth = board.collector.fifo_depth;
    analytic.drain_per_cycle = board.collector.drain_per_cycle;
    analytic.buffer_depth = board.collector.buffer_depth;
    analytic.tiles = board.tiles;
    return analytic;
}

namespace {
std::shared_ptr<const BusTiming> bus_or_ideal(const std::shared_ptr<const BusTiming>& bus) {
    return bus ? bus : std::make_shared<IdealBusTiming>();
}
}  // namespace

AnalyticPlatform::AnalyticPlatform(const PlatformConfig& config, uint32_t capacity)
    : capacity_(capacity),
      stall_free_pairs_(config.board.collector.fifo_depth > config.board.lanes()
                            ? config.board.collector.fifo_depth - config.board.lanes()
                            : 0),
      format_(config.board.format),
      bus_(bus_or_ideal(config.bus)),
      frame_(config.driver, *bus_, analytic_board(config.board)),
      finder_(config.board.format, config.pair_budget),
      m_(config.board.m),
      tiles_(config.board.tiles) {
    if (!config.faults.empty()) throw std::invalid_argument("the analytic level has no engine to inject faults into");
}

bool AnalyticPlatform::exact_by_bound(const FrameResult& result) const {
    return result.pairs.size() <= stall_free_pairs_ && result.phases.overflow_pauses == 0;
}

const FrameResult* AnalyticPlatform::try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                                   FrameFault& fault) {
    (void)number;
    if (boxes.size() > capacity_) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) +
                                    " boxes exceeds the board's capacity of " + std::to_string(capacity_));
    }
    const auto objects = static_cast<uint32_t>(boxes.size());
    // The words the driver would upload: float32 bits, or fixed-point codes over the frame's bounds.
    const Quantiser quantiser(format_, boxes);
    CoordinateWords view{};
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        words_[c].resize(objects);
        quantiser.write_column(boxes, c, words_[c].data());
        view[c] = words_[c].data();
    }
    fault = FrameFault{};
    try {
        finder_.find(objects, view, result_.pairs);
    } catch (const PairBudgetExceeded& e) {
        fault.kind = FrameFault::Kind::kPairBudget;
        fault.message = e.what();
        fault.pairs_found = e.found();
        return nullptr;
    }
    // In the order the board finds them, as the engines give them.
    if (tiles_.tiled() && objects > tiles_.boxes) {
        SweepSchedule(m_, tiles_, objects).order_by_block(result_.pairs, by_block_, block_ends_);
    }
    result_.phases = frame_.estimate(objects, result_.pairs.size());
    return &result_;
}

}  // namespace cdvp
