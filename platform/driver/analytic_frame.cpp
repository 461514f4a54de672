#include "platform/driver/analytic_frame.h"

#include <algorithm>
#include <cmath>

#include "models/address_generator/address_generator.h"
#include "models/address_generator/sweep_schedule.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"
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

SimTime AnalyticFrame::poll_gap_fs(uint32_t k) const {
    const SimTime gap_fs = fs_from_ns(driver_.poll_gap_ns);
    const SimTime base = gap_fs > 0 ? gap_fs : board_.period_fs;
    if (driver_.poll_backoff <= 1.0) return base;
    const double grown = ns_from_fs(base) * std::pow(driver_.poll_backoff, std::min<uint32_t>(k, 64));
    return fs_from_ns(std::max(ns_from_fs(base), std::min(grown, driver_.poll_gap_max_ns)));
}

// Polls read at R, R + (g0 + R), R + (g0 + R) + (g1 + R), ... after the
// command; a read sees the state at its end. Between two polls the driver
// waits the poll gap (a board period on an untimed gap), growing under
// back-off until it stops growing, from where the polls are evenly spaced.
SimTime AnalyticFrame::notice_fs(SimTime event_fs, bool by_interrupt) const {
    if (by_interrupt) return event_fs + fs_from_ns(bus_.interrupt_ns());
    const SimTime read = read_fs();
    SimTime t = read;
    for (uint32_t k = 0; t < event_fs; ++k) {
        const SimTime gap = poll_gap_fs(k);
        if (k >= 64 || gap == poll_gap_fs(k + 1)) {
            const SimTime period = gap + read;
            return t + ceil_div(event_fs - t, period) * period;
        }
        t += gap + read;
    }
    return t;
}

// Four set-up registers and the control write, the wait, the status read
// and the write that clears it (BoardDriver::dma and run_dma).
SimTime AnalyticFrame::dma_fs(uint64_t bytes, Direction direction) const {
    return 5 * write_fs() + notice_fs(fs_from_ns(bus_.dma_ns(bytes, direction)), dma_by_interrupt()) +
           status_read_fs(dma_by_interrupt()) + write_fs();
}

SimTime AnalyticFrame::chain_fs(double bus_ns) const {
    return 3 * write_fs() + notice_fs(fs_from_ns(bus_ns), dma_by_interrupt()) + status_read_fs(dma_by_interrupt()) +
           write_fs();
}

// DMA: one chain of six descriptors, each fetched (a 24-byte read) before
// its array moves, summed in the bridge's order. PIO: each coordinate array
// is one access of `objects` words.
SimTime AnalyticFrame::upload_fs(uint32_t objects) const {
    if (objects == 0) return 0;
    if (driver_.transfer != Transfer::kDma) return kCoordinates * write_fs(objects);
    return chain_fs(upload_bus_ns(objects));
}

double AnalyticFrame::upload_bus_ns(uint32_t objects) const {
    double chain_ns = 0;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        chain_ns += bus_.dma_ns(sizeof(DmaDescriptor), Direction::kToBoard);
        chain_ns += bus_.dma_ns(4 * uint64_t{objects}, Direction::kToBoard);
    }
    return chain_ns;
}

// The delta stream in window-sized pieces: one access each by PIO, one
// descriptor each in the DMA chain.
SimTime AnalyticFrame::delta_fs(uint64_t records) const {
    if (records == 0) return 0;
    const uint64_t words = uint64_t{address_map::kDeltaRecordWords} * records;
    if (driver_.transfer != Transfer::kDma) {
        SimTime fs = 0;
        for (uint64_t left = words; left > 0;) {
            const uint64_t piece = std::min<uint64_t>(left, address_map::kDeltaStreamSize / 4);
            fs += write_fs(piece);
            left -= piece;
        }
        return fs;
    }
    return chain_fs(delta_upload_bus_ns(bus_, Transfer::kDma, records));
}

uint64_t AnalyticFrame::sweep_slots(uint32_t objects) const {
    if (listed_slots_ != nullptr) return listed_end_;
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

AnalyticFrame::SweepPlan AnalyticFrame::sweep_plan(uint32_t objects, uint64_t pairs) const {
    SweepPlan plan;
    plan.pairs = pairs;
    plan.depth = board_.buffer_depth;
    plan.pauses = pairs == 0 ? 0 : (pairs - 1) / plan.depth;
    const uint64_t slots = sweep_slots(objects);
    plan.stalls = fifo_stall_estimate(slots, pairs) + plan.pauses;
    plan.cycles = slots + board_.pipeline_latency + plan.stalls;
    return plan;
}

// Pair q of the sweep (board order) enters the pair FIFO on the edge after
// its slot c_q reaches the collector: edge c_q + L of the advancing edges
// (L = the pipeline's latency). The pause that ends segment k waits on pair
// q = (k + 1) B, the first that finds the buffer full: it comes on the edge
// after both that pair has entered the FIFO and pair q - 1 has moved into
// the buffer. The drain moves d pairs an edge from the first pair's
// arrival, so pair q - 1 has moved by edge c_0 + L + ceil(q / d) at the
// earliest (a fluid bound, exact while the FIFO does not back up). Each
// earlier pause's edge is one more edge before it.
AnalyticFrame::SweepPlan AnalyticFrame::sweep_plan(uint32_t objects, const PairList& pairs) const {
    SweepPlan plan = sweep_plan(objects, pairs.size());
    if (plan.pauses == 0) return plan;
    const SweepSchedule schedule(board_.m, board_.tiles, listed_slots_ != nullptr ? 0 : objects);
    const auto slot_of = [&](uint64_t q) {
        return listed_slots_ != nullptr ? (*listed_slots_)[q] : schedule.pair_slot(pairs[q].first, pairs[q].second);
    };
    const uint64_t latency = board_.pipeline_latency;
    const uint64_t first_entry = slot_of(0) + latency;
    plan.pause_edges.resize(plan.pauses);
    uint64_t previous = 0;
    for (uint64_t k = 0; k < plan.pauses; ++k) {
        const uint64_t q = (k + 1) * plan.depth;
        const uint64_t entry = slot_of(q) + latency;
        const uint64_t drained = first_entry + ceil_div(q, board_.drain_per_cycle);
        // Within the sweep's cycles, one edge at least after the pause before, one left for each after.
        const uint64_t edge = std::max(entry, drained) + 1 + k;
        plan.pause_edges[k] = std::min(std::max(edge, previous + 1), plan.cycles - (plan.pauses - k));
        previous = plan.pause_edges[k];
    }
    return plan;
}

uint64_t AnalyticFrame::UploadPlan::bytes() const {
    return (delta ? 4 * uint64_t{address_map::kDeltaRecordWords} : 24) * sent;
}

AnalyticFrame::UploadPlan AnalyticFrame::upload_plan(uint32_t objects, uint64_t changed) const {
    const bool delta = objects > 0 && upload_as_delta(driver_, bus_, objects, changed);
    return {delta, delta ? changed : objects};
}

FramePhases AnalyticFrame::estimate(uint32_t objects, uint64_t pairs) const {
    return estimate_with(objects, sweep_plan(objects, pairs), UploadPlan{false, objects},
                         [](uint64_t, uint64_t count) { return 2 * count; });
}

FramePhases AnalyticFrame::estimate(uint32_t objects, const PairList& pairs, uint64_t changed) const {
    const uint64_t depth = board_.buffer_depth;
    return estimate_with(objects, sweep_plan(objects, pairs), upload_plan(objects, changed),
                         [&](uint64_t k, uint64_t count) {
                             return encoded_words(driver_.pair_format, pairs.data() + k * depth, count, objects);
                         });
}

template <class Words>
FramePhases AnalyticFrame::estimate_with(uint32_t objects, const SweepPlan& sweep, const UploadPlan& sent,
                                         Words words_of) const {
    const uint64_t segments = sweep.segments();
    SimTime upload = 0, start = 0, compute = 0, irq = 0, readback = 0, driver = 0;
    if (objects > 0) driver += cpu_fs(driver_.call_ns + driver_.ns_per_box * objects);
    upload += sent.delta ? delta_fs(sent.sent) : upload_fs(objects);
    start += 2 * write_fs();  // the object count and START
    const bool board_irq = board_by_interrupt();
    const SimTime board_ack = board_irq ? write_fs() : 0;
    const bool list = driver_.pair_format == PairFormat::kList;
    uint64_t readback_bytes = 0;
    for (uint64_t k = 0; k < segments; ++k) {
        const SimTime busy = sweep.segment_cycles(k) * board_.period_fs;
        compute += busy;
        irq += notice_fs(busy, board_irq) - busy;
        // Status, acknowledge, the CYCLES counter, PAIR_COUNT.
        readback += status_read_fs(board_irq) + board_ack + 2 * read_fs() + read_fs();
        const uint64_t count = sweep.segment_pairs(k);
        if (count > 0) {
            const uint64_t words = words_of(k, count);
            if (!list) readback += read_fs();  // PAIR_WORDS
            readback += driver_.transfer == Transfer::kDma ? dma_fs(4 * words, Direction::kToHost) : read_fs(words);
            readback_bytes += 4 * words;
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
    phases.latency_ns = phases.total_ns;  // one frame at a time
    phases.compute_cycles = sweep.cycles;
    phases.stall_cycles = sweep.stalls;
    phases.overflow_pauses = static_cast<uint32_t>(sweep.pauses);
    phases.boxes_sent = static_cast<uint32_t>(sent.sent);
    phases.upload_bytes = sent.bytes();
    phases.readback_bytes = readback_bytes;
    return phases;
}

}  // namespace cdvp
