#include "platform/driver/analytic_frame.h"

#include <algorithm>

#include "models/address_generator/address_generator.h"
#include "models/address_generator/sweep_schedule.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/pci/dma_registers.h"

namespace cdvp {

namespace {
uint64_t ceil_div(uint64_t a, uint64_t b) { return (a + b - 1) / b; }
}  // namespace

AnalyticFrame::AnalyticFrame(const DriverConfig& driver, const BusTiming& bus, const AnalyticBoard& board)
    : driver_(driver), bus_(bus), board_(board) {
    board_.buffer_depth = std::max<uint32_t>(board_.buffer_depth, 1);
    board_.drain_per_cycle = std::max<uint32_t>(board_.drain_per_cycle, 1);
}

// The bus annotates words x the per-word time as one delay (PciBus).
SimTime AnalyticFrame::read_fs(uint64_t words) const {
    return fs_from_ns(static_cast<double>(words) * bus_.pio_read_ns());
}

SimTime AnalyticFrame::write_fs(uint64_t words) const {
    return fs_from_ns(static_cast<double>(words) * bus_.pio_write_ns());
}

// Polls read at R, R + (R + g), ... after the command; a read sees the
// state at its end. Between two polls the driver waits the poll gap, or a
// board period on an untimed gap.
SimTime AnalyticFrame::notice_fs(SimTime event_fs) const {
    if (driver_.wait == WaitMode::kIrq) return event_fs + fs_from_ns(bus_.interrupt_ns());
    const SimTime gap_fs = fs_from_ns(driver_.poll_gap_ns);
    const SimTime read = read_fs(), period = read + (gap_fs > 0 ? gap_fs : board_.period_fs);
    return read + (event_fs > read ? ceil_div(event_fs - read, period) : 0) * period;
}

// Four set-up registers and the control write, the wait, the status read
// and the write that clears it (BoardDriver::dma and run_dma).
SimTime AnalyticFrame::dma_fs(uint64_t bytes, Direction direction) const {
    return 5 * write_fs() + notice_fs(fs_from_ns(bus_.dma_ns(bytes, direction))) + status_read_fs() + write_fs();
}

// DMA: one chain of six descriptors, each fetched (a 24-byte read) before
// its array moves; the chain registers, control, wait, status, clear.
// PIO: each coordinate array is one access of `objects` words.
SimTime AnalyticFrame::upload_fs(uint32_t objects) const {
    if (objects == 0) return 0;
    if (driver_.transfer != Transfer::kDma) return kCoordinates * write_fs(objects);
    double chain_ns = 0;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        chain_ns += bus_.dma_ns(sizeof(DmaDescriptor), Direction::kToBoard);
        chain_ns += bus_.dma_ns(4 * uint64_t{objects}, Direction::kToBoard);
    }
    return 3 * write_fs() + notice_fs(fs_from_ns(chain_ns)) + status_read_fs() + write_fs();
}

uint64_t AnalyticFrame::sweep_slots(uint32_t objects) const {
    return board_.tiles.tiled() ? SweepSchedule(board_.m, board_.tiles, objects).slots()
                                : AddressGenerator::sweep_cycles(objects, board_.m);
}

uint64_t AnalyticFrame::fifo_stall_estimate(uint64_t slots, uint64_t pairs) const {
    const uint64_t drain_edges = ceil_div(pairs, board_.drain_per_cycle);
    return drain_edges > slots ? drain_edges - slots : 0;
}

FramePhases AnalyticFrame::estimate(const std::vector<FloatBox>& boxes) {
    return estimate(static_cast<uint32_t>(boxes.size()), counter_.count(boxes));
}

FramePhases AnalyticFrame::estimate(uint32_t objects, uint64_t pairs) const {
    const uint64_t depth = board_.buffer_depth;
    // Each pause comes when a pair must move into a full buffer: every
    // segment but the last reads a full buffer back.
    const uint64_t pauses = pairs == 0 ? 0 : (pairs - 1) / depth;
    const uint64_t segments = pauses + 1;
    const uint64_t slots = sweep_slots(objects);
    const uint64_t stalls = fifo_stall_estimate(slots, pairs) + pauses;  // a pause's edge is a stall
    const uint64_t cycles = slots + board_.pipeline_latency + stalls;

    SimTime upload = 0, start = 0, compute = 0, irq = 0, readback = 0, driver = 0;
    if (objects > 0) driver += cpu_fs(driver_.call_ns + driver_.ns_per_box * objects);
    upload += upload_fs(objects);
    start += 2 * write_fs();  // the object count and START
    const SimTime board_ack = driver_.wait == WaitMode::kIrq ? write_fs() : 0;
    for (uint64_t k = 0; k < segments; ++k) {
        // The segments' cycles are not known one by one: spread evenly.
        const uint64_t segment_cycles = cycles / segments + (k + 1 == segments ? cycles % segments : 0);
        const SimTime busy = segment_cycles * board_.period_fs;
        compute += busy;
        irq += notice_fs(busy) - busy;
        // Status, acknowledge, the CYCLES counter, PAIR_COUNT.
        readback += status_read_fs() + board_ack + 2 * read_fs() + read_fs();
        const uint64_t count = k + 1 < segments ? depth : pairs - pauses * depth;
        if (count > 0) {
            readback += driver_.transfer == Transfer::kDma ? dma_fs(8 * count, Direction::kToHost) : read_fs(2 * count);
            driver += cpu_fs(driver_.ns_per_pair * static_cast<double>(count));
        }
        if (k + 1 < segments) readback += write_fs();  // RESUME
    }
    readback += 4 * read_fs();  // the STALLS and TOTAL_PAIRS counters

    FramePhases phases;
    phases.upload_ns = ns_from_fs(upload);
    phases.start_ns = ns_from_fs(start);
    phases.compute_ns = ns_from_fs(compute);
    phases.irq_ns = ns_from_fs(irq);
    phases.readback_ns = ns_from_fs(readback);
    phases.driver_ns = ns_from_fs(driver);
    phases.total_ns = ns_from_fs(upload + start + compute + irq + readback + driver);
    phases.compute_cycles = cycles;
    phases.stall_cycles = stalls;
    phases.overflow_pauses = static_cast<uint32_t>(pauses);
    phases.boxes_sent = objects;
    phases.upload_bytes = uint64_t{24} * objects;
    phases.readback_bytes = 8 * pairs;
    return phases;
}

}  // namespace cdvp
