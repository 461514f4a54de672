// Generated scenes kept across the runs of one process: a sweep of analytic
// points generates the same scene again at every m, clock and bus. A
// scene's frames depend on its settings alone (the application steps on the
// float32 pairs, whatever the board), so a scene of the same settings is
// replayed frame for frame. Bounded in bytes, least recently used first out.
#pragma once

#include <cstddef>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sw/apps/bouncing_spheres.h"
#include "sw/run/frame_source.h"

namespace cdvp {

class SceneMemo {
public:
    static constexpr std::size_t kDefaultBytes = std::size_t{256} << 20;
    explicit SceneMemo(std::size_t max_bytes = kDefaultBytes) : max_bytes_(max_bytes) {}

    // The first `frames` frames of the bouncing spheres of `config`: replayed
    // when kept, else generated (spheres_source) and kept once the run has
    // taken every one of them.
    std::unique_ptr<FrameSource> spheres(const BouncingSpheresConfig& config, std::size_t frames);
    // The same for any generated scene: `key` names it and its every setting
    // (the frame count among them), `open` generates it.
    std::unique_ptr<FrameSource> generated(const std::string& key, std::size_t frames,
                                           const std::function<std::unique_ptr<FrameSource>()>& open);

    std::size_t hits() const { return hits_; }
    std::size_t misses() const { return misses_; }

private:
    // A generated scene's frames and what its source said of itself.
    struct Scene {
        std::vector<Frame> frames;
        std::size_t max_objects = 0;
        std::string description;
        // Each frame's float32 boxes, converted when first asked for.
        mutable std::vector<std::vector<FloatBox>> float_boxes;
        const std::vector<FloatBox>& floats(std::size_t frame) const;
    };
    class Replay;
    class Recording;
    void keep(const std::string& key, std::shared_ptr<const Scene> scene);

    struct Entry {
        std::string key;
        std::shared_ptr<const Scene> scene;
        std::size_t bytes = 0;
    };
    std::size_t max_bytes_;
    std::size_t bytes_ = 0, hits_ = 0, misses_ = 0;
    std::list<Entry> entries_;  // most recently used first
    std::map<std::string, std::list<Entry>::iterator> by_key_;
};

}  // namespace cdvp
