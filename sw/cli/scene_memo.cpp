#include "sw/cli/scene_memo.h"

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
        if (next_ == 0) return nullptr;
        std::vector<std::vector<FloatBox>>& converted = scene_->float_boxes;
        converted.resize(scene_->frames.size());
        std::vector<FloatBox>& boxes = converted[next_ - 1];
        if (boxes.size() != scene_->frames[next_ - 1].boxes.size()) boxes = to_float_boxes(scene_->frames[next_ - 1].boxes);
        return &boxes;
    }

private:
    std::shared_ptr<const Scene> scene_;  // at least one frame
    std::size_t next_ = 0;
};

// The generator, its frames copied as they go; kept in the memo once the
// last one has been given (a run that ends early keeps nothing).
class SceneMemo::Recording : public FrameSource {
public:
    Recording(SceneMemo& memo, std::string key, std::unique_ptr<FrameSource> source)
        : memo_(memo), key_(std::move(key)), source_(std::move(source)) {
        recorded_->max_objects = source_->max_objects();
        recorded_->description = source_->describe();
    }
    std::optional<Frame> next() override {
        std::optional<Frame> frame = source_->next();
        if (!frame || recorded_ == nullptr) return frame;
        recorded_->frames.push_back(*frame);
        if (recorded_->frames.size() == source_->frame_count()) {
            memo_.keep(key_, std::move(recorded_));
            recorded_ = nullptr;
        }
        return frame;
    }
    void feed(const PairList& pairs) override { source_->feed(pairs); }
    void rewind() override {
        source_->rewind();
        if (recorded_ != nullptr) recorded_->frames.clear();
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
};

std::unique_ptr<FrameSource> SceneMemo::spheres(const BouncingSpheresConfig& config, std::size_t frames) {
    const std::string key = key_of(config, frames);
    if (const auto at = by_key_.find(key); at != by_key_.end()) {
        ++hits_;
        entries_.splice(entries_.begin(), entries_, at->second);
        return std::make_unique<Replay>(at->second->scene);
    }
    ++misses_;
    std::unique_ptr<FrameSource> source = spheres_source(config, frames);
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
