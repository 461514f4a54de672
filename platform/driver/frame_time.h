// How long the driver lets each wait take, and how long a frame can take at
// most, from the same numbers: the estimate that cdvp run makes before any
// work (sw/run/run_budgets.h) therefore covers every deadline the driver will
// set, and both are held to one limit, kSimulatedTimeLimit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "models/address_generator/tile_config.h"
#include "models/grid_binning/grid_config.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/host_port.h"

namespace cdvp {

// The latest simulated time a run may reach: 2^63 fs, about 9,223.372 s,
// half of SystemC's 64-bit femtosecond clock. Half, so that no deadline (a
// time below the limit plus a timeout below it) can wrap the kernel's clock,
// and no rounding near its end matters. Declared once: the driver refuses a
// wait whose deadline would pass it, and cdvp run refuses up front a run
// whose estimate would.
constexpr SimTime kSimulatedTimeLimit = SimTime{1} << 63;

// Simulated time as every message quotes it: seconds with three decimals
// ("9223.372 s").
std::string simulated_seconds(double ns);

// The bus time of an upload alone, by the bus formula (no register accesses,
// no notice): the six arrays, each after its descriptor, by DMA, or every
// word by programmed I/O; the delta stream's records likewise, a descriptor
// a window-sized piece. run.upload auto takes the smaller, in the driver and
// at the analytic level alike.
double full_upload_bus_ns(const BusTiming& bus, Transfer transfer, uint32_t objects);
double delta_upload_bus_ns(const BusTiming& bus, Transfer transfer, uint64_t records);
// Whether run.upload sends the `changed` boxes of a frame of `objects` as deltas.
bool upload_as_delta(const DriverConfig& config, const BusTiming& bus, uint32_t objects, uint64_t changed);

// The pause after the k-th poll of a wait: the poll gap (a board period when
// it is 0, so that an untimed bus still lets time pass), growing by the
// back-off factor each poll up to the largest gap.
SimTime poll_gap_fs(const DriverConfig& config, SimTime period_fs, uint32_t k);

// What a frame's waits and work cost on one board and bus. All times in ns.
class FrameTime {
public:
    // period_fs: the board's clock; m, buffer_depth, tiles: its parallelism,
    // pair buffer and memory (the driver reads them from the board's
    // registers at open; the estimate before a run takes the board's
    // configuration); quantum_ns: how far the host CPU may run ahead, which
    // delays each wait's end.
    FrameTime(const DriverConfig& config, const BusTiming& bus, SimTime period_fs, uint32_t m, uint32_t buffer_depth,
              const TileConfig& tiles, double quantum_ns = 0.0);
    // A grid board (docs/grid_board.md): its sweep's worst case comes from
    // its grid and its SSRAM's timing (tiles' latency and cycles a box), and a
    // row's pairs may come in any number of runs.
    void set_grid(const GridConfig& grid) { grid_ = grid; }

    // A wait gives up after config.timeout_factor x its worst case plus
    // config.timeout_floor_ns.
    double timeout_ns(double worst_ns) const;
    // The worst cases the timeouts are taken from: the upload's DMA chain of
    // six arrays and its interrupt; a DMA of `bytes` and its interrupt; the
    // board from START or RESUME to its next event (every sweep slot, a full
    // buffer's drain, the pipeline's tail) and its interrupt.
    double upload_worst_ns(uint32_t objects) const;
    double dma_worst_ns(uint64_t bytes, Direction direction) const;
    // A delta upload of `records` boxes: its chain and its interrupt; the
    // worse of the uploads run.upload may choose.
    double delta_worst_ns(uint64_t records) const;
    double any_upload_worst_ns(uint32_t objects) const;
    // The most bytes a read-back of `pairs` pairs moves in the pair format.
    uint64_t readback_bytes(uint64_t pairs, uint32_t objects) const;
    double board_worst_ns(uint32_t objects) const;
    // The longest timeout any wait of a frame of `objects` boxes gets.
    double longest_timeout_ns(uint32_t objects) const;

    // At most how long a frame of `objects` boxes and at most `pairs` pairs
    // takes when none of its waits times out: the upload, every sweep slot,
    // one stall a pair (a stall edge moves a pair) and each pause's slack,
    // each wait's notice, the read-back and the driver's own work, generously.
    double frame_bound_ns(uint32_t objects, uint64_t pairs) const;
    // Waits in such a frame: the upload's, and two a board segment.
    uint64_t waits(uint64_t pairs) const;

    // Edges the board may run from START or RESUME to its next event.
    uint64_t worst_run_cycles(uint32_t objects) const;

private:
    uint64_t segments(uint64_t pairs) const { return 1 + pairs / buffer_depth_; }
    // From an event to the driver acting on it: the interrupt, or a poll.
    double notice_ns() const;
    // One programmed access of a register, the slower direction.
    double access_ns() const;

    DriverConfig config_;
    const BusTiming& bus_;  // outlives this (the driver's, or the run's estimate)
    double period_ns_;
    uint32_t m_;
    uint32_t buffer_depth_;
    TileConfig tiles_;
    double quantum_ns_;
    std::optional<GridConfig> grid_;
};

}  // namespace cdvp
