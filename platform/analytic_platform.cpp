#include "platform/analytic_platform.h"

#include <algorithm>
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

AnalyticPlatform::AnalyticPlatform(const PlatformConfig& config, uint32_t capacity)
    : capacity_(capacity),
      stall_free_pairs_(config.board.collector.fifo_depth > config.board.lanes()
                            ? config.board.collector.fifo_depth - config.board.lanes()
                            : 0),
      format_(config.board.format),
      bus_(bus_or_ideal(config.bus)),
      frame_(config.driver, *bus_, analytic_board(config.board)),
      finder_(config.board.format, config.pair_budget),
      memo_(config.pair_memo),
      m_(config.board.m),
      tiles_(config.board.tiles),
      pair_format_(config.driver.pair_format),
      buffer_depth_(std::max<uint32_t>(config.board.collector.buffer_depth, 1)) {
    if (!config.faults.empty()) throw std::invalid_argument("the analytic level has no engine to inject faults into");
    if (config.board.box_banks > 1) pipeline_.emplace(frame_);
    if (config.board.grid_board()) grid_.emplace(config.board, config.pair_budget);
}

bool AnalyticPlatform::exact_by_bound(const FrameResult& result) const {
    return result.pairs.size() <= stall_free_pairs_ && result.phases.overflow_pauses == 0;
}

uint64_t AnalyticPlatform::prepare(const std::vector<FloatBox>& boxes, PairList& pairs) {
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
    // The boxes whose words differ from what the host's bank holds (every one when unknown).
    const uint64_t changed = banks_.compare(view.data(), objects, [](uint32_t) {});
    // In the order the board finds them, as the engines give them: a tiled
    // board's by block, which depends on the tile size alone (not on m).
    PairMemo::Order by_block;
    if (tiles_.tiled() && objects > tiles_.boxes) {
        by_block.key = (uint64_t{1} << 32) | tiles_.boxes;
        by_block.apply = [this, objects](PairList& found) {
            SweepSchedule(m_, tiles_, objects).order_by_block(found, by_block_, block_ends_);
        };
    }
    try {
        if (grid_) {
            // The grid board's pairs in its order, each in its slot; AnalyticFrame times them.
            const uint64_t end = grid_->run(objects, view, pairs, grid_slots_);
            frame_.set_listed_schedule(&grid_slots_, end);
        } else {
            find_pairs(memo_.get(), finder_, objects, view, pairs, &by_block);
        }
    } catch (const PairBudgetExceeded&) {
        banks_.forget();  // the driver fails the frame and forgets the board's words
        throw;
    }
    // The bank takes this frame's words; words_ is rewritten whole by the next frame.
    if (objects > 0) banks_.take(words_, objects);
    return changed;
}

void AnalyticPlatform::order_as_read_back(PairList& pairs) const {
    if (pair_format_ != PairFormat::kBitmap) return;
    for (std::size_t k = 0; k < pairs.size(); k += buffer_depth_) {
        const auto first = pairs.begin() + static_cast<std::ptrdiff_t>(k);
        std::sort(first, first + static_cast<std::ptrdiff_t>(std::min<std::size_t>(buffer_depth_, pairs.size() - k)));
    }
}

namespace {
// A pair budget's refusal as the platform reports it.
void budget_fault(const PairBudgetExceeded& e, FrameFault& fault) {
    fault.kind = FrameFault::Kind::kPairBudget;
    fault.message = e.what();
    fault.pairs_found = e.found();
}
}  // namespace

const FrameResult* AnalyticPlatform::try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                                   FrameFault& fault) {
    (void)number;
    if (pipeline_) throw std::logic_error("try_run_frame: the board has two box banks; use try_submit_frame");
    fault = FrameFault{};
    uint64_t changed = 0;
    try {
        changed = prepare(boxes, result_.pairs);
    } catch (const PairBudgetExceeded& e) {
        budget_fault(e, fault);
        return nullptr;
    }
    result_.phases = frame_.estimate(static_cast<uint32_t>(boxes.size()), result_.pairs, changed);
    order_as_read_back(result_.pairs);
    return &result_;
}

const FrameResult* AnalyticPlatform::try_submit_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                                      FrameFault& fault) {
    (void)number;
    if (!pipeline_) throw std::logic_error("try_submit_frame: the board has one box bank; use try_run_frame");
    fault = FrameFault{};
    PairList pairs;
    uint64_t changed = 0;
    try {
        changed = prepare(boxes, pairs);
    } catch (const PairBudgetExceeded& e) {
        budget_fault(e, fault);  // as the driver does, the frame in flight fails with it
        pipeline_.emplace(frame_);
        return nullptr;
    }
    banks_.hand_over();  // START hands the bank over
    const std::optional<FramePhases> finished =
        pipeline_->submit(static_cast<uint32_t>(boxes.size()), std::move(pairs), changed, result_.pairs);
    if (!finished) return nullptr;
    result_.phases = *finished;
    order_as_read_back(result_.pairs);
    return &result_;
}

const FrameResult* AnalyticPlatform::try_finish_frames(FrameFault& fault) {
    fault = FrameFault{};
    const std::optional<FramePhases> finished = pipeline_ ? pipeline_->finish(result_.pairs) : std::nullopt;
    if (!finished) return nullptr;
    result_.phases = *finished;
    order_as_read_back(result_.pairs);
    return &result_;
}

}  // namespace cdvp
