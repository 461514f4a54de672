#include "platform/driver/analytic_frame.h"

#include <algorithm>

#include "models/address_generator/address_generator.h"
#include "models/address_generator/sweep_schedule.h"
#include "models/common/integer_math.h"
#include "platform/driver/driver_sequence.h"

namespace cdvp {

namespace {
DriverConfig uploading_every_box(DriverConfig driver) {
    driver.upload = UploadMode::kFull;
    return driver;
}
}  // namespace

AnalyticFrame::AnalyticFrame(const DriverConfig& driver, const BusTiming& bus, const AnalyticBoard& board)
    : driver_(driver), full_upload_(uploading_every_box(driver)), bus_(bus), board_(board) {
    board_.buffer_depth = std::max<uint32_t>(board_.buffer_depth, 1);
    board_.drain_per_cycle = std::max<uint32_t>(board_.drain_per_cycle, 1);
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

SweepPlan AnalyticFrame::sweep_plan(uint32_t objects, uint64_t pairs) const {
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
SweepPlan AnalyticFrame::sweep_plan(uint32_t objects, const PairList& pairs) const {
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

FramePhases AnalyticFrame::run(const DriverConfig& driver, const FramePlan& plan) const {
    ClosedForm form(driver, bus_, board_);
    DriverSequence<ClosedForm> sequence(form, driver, board_.period_fs);
    ClosedForm::Pairs read_back;
    return sequence.frame(plan, read_back);
}

FramePhases AnalyticFrame::estimate(uint32_t objects, uint64_t pairs) const {
    return run(full_upload_, FramePlan{objects, objects, sweep_plan(objects, pairs), nullptr});
}

FramePhases AnalyticFrame::estimate(uint32_t objects, const PairList& pairs, uint64_t changed) const {
    return run(driver_, FramePlan{objects, changed, sweep_plan(objects, pairs), pairs.data()});
}

}  // namespace cdvp
