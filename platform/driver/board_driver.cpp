#include "platform/driver/board_driver.h"

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"
#include "models/pci/dma_registers.h"
#include "platform/driver/quantiser.h"

namespace cdvp {

using R = ControlRegisters;
using D = DmaRegisters;

namespace {
// Host RAM layout: the six coordinate arrays, the pair area, then the DMA
// descriptors of the upload chain.
uint64_t coordinate_area(uint32_t capacity, uint32_t c) { return uint64_t{c} * 4 * capacity; }
uint64_t pair_area(uint32_t capacity) { return (uint64_t{24} * capacity + 7) / 8 * 8; }
uint64_t descriptor_area(uint32_t capacity, uint32_t buffer_depth) {
    return pair_area(capacity) + uint64_t{8} * buffer_depth;
}

std::string hex(uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "0x%" PRIx64, value);
    return text;
}

std::string mebibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g MiB", static_cast<double>(bytes) / (1 << 20));
    return text;
}

std::string microseconds(SimTime t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g us", ns_from_fs(t) * 1e-3);
    return text;
}

}  // namespace

uint64_t BoardDriver::host_memory_bytes(uint32_t capacity, uint32_t buffer_depth) {
    return descriptor_area(capacity, buffer_depth) + kCoordinates * sizeof(DmaDescriptor);
}

BoardDriver::BoardDriver(HostPort& port, SimTime period_fs, const DriverConfig& config,
                         std::shared_ptr<const BusTiming> bus)
    : port_(port),
      period_(period_fs),
      config_(config),
      bus_(bus ? std::move(bus) : std::make_shared<IdealBusTiming>()) {}

void BoardDriver::pio_read(uint64_t address, void* data, uint32_t length) {
    if (const std::string error = port_.read(address, data, length); !error.empty()) {
        throw DeviceFault("board read at " + hex(address) + " failed: " + error);
    }
}

void BoardDriver::pio_write(uint64_t address, const void* data, uint32_t length) {
    if (const std::string error = port_.write(address, data, length); !error.empty()) {
        throw DeviceFault("board write at " + hex(address) + " failed: " + error);
    }
}

uint32_t BoardDriver::read(uint64_t address) {
    uint32_t value = 0;
    pio_read(address, &value, 4);
    return value;
}

void BoardDriver::write(uint64_t address, uint32_t value) { pio_write(address, &value, 4); }

uint64_t BoardDriver::read_counter(uint32_t low_offset) {
    const uint64_t low = read(low_offset);
    return low | uint64_t{read(low_offset + 4)} << 32;
}

void BoardDriver::open() {
    if (read(R::kId) != R::kIdValue) throw std::runtime_error("no collision board answers at the BAR");
    capacity_ = read(R::kCapacity);
    buffer_depth_ = read(R::kPairBufferDepth);
    parallelism_ = read(R::kParallelism);
    format_ = NumberFormat::from_register(read(R::kFormat));
    // Where the boxes sit bounds a sweep's cycles (the timeouts): block RAM,
    // or SSRAM swept in tiles.
    TileConfig tiles;
    tiles.boxes = read(R::kTileBoxes);
    if (tiles.tiled()) {
        const uint32_t timing = read(R::kTileTiming);
        tiles.load_latency_cycles = timing & R::kTileTimingLatencyMask;
        tiles.cycles_per_box = timing >> R::kTileTimingCyclesShift;
    }
    time_.emplace(config_, *bus_, period_, parallelism_, buffer_depth_, tiles);
    if (port_.memory_size() < host_memory_bytes(capacity_, buffer_depth_)) {
        throw std::runtime_error("host memory too small for the board's capacity and pair buffer");
    }
}

void BoardDriver::charge(Phase phase) {
    spent_[phase] += ns_from_fs(port_.now() - mark_);
    mark_ = port_.now();
}

void BoardDriver::cpu_work(double ns) {
    if (ns > 0) port_.wait(fs_from_ns(ns));
    charge(kDriver);
}

// Between two polls: the configured gap, and never no time at all (on an
// untimed bus a poll costs nothing, and the loop would not let time pass).
void BoardDriver::poll_pause() {
    const SimTime gap = fs_from_ns(config_.poll_gap_ns);
    port_.wait(gap > 0 ? gap : period_);
}

// Compared in ns before converting: a timeout too long for 64-bit
// femtoseconds never reaches fs_from_ns.
SimTime BoardDriver::timeout_for(double worst_ns) const {
    const double timeout_ns = time_->timeout_ns(worst_ns);
    const double now_ns = ns_from_fs(port_.now());
    if (!(now_ns + timeout_ns <= ns_from_fs(kSimulatedTimeLimit))) {
        throw SimulatedTimeLimit("a wait from " + simulated_seconds(now_ns) + " of simulated time could last until " +
                                 simulated_seconds(now_ns + timeout_ns) + ", past the limit of " +
                                 simulated_seconds(ns_from_fs(kSimulatedTimeLimit)) +
                                 " (2^63 fs, half SystemC's 64-bit femtosecond clock)");
    }
    return fs_from_ns(timeout_ns);
}

// By interrupt: each interrupt (the line is shared) or the timeout is
// followed by one status read. By polling: status reads until the deadline.
uint32_t BoardDriver::wait_for(uint64_t status_address, uint32_t bits, SimTime timeout, const char* what) {
    const SimTime deadline = port_.now() + timeout;
    for (;;) {
        if (config_.wait == WaitMode::kIrq) port_.wait_for_interrupt(deadline - port_.now());
        noticed_ = port_.now();  // the handler runs: the status read is readback work
        const uint32_t value = read(status_address);
        if (config_.wait != WaitMode::kIrq) noticed_ = port_.now();  // a poll notices when its read returns
        const bool late = port_.now() >= deadline;
        if (value & bits) {
            if (late && config_.wait == WaitMode::kIrq) ++timeouts_recovered_;  // the interrupt was lost
            return value;
        }
        if (late) {
            throw DeviceFault(std::string(what) + " timed out: no completion within " + microseconds(timeout) +
                              " of simulated time");
        }
        if (config_.wait != WaitMode::kIrq) poll_pause();
    }
}

// Starts the bridge's DMA engine (registers already set) and waits for it
// by interrupt or polling; a fault the engine reports fails the frame.
void BoardDriver::run_dma(uint32_t control, double worst_ns) {
    const SimTime timeout = timeout_for(worst_ns);
    write(D::kBase + D::kControl,
          control | D::kStart | (config_.wait == WaitMode::kIrq ? uint32_t{D::kInterruptOnDone} : 0u));
    const uint32_t status = wait_for(D::kBase + D::kStatus, D::kDone | D::kError, timeout, "DMA");
    if (status & D::kError) dma_fault();
    write(D::kBase + D::kStatus, D::kDone);  // clear done: the shared line falls
}

void BoardDriver::dma_fault() {
    const auto cause = static_cast<DmaFault>(read(D::kBase + D::kErrorCause));
    const uint64_t address = read_counter(D::kBase + D::kErrorAddressLo);
    if (cause == DmaFault::kMasterAbort && address >= port_.memory_size()) {
        throw DeviceFault("DMA fault: host address " + hex(address) + " beyond host memory (" +
                          mebibytes(port_.memory_size()) + ")");
    }
    throw DeviceFault(std::string("DMA fault: ") + describe(cause) + " at address " + hex(address));
}

void BoardDriver::dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host) {
    write(D::kBase + D::kHostAddressLo, static_cast<uint32_t>(host_address));
    write(D::kBase + D::kHostAddressHi, static_cast<uint32_t>(host_address >> 32));
    write(D::kBase + D::kLocalAddress, local_address);
    write(D::kBase + D::kBytes, bytes);
    const Direction direction = to_host ? Direction::kToHost : Direction::kToBoard;
    run_dma(to_host ? uint32_t{D::kToHost} : 0u, time_->dma_worst_ns(bytes, direction));
}

void BoardDriver::upload(const std::vector<FloatBox>& boxes) {
    const auto n = static_cast<uint32_t>(boxes.size());
    if (n == 0) return;
    // In the board's format: float32 bit patterns, or fixed-point codes over
    // the frame's bounds, rounded outward.
    const Quantiser quantiser(format_, boxes);
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        quantiser.write_column(boxes, c, reinterpret_cast<uint32_t*>(port_.memory(coordinate_area(capacity_, c))));
    }
    auto local = [](uint32_t c) {
        return static_cast<uint32_t>(address_map::kCoordinateBase + c * address_map::kWindowSize);
    };
    if (config_.transfer != Transfer::kDma) {
        cpu_work(config_.call_ns + config_.ns_per_box * n);  // packing, done natively above
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            pio_write(local(c), port_.memory(coordinate_area(capacity_, c)), 4 * n);
        }
        charge(kUpload);
        return;
    }
    // One scatter-gather chain of six descriptors: one set-up, one interrupt.
    const uint64_t chain = descriptor_area(capacity_, buffer_depth_);
    auto* descriptors = reinterpret_cast<DmaDescriptor*>(port_.memory(chain));
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        const uint64_t next = c + 1 < kCoordinates ? chain + (c + 1) * sizeof(DmaDescriptor) : 0;
        descriptors[c] = DmaDescriptor{coordinate_area(capacity_, c), next, local(c), 4 * n};
    }
    cpu_work(config_.call_ns + config_.ns_per_box * n);  // packing and the chain, done natively above
    write(D::kBase + D::kChainLo, static_cast<uint32_t>(chain));
    write(D::kBase + D::kChainHi, static_cast<uint32_t>(chain >> 32));
    run_dma(D::kChain, time_->upload_worst_ns(n));
    charge(kUpload);
}

uint32_t BoardDriver::wait_for_board(uint32_t objects) {
    const SimTime started = mark_;
    const SimTime timeout = timeout_for(time_->board_worst_ns(objects));
    const uint32_t status = wait_for(R::kStatus, R::kDone | R::kOverflow | R::kError, timeout, "board");
    mark_ = noticed_;
    if (config_.wait == WaitMode::kIrq) write(R::kControl, R::kAcknowledge);
    if (status & R::kError) {
        throw DeviceFault(std::string("board error status: ") + R::describe(read(R::kErrorCause)));
    }
    // The segment from the command to noticing the board is its compute time
    // (cycles x period) plus the notification's lag.
    const uint64_t cycles = read_counter(R::kCyclesLo);
    const double segment = ns_from_fs(mark_ - started);
    const double compute = ns_from_fs(period_ * (cycles - cycles_seen_));
    cycles_seen_ = cycles;
    spent_[kCompute] += compute;
    spent_[kIrq] += segment - compute;
    return status;
}

void BoardDriver::read_pairs(PairList& pairs) {
    const uint32_t count = read(R::kPairCount);
    if (count == 0) return;
    config_.pair_budget.check(uint64_t{pairs.size()} + count);
    const uint64_t area = pair_area(capacity_);
    if (config_.transfer == Transfer::kDma) {
        dma(area, static_cast<uint32_t>(address_map::kPairBuffer), 8 * count, true);
    } else {
        pio_read(address_map::kPairBuffer, port_.memory(area), 8 * count);
    }
    charge(kReadback);
    const auto* words = reinterpret_cast<const uint32_t*>(port_.memory(area));
    for (uint32_t k = 0; k < count; ++k) pairs.push_back({words[2 * k], words[2 * k + 1]});
    cpu_work(config_.ns_per_pair * count);
}

FramePhases BoardDriver::run_frame(const std::vector<FloatBox>& boxes, PairList& pairs) {
    if (boxes.size() > capacity_) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) + " boxes exceeds the board's capacity of " +
                                    std::to_string(capacity_));
    }
    try {
        return frame(boxes, pairs);
    } catch (const std::exception&) {
        pairs.clear();  // never a partial set
        recover();
        throw;
    }
}

void BoardDriver::recover() {
    try {
        write(D::kBase + D::kControl, D::kAbort);
        write(R::kControl, R::kAbort);
        // Let an aborted transfer's engine settle before the next frame.
        port_.wait(0);
        port_.wait(0);
    } catch (const DeviceFault&) {
        // The next frame's accesses report the board's state.
    }
}

FramePhases BoardDriver::frame(const std::vector<FloatBox>& boxes, PairList& pairs) {
    pairs.clear();
    for (double& s : spent_) s = 0;
    const SimTime frame_start = port_.now();
    mark_ = frame_start;
    cycles_seen_ = 0;
    timeouts_recovered_ = 0;
    FramePhases phases;

    upload(boxes);
    write(R::kObjectCount, static_cast<uint32_t>(boxes.size()));
    write(R::kControl, R::kStart);
    charge(kStart);
    for (;;) {
        const uint32_t status = wait_for_board(static_cast<uint32_t>(boxes.size()));
        read_pairs(pairs);
        if (status & R::kOverflow) {
            ++phases.overflow_pauses;
            write(R::kControl, R::kResume);
            charge(kReadback);
            continue;
        }
        if (status & R::kDone) break;
        throw DeviceFault("board interrupt with unexpected status " + hex(status));
    }
    phases.compute_cycles = cycles_seen_;
    phases.stall_cycles = read_counter(R::kStallsLo);
    const uint64_t found = read_counter(R::kTotalPairsLo);
    charge(kReadback);
    if (found != pairs.size()) {
        throw DeviceFault("the board found " + std::to_string(found) + " pairs but " + std::to_string(pairs.size()) +
                          " were read back");
    }
    phases.upload_ns = spent_[kUpload];
    phases.start_ns = spent_[kStart];
    phases.compute_ns = spent_[kCompute];
    phases.irq_ns = spent_[kIrq];
    phases.readback_ns = spent_[kReadback];
    phases.driver_ns = spent_[kDriver];
    phases.total_ns = ns_from_fs(port_.now() - frame_start);
    phases.timeouts_recovered = timeouts_recovered_;
    return phases;
}

}  // namespace cdvp
