// Where a run gets its frames: a trace file, a generated scene, or an
// application that runs them on the platform itself (Bullet's worlds).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "platform/frame_platform.h"
#include "sw/scene/input_spool.h"
#include "sw/scene/scene.h"
#include "sw/scene/trace_csv.h"
#include "models/common/aabb.h"
#include "sw/apps/bouncing_spheres.h"

namespace cdvp {

class FrameSource {
public:
    virtual ~FrameSource() = default;
    virtual std::optional<Frame> next() = 0;
    // The broad phase's pairs for the frame next() returned last (an
    // application steps its physics on them; a trace ignores them).
    virtual void feed(const PairList& /*pairs*/) {}
    // Starts the frames again from the first, as they were (the later runs
    // of --repeat time the baselines on the same frames).
    virtual void rewind() = 0;
    virtual std::size_t frame_count() const = 0;
    // The most boxes any frame holds: the board's memory depth.
    virtual std::size_t max_objects() const = 0;
    // The number of the last frame (nothing: no frames), and whether a
    // number is one of the frames' (a trace may skip numbers).
    virtual std::optional<uint64_t> last_frame() const = 0;
    virtual bool has_frame(uint64_t number) const = 0;
    // For the report: what the frames come from.
    virtual std::string describe() const = 0;
    // The float32 boxes (to_float_boxes) of the frame next() gave last when
    // the source keeps them converted (a replayed scene), else null.
    virtual const std::vector<FloatBox>* float_boxes() const { return nullptr; }

    // Whether the application behind the frames runs each frame on the
    // platform itself (Bullet's world calls its broad phase from inside its
    // step): the run then takes each frame's result from the source instead
    // of simulating its boxes again. Such a source is attached to the
    // platform before its first frame.
    virtual bool drives_platform() const { return false; }
    virtual void attach(FramePlatform& platform) { (void)platform; }
    // With drives_platform(): the result of the frame next() gave last (null
    // with `fault` set) and the simulator's native time for it.
    virtual const FrameResult* driven_result(FrameFault& fault, double& simulate_ns) {
        (void)fault, (void)simulate_ns;
        return nullptr;
    }
};

// A frame may hold as many boxes as the board's address map has room for.
TraceLimits board_trace_limits();

// The frames of a trace file, all checked up front (bad input fails before
// anything is simulated or written), then read again one frame at a time so
// memory holds the largest frame, not the file. A frame with more boxes, or
// a trace with more frames, than `limits` allow fails as bad input naming its
// line; so does a trace past `input`'s size or line limits, a file or a pipe
// (which is copied to an unlinked temporary file as the first reading goes,
// so it too is read twice).
std::unique_ptr<FrameSource> trace_source(const std::string& path, const TraceLimits& limits = board_trace_limits(),
                                          const InputLimits& input = {});

// The paper's application: spheres bouncing off the walls and each other,
// stepped on the broad phase's pairs (no frame is kept).
std::unique_ptr<FrameSource> spheres_source(const BouncingSpheresConfig& config, std::size_t frames);

}  // namespace cdvp
