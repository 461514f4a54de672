#include "sw/cli/frame_source.h"

#include <algorithm>

#include "sw/scene/trace_csv.h"

namespace cdvp {

namespace {

class TraceSource : public FrameSource {
public:
    explicit TraceSource(const std::string& path) : path_(path), frames_(read_trace_csv(path)) {
        for (const Frame& f : frames_) max_objects_ = std::max(max_objects_, f.boxes.size());
    }
    std::optional<Frame> next() override {
        if (next_ == frames_.size()) return std::nullopt;
        return std::move(frames_[next_++]);
    }
    std::size_t frame_count() const override { return frames_.size(); }
    std::size_t max_objects() const override { return max_objects_; }
    std::string describe() const override { return "trace " + path_; }

private:
    std::string path_;
    std::vector<Frame> frames_;
    std::size_t next_ = 0;
    std::size_t max_objects_ = 0;
};

class SpheresSource : public FrameSource {
public:
    SpheresSource(const BouncingSpheresConfig& config, std::size_t frames)
        : config_(config), scene_(config), frames_(frames) {}
    std::optional<Frame> next() override {
        if (produced_ == frames_) return std::nullopt;
        ++produced_;
        return scene_.frame();
    }
    void feed(const PairList& pairs) override { scene_.step(pairs); }
    std::size_t frame_count() const override { return frames_; }
    std::size_t max_objects() const override { return config_.objects; }
    std::string describe() const override {
        return "spheres objects=" + std::to_string(config_.objects) + " seed=" + std::to_string(config_.seed);
    }

private:
    BouncingSpheresConfig config_;
    BouncingSpheres scene_;
    std::size_t frames_;
    std::size_t produced_ = 0;
};

}  // namespace

std::unique_ptr<FrameSource> trace_source(const std::string& path) { return std::make_unique<TraceSource>(path); }

std::unique_ptr<FrameSource> spheres_source(const BouncingSpheresConfig& config, std::size_t frames) {
    return std::make_unique<SpheresSource>(config, frames);
}

}  // namespace cdvp
