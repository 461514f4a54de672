#include "sw/scene/pile.h"

#include <algorithm>
#include <cmath>

namespace cdvp {

namespace {

// Box extents in cells: kMinExtent to kMaxExtent in whole cells.
constexpr int64_t kMinCells = static_cast<int64_t>(kMinExtent / kPileCell);
constexpr int64_t kMaxCells = static_cast<int64_t>(kMaxExtent / kPileCell);

}  // namespace

PileScene::PileScene(const PileConfig& config) : config_(config) {
    check_scene(config.clusters >= 1 && config.clusters <= (uint64_t{1} << 20), "pile",
                "expected clusters from 1 to 1048576");
    check_scene(std::isfinite(config.layers) && config.layers > 0.0, "pile", "expected layers > 0");
    check_scene(config.settled_fraction >= 0.0 && config.settled_fraction <= 1.0, "pile",
                "expected settled_fraction in [0, 1]");
    check_scene(config.release_frames >= 1, "pile", "expected release_frames >= 1");
    check_scene(std::isfinite(config.drop) && config.drop >= 0.0, "pile", "expected drop >= 0");
    check_scene(std::isfinite(config.gravity) && config.gravity >= 0.0, "pile", "expected gravity >= 0");
    check_scene(std::isfinite(config.dt) && config.dt >= 0.0, "pile", "expected dt >= 0");
    const std::size_t n = config.objects;
    const uint64_t count = config.clusters;
    // A cluster's footprint: its boxes' mean footprint (6 x 6 cells) over
    // the layers, and at least the largest box.
    const double per_cluster = std::ceil(static_cast<double>(n) / static_cast<double>(count));
    const double mean_cells = (kMinCells + kMaxCells) / 2.0;
    const auto side = std::max(kMaxCells, static_cast<int64_t>(std::ceil(
                                              std::sqrt(per_cluster * mean_cells * mean_cells / config.layers))));
    // Clusters on a square grid, a footprint's side apart.
    const auto row = static_cast<int64_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    clusters_.resize(count);
    for (uint64_t c = 0; c < count; ++c) {
        Cluster& cluster = clusters_[c];
        cluster.x = 2 * side * (static_cast<int64_t>(c) % row);
        cluster.y = 2 * side * (static_cast<int64_t>(c) / row);
        cluster.side = side;
    }
    SceneRng rng(config.seed);
    boxes_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        PileBox& box = boxes_[k];
        box.cluster = k % count;
        for (int64_t& s : box.size) s = kMinCells + static_cast<int64_t>(rng.below(kMaxCells - kMinCells + 1));
        box.x = static_cast<int64_t>(rng.below(static_cast<uint64_t>(side - box.size[0] + 1)));
        box.y = static_cast<int64_t>(rng.below(static_cast<uint64_t>(side - box.size[1] + 1)));
        box.lift = 1.0 + rng.unit();
    }
    // Height maps only for the clusters that get boxes.
    for (uint64_t c = 0; c < std::min<uint64_t>(count, n); ++c) {
        clusters_[c].heights.assign(static_cast<std::size_t>(side * side), 0.0);
    }
    settled_ = static_cast<std::size_t>(std::floor(static_cast<double>(n) * config.settled_fraction));
    settled_ = std::min(settled_, n);
    batch_ = static_cast<std::size_t>((n - settled_ + config.release_frames - 1) / config.release_frames);
    for (std::size_t k = 0; k < settled_; ++k) land(boxes_[k], base(boxes_[k]));
    released_ = settled_;
}

double PileScene::base(const PileBox& box) const {
    const Cluster& cluster = clusters_[box.cluster];
    double height = 0.0;
    for (int64_t y = box.y; y < box.y + box.size[1]; ++y) {
        const double* row = &cluster.heights[static_cast<std::size_t>(y * cluster.side)];
        for (int64_t x = box.x; x < box.x + box.size[0]; ++x) height = std::max(height, row[x]);
    }
    return height;
}

void PileScene::land(PileBox& box, double z) {
    box.z = z;
    box.speed = 0.0;
    box.resting = true;
    Cluster& cluster = clusters_[box.cluster];
    const double top = z + static_cast<double>(box.size[2]) * kPileCell;
    for (int64_t y = box.y; y < box.y + box.size[1]; ++y) {
        double* row = &cluster.heights[static_cast<std::size_t>(y * cluster.side)];
        for (int64_t x = box.x; x < box.x + box.size[0]; ++x) row[x] = top;  // every cell was <= z
    }
    cluster.top = std::max(cluster.top, top);
}

void PileScene::release(std::size_t k) {
    PileBox& box = boxes_[k];
    box.z = clusters_[box.cluster].top + config_.drop * box.lift;
    box.speed = 0.0;
    box.resting = false;
}

std::size_t PileScene::released_by(uint64_t frame) const {
    const std::size_t falling = boxes_.size() - settled_;
    if (batch_ == 0) return settled_;
    // Batches of frames 0..frame, without overflow for a huge frame number.
    const uint64_t batches = frame >= falling / batch_ ? falling / batch_ + 1 : frame + 1;
    return settled_ + static_cast<std::size_t>(std::min<uint64_t>(falling, batches * batch_));
}

std::size_t PileScene::max_boxes(std::size_t frames) const {
    return released_by(frames == 0 ? 0 : frames - 1);
}

Frame PileScene::next() {
    if (next_number_ > 0) {
        // The falling boxes fall (semi-implicit Euler), then land in id order.
        for (std::size_t k = settled_; k < released_; ++k) {
            PileBox& box = boxes_[k];
            if (box.resting) continue;
            box.speed += config_.gravity * config_.dt;
            box.z -= box.speed * config_.dt;
        }
        for (std::size_t k = settled_; k < released_; ++k) {
            PileBox& box = boxes_[k];
            if (box.resting) continue;
            const double under = base(box);
            if (box.z <= under) land(box, under);
        }
    }
    const std::size_t upto = released_by(next_number_);
    for (std::size_t k = released_; k < upto; ++k) release(k);
    released_ = upto;
    Frame frame;
    frame.number = next_number_++;
    frame.ids.resize(released_);
    frame.boxes.resize(released_);
    for (std::size_t k = 0; k < released_; ++k) {
        const PileBox& box = boxes_[k];
        const Cluster& cluster = clusters_[box.cluster];
        frame.ids[k] = k;
        Box& out = frame.boxes[k];
        out.min[0] = static_cast<double>(cluster.x + box.x) * kPileCell;
        out.min[1] = static_cast<double>(cluster.y + box.y) * kPileCell;
        out.min[2] = box.z;
        out.max[0] = static_cast<double>(cluster.x + box.x + box.size[0]) * kPileCell;
        out.max[1] = static_cast<double>(cluster.y + box.y + box.size[1]) * kPileCell;
        out.max[2] = box.z + static_cast<double>(box.size[2]) * kPileCell;
    }
    return frame;
}

}  // namespace cdvp
