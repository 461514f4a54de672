// The seam every modelling level of the platform implements for a run's
// frames: the SystemC platform (VirtualBoard: the clocked, fast or RTL engine
// under a simulated host, bus and driver), the analytic level
// (AnalyticPlatform: closed forms, no kernel) and the auto policy between
// them (AutoLevelPlatform). A run hands it each frame's boxes and gets the
// frame's pairs and simulated phases back, one frame at a time or pipelined
// on a board with two box banks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "models/common/aabb.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/board_driver.h"

namespace cdvp {

struct FrameResult {
    PairList pairs;  // in the order the board found them
    FramePhases phases;
};

// Why a frame did not complete. Faults travel by value from the CPU thread to
// the caller: an exception rethrown on the main stack after the coroutines
// have run trips AddressSanitizer's stale stack bounds (docs/testing.md).
// kPairBudget: the frame's pairs outgrew the run's pair budget, bad input
// like kTimeLimit (the system did not fault); pairs_found says where the
// search stopped.
struct FrameFault {
    enum class Kind : uint8_t { kNone, kDevice, kTimeLimit, kPairBudget };
    Kind kind = Kind::kNone;
    std::string message;  // the driver's message, one line
    uint64_t pairs_found = 0;
    explicit operator bool() const { return kind != Kind::kNone; }
};

class FramePlatform {
public:
    virtual ~FramePlatform() = default;
    // The frame numbered `number` (a trace's own frame number): its result,
    // valid until the next call, or null with `fault` set.
    virtual const FrameResult* try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) = 0;
    // Frames pipelined, on a board with two box banks: submitting a frame
    // finishes the one before it (null, fault unset, on the first call);
    // finishing completes the frame in flight.
    virtual bool pipelined() const = 0;
    virtual const FrameResult* try_submit_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                                FrameFault& fault) = 0;
    virtual const FrameResult* try_finish_frames(FrameFault& fault) = 0;
    // The bus the frames cross, for the report.
    virtual const BusTiming& bus_timing() const = 0;
};

}  // namespace cdvp
