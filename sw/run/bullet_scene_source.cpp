#include "sw/run/bullet_scene_source.h"

#include "sw/bullet/scene_recording.h"

namespace cdvp {

namespace {

class BulletSceneSource : public FrameSource {
public:
    BulletSceneSource(const SceneSpec& spec, std::size_t frames) : spec_(spec), recording_(spec), frames_(frames) {}
    void rewind() override {
        recording_.restart();
        produced_ = 0;
    }
    std::optional<Frame> next() override {
        if (produced_ == frames_) return std::nullopt;
        ++produced_;
        return recording_.next();
    }
    std::size_t frame_count() const override { return frames_; }
    std::optional<uint64_t> last_frame() const override {
        return frames_ == 0 ? std::nullopt : std::optional<uint64_t>(frames_ - 1);
    }
    bool has_frame(uint64_t number) const override { return number < frames_; }
    std::size_t max_objects() const override { return recording_.boxes(); }
    std::string describe() const override { return cdvp::describe(spec_); }

private:
    SceneSpec spec_;
    SceneRecording recording_;
    std::size_t frames_;
    std::size_t produced_ = 0;
};

}  // namespace

std::unique_ptr<FrameSource> bullet_scene_source(const SceneSpec& spec, std::size_t frames) {
    return std::make_unique<BulletSceneSource>(spec, frames);
}

}  // namespace cdvp
