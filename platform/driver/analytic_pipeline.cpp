#include "platform/driver/analytic_pipeline.h"

#include <algorithm>

#include "models/control_registers/control_registers.h"
#include "models/pair_collector/pair_format.h"
#include "platform/driver/frame_time.h"

namespace cdvp {

std::optional<FramePhases> AnalyticPipeline::submit(uint32_t objects, const PairList& pairs, uint64_t changed) {
    const AnalyticFrame& a = frame_;
    const DriverConfig& driver = a.driver_;
    Flight next;
    next.objects = objects;
    next.began = now_;
    // The sweep as AnalyticFrame sees it: segments of the pair buffer's
    // depth, the FIFO stalls estimated, a pause's edge a stall.
    const uint64_t depth = a.board_.buffer_depth, p = pairs.size();
    const uint64_t pauses = p == 0 ? 0 : (p - 1) / depth;
    const uint64_t slots = a.sweep_slots(objects);
    const uint64_t stalls = a.fifo_stall_estimate(slots, p) + pauses;
    next.cycles = slots + a.board_.pipeline_latency + stalls;
    for (uint64_t k = 0; k <= pauses; ++k) {
        const uint64_t count = k < pauses ? depth : p - pauses * depth;
        next.counts.push_back(count);
        next.words.push_back(count == 0 ? 0 : encoded_words(driver.pair_format, pairs.data() + k * depth, count, objects));
    }
    next.phases.compute_cycles = next.cycles;
    next.phases.stall_cycles = stalls;
    next.phases.overflow_pauses = static_cast<uint32_t>(pauses);

    // Packing the boxes, then uploading them into the host's bank while the
    // board sweeps the frame in flight.
    if (objects > 0) {
        spend(next, kDriver, AnalyticFrame::cpu_fs(driver.call_ns + driver.ns_per_box * objects));
        const bool delta = upload_as_delta(driver, a.bus_, objects, changed);
        const uint64_t sent = delta ? changed : objects;
        SimTime upload = delta ? a.delta_fs(sent) : a.upload_fs(objects);
        if (in_flight_ && sent > 0 && driver.transfer == Transfer::kDma && a.dma_by_interrupt()) {
            // The chain's wait beside the sweep in flight, whose interrupt may wake it first.
            const double bus_ns = delta ? delta_upload_bus_ns(a.bus_, Transfer::kDma, sent) : a.upload_bus_ns(objects);
            const SimTime wait_from = now_ + 3 * a.write_fs();
            upload = 3 * a.write_fs() + dma_wait_beside(wait_from, fs_from_ns(bus_ns), first_event(*in_flight_)) -
                     wait_from + a.write_fs();
        }
        spend(next, kUpload, upload);
        next.phases.boxes_sent = static_cast<uint32_t>(sent);
        next.phases.upload_bytes = (delta ? 4 * uint64_t{address_map::kDeltaRecordWords} : 24) * sent;
    }
    std::optional<FramePhases> finished;
    if (in_flight_) finish_sweep(*in_flight_, true);
    spend(next, kStart, 2 * a.write_fs());  // the object count and START
    next.segment_start = now_;
    if (in_flight_) {
        // The finished frame's last pairs, from the previous pair buffer, while the new frame sweeps.
        show_pair_bank(true, *in_flight_);
        read_pairs(*in_flight_, in_flight_->counts.size() - 1);
        finished = close(*in_flight_);
    }
    in_flight_ = std::move(next);
    return finished;
}

std::optional<FramePhases> AnalyticPipeline::finish() {
    if (!in_flight_) return std::nullopt;
    finish_sweep(*in_flight_, false);
    const FramePhases phases = close(*in_flight_);
    in_flight_.reset();
    return phases;
}

void AnalyticPipeline::finish_sweep(Flight& f, bool defer_last) {
    const AnalyticFrame& a = frame_;
    const bool by_interrupt = a.board_by_interrupt();
    const uint64_t segments = f.counts.size();
    for (uint64_t k = 0; k < segments; ++k) {
        const uint64_t cycles = f.cycles / segments + (k + 1 == segments ? f.cycles % segments : 0);
        const SimTime busy = cycles * a.board_.period_fs;
        const SimTime done = f.segment_start + busy;
        const SimTime waiting_from = now_;
        SimTime noticed = 0;
        if (by_interrupt) {
            // The first wait reads STATUS before waiting (the sweep may have
            // ended while the host uploaded); a read sees the state at its end.
            const bool looked_first = k == 0;
            if (looked_first && done <= now_ + a.read_fs()) {
                noticed = now_;
            } else {
                const SimTime from = looked_first ? now_ + a.read_fs() : now_;
                noticed = std::max(from, done + fs_from_ns(a.bus_.interrupt_ns()));
            }
        } else {
            // Polls from here on, the first at once.
            noticed = waiting_from + a.notice_fs(done > waiting_from ? done - waiting_from : 0, false);
        }
        now_ = noticed;
        // The part of the sweep the wait saw is compute, the rest of the wait
        // the notification's lag; the sweep before the wait was hidden.
        const SimTime waited = noticed - waiting_from;
        const SimTime ran_before = waiting_from > f.segment_start ? waiting_from - f.segment_start : 0;
        const SimTime exposed = std::min(busy > ran_before ? busy - ran_before : 0, waited);
        f.spent[kCompute] += exposed;
        f.spent[kIrq] += waited - exposed;
        f.phases.overlap_ns += ns_from_fs(busy - exposed);
        // Status (under interrupts), acknowledge, the CYCLES counter.
        spend(f, kReadback, a.status_read_fs(by_interrupt) + (by_interrupt ? a.write_fs() : 0) + 2 * a.read_fs());
        if (k + 1 < segments) {
            show_pair_bank(false, f);
            read_pairs(f, k);
            spend(f, kReadback, a.write_fs());  // RESUME
            f.segment_start = now_;
        } else if (!defer_last) {
            show_pair_bank(false, f);
            read_pairs(f, k);
        }
    }
    spend(f, kReadback, 4 * a.read_fs());  // the STALLS and TOTAL_PAIRS counters
}

SimTime AnalyticPipeline::first_event(const Flight& f) const {
    return f.segment_start + f.cycles / f.counts.size() * frame_.board_.period_fs;
}

// BoardDriver::wait_for on a DMA under interrupts while a sweep runs: STATUS
// read (and the board's interrupt acknowledged) first, during the transfer;
// then the first interrupt wakes the host. The DMA's own comes its end plus
// the interrupt's lag after; the board's, when it comes first, has the host
// read the DMA's status early (and, not done yet, acknowledge the board and
// look again, then wait since that look).
SimTime AnalyticPipeline::dma_wait_beside(SimTime wait_from, SimTime transfer, SimTime board_event) const {
    const AnalyticFrame& a = frame_;
    const SimTime read = a.read_fs(), write = a.write_fs(), lag = fs_from_ns(a.bus_.interrupt_ns());
    const SimTime dma_end = wait_from + transfer;
    SimTime t = wait_from + read;
    const bool board_pending = board_event <= t;
    if (board_pending) t += write;  // acknowledged before the wait: the line stays free for the DMA
    const SimTime board_irq = board_event + lag, dma_irq = dma_end + lag;
    if (board_pending || board_irq >= dma_irq || board_irq < t) return std::max(t, dma_irq) + read;
    t = board_irq + read;  // woken by the board: the DMA's status
    if (dma_end <= t) return t;
    t += read + write;  // the board's interrupt acknowledged
    t += read;          // the DMA's status again
    if (dma_end <= t) return t;
    const SimTime looked = t - read;
    t += read;  // STATUS: nothing new
    return std::max(t, std::max(looked, dma_irq)) + read;
}

void AnalyticPipeline::read_pairs(Flight& f, uint64_t segment) {
    const AnalyticFrame& a = frame_;
    const DriverConfig& driver = a.driver_;
    spend(f, kReadback, a.read_fs());  // PAIR_COUNT
    const uint64_t count = f.counts[segment];
    if (count == 0) return;
    const uint64_t words = f.words[segment];
    if (driver.pair_format != PairFormat::kList) spend(f, kReadback, a.read_fs());  // PAIR_WORDS
    if (driver.transfer == Transfer::kDma) {
        spend(f, kReadback, a.dma_fs(4 * words, Direction::kToHost));
    } else {
        spend(f, kReadback, a.read_fs(words));
    }
    f.phases.readback_bytes += 4 * words;
    spend(f, kDriver, AnalyticFrame::cpu_fs(driver.ns_per_pair * static_cast<double>(count)));
}

void AnalyticPipeline::show_pair_bank(bool previous, Flight& f) {
    if (showing_previous_ == previous) return;
    spend(f, kReadback, frame_.write_fs());
    showing_previous_ = previous;
}

FramePhases AnalyticPipeline::close(Flight& f) const {
    FramePhases phases = f.phases;
    phases.upload_ns = ns_from_fs(f.spent[kUpload]);
    phases.start_ns = ns_from_fs(f.spent[kStart]);
    phases.compute_ns = ns_from_fs(f.spent[kCompute]);
    phases.irq_ns = ns_from_fs(f.spent[kIrq]);
    phases.readback_ns = ns_from_fs(f.spent[kReadback]);
    phases.driver_ns = ns_from_fs(f.spent[kDriver]);
    SimTime charged = 0;
    for (SimTime spent : f.spent) charged += spent;
    phases.total_ns = ns_from_fs(charged);  // the host's time on this frame
    phases.latency_ns = ns_from_fs(now_ - f.began);
    return phases;
}

}  // namespace cdvp
