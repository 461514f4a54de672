#include "sw/run/scene_memo.h"

#include <cstdio>

#include "sw/scene/conversion.h"

namespace cdvp {

namespace {

// Every field of the config, reals exactly (hexadecimal), and the frame count.
std::string key_of(const BouncingSpheresConfig& c, std::size_t frames) {
    char text[512];
    std::snprintf(text, sizeof text, "spheres %zu %llu %a %a %a %a %a %a %a %zu", c.objects,
                  static_cast<unsigned long long>(c.seed), c.radius_min, c.radius_max, c.volume_fraction, c.max_speed,
                  c.dt, c.moving_fraction, c.restitution, frames);
    return text;
}

// The frames and their float32 boxes, once converted.
std::size_t bytes_of(const std::vector<Frame>& frames) {
    std::size_t bytes = 0;
    for (const Frame& f : frames) {
        bytes += sizeof(Frame) + f.ids.size() * sizeof(uint64_t) + f.boxes.size() * (sizeof(Box) + sizeof(FloatBox));
    }
    return bytes;
}

}  // namespace

// The kept frames, as the generator gave them; the pairs fed back change nothing.
class SceneMemo::Replay : public FrameSource {
public:
    explicit Replay(std::shared_ptr<const Scene> scene) : scene_(std::move(scene)) {}
    std::optional<Frame> next() override {
        if (next_ == scene_->frames.size()) return std::nullopt;
        return scene_->frames[next_++];
    }
    void rewind() override { next_ = 0; }
    std::size_t frame_count() const override { return scene_->frames.size(); }
    std::size_t max_objects() const override { return scene_->max_objects; }
    std::optional<uint64_t> last_frame() const override { return scene_->frames.back().number; }
    bool has_frame(uint64_t number) const override {
        for (const Frame& frame : scene_->frames) {
            if (frame.number == number) return true;
        }
        return false;
    }
    std::string describe() const override { return scene_->description; }
    const std::vector<FloatBox>* float_boxes() const override {
        return next_ == 0 ? nullptr : &scene_->floats(next_ - 1);
    }

private:
    std::shared_ptr<const Scene> scene_;  // at least one frame
    std::size_t next_ = 0;
};

const std::vector<FloatBox>& SceneMemo::Scene::floats(std::size_t frame) const {
    float_boxes.resize(frames.size());
    std::vector<FloatBox>& boxes = float_boxes[frame];
    if (boxes.size() != frames[frame].boxes.size()) boxes = to_float_boxes(frames[frame].boxes);
    return boxes;
}

// The generator, its frames copied as they go; kept in the memo once the
// last one has been given (a run that ends early keeps nothing). Its float32
// boxes are converted into the scene, so that a replay need not again.
class SceneMemo::Recording : public FrameSource {
public:
    Recording(SceneMemo& memo, std::string key, std::unique_ptr<FrameSource> source)
        : memo_(memo), key_(std::move(key)), source_(std::move(source)) {
        recorded_->max_objects = source_->max_objects();
        recorded_->description = source_->describe();
    }
    std::optional<Frame> next() override {
        std::optional<Frame> frame = source_->next();
        if (!frame) return frame;
        ++given_;
        if (recorded_ == nullptr) return frame;
        recorded_->frames.push_back(*frame);
        if (recorded_->frames.size() == source_->frame_count()) {
            kept_ = recorded_;
            memo_.keep(key_, std::move(recorded_));
            recorded_ = nullptr;
        }
        return frame;
    }
    void feed(const PairList& pairs) override { source_->feed(pairs); }
    void rewind() override {
        source_->rewind();
        given_ = 0;
        if (recorded_ != nullptr) recorded_->frames.clear();
    }
    // The frame just given, as recorded (the generator gives the same frames after a rewind).
    const std::vector<FloatBox>* float_boxes() const override {
        const Scene* scene = recorded_ != nullptr ? recorded_.get() : kept_.get();
        if (given_ == 0 || scene == nullptr || given_ > scene->frames.size()) return nullptr;
        return &scene->floats(given_ - 1);
    }
    std::size_t frame_count() const override { return source_->frame_count(); }
    std::size_t max_objects() const override { return source_->max_objects(); }
    std::optional<uint64_t> last_frame() const override { return source_->last_frame(); }
    bool has_frame(uint64_t number) const override { return source_->has_frame(number); }
    std::string describe() const override { return source_->describe(); }

private:
    SceneMemo& memo_;
    std::string key_;
    std::unique_ptr<FrameSource> source_;
    std::shared_ptr<Scene> recorded_ = std::make_shared<Scene>();
    std::shared_ptr<const Scene> kept_;  // once recorded_ is in the memo
    std::size_t given_ = 0;              // frames given since the start or the last rewind
};

std::unique_ptr<FrameSource> SceneMemo::spheres(const BouncingSpheresConfig& config, std::size_t frames) {
    return generated(key_of(config, frames), frames, [&] { return spheres_source(config, frames); });
}

std::unique_ptr<FrameSource> SceneMemo::generated(const std::string& key, std::size_t frames,
                                                  const std::function<std::unique_ptr<FrameSource>()>& open) {
    if (const auto at = by_key_.find(key); at != by_key_.end()) {
        ++hits_;
        entries_.splice(entries_.begin(), entries_, at->second);
        return std::make_unique<Replay>(at->second->scene);
    }
    ++misses_;
    std::unique_ptr<FrameSource> source = open();
    if (frames == 0) return source;
    return std::make_unique<Recording>(*this, key, std::move(source));
}

void SceneMemo::keep(const std::string& key, std::shared_ptr<const Scene> scene) {
    const std::size_t bytes = bytes_of(scene->frames) + key.size() + scene->description.size() + 128;
    if (bytes > max_bytes_ || by_key_.count(key) != 0) return;
    while (bytes_ + bytes > max_bytes_ && !entries_.empty()) {
        bytes_ -= entries_.back().bytes;
        by_key_.erase(entries_.back().key);
        entries_.pop_back();
    }
    entries_.push_front({key, std::move(scene), bytes});
    by_key_[key] = entries_.begin();
    bytes_ += bytes;
}

}  // namespace cdvp
