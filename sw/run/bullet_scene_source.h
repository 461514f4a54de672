// `cdvp run --scene NAME` for one of Bullet's scenes: its frames as `cdvp
// record` records them, so a run of the scene and a run of its recorded trace
// give the board the same boxes, and so does `cdvp bullet` on it.
#pragma once

#include <cstddef>
#include <memory>

#include "sw/bullet/scenes.h"
#include "sw/run/frame_source.h"

namespace cdvp {

// The world steps on its own, whatever the board finds, as a trace would;
// no frame is kept, and a rewind builds the world again from its seed.
std::unique_ptr<FrameSource> bullet_scene_source(const SceneSpec& spec, std::size_t frames);

}  // namespace cdvp
