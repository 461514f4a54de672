#include "sw/baselines/hierarchical_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "sw/baselines/box_bounds.h"

namespace cdvp {

namespace {

// Query boxes a task takes at a time, and the cells of a level's scan a task
// takes when the frame is split over threads.
constexpr std::size_t kQueryChunk = 512;
constexpr std::size_t kTasksPerThread = 32;
// Boxes below which filing them is not split over threads, and the most
// parts it is split into (each part counts every cell of every level).
constexpr std::size_t kBoxesPerPart = 4096;
constexpr std::size_t kMaxParts = 8;

// Each axis's bulk: extents up to four times the median (a sample of the
// boxes gives the median). The largest extent within it sizes level 0's
// cells; a box past it goes to a coarser level.
void bulk_limits(const std::vector<FloatBox>& boxes, const std::vector<uint32_t>& valid, std::vector<float>& sample,
                 float limit[3]) {
    constexpr std::size_t kSample = 4096;
    const std::size_t stride = std::max<std::size_t>(1, valid.size() / kSample);
    for (int axis = 0; axis < 3; ++axis) {
        limit[axis] = 0;
        if (valid.empty()) continue;
        sample.clear();
        for (std::size_t k = 0; k < valid.size(); k += stride) sample.push_back(extent(boxes[valid[k]], axis));
        auto middle = sample.begin() + static_cast<std::ptrdiff_t>(sample.size() / 2);
        std::nth_element(sample.begin(), middle, sample.end());
        limit[axis] = 4.0f * *middle;
    }
}

}  // namespace

int32_t HierarchicalGridBroadPhase::Level::cell(int axis, float x) const {
    // Monotone in x and clamped to the grid: the neighbourhood argument needs
    // nothing more. (x - origin) * 0 for an infinite x is NaN: cell 0, where
    // the axis has one cell.
    double t = (double(x) - origin[axis]) * inv_size[axis];
    const double top = double(dims[axis] - 1);
    if (!(t > 0)) t = 0;
    if (t > top) t = top;
    return static_cast<int32_t>(t);
}

HierarchicalGridBroadPhase::HierarchicalGridBroadPhase(unsigned threads, bool multi_threaded)
    : multi_threaded_(multi_threaded),
      pool_(multi_threaded ? (threads == 0 ? machine_threads() : threads) : 1),
      found_(pool_.size()),
      levels_(kMaxLevels) {}

std::size_t HierarchicalGridBroadPhase::parts_for(std::size_t n) const {
    return std::clamp<std::size_t>(n / kBoxesPerPart, 1, std::min<std::size_t>(pool_.size(), kMaxParts));
}

// Runs fn(part, first, last) over the parts of [0, n), each part taken by
// whichever thread asks next: a thread the machine keeps waiting holds up
// no other.
template <typename Fn>
void HierarchicalGridBroadPhase::for_parts(std::size_t n, std::size_t parts, Fn&& fn) {
    std::atomic<std::size_t> next{0};
    pool_.run([&](unsigned) {
        for (std::size_t p = next++; p < parts; p = next++) fn(p, n * p / parts, n * (p + 1) / parts);
    });
}

// The boxes with no NaN bound (valid_, in index order), and the lowest
// finite coordinate and the span to the highest, per axis (0 and 0 where
// there is none).
void HierarchicalGridBroadPhase::survey(const std::vector<FloatBox>& boxes, double lo[3], double span[3]) {
    struct Range {
        float low[3] = {INFINITY, INFINITY, INFINITY}, high[3] = {-INFINITY, -INFINITY, -INFINITY};
    };
    const std::size_t parts = parts_for(boxes.size());
    std::array<Range, kMaxParts> ranges{};
    part_valid_.resize(parts);
    for_parts(boxes.size(), parts, [&](std::size_t p, std::size_t first, std::size_t last) {
        // Filled here and handed back: the parts' vectors share cache lines.
        std::vector<uint32_t> valid;
        valid.swap(part_valid_[p]);
        valid.clear();
        Range r;  // kept here, not in ranges, whose parts share a cache line
        for (std::size_t i = first; i < last; ++i) {
            const FloatBox& b = boxes[i];
            if (has_nan(b)) continue;
            valid.push_back(static_cast<uint32_t>(i));
            for (int axis = 0; axis < 3; ++axis) {
                for (const float x : {b.min[axis], b.max[axis]}) {
                    if (std::isfinite(x)) r.low[axis] = std::min(r.low[axis], x), r.high[axis] = std::max(r.high[axis], x);
                }
            }
        }
        ranges[p] = r;
        part_valid_[p].swap(valid);
    });
    valid_.clear();
    Range all;
    for (std::size_t p = 0; p < parts; ++p) {
        valid_.insert(valid_.end(), part_valid_[p].begin(), part_valid_[p].end());
        for (int axis = 0; axis < 3; ++axis) {
            all.low[axis] = std::min(all.low[axis], ranges[p].low[axis]);
            all.high[axis] = std::max(all.high[axis], ranges[p].high[axis]);
        }
    }
    for (int axis = 0; axis < 3; ++axis) {
        const bool any = all.low[axis] <= all.high[axis];
        lo[axis] = any ? double(all.low[axis]) : 0.0;
        span[axis] = any ? double(all.high[axis]) - double(all.low[axis]) : 0.0;
    }
}

// The largest extent, per axis, among the boxes within the bulk's limits.
void HierarchicalGridBroadPhase::bulk_extents(const std::vector<FloatBox>& boxes, double size[3]) {
    float limit[3];
    bulk_limits(boxes, valid_, sample_, limit);
    const std::size_t parts = parts_for(valid_.size());
    std::array<std::array<float, 3>, kMaxParts> bulk{};
    for_parts(valid_.size(), parts, [&](std::size_t p, std::size_t first, std::size_t last) {
        std::array<float, 3> most{};  // kept here, not in bulk, whose parts share a cache line
        for (std::size_t k = first; k < last; ++k) {
            for (int axis = 0; axis < 3; ++axis) {
                const float e = extent(boxes[valid_[k]], axis);
                if (e <= limit[axis] && e > most[axis]) most[axis] = e;
            }
        }
        bulk[p] = most;
    });
    for (int axis = 0; axis < 3; ++axis) {
        size[axis] = 0;
        for (std::size_t p = 0; p < parts; ++p) size[axis] = std::max(size[axis], double(bulk[p][axis]));
    }
}

// The grid spans the finite bounds of the boxes; level 0's cells are the
// bulk's extent, capped so that no level holds more than twice as many cells
// as boxes (a sparse scene gets coarser cells, not a huge empty array).
void HierarchicalGridBroadPhase::plan_levels(const std::vector<FloatBox>& boxes) {
    double lo[3], span[3], size[3];
    survey(boxes, lo, span);
    bulk_extents(boxes, size);
    const double cap = std::max<double>(64.0, 2.0 * double(valid_.size()));
    const double n_root = std::cbrt(std::max<double>(1.0, double(valid_.size())));
    for (int axis = 0; axis < 3; ++axis) {
        // Boxes of no extent (points, flat boxes) still spread over the span.
        if (!(size[axis] > 0)) size[axis] = span[axis] > 0 ? span[axis] / n_root : 1.0;
    }
    used_ = 0;
    for (int k = 0; k < kMaxLevels; ++k) {
        Level& level = levels_[k];
        double dims[3];
        for (int axis = 0; axis < 3; ++axis) {
            if (k > 0) size[axis] *= kLevelRatio;
            const bool top = k + 1 == kMaxLevels;
            dims[axis] = top ? 1.0 : std::clamp(std::ceil(span[axis] / size[axis]), 1.0, 1e12);
        }
        // Coarsen until the level holds no more cells than the cap.
        while (dims[0] * dims[1] * dims[2] > cap) {
            const double grow = std::cbrt(dims[0] * dims[1] * dims[2] / cap) * 1.01;
            for (int axis = 0; axis < 3; ++axis) {
                if (dims[axis] <= 1) continue;
                size[axis] *= grow;
                dims[axis] = std::max(1.0, std::ceil(span[axis] / size[axis]));
            }
        }
        for (int axis = 0; axis < 3; ++axis) {
            level.origin[axis] = lo[axis];
            level.dims[axis] = static_cast<int32_t>(dims[axis]);
            level.inv_size[axis] = dims[axis] > 1 ? 1.0 / size[axis] : 0.0;
        }
        used_ = std::size_t(k) + 1;
        if (level.dims[0] == 1 && level.dims[1] == 1 && level.dims[2] == 1) break;
    }
}

// Each valid box to the lowest level where it spans at most two cells on
// every axis (the top level, one cell, takes any), then a counting sort puts
// each level's boxes in cell order. On several threads the boxes are cut
// into parts, each counted and placed by one thread at a time (a cell holds part 0's
// boxes, then part 1's, ...: the order is the same whatever the timing).
void HierarchicalGridBroadPhase::file_boxes(const std::vector<FloatBox>& boxes) {
    const std::size_t n = valid_.size();
    level_of_.resize(n);
    cell_of_.resize(n);
    std::size_t total = 0;  // the cells of every level, one after another
    for (std::size_t l = 0; l < used_; ++l) base_[l] = total, total += levels_[l].cells();
    const std::size_t parts = parts_for(n);
    counts_.resize(parts);
    for_parts(n, parts, [&](std::size_t p, std::size_t first, std::size_t last) {
        std::vector<uint32_t>& count = counts_[p];
        count.assign(total, 0);
        for (std::size_t k = first; k < last; ++k) {
            float lo[3], hi[3];
            normalised(boxes[valid_[k]], lo, hi);
            for (std::size_t l = 0; l < used_; ++l) {
                const Level& level = levels_[l];
                int32_t c[3];
                bool fits = true;
                for (int axis = 0; axis < 3 && fits; ++axis) {
                    c[axis] = level.cell(axis, lo[axis]);
                    fits = level.cell(axis, hi[axis]) - c[axis] <= 1;
                }
                if (!fits) continue;
                level_of_[k] = static_cast<uint8_t>(l);
                cell_of_[k] = static_cast<uint32_t>(
                    base_[l] + (std::size_t(c[2]) * level.dims[1] + c[1]) * level.dims[0] + c[0]);
                ++count[cell_of_[k]];
                break;
            }
        }
    });
    // Each cell's start, and in the counts each part's first place in it.
    for (std::size_t l = 0; l < used_; ++l) {
        Level& level = levels_[l];
        const std::size_t cells = level.cells();
        level.start.resize(cells + 1);
        uint32_t at = 0;
        for (std::size_t c = 0; c < cells; ++c) {
            level.start[c] = at;
            for (std::vector<uint32_t>& count : counts_) at += std::exchange(count[base_[l] + c], at);
        }
        level.start[cells] = at;
        level.entries.resize(at);
    }
    for_parts(n, parts, [&](std::size_t p, std::size_t first, std::size_t last) {
        std::vector<uint32_t>& place = counts_[p];
        for (std::size_t k = first; k < last; ++k) {
            const FloatBox& box = boxes[valid_[k]];
            levels_[level_of_[k]].entries[place[cell_of_[k]]++] = {{box.min[0], box.min[1], box.min[2]},
                                                                  {box.max[0], box.max[1], box.max[2]},
                                                                  valid_[k],
                                                                  0};
        }
    });
}

// The frame's work as tasks: each level's cells, and for each two levels
// with boxes, the boxes of the one whose queries cost less against the
// other's cells (a few large boxes query the fine level; many small boxes
// query a coarse level with few cells).
void HierarchicalGridBroadPhase::plan_work() {
    tasks_.clear();
    const std::size_t pieces = pool_.size() == 1 ? 1 : pool_.size() * kTasksPerThread;
    for (std::size_t l = 0; l < used_; ++l) {
        const Level& level = levels_[l];
        if (level.boxes() < 2) continue;
        const std::size_t cells = level.cells();
        const std::size_t chunk = std::max<std::size_t>(1, (cells + pieces - 1) / pieces);
        for (std::size_t first = 0; first < cells; first += chunk) {
            tasks_.push_back({int(l), -1, first, std::min(cells, first + chunk)});
        }
    }
    for (std::size_t a = 0; a < used_; ++a) {
        for (std::size_t b = a + 1; b < used_; ++b) {
            const Level& fine = levels_[a];
            const Level& coarse = levels_[b];
            if (fine.boxes() == 0 || coarse.boxes() == 0) continue;
            // A query looks at up to 3 cells an axis: the cells and boxes it meets.
            const auto query_cost = [](const Level& grid, double reach[3]) {
                double cells = 1;
                for (int axis = 0; axis < 3; ++axis) cells *= std::min<double>(grid.dims[axis], reach[axis]);
                return cells + cells * double(grid.boxes()) / double(grid.cells());
            };
            double three[3] = {3, 3, 3}, down_reach[3];
            for (int axis = 0; axis < 3; ++axis) {
                down_reach[axis] = coarse.inv_size[axis] > 0 && fine.inv_size[axis] > 0
                                       ? 2.0 * fine.inv_size[axis] / coarse.inv_size[axis] + 2.0
                                       : double(fine.dims[axis]);
            }
            const double up = double(fine.boxes()) * query_cost(coarse, three);
            const double down = double(coarse.boxes()) * query_cost(fine, down_reach);
            const int from = up <= down ? int(a) : int(b), into = up <= down ? int(b) : int(a);
            const std::size_t n = levels_[from].boxes();
            for (std::size_t first = 0; first < n; first += kQueryChunk) {
                tasks_.push_back({from, into, first, std::min(n, first + kQueryChunk)});
            }
        }
    }
}

void HierarchicalGridBroadPhase::run_work(unsigned thread) {
    PairList& out = found_.list(thread);
    while (true) {
        const std::size_t t = next_task_.fetch_add(1, std::memory_order_relaxed);
        if (t >= tasks_.size()) return;
        const Task& task = tasks_[t];
        const Level& level = levels_[task.level];
        if (task.other < 0) {
            scan_cells(level, task.first, task.last, out);
        } else {
            const Level& other = levels_[task.other];
            for (std::size_t k = task.first; k < task.last; ++k) {
                const Level::Entry& e = level.entries[k];
                query(other, e.lo, e.hi, e.index, out);
                if (out.size() > budget_.max_pairs()) break;
            }
        }
        if (!found_.report(thread, budget_)) return;
    }
}

namespace {

// The boxes [first, last) of a level that overlap box i: the exact test.
inline void test_run(const HierarchicalGridBroadPhase::Level& level, const float lo[3], const float hi[3], uint32_t id,
                     std::size_t first, std::size_t last, PairList& out) {
    const HierarchicalGridBroadPhase::Level::Entry* const e = level.entries.data();
    for (std::size_t j = first; j < last; ++j) {
        if ((e[j].lo[0] <= hi[0]) & (lo[0] <= e[j].hi[0]) & (e[j].lo[1] <= hi[1]) & (lo[1] <= e[j].hi[1]) &
            (e[j].lo[2] <= hi[2]) & (lo[2] <= e[j].hi[2])) {
            const uint32_t other = e[j].index;
            out.push_back({std::min(id, other), std::max(id, other)});
        }
    }
}

}  // namespace

// Cells [first, last) of a level against themselves and half their
// neighbours: the next cell in the row, and three cells of each of the rows
// (y+1, z), (y-1, z+1), (y, z+1), (y+1, z+1); the other half's pairs are
// found from the other side.
void HierarchicalGridBroadPhase::scan_cells(const Level& level, std::size_t first, std::size_t last,
                                            PairList& out) const {
    const int32_t dx = level.dims[0], dy = level.dims[1], dz = level.dims[2];
    const uint32_t* const start = level.start.data();
    int32_t x = int32_t(first % dx), y = int32_t((first / dx) % dy), z = int32_t(first / (std::size_t(dx) * dy));
    constexpr int32_t kRows[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
    for (std::size_t c = first; c < last; ++c) {
        const uint32_t begin = start[c], end = start[c + 1];
        if (begin != end) {
            // The boxes after i in its cell and the next cell are one run.
            const uint32_t own_end = start[c + (x + 1 < dx ? 2 : 1)];
            std::size_t runs[4][2];
            int n_runs = 0;
            for (const auto& row : kRows) {
                const int32_t ry = y + row[0], rz = z + row[1];
                if (ry < 0 || ry >= dy || rz >= dz) continue;
                const std::size_t base = (std::size_t(rz) * dy + ry) * dx;
                runs[n_runs][0] = start[base + std::max(x - 1, 0)];
                runs[n_runs][1] = start[base + std::min(x + 1, dx - 1) + 1];
                n_runs += runs[n_runs][0] != runs[n_runs][1];
            }
            for (uint32_t i = begin; i < end; ++i) {
                const Level::Entry& box = level.entries[i];
                test_run(level, box.lo, box.hi, box.index, i + 1, own_end, out);
                for (int r = 0; r < n_runs; ++r) test_run(level, box.lo, box.hi, box.index, runs[r][0], runs[r][1], out);
                if (out.size() > budget_.max_pairs()) return;  // the frame will be refused
            }
        }
        if (++x == dx) {
            x = 0;
            if (++y == dy) y = 0, ++z;
        }
    }
}

// The boxes of a level that overlap a box of another level: a box of this
// level spans at most two cells an axis and is filed by its lower corner, so
// any that overlaps has its corner in the cells from one before the query's
// lower corner to its upper corner.
void HierarchicalGridBroadPhase::query(const Level& level, const float lo[3], const float hi[3], uint32_t id,
                                       PairList& out) const {
    int32_t from[3], to[3];
    for (int axis = 0; axis < 3; ++axis) {
        const float a = std::min(lo[axis], hi[axis]), b = std::max(lo[axis], hi[axis]);
        from[axis] = std::max(level.cell(axis, a) - 1, 0);
        to[axis] = level.cell(axis, b);
    }
    const int32_t dx = level.dims[0], dy = level.dims[1];
    for (int32_t z = from[2]; z <= to[2]; ++z) {
        for (int32_t y = from[1]; y <= to[1]; ++y) {
            const std::size_t base = (std::size_t(z) * dy + y) * dx;
            test_run(level, lo, hi, id, level.start[base + from[0]], level.start[base + to[0] + 1], out);
        }
    }
}

void HierarchicalGridBroadPhase::find_pairs(const std::vector<FloatBox>& boxes, PairList& out) {
    out.clear();
    plan_levels(boxes);
    file_boxes(boxes);
    plan_work();
    found_.clear();
    next_task_.store(0);
    pool_.run([this](unsigned thread) { run_work(thread); });
    found_.join(out, budget_);
}

}  // namespace cdvp
