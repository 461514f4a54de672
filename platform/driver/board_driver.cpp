#include "platform/driver/board_driver.h"

#include <stdexcept>
#include <string>

#include "models/control_registers/control_registers.h"
#include "models/pci/dma_registers.h"

namespace cdvp {

using R = ControlRegisters;
using D = DmaRegisters;

uint64_t BoardDriver::host_memory_bytes(uint32_t capacity, uint32_t buffer_depth, const DriverConfig& config) {
    return PortExecutor::host_memory_bytes(capacity, buffer_depth, config);
}

BoardDriver::BoardDriver(HostPort& port, SimTime period_fs, const DriverConfig& config,
                         std::shared_ptr<const BusTiming> bus)
    : port_(port),
      config_(config),
      executor_(port, period_fs, config, std::move(bus)),
      sequence_(executor_, config, period_fs) {}

void BoardDriver::open() {
    PortExecutor& x = executor_;
    const uint32_t id = x.read(R::kId);
    if (id != R::kIdValue && id != R::kGridIdValue) throw std::runtime_error("no collision board answers at the BAR");
    const bool grid_board = id == R::kGridIdValue;
    const uint32_t capacity = x.read(R::kCapacity);
    const uint32_t buffer_depth = x.read(R::kPairBufferDepth);
    const uint32_t parallelism = x.read(R::kParallelism);
    const NumberFormat format = NumberFormat::from_register(x.read(R::kFormat));
    // Where the boxes sit bounds a sweep's cycles (the timeouts): block RAM,
    // or SSRAM swept in tiles; a grid board's SSRAM and grid.
    TileConfig tiles;
    tiles.boxes = x.read(R::kTileBoxes);
    if (tiles.tiled() || grid_board) {
        const uint32_t timing = x.read(R::kTileTiming);
        tiles.load_latency_cycles = timing & R::kTileTimingLatencyMask;
        tiles.cycles_per_box = timing >> R::kTileTimingCyclesShift;
    }
    std::optional<GridConfig> grid;
    if (grid_board) {
        grid.emplace();
        grid->dims = x.read(R::kGridDims);
        grid->cell_capacity = x.read(R::kGridCellCapacity);
        grid->max_span = x.read(R::kGridMaxSpan);
    }
    x.open(capacity, buffer_depth, parallelism, format, tiles, grid);
    // Two banks pipeline frames; the host's bank is where the next upload goes.
    const uint32_t box_banks = x.read(R::kBoxBanks);
    const uint32_t host_bank = x.read(R::kHostBank);
    if (box_banks < 1 || box_banks > 2 || host_bank >= box_banks) {
        throw std::runtime_error("the board reports " + std::to_string(box_banks) + " box banks and host bank " +
                                 std::to_string(host_bank));
    }
    x.set_host_bank(host_bank);
    sequence_.open(box_banks, x.read(R::kPairBank));
    // The pair format stays set across frames and aborts.
    x.write(R::kPairFormat, static_cast<uint32_t>(config_.pair_format));
    if (x.read(R::kPairFormat) != static_cast<uint32_t>(config_.pair_format)) {
        throw std::runtime_error("the board refused pair format " + std::to_string(static_cast<int>(config_.pair_format)));
    }
    x.forget_banks();
}

void BoardDriver::check_capacity(const std::vector<FloatBox>& boxes) const {
    if (boxes.size() > capacity()) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) + " boxes exceeds the board's capacity of " +
                                    std::to_string(capacity()));
    }
}

FramePhases BoardDriver::run_frame(const std::vector<FloatBox>& boxes, PairList& pairs) {
    check_capacity(boxes);
    if (sequence_.in_flight()) throw std::logic_error("run_frame with a pipelined frame in flight: finish() it first");
    try {
        return sequence_.frame(boxes, pairs);
    } catch (const std::exception&) {
        fail_frames(pairs);
        throw;
    }
}

bool BoardDriver::submit(const std::vector<FloatBox>& boxes, PairList& pairs, FramePhases& phases) {
    if (!pipelined()) throw std::logic_error("submit: the board has one box bank; use run_frame");
    check_capacity(boxes);
    try {
        return sequence_.submit(boxes, pairs, phases);
    } catch (const std::exception&) {
        fail_frames(pairs);
        throw;
    }
}

bool BoardDriver::finish(PairList& pairs, FramePhases& phases) {
    if (!sequence_.in_flight()) return false;
    try {
        return sequence_.finish(pairs, phases);
    } catch (const std::exception&) {
        fail_frames(pairs);
        throw;
    }
}

void BoardDriver::fail_frames(PairList& pairs) {
    pairs.clear();  // never a partial set
    sequence_.abandon();
    executor_.forget_banks();  // what the board's memories hold is not known now
    recover();
}

void BoardDriver::recover() {
    try {
        executor_.write(D::kBase + D::kControl, D::kAbort);
        executor_.write(R::kControl, R::kAbort);
        // Let an aborted transfer's engine settle before the next frame.
        port_.wait(0);
        port_.wait(0);
        if (pipelined()) executor_.set_host_bank(executor_.read(R::kHostBank));
    } catch (const DeviceFault&) {
        // The next frame's accesses report the board's state.
    }
}

}  // namespace cdvp
