// Sweep and prune on several threads ("sap_mt"): the boxes sorted by their
// lower bound on the axis their centres spread most along, then the sorted
// list cut into chunks that the threads take one at a time, each sweeping
// forward from its boxes while the next box starts before this one ends,
// and testing the other two axes. The order is kept from frame to frame
// (the same boxes moved: an insertion sort on one thread); the sweep, most
// of the work, splits over the threads. Each thread keeps its
// own pairs; they are joined after. Its time is the wall time a frame (the
// threads run side by side); its threads' CPU time is kept beside it
// (docs/timing.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/thread_pairs.h"
#include "sw/baselines/worker_pool.h"

namespace cdvp {

class ParallelSapBroadPhase : public BroadPhase {
public:
    // threads: 0 for this machine's cores.
    explicit ParallelSapBroadPhase(unsigned threads = 0);
    std::string name() const override { return "sap_mt"; }
    unsigned threads() const override { return pool_.size(); }
    void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) override;

    // Sorted boxes a thread takes at a time: small enough to balance a
    // crowded stretch of the axis, large enough that taking one is rare.
    static constexpr std::size_t kChunk = 32;

private:
    void sort_boxes(const std::vector<FloatBox>& boxes);
    void sweep(unsigned thread);

    WorkerPool pool_;
    // The boxes with no NaN bound (a NaN overlaps nothing), in order of
    // their lower bound on the swept axis: their indices and bounds, the
    // swept axis first.
    std::vector<uint32_t> index_;
    int swept_ = -1;               // the axis of the last frame's sort
    std::size_t frame_boxes_ = 0;  // the last frame's box count
    std::vector<float> lo_[3], hi_[3];
    ThreadPairs found_;
    std::atomic<std::size_t> next_{0};
};

}  // namespace cdvp
