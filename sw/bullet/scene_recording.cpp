#include "sw/bullet/scene_recording.h"

namespace cdvp {

SceneRecording::SceneRecording(const SceneSpec& spec)
    : spec_(spec), boxes_(scene_layout(spec).proxies), link_(boxes_) {
    restart();
}

SceneRecording::~SceneRecording() = default;

void SceneRecording::restart() {
    world_.reset();  // its memory is not the new world's to share
    world_ = make_scene_world(spec_, BroadphaseKind::kBoard, &link_);
    frames_ = 0;
}

Frame SceneRecording::next() {
    world_->step();
    return world_->aabbs(frames_++);  // the AABBs this step's broad phase was given
}

}  // namespace cdvp
