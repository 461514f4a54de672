// The kinematic scene families (pile, heavy, planar, brownian): boxes moved
// by a rule of their own, whatever pairs a broad phase finds in them, so a
// frame never waits on the last one's pairs. Each is deterministic by its
// seed on every platform (scene_random.h) and keeps its density as the
// object count grows, as the spheres do. Boxes are given with ids 0..n-1.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sw/scene/scene.h"
#include "sw/scene/scene_random.h"

namespace cdvp {

// What every family's config holds. Lengths in scene units, times in seconds.
struct KinematicConfig {
    std::size_t objects = 500;
    uint64_t seed = 1;
    double dt = 1.0 / 60.0;  // time between frames
};

class KinematicScene {
public:
    virtual ~KinematicScene() = default;
    // Frame k (k = 0, 1, ...): frame 0 is the first state; each later call
    // first advances by dt.
    virtual Frame next() = 0;
    // The most boxes any of the first `frames` frames holds.
    virtual std::size_t max_boxes(std::size_t frames) const = 0;
};

// A box's extent along one axis in every family but heavy's large boxes:
// uniform in [kMinExtent, kMaxExtent], as the spheres' diameters.
constexpr double kMinExtent = 1.0;
constexpr double kMaxExtent = 2.0;
constexpr double kMeanExtent = 1.5;
// The mean volume of a box of three such extents, drawn independently.
constexpr double kMeanBoxVolume = kMeanExtent * kMeanExtent * kMeanExtent;

// A box moving at constant velocity inside a room [0, room[axis]] per axis,
// mirrored at its walls.
struct MovingBox {
    std::array<double, 3> centre{};
    std::array<double, 3> half{};      // half extents
    std::array<double, 3> velocity{};
    std::array<double, 3> hi{};        // centre_limit(room, half) per axis
};

// Extents drawn per axis in [kMinExtent, kMaxExtent].
std::array<double, 3> draw_extents(SceneRng& rng);
// A box of these extents at a uniform place inside the room, at rest.
MovingBox place_box(SceneRng& rng, const std::array<double, 3>& extents, const std::array<double, 3>& room);
// One step of dt, mirrored at the walls.
void move_box(MovingBox& box, double dt);
// Frame `number`: ids 0..N-1, boxes centre +- half.
Frame moving_frame(uint64_t number, const std::vector<MovingBox>& boxes);

// InputError "FAMILY scene: WHAT" unless ok.
void check_scene(bool ok, const std::string& family, const std::string& what);

}  // namespace cdvp
