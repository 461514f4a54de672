// How the driver works a board (transfer, waiting, timeouts) and what its
// host's CPU costs: the settings of the driver, apart from the driver itself
// so that the estimate before a run (platform/driver/frame_time.h) reads the same.
#pragma once

#include <cstdint>

#include "models/common/pair_budget.h"
#include "models/pair_collector/pair_format.h"

namespace cdvp {

// How the driver moves boxes and pairs (run.transfer), and how it waits for
// the board (run.wait); their names are the settings table's
// (platform/settings/setting_choices.h).
enum class Transfer : uint8_t { kDma, kPio };
enum class WaitMode : uint8_t { kIrq, kPoll };
// How the boxes reach the board (run.upload): all six arrays every frame;
// only the boxes whose words changed since the last upload, as records of
// the delta stream; or per frame whichever the bus formula says is cheaper.
enum class UploadMode : uint8_t { kFull, kDelta, kAuto };
// Which completions interrupt the host (run.interrupts), when it waits by
// interrupt: every DMA's and the board's, or only the board's (one a frame
// without overflow pauses), the DMA completions then polled.
enum class InterruptPolicy : uint8_t { kEvery, kBoard };

struct DriverConfig {
    Transfer transfer = Transfer::kDma;  // kPio: boxes and pairs by programmed I/O
    WaitMode wait = WaitMode::kIrq;      // kPoll: poll the status register
    double poll_gap_ns = 0.0;     // CPU time between two status polls
    // Polling with back-off: each gap is poll_backoff x the one before
    // (from the poll gap, or a board period when it is 0), up to
    // poll_gap_max_ns. 1: a constant gap.
    double poll_backoff = 1.0;
    double poll_gap_max_ns = 100000.0;
    UploadMode upload = UploadMode::kFull;
    PairFormat pair_format = PairFormat::kList;  // how the pair buffer reads back (the board's PAIR_FORMAT)
    InterruptPolicy interrupts = InterruptPolicy::kEvery;
    // Host CPU work, per frame (assumptions of the host preset): packing a box
    // (six double-to-float conversions and stores), unpacking a pair, and a
    // call into the kernel driver per board operation.
    double ns_per_box = 0.0;
    double ns_per_pair = 0.0;
    double call_ns = 0.0;
    // Simulated-time timeouts: a wait for the DMA engine or the board gives
    // up after timeout_factor x its worst-case time plus timeout_floor_ns
    // (worst case: the bus's DMA time, or every sweep cycle plus a full pair
    // buffer's drain, plus an interrupt). On timeout the driver polls the
    // status once (a lost interrupt recovers) and otherwise fails the frame.
    double timeout_factor = 2.0;
    double timeout_floor_ns = 100000.0;
    // The most pairs a frame may hold (run.max_pairs): the read-back stops
    // with PairBudgetExceeded before the pairs past it are copied. Not a
    // setting of its own: the platform passes the run's budget.
    PairBudget pair_budget{};
};

}  // namespace cdvp
