// Box pruning ("prune", and "prune_mt" over a worker pool): Terdiman's
// sweep of boxes sorted by their lower bound on one axis, rebuilt every
// frame with a radix sort, each box tested against the boxes that start
// before it ends, eight (AVX2) or four (SSE2) at a time. The fastest
// choice for a few hundred to a few thousand boxes, and the baseline of
// Broadmark's SAP_AVX (Serpa and Rodrigues 2020): no state between frames,
// so incoherent motion costs nothing extra.
//
// The axis is the one the boxes' centres spread most along. Boxes are
// sorted by the lower of their two bounds there (an inverted box, min above
// max, overlaps only what the box between its bounds overlaps), and every
// candidate is tested exactly (float32, closed intervals). The SIMD width is
// chosen when the baseline is built, from what the CPU has
// (__builtin_cpu_supports), not from how cdvp was compiled.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/box_pruning_kernel.h"
#include "sw/baselines/thread_pairs.h"
#include "sw/baselines/worker_pool.h"

namespace cdvp {

class BoxPruningBroadPhase : public BroadPhase {
public:
    // threads: 0 for this machine's cores; multi_threaded names it "prune_mt".
    BoxPruningBroadPhase(unsigned threads, bool multi_threaded);
    std::string name() const override { return multi_threaded_ ? "prune_mt" : "prune"; }
    unsigned threads() const override { return pool_.size(); }
    void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) override;

    // Floats tested at once: 8 with AVX2, 4 with SSE2, 1 elsewhere.
    int simd_width() const { return width_; }
    // Sorted boxes a thread takes at a time.
    static constexpr uint32_t kChunk = 64;

private:
    void sort_boxes(const std::vector<FloatBox>& boxes);

    bool multi_threaded_;
    int width_;
    PruneSweep sweep_;  // the kernel of that width
    WorkerPool pool_;
    ThreadPairs found_;
    std::vector<uint32_t> valid_;
    int axis_ = 0;  // the swept axis of the last frame
    std::vector<uint32_t> keys_, order_, scratch_keys_, scratch_order_;
    // In sorted order, padded with NaN: the sweep key (the lower bound on the
    // swept axis) and every box's own bounds.
    std::vector<float> key_, min_[3], max_[3];
    std::atomic<uint32_t> next_{0};
};

}  // namespace cdvp
