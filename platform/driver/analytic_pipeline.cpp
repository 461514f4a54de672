#include "platform/driver/analytic_pipeline.h"

#include <algorithm>

#include "models/pair_collector/pair_format.h"
#include "platform/driver/frame_time.h"

namespace cdvp {

AnalyticPipeline::AnalyticPipeline(const AnalyticFrame& frame)
    : frame_(frame), read_(frame.read_fs()), write_(frame.write_fs()), lag_(fs_from_ns(frame.bus_.interrupt_ns())) {}

std::optional<FramePhases> AnalyticPipeline::submit(uint32_t objects, const PairList& pairs, uint64_t changed) {
    const AnalyticFrame& a = frame_;
    const DriverConfig& driver = a.driver_;
    Flight next;
    next.objects = objects;
    next.began = now_;
    next.sweep = a.sweep_plan(objects, pairs);
    for (uint64_t k = 0; k < next.sweep.segments(); ++k) {
        const uint64_t count = next.sweep.segment_pairs(k);
        const IndexPair* first = pairs.data() + k * next.sweep.depth;
        next.words.push_back(count == 0 ? 0 : encoded_words(driver.pair_format, first, count, objects));
    }
    next.phases.compute_cycles = next.sweep.cycles;
    next.phases.stall_cycles = next.sweep.stalls;
    next.phases.overflow_pauses = static_cast<uint32_t>(next.sweep.pauses);

    // Packing the boxes, then uploading them into the host's bank while the
    // board sweeps the frame in flight.
    if (objects > 0) {
        spend(next, kDriver, AnalyticFrame::cpu_fs(driver.call_ns + driver.ns_per_box * objects));
        const AnalyticFrame::UploadPlan sent = a.upload_plan(objects, changed);
        SimTime upload = 0;
        if (driver.transfer != Transfer::kDma || sent.sent == 0) {
            upload = sent.delta ? a.delta_fs(sent.sent) : a.upload_fs(objects);
        } else {
            // One chain (its address in two registers, then the control write).
            const double bus_ns =
                sent.delta ? delta_upload_bus_ns(a.bus_, Transfer::kDma, sent.sent) : a.upload_bus_ns(objects);
            upload = dma(3, fs_from_ns(bus_ns));
        }
        spend(next, kUpload, upload);
        next.phases.boxes_sent = static_cast<uint32_t>(sent.sent);
        next.phases.upload_bytes = sent.bytes();
    }
    std::optional<FramePhases> finished;
    if (in_flight_) finish_sweep(*in_flight_, true);
    spend(next, kStart, 2 * write_);  // the object count and START
    next.segment_start = now_;
    line_.board_at = now_ + next.sweep.segment_cycles(0) * a.board_.period_fs;
    if (in_flight_) {
        // The finished frame's last pairs, from the previous pair buffer, while the new frame sweeps.
        show_pair_bank(true, *in_flight_);
        read_pairs(*in_flight_, in_flight_->sweep.segments() - 1);
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
    const uint64_t segments = f.sweep.segments();
    for (uint64_t k = 0; k < segments; ++k) {
        const SimTime busy = f.sweep.segment_cycles(k) * a.board_.period_fs;
        const SimTime done = f.segment_start + busy;
        const SimTime waiting_from = now_;
        SimTime noticed = 0, t = now_;
        if (by_interrupt) {
            // BoardDriver::wait_for on STATUS: the first wait reads it before
            // waiting (the sweep may have ended while the host uploaded); a
            // read sees the state at its end.
            const bool check_first = k == 0;
            bool look_now = check_first;
            SimTime looked = t;
            for (uint32_t polls = 0;; ++polls) {
                if (!look_now) {
                    const SimTime at = t;
                    t = polls > 0 || check_first ? notification_since(looked, t) : next_notification(t);
                    if (t == kNever) t = std::max(at, done);  // no notification comes: found by the timeout's look
                }
                look_now = false;
                noticed = looked = t;
                t += read_;
                advance(t);
                if (done <= t) break;
            }
        } else {
            // Polls from here on, the first at once.
            noticed = t = waiting_from + a.notice_fs(done > waiting_from ? done - waiting_from : 0, false);
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
        spend(f, kReadback, t - noticed);  // the status read under interrupts (a poll's is in the wait)
        if (by_interrupt) {
            spend(f, kReadback, write_);  // acknowledge
            advance(now_);
            line_.board_high = false;
        }
        spend(f, kReadback, 2 * read_);  // the CYCLES counter
        if (k + 1 < segments) {
            show_pair_bank(false, f);
            read_pairs(f, k);
            spend(f, kReadback, write_);  // RESUME
            f.segment_start = now_;
            line_.board_at = now_ + f.sweep.segment_cycles(k + 1) * a.board_.period_fs;
        } else if (!defer_last) {
            show_pair_bank(false, f);
            read_pairs(f, k);
        }
    }
    spend(f, kReadback, 4 * read_);  // the STALLS and TOTAL_PAIRS counters
}

void AnalyticPipeline::read_pairs(Flight& f, uint64_t segment) {
    const DriverConfig& driver = frame_.driver_;
    spend(f, kReadback, read_);  // PAIR_COUNT
    const uint64_t count = f.sweep.segment_pairs(segment);
    if (count == 0) return;
    const uint64_t words = f.words[segment];
    if (driver.pair_format != PairFormat::kList) spend(f, kReadback, read_);  // PAIR_WORDS
    if (driver.transfer == Transfer::kDma) {
        // Host address (two registers), local address, bytes, then the control write.
        spend(f, kReadback, dma(5, fs_from_ns(frame_.bus_.dma_ns(4 * words, Direction::kToHost))));
    } else {
        spend(f, kReadback, frame_.read_fs(words));
    }
    f.phases.readback_bytes += 4 * words;
    spend(f, kDriver, AnalyticFrame::cpu_fs(driver.ns_per_pair * static_cast<double>(count)));
}

SimTime AnalyticPipeline::dma(uint32_t setup, SimTime transfer) {
    const AnalyticFrame& a = frame_;
    SimTime t = now_ + setup * write_;
    const SimTime end = t + transfer;
    if (!a.dma_by_interrupt()) return setup * write_ + a.notice_fs(transfer, false) + write_;  // polled, then cleared
    // BoardDriver::wait_for on the DMA's status under interrupts. With a
    // frame in flight its sweep's request shares the line: acknowledged
    // first, and again when it is what woke the host.
    line_.dma_at = end;
    const bool shared = in_flight_.has_value();
    const auto acknowledge_board = [&] {
        t += read_;  // STATUS
        advance(t);
        if (!line_.board_high) return false;
        t += write_;
        advance(t);
        line_.board_high = false;
        return true;
    };
    if (shared) acknowledge_board();
    bool look_now = false;
    SimTime looked = t;
    for (uint32_t polls = 0;; ++polls) {
        if (!look_now) {
            const SimTime at = t;
            t = polls > 0 ? notification_since(looked, t) : next_notification(t);
            if (t == kNever) t = std::max(at, end);  // no notification comes: found by the timeout's look
        }
        look_now = false;
        looked = t;
        t += read_;  // the DMA's status
        advance(t);
        if (end <= t) break;
        if (shared) look_now = acknowledge_board();
    }
    t += write_;  // clears the DMA's status
    advance(t);
    line_.dma_high = false;
    return t - now_;
}

void AnalyticPipeline::advance(SimTime t) {
    for (;;) {
        const SimTime next = std::min({line_.pending, line_.board_at, line_.dma_at});
        if (next == kNever || next > t) return;
        if (line_.pending == next) {
            line_.fired = next;
            line_.pending = kNever;
        } else if (line_.board_at == next) {
            line_.board_at = kNever;
            rise(true, next);
        } else {
            line_.dma_at = kNever;
            rise(false, next);
        }
    }
}

// The bus notifies the host one lag after the line rises, unless a
// notification is already on its way (a later one would be dropped for it).
void AnalyticPipeline::rise(bool board, SimTime at) {
    const bool was_high = line_.board_high || line_.dma_high;
    (board ? line_.board_high : line_.dma_high) = true;
    if (!was_high && line_.pending == kNever) line_.pending = at + lag_;
}

SimTime AnalyticPipeline::next_notification(SimTime t) {
    advance(t);
    for (;;) {
        const SimTime next = std::min({line_.pending, line_.board_at, line_.dma_at});
        if (next == kNever) return kNever;  // nothing will come (the driver's timeout finds the event)
        const bool notification = line_.pending == next;
        advance(next);
        if (notification) return next;
    }
}

SimTime AnalyticPipeline::notification_since(SimTime since, SimTime t) {
    advance(t);
    if (line_.fired != kNever && line_.fired >= since && line_.fired != line_.taken) {
        line_.taken = line_.fired;
        return t;
    }
    return next_notification(t);
}

void AnalyticPipeline::show_pair_bank(bool previous, Flight& f) {
    if (showing_previous_ == previous) return;
    spend(f, kReadback, write_);
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
