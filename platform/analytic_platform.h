// The analytic level of the platform (--fidelity analytic): no SystemC kernel,
// no engine stepping. A frame's pairs are those the board's comparison unit
// accepts in its number format, found by the fast engine's PairFinder (so the
// application and the float32 check see the board's exact pairs; on a grid
// board by its GridSearch, which places each pair in its slot by the grid's
// closed forms); its time is AnalyticFrame's closed forms for those pairs (docs/analytic.md says which
// phases are exact and measures the rest). Nothing is elaborated, so a process
// may build any number of these: a sweep evaluates analytic points in process.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "models/fast_engine/pair_finder.h"
#include "models/grid_fast_engine/grid_search.h"
#include "platform/driver/analytic_frame.h"
#include "platform/driver/analytic_pipeline.h"
#include "platform/driver/bank_copies.h"
#include "platform/frame_platform.h"
#include "platform/virtual_board.h"

namespace cdvp {

// What AnalyticFrame needs of a board configuration; the clock period rounded
// to femtoseconds as sc_time rounds the board's (CollisionBoard::period()).
AnalyticBoard analytic_board(const BoardConfig& board);

class AnalyticPlatform : public FramePlatform {
public:
    // config's faults must be empty (there is no engine to inject into) and its
    // quantum is not modelled: callers refuse both with the setting's name.
    AnalyticPlatform(const PlatformConfig& config, uint32_t capacity);

    // As VirtualBoard::try_run_frame: the frame's result, or null with fault
    // set (only a pair budget's refusal: nothing here can fault).
    const FrameResult* try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) override;
    // Frames pipelined on a board with two box banks (AnalyticPipeline), as
    // VirtualBoard's: submit a frame and get the one before it, finished (null
    // for the first, with fault empty); finish the frame in flight.
    bool pipelined() const override { return pipeline_.has_value(); }
    const FrameResult* try_submit_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) override;
    const FrameResult* try_finish_frames(FrameFault& fault) override;
    const BusTiming& bus_timing() const override { return *bus_; }
    // Whether every phase of a frame this platform timed one at a time is exact by bound,
    // not by estimate: its pairs and a full row of lane hits fit the pair
    // FIFO together (so the FIFO never pushes back) and the pair buffer took
    // them in one segment (docs/analytic.md).
    bool exact_by_bound(const FrameResult& result) const;

private:
    // The frame's words into words_ and its pairs into pairs (board order);
    // the boxes whose words differ from what its bank holds. Throws
    // PairBudgetExceeded as the finder does.
    uint64_t prepare(const std::vector<FloatBox>& boxes, PairList& pairs);
    // A bitmap read-back hands each segment's pairs over sorted by row.
    void order_as_read_back(PairList& pairs) const;

    uint32_t capacity_;
    uint64_t stall_free_pairs_;  // FIFO depth less one row of hits (2m - 1 lanes)
    NumberFormat format_;
    std::shared_ptr<const BusTiming> bus_;
    AnalyticFrame frame_;
    PairFinder finder_;
    std::shared_ptr<PairMemo> memo_;  // may be null
    uint32_t m_;
    TileConfig tiles_;
    PairFormat pair_format_;
    uint32_t buffer_depth_;
    std::vector<uint32_t> words_[kCoordinates];
    PairList by_block_;                 // scratch: a tiled board's order
    std::vector<uint64_t> block_ends_;
    FrameResult result_;
    // The words each box bank holds from the last frame uploaded into it,
    // for delta uploads (as the driver keeps them).
    BankCopies banks_;
    std::optional<AnalyticPipeline> pipeline_;  // two box banks
    // A grid board: its search, and the slots of the frame being timed.
    std::optional<GridSearch> grid_;
    std::vector<uint64_t> grid_slots_;
};

}  // namespace cdvp
