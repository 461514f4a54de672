// A clustered pile settling under gravity: boxes of mixed sizes dropped over
// a few small footprints (clusters) fall and come to rest on the floor or
// on the boxes already landed there, touching them exactly, so the pile's
// boxes meet many neighbours and crowd every axis. Half the boxes have
// landed before the first frame; the rest are released over the frames, a
// batch a frame, from above their cluster's top.
//
// Positions and extents are whole multiples of kPileCell in x and y, and
// extents in z too, so a cluster's height map (the top of the boxes landed
// over each cell) is exact: a box rests at the highest top under its
// footprint, its min z that box's max z bit for bit. A falling box lands
// when its bottom reaches that height (and, kinematic, is set onto it should
// a box below have landed past its bottom in the same step).
#pragma once

#include "sw/scene/kinematic_scene.h"

namespace cdvp {

constexpr double kPileCell = 0.25;

struct PileConfig : KinematicConfig {
    // Footprints the boxes fall onto, box k onto cluster k mod clusters.
    uint64_t clusters = 3;
    // A cluster's footprint holds this many layers of its boxes, on average.
    double layers = 4.0;
    // The share of boxes landed before frame 0.
    double settled_fraction = 0.5;
    // The others are released in equal batches over this many frames.
    uint64_t release_frames = 120;
    // A released box's bottom starts drop to 2 drop above its cluster's top.
    double drop = 1.0;
    double gravity = 9.81;  // scene units / s^2
};

class PileScene : public KinematicScene {
public:
    // Throws InputError for a config out of range.
    explicit PileScene(const PileConfig& config);
    Frame next() override;
    std::size_t max_boxes(std::size_t frames) const override;
    // Box k is in the frames and has landed (its bottom on the floor or on a box).
    bool resting(std::size_t k) const { return k < released_ && boxes_[k].resting; }

private:
    struct Cluster {
        int64_t x = 0, y = 0;  // its footprint's first cell
        int64_t side = 0;      // cells a side
        std::vector<double> heights;  // side x side, row by row
        double top = 0.0;      // the highest height
    };
    struct PileBox {
        std::size_t cluster = 0;
        int64_t x = 0, y = 0;        // first cell, within the cluster's footprint
        std::array<int64_t, 3> size{};  // extents in cells
        double lift = 0.0;           // drop's share above the cluster's top at release, in [1, 2)
        double z = 0.0;              // bottom
        double speed = 0.0;          // downward
        bool resting = false;
    };
    double base(const PileBox& box) const;
    void land(PileBox& box, double z);
    void release(std::size_t k);
    std::size_t released_by(uint64_t frame) const;

    PileConfig config_;
    std::vector<Cluster> clusters_;
    std::vector<PileBox> boxes_;
    std::size_t settled_ = 0, batch_ = 0, released_ = 0;
    uint64_t next_number_ = 0;
};

}  // namespace cdvp
