#include "sw/cli/frame_source.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <utility>

#include "models/control_registers/control_registers.h"
#include "sw/scene/csv_reader.h"
#include "sw/scene/trace_csv.h"

namespace cdvp {

namespace {

// The trace is read twice: once up front, so that bad input fails before
// anything is simulated or written and the frame count and the largest frame
// are known; then frame by frame while the board runs, so memory holds one
// frame, not the file. A pipe cannot be read twice; its frames are kept.
class TraceSource : public FrameSource {
public:
    explicit TraceSource(const std::string& path) : path_(path), in_(open_input(path)) {
        const TraceLimits limits{address_map::kMaxObjects, "the board's address map"};
        std::error_code ec;
        const bool rereadable = std::filesystem::is_regular_file(path, ec);
        TraceReader check(in_, path_, limits);
        while (std::optional<Frame> frame = check.next_frame()) {
            ++frame_count_;
            max_objects_ = std::max(max_objects_, frame->boxes.size());
            if (!rereadable) kept_.push_back(std::move(*frame));
        }
        if (rereadable) {
            in_.clear();
            in_.seekg(0);
            // The second reading may not find more than the first did.
            reader_.emplace(in_, path_, TraceLimits{max_objects_, "the file changed while being read"});
        }
    }
    std::optional<Frame> next() override {
        if (delivered_ == frame_count_) return std::nullopt;
        std::optional<Frame> frame;
        if (reader_) {
            frame = reader_->next_frame();
            if (!frame) throw InputError(path_ + ": the file changed while being read (fewer frames)");
        } else {
            frame = std::move(kept_[delivered_]);
        }
        ++delivered_;
        return frame;
    }
    std::size_t frame_count() const override { return frame_count_; }
    std::size_t max_objects() const override { return max_objects_; }
    std::string describe() const override { return "trace " + path_; }

private:
    std::string path_;
    std::ifstream in_;
    std::optional<TraceReader> reader_;
    std::vector<Frame> kept_;
    std::size_t frame_count_ = 0;
    std::size_t delivered_ = 0;
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
