// A Bullet scene's frames as boxes: each step, the AABBs the world handed its
// broad phase, one box per collision object in the world's order (ids 0 ..
// n-1), frames numbered from 0. The world steps on the board's broad phase
// (BoardBroadphase) with a float32 board's pairs found on the host
// (HostPairsLink), so it moves bit for bit as the world `cdvp bullet` steps
// on a float32 board, and as one on btSimpleBroadphase (tests/bullet hold
// the two equal), at the cost of a sort and sweep a frame rather than all
// pairs: a recorded frame holds the boxes the board is given in that frame
// of `cdvp bullet`. `cdvp record` writes these frames as a trace; `cdvp run
// --scene NAME` simulates them.
#pragma once

#include <cstdint>
#include <memory>

#include "sw/bullet/scenes.h"
#include "sw/scene/scene.h"

namespace cdvp {

class SceneRecording {
public:
    // std::invalid_argument for a scene scene_layout() refuses.
    explicit SceneRecording(const SceneSpec& spec);
    ~SceneRecording();

    // Steps the world once and returns that step's boxes.
    Frame next();
    // Back to the scene's first frame, the world built again from its seed.
    void restart();
    // Boxes a frame: every collision object of the scene.
    uint32_t boxes() const { return boxes_; }

private:
    SceneSpec spec_;
    uint32_t boxes_ = 0;
    HostPairsLink link_;  // outlives the world, whose broad phase uses it
    std::unique_ptr<BulletWorld> world_;
    uint64_t frames_ = 0;
};

}  // namespace cdvp
