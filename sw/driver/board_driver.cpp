#include "sw/driver/board_driver.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include "models/comparison_unit/comparison_unit.h"
#include "models/common/transaction.h"
#include "models/control_registers/control_registers.h"
#include "models/pci/pci_bridge.h"
#include "platform/host_memory.h"

namespace cdvp {

using namespace sc_core;
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
}  // namespace

uint64_t BoardDriver::host_memory_bytes(uint32_t capacity, uint32_t buffer_depth) {
    return descriptor_area(capacity, buffer_depth) + kCoordinates * sizeof(DmaDescriptor);
}

BoardDriver::BoardDriver(Transport pio, HostMemory& memory, const sc_event& interrupt, const sc_time& period,
                         const DriverConfig& config)
    : pio_(std::move(pio)), memory_(memory), interrupt_(interrupt), period_(period), config_(config) {}

void BoardDriver::pio(tlm::tlm_command command, uint64_t address, void* data, unsigned int length) {
    tlm::tlm_generic_payload p;
    prepare_transaction(p, command, address, data, length);
    sc_time delay = SC_ZERO_TIME;
    pio_(p, delay);
    wait(delay);
    if (p.is_response_error()) {
        throw std::runtime_error("board access at offset " + std::to_string(address) + " failed: " +
                                 p.get_response_string());
    }
}

uint32_t BoardDriver::read(uint64_t address) {
    uint32_t value = 0;
    pio(tlm::TLM_READ_COMMAND, address, &value, 4);
    return value;
}

void BoardDriver::write(uint64_t address, uint32_t value) { pio(tlm::TLM_WRITE_COMMAND, address, &value, 4); }

uint64_t BoardDriver::read_counter(uint32_t low_offset) {
    const uint64_t low = read(low_offset);
    return low | uint64_t{read(low_offset + 4)} << 32;
}

void BoardDriver::open() {
    if (read(R::kId) != R::kIdValue) throw std::runtime_error("no collision board answers at the BAR");
    capacity_ = read(R::kCapacity);
    buffer_depth_ = read(R::kPairBufferDepth);
    if (memory_.size() < host_memory_bytes(capacity_, buffer_depth_)) {
        throw std::runtime_error("host memory too small for the board's capacity and pair buffer");
    }
}

void BoardDriver::charge(Phase phase) {
    spent_[phase] += (sc_time_stamp() - mark_).to_seconds() * 1e9;
    mark_ = sc_time_stamp();
}

void BoardDriver::cpu_work(double ns) {
    if (ns > 0) wait(sc_time(ns, SC_NS));
    charge(kDriver);
}

// Between two polls: the configured gap, and never no time at all (on an
// untimed bus a poll costs nothing, and the loop would not let time pass).
void BoardDriver::poll_pause() {
    const sc_time gap(config_.poll_gap_ns, SC_NS);
    wait(gap > SC_ZERO_TIME ? gap : period_);
}

// Starts the bridge's DMA engine (registers already set) and waits for it
// by interrupt or polling.
void BoardDriver::run_dma(uint32_t control) {
    write(D::kBase + D::kControl,
          control | D::kStart | (config_.use_interrupts ? uint32_t{D::kInterruptOnDone} : 0u));
    for (;;) {
        if (config_.use_interrupts) wait(interrupt_);
        else poll_pause();
        if (read(D::kBase + D::kStatus) & D::kDone) break;
    }
    write(D::kBase + D::kStatus, D::kDone);  // clear done: the shared line falls
}

void BoardDriver::dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host) {
    write(D::kBase + D::kHostAddressLo, static_cast<uint32_t>(host_address));
    write(D::kBase + D::kHostAddressHi, static_cast<uint32_t>(host_address >> 32));
    write(D::kBase + D::kLocalAddress, local_address);
    write(D::kBase + D::kBytes, bytes);
    run_dma(to_host ? uint32_t{D::kToHost} : 0u);
}

void BoardDriver::upload(const std::vector<FloatBox>& boxes) {
    const auto n = static_cast<uint32_t>(boxes.size());
    if (n == 0) return;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        auto* words = reinterpret_cast<uint32_t*>(memory_.data(coordinate_area(capacity_, c)));
        for (uint32_t i = 0; i < n; ++i) {
            words[i] = ComparisonUnit::as_bits(c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3]);
        }
    }
    auto local = [](uint32_t c) {
        return static_cast<uint32_t>(address_map::kCoordinateBase + c * address_map::kWindowSize);
    };
    if (!config_.use_dma) {
        cpu_work(config_.call_ns + config_.ns_per_box * n);  // packing, done natively above
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            pio(tlm::TLM_WRITE_COMMAND, local(c), memory_.data(coordinate_area(capacity_, c)), 4 * n);
        }
        charge(kUpload);
        return;
    }
    // One scatter-gather chain of six descriptors: one set-up, one interrupt.
    const uint64_t chain = descriptor_area(capacity_, buffer_depth_);
    auto* descriptors = reinterpret_cast<DmaDescriptor*>(memory_.data(chain));
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        const uint64_t next = c + 1 < kCoordinates ? chain + (c + 1) * sizeof(DmaDescriptor) : 0;
        descriptors[c] = DmaDescriptor{coordinate_area(capacity_, c), next, local(c), 4 * n};
    }
    cpu_work(config_.call_ns + config_.ns_per_box * n);  // packing and the chain, done natively above
    write(D::kBase + D::kChainLo, static_cast<uint32_t>(chain));
    write(D::kBase + D::kChainHi, static_cast<uint32_t>(chain >> 32));
    run_dma(D::kChain);
    charge(kUpload);
}

uint32_t BoardDriver::wait_for_board() {
    const sc_time started = mark_;
    uint32_t status = 0;
    if (config_.use_interrupts) {
        wait(interrupt_);
        mark_ = sc_time_stamp();
        status = read(R::kStatus);
        write(R::kControl, R::kAcknowledge);
    } else {
        constexpr uint32_t kEvents = R::kDone | R::kOverflow | R::kError;
        while (!((status = read(R::kStatus)) & kEvents)) poll_pause();
        mark_ = sc_time_stamp();
    }
    // The segment from the command to noticing the board is its compute time
    // (cycles x period) plus the notification's lag.
    const uint64_t cycles = read_counter(R::kCyclesLo);
    const double segment = (mark_ - started).to_seconds() * 1e9;
    const double compute = (period_ * static_cast<double>(cycles - cycles_seen_)).to_seconds() * 1e9;
    cycles_seen_ = cycles;
    spent_[kCompute] += compute;
    spent_[kIrq] += segment - compute;
    return status;
}

void BoardDriver::read_pairs(PairList& pairs) {
    const uint32_t count = read(R::kPairCount);
    if (count == 0) return;
    const uint64_t area = pair_area(capacity_);
    if (config_.use_dma) {
        dma(area, static_cast<uint32_t>(address_map::kPairBuffer), 8 * count, true);
    } else {
        pio(tlm::TLM_READ_COMMAND, address_map::kPairBuffer, memory_.data(area), 8 * count);
    }
    charge(kReadback);
    const auto* words = reinterpret_cast<const uint32_t*>(memory_.data(area));
    for (uint32_t k = 0; k < count; ++k) pairs.push_back({words[2 * k], words[2 * k + 1]});
    cpu_work(config_.ns_per_pair * count);
}

FramePhases BoardDriver::run_frame(const std::vector<FloatBox>& boxes, PairList& pairs) {
    if (boxes.size() > capacity_) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) + " boxes exceeds the board's capacity of " +
                                    std::to_string(capacity_));
    }
    pairs.clear();
    for (double& s : spent_) s = 0;
    const sc_time frame_start = sc_time_stamp();
    mark_ = frame_start;
    cycles_seen_ = 0;
    FramePhases phases;

    upload(boxes);
    write(R::kObjectCount, static_cast<uint32_t>(boxes.size()));
    write(R::kControl, R::kStart);
    charge(kStart);
    for (;;) {
        const uint32_t status = wait_for_board();
        if (status & R::kError) throw std::runtime_error("the board refused the frame (status error)");
        read_pairs(pairs);
        if (status & R::kOverflow) {
            ++phases.overflow_pauses;
            write(R::kControl, R::kResume);
            charge(kReadback);
            continue;
        }
        if (status & R::kDone) break;
        throw std::runtime_error("board interrupt with unexpected status " + std::to_string(status));
    }
    phases.compute_cycles = cycles_seen_;
    phases.stall_cycles = read_counter(R::kStallsLo);
    const uint64_t found = read_counter(R::kTotalPairsLo);
    charge(kReadback);
    if (found != pairs.size()) {
        throw std::runtime_error("the board found " + std::to_string(found) + " pairs but " +
                                 std::to_string(pairs.size()) + " were read back");
    }
    phases.upload_ns = spent_[kUpload];
    phases.start_ns = spent_[kStart];
    phases.compute_ns = spent_[kCompute];
    phases.irq_ns = spent_[kIrq];
    phases.readback_ns = spent_[kReadback];
    phases.driver_ns = spent_[kDriver];
    phases.total_ns = (sc_time_stamp() - frame_start).to_seconds() * 1e9;
    return phases;
}

}  // namespace cdvp
