// A hierarchical uniform grid rebuilt every frame ("hgrid", and "hgrid_mt"
// over a worker pool): the broad phase an engineer picks for many boxes of
// similar size and for incoherent motion, and, through its levels, for boxes
// of very different sizes (Ericson, Real-Time Collision Detection, 7.2;
// Mirtich's hierarchical hash grid).
//
// Level 0's cells are as large as the bulk of the boxes (the largest extent
// within four times the median, per axis); each level above has cells four
// times larger, and the top level is one cell. A box lives in the lowest
// level where it spans at most two cells on every axis, filed once, in the
// cell of its lower corner (a counting sort: count, scan, place). Two boxes
// of one level can then overlap only if their cells are neighbours, so each
// cell is tested against itself and half of its 26 neighbours (each pair of
// cells once); boxes of two levels are found by querying one level's cells
// around each box of the other, whichever side is cheaper. No pair is ever
// reported twice, so nothing is sorted or deduplicated.
//
// Exactness: cells are found from each box's normalised bounds (an inverted
// box, min above max, as the box between its bounds: it overlaps a subset of
// what that box overlaps), in double precision and clamped to the grid, a
// monotone map, so the neighbourhood argument holds for infinite and huge
// bounds too; every candidate is then tested with the exact float32
// closed-interval test. A box with a NaN bound overlaps nothing and is left
// out. docs/baselines.md has the argument and the measured figures.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/thread_pairs.h"
#include "sw/baselines/worker_pool.h"

namespace cdvp {

class HierarchicalGridBroadPhase : public BroadPhase {
public:
    // threads: 0 for this machine's cores; multi_threaded names it "hgrid_mt".
    HierarchicalGridBroadPhase(unsigned threads, bool multi_threaded);
    std::string name() const override { return multi_threaded_ ? "hgrid_mt" : "hgrid"; }
    unsigned threads() const override { return pool_.size(); }
    void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) override;

    // The most levels, the top one a single cell.
    static constexpr int kMaxLevels = 12;
    // Each level's cells are this many times the level's below on every axis.
    static constexpr double kLevelRatio = 4.0;

    struct Level {
        double origin[3] = {0, 0, 0};
        double inv_size[3] = {0, 0, 0};  // cells per unit length (0: one cell on that axis)
        int32_t dims[3] = {1, 1, 1};
        std::vector<uint32_t> start;     // a cell's first box; cells + 1 entries
        // A box as a level holds it: its own bounds and its index in the
        // frame, in one 32-byte line, so a candidate costs one cache line.
        struct Entry {
            float lo[3], hi[3];
            uint32_t index;
            uint32_t unused;
        };
        std::vector<Entry> entries;      // in cell order
        std::size_t cells() const { return std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]); }
        std::size_t boxes() const { return entries.size(); }
        int32_t cell(int axis, float x) const;
    };
    // For tests: the last frame's levels, finest first.
    std::size_t level_count() const { return used_; }
    const Level& level(std::size_t k) const { return levels_[k]; }

private:
    std::size_t parts_for(std::size_t n) const;
    template <typename Fn>
    void for_parts(std::size_t n, std::size_t parts, Fn&& fn);
    void survey(const std::vector<FloatBox>& boxes, double lo[3], double span[3]);
    void bulk_extents(const std::vector<FloatBox>& boxes, double size[3]);
    void plan_levels(const std::vector<FloatBox>& boxes);
    void file_boxes(const std::vector<FloatBox>& boxes);
    void plan_work();
    void run_work(unsigned thread);
    void scan_cells(const Level& level, std::size_t first, std::size_t last, PairList& out) const;
    void query(const Level& level, const float lo[3], const float hi[3], uint32_t id, PairList& out) const;

    bool multi_threaded_;
    WorkerPool pool_;
    ThreadPairs found_;
    std::vector<uint32_t> valid_;        // the boxes with no NaN bound
    std::vector<std::vector<uint32_t>> part_valid_;  // a part's of them
    std::vector<uint8_t> level_of_;      // per valid box
    std::vector<uint32_t> cell_of_;      // per valid box: its cell, counted over every level's cells
    std::size_t base_[kMaxLevels] = {};  // a level's first cell in that count
    std::vector<std::vector<uint32_t>> counts_;  // a part's boxes a cell, then where they go
    std::vector<float> sample_;          // extents, to size level 0
    std::vector<Level> levels_;          // kMaxLevels, kept (and their memory) from frame to frame
    std::size_t used_ = 0;               // of which the last frame used these

    // A piece of a frame's work: a run of one level's cells, or a run of one
    // level's boxes each queried against another level.
    struct Task {
        int level, other;  // other < 0: scan level's cells [first, last)
        std::size_t first, last;
    };
    std::vector<Task> tasks_;
    std::atomic<std::size_t> next_task_{0};
};

}  // namespace cdvp
