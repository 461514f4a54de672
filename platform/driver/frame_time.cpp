#include "platform/driver/frame_time.h"

#include "models/grid_schedule/grid_slots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "models/address_generator/address_generator.h"
#include "models/address_generator/sweep_schedule.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"
#include "models/pci/dma_registers.h"

namespace cdvp {

namespace {

// Edges beyond the sweep a run between events may take: the pipeline's and
// the FIFO's tail (the pipeline is at most 66 edges deep).
constexpr uint64_t kPipelineSlack = 1024;
// Register accesses a frame makes besides its data (chain and DMA registers,
// the object count and START, the counters at the end), and a segment (the
// status, acknowledge, counters, pair count, RESUME and the read-back's
// DMA registers): generous counts, so that the bound holds as the driver
// changes.
constexpr double kAccessesPerFrame = 32;
constexpr double kAccessesPerSegment = 32;

}  // namespace

std::string simulated_seconds(double ns) {
    char text[48];
    std::snprintf(text, sizeof text, "%.3f s", ns * 1e-9);
    return text;
}

FrameTime::FrameTime(const DriverConfig& config, const BusTiming& bus, SimTime period_fs, uint32_t m,
                     uint32_t buffer_depth, const TileConfig& tiles, double quantum_ns)
    : config_(config),
      bus_(bus),
      period_ns_(ns_from_fs(period_fs)),
      m_(m),
      buffer_depth_(std::max<uint32_t>(buffer_depth, 1)),
      tiles_(tiles),
      quantum_ns_(quantum_ns) {}

SimTime poll_gap_fs(const DriverConfig& config, SimTime period_fs, uint32_t k) {
    const SimTime gap = fs_from_ns(config.poll_gap_ns);
    const SimTime base = gap > 0 ? gap : period_fs;
    if (config.poll_backoff <= 1.0) return base;
    const double grown = ns_from_fs(base) * std::pow(config.poll_backoff, std::min<uint32_t>(k, 64));
    return fs_from_ns(std::max(ns_from_fs(base), std::min(grown, config.poll_gap_max_ns)));
}

double FrameTime::timeout_ns(double worst_ns) const {
    return config_.timeout_floor_ns + config_.timeout_factor * worst_ns;
}

double full_upload_bus_ns(const BusTiming& bus, Transfer transfer, uint32_t objects) {
    if (transfer != Transfer::kDma) return kCoordinates * static_cast<double>(objects) * bus.pio_write_ns();
    return kCoordinates * (bus.dma_ns(sizeof(DmaDescriptor), Direction::kToBoard) +
                           bus.dma_ns(4 * uint64_t{objects}, Direction::kToBoard));
}

double delta_upload_bus_ns(const BusTiming& bus, Transfer transfer, uint64_t records) {
    const uint64_t bytes = 4 * uint64_t{address_map::kDeltaRecordWords} * records;
    if (transfer != Transfer::kDma) return static_cast<double>(bytes / 4) * bus.pio_write_ns();
    double ns = 0;
    for (uint64_t left = bytes; left > 0;) {
        const uint64_t piece = std::min<uint64_t>(left, address_map::kDeltaStreamSize);
        ns += bus.dma_ns(sizeof(DmaDescriptor), Direction::kToBoard) + bus.dma_ns(piece, Direction::kToBoard);
        left -= piece;
    }
    return ns;
}

bool upload_as_delta(const DriverConfig& config, const BusTiming& bus, uint32_t objects, uint64_t changed) {
    if (config.upload == UploadMode::kFull) return false;
    return config.upload == UploadMode::kDelta ||
           delta_upload_bus_ns(bus, config.transfer, changed) < full_upload_bus_ns(bus, config.transfer, objects);
}

double FrameTime::upload_worst_ns(uint32_t objects) const {
    return full_upload_bus_ns(bus_, Transfer::kDma, objects) + bus_.interrupt_ns();
}

double FrameTime::delta_worst_ns(uint64_t records) const {
    return bus_.interrupt_ns() + delta_upload_bus_ns(bus_, Transfer::kDma, records);
}

double FrameTime::any_upload_worst_ns(uint32_t objects) const {
    const double full = upload_worst_ns(objects);
    return config_.upload == UploadMode::kFull ? full : std::max(full, delta_worst_ns(objects));
}

uint64_t FrameTime::readback_bytes(uint64_t pairs, uint32_t objects) const {
    const uint64_t row_pieces = grid_ ? 0 : tiles_.row_pieces(objects);
    return std::min<uint64_t>(4 * worst_encoded_words(config_.pair_format, pairs, objects, row_pieces),
                              address_map::kPairBufferSize);
}

double FrameTime::dma_worst_ns(uint64_t bytes, Direction direction) const {
    return bus_.dma_ns(bytes, direction) + bus_.interrupt_ns();
}

// Every stall edge moves a pair, so a run between two events drains at most
// one buffer beyond the sweep.
uint64_t FrameTime::worst_run_cycles(uint32_t objects) const {
    const uint64_t slots =
        grid_ ? worst_grid_slots(objects, *grid_, {2 * m_ - 1, tiles_.cycles_per_box, tiles_.load_latency_cycles})
        : tiles_.tiled() ? SweepSchedule(m_, tiles_, objects).slots()
                         : AddressGenerator::sweep_cycles(objects, m_);
    return slots + buffer_depth_ + kPipelineSlack;
}

double FrameTime::board_worst_ns(uint32_t objects) const {
    return period_ns_ * static_cast<double>(worst_run_cycles(objects)) + bus_.interrupt_ns();
}

double FrameTime::longest_timeout_ns(uint32_t objects) const {
    const double worst = std::max({any_upload_worst_ns(objects), board_worst_ns(objects),
                                   dma_worst_ns(readback_bytes(buffer_depth_, objects), Direction::kToHost)});
    return timeout_ns(worst);
}

double FrameTime::access_ns() const { return std::max(bus_.pio_read_ns(), bus_.pio_write_ns()); }

// A poll may just miss the event: one more gap (the largest, with
// back-off) and read, and the read that finds it. Under run.interrupts
// board the DMA completions are polled even when the board interrupts.
double FrameTime::notice_ns() const {
    const double gap = config_.poll_backoff > 1.0 ? std::max(config_.poll_gap_max_ns, config_.poll_gap_ns)
                                                  : config_.poll_gap_ns;
    const double poll = 2 * bus_.pio_read_ns() + std::max(gap, period_ns_);
    double notice = config_.wait == WaitMode::kIrq ? bus_.interrupt_ns() : poll;
    if (config_.wait == WaitMode::kIrq && config_.interrupts != InterruptPolicy::kEvery) notice = std::max(notice, poll);
    return notice + quantum_ns_;  // a CPU that ran ahead notices up to a quantum late
}

uint64_t FrameTime::waits(uint64_t pairs) const { return 1 + 2 * segments(pairs); }

double FrameTime::frame_bound_ns(uint32_t objects, uint64_t pairs) const {
    const uint64_t segments = this->segments(pairs);
    const double n = objects, p = static_cast<double>(pairs), s = static_cast<double>(segments);
    // Upload: the DMA chain and its notice, or every word by programmed I/O.
    double ns = config_.transfer == Transfer::kDma
                    ? any_upload_worst_ns(objects) + notice_ns()
                    : (kCoordinates + (config_.upload == UploadMode::kFull ? 0 : 1)) * n * bus_.pio_write_ns();
    // The board: every slot of the sweep, a stall a pair, each segment's tail.
    const double cycles = static_cast<double>(worst_run_cycles(objects) - buffer_depth_) + p +
                          s * static_cast<double>(kPipelineSlack);
    ns += cycles * period_ns_ + s * notice_ns();
    // Read-back: full buffers at each pause, then the rest.
    const uint64_t last = std::min<uint64_t>(pairs, buffer_depth_);
    const double full_bytes = static_cast<double>(readback_bytes(buffer_depth_, objects));
    const double last_bytes = static_cast<double>(readback_bytes(last, objects));
    if (config_.transfer == Transfer::kDma) {
        ns += (s - 1) * dma_worst_ns(readback_bytes(buffer_depth_, objects), Direction::kToHost) +
              dma_worst_ns(readback_bytes(last, objects), Direction::kToHost) + s * notice_ns();
    } else {
        ns += ((s - 1) * full_bytes + last_bytes) / 4 * bus_.pio_read_ns();
    }
    // Registers, and the driver's own work.
    ns += (kAccessesPerFrame + kAccessesPerSegment * s) * access_ns();
    ns += (1 + s) * config_.call_ns + n * config_.ns_per_box + p * config_.ns_per_pair;
    return ns;
}

}  // namespace cdvp
