#include "sw/run/frame_source.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

#include "models/control_registers/control_registers.h"
#include "sw/scene/csv_reader.h"
#include "sw/scene/input_spool.h"
#include "sw/scene/trace_csv.h"

namespace cdvp {

namespace {

// FNV-1a, a 64-bit word at a time, over a frame's number, ids and bound
// bits: tells whether the second reading of a trace found the same frame.
uint64_t frame_digest(const Frame& frame) {
    uint64_t hash = 14695981039346656037ull;
    auto mix = [&hash](uint64_t word) { hash = (hash ^ word) * 1099511628211ull; };
    mix(frame.number);
    for (uint64_t id : frame.ids) mix(id);
    for (const Box& box : frame.boxes) {
        for (const double* bounds : {box.min, box.max}) {
            for (int axis = 0; axis < 3; ++axis) {
                uint64_t bits;
                std::memcpy(&bits, &bounds[axis], sizeof bits);
                mix(bits);
            }
        }
    }
    return hash;
}

// The trace is read twice: once up front, so that bad input fails before
// anything is simulated or written and the frame count and the largest frame
// are known; then frame by frame while the board runs, so memory holds one
// frame, not the file. Each frame of the second reading must equal the
// first's (by digest), or the run fails as bad input. A pipe cannot be read
// twice: the first reading copies it to a temporary file as it goes, and the
// second reads the copy. Either way the first reading holds the input to the
// same limits (sw/scene/input_spool.h), so a bad or endless one stops at its
// first line or byte past them.
class TraceSource : public FrameSource {
public:
    TraceSource(const std::string& path, const TraceLimits& limits, const InputLimits& input) : path_(path) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec) && !std::filesystem::is_directory(path, ec) &&
            std::filesystem::exists(path, ec)) {
            spool_.emplace(path, input);
            read_first(spool_->stream(), limits);
            spool_->finish();
            readable_ = spool_->path();
        } else {
            LimitedFile file(path, input);
            read_first(file.stream(), limits);
            readable_ = path;
        }
        rewind();
    }
    // Each reading must equal the first, so a rewind is checked as the second reading is.
    void rewind() override {
        reader_.reset();
        in_ = open_input(readable_);
        // Bounds memory should the file grow in between.
        reader_.emplace(in_, path_, TraceLimits{max_objects_, "the largest frame of the first reading"});
        delivered_ = 0;
    }
    std::optional<Frame> next() override {
        std::optional<Frame> frame;
        try {
            frame = reader_->next_frame();
        } catch (const InputError& e) {
            changed(e.what());  // the first reading found no such problem
        }
        if (delivered_ == digests_.size()) {
            if (frame) changed("more frames than on the first reading");
            return std::nullopt;
        }
        if (!frame) changed("fewer frames than on the first reading");
        if (frame_digest(*frame) != digests_[delivered_]) {
            changed("frame " + std::to_string(frame->number) + " differs from the first reading");
        }
        ++delivered_;
        return frame;
    }
    std::size_t frame_count() const override { return digests_.size(); }
    std::optional<uint64_t> last_frame() const override {
        return numbers_.empty() ? std::nullopt : std::optional<uint64_t>(numbers_.back());
    }
    bool has_frame(uint64_t number) const override {
        return std::binary_search(numbers_.begin(), numbers_.end(), number);  // ascending, as the reader checks
    }
    std::size_t max_objects() const override { return max_objects_; }
    std::string describe() const override { return "trace " + path_; }

private:
    void read_first(std::istream& in, const TraceLimits& limits) {
        TraceReader check(in, path_, limits);
        while (std::optional<Frame> frame = check.next_frame()) {
            max_objects_ = std::max(max_objects_, frame->boxes.size());
            digests_.push_back(frame_digest(*frame));
            numbers_.push_back(frame->number);
        }
    }
    [[noreturn]] void changed(const std::string& how) const {
        throw InputError(path_ + ": the file changed while being read (" + how + "); expected it unchanged during the run");
    }

    std::string path_;
    std::optional<InputSpool> spool_;  // a pipe's copy
    std::string readable_;        // the file read: the path, or the pipe's copy
    std::ifstream in_;
    std::optional<TraceReader> reader_;
    std::vector<uint64_t> digests_;  // one a frame, from the first reading
    std::vector<uint64_t> numbers_;  // the frames' numbers, from the first reading
    std::size_t delivered_ = 0;
    std::size_t max_objects_ = 0;
};

class SpheresSource : public FrameSource {
public:
    SpheresSource(const BouncingSpheresConfig& config, std::size_t frames)
        : config_(config), scene_(config), frames_(frames) {}
    void rewind() override {
        scene_.emplace(config_);
        produced_ = 0;
    }
    std::optional<Frame> next() override {
        if (produced_ == frames_) return std::nullopt;
        ++produced_;
        return scene_->frame();
    }
    // After the last frame no step is seen: none is taken.
    void feed(const PairList& pairs) override {
        if (produced_ < frames_) scene_->step(pairs);
    }
    std::size_t frame_count() const override { return frames_; }
    std::optional<uint64_t> last_frame() const override {
        return frames_ == 0 ? std::nullopt : std::optional<uint64_t>(frames_ - 1);
    }
    bool has_frame(uint64_t number) const override { return number < frames_; }
    std::size_t max_objects() const override { return config_.objects; }
    std::string describe() const override {
        return "spheres objects=" + std::to_string(config_.objects) + " seed=" + std::to_string(config_.seed);
    }

private:
    BouncingSpheresConfig config_;
    std::optional<BouncingSpheres> scene_;
    std::size_t frames_;
    std::size_t produced_ = 0;
};

}  // namespace

TraceLimits board_trace_limits() { return TraceLimits{address_map::kMaxObjects, "the board's address map"}; }

std::unique_ptr<FrameSource> trace_source(const std::string& path, const TraceLimits& limits,
                                          const InputLimits& input) {
    return std::make_unique<TraceSource>(path, limits, input);
}

std::unique_ptr<FrameSource> spheres_source(const BouncingSpheresConfig& config, std::size_t frames) {
    return std::make_unique<SpheresSource>(config, frames);
}

}  // namespace cdvp
