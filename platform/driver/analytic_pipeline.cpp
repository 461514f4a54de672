#include "platform/driver/analytic_pipeline.h"

#include <utility>

namespace cdvp {

AnalyticPipeline::AnalyticPipeline(const AnalyticFrame& frame)
    : frame_(frame),
      form_(frame.driver(), frame.bus(), frame.board()),
      sequence_(form_, frame.driver(), frame.board().period_fs) {
    sequence_.open(2, 0);
}

std::optional<FramePhases> AnalyticPipeline::submit(uint32_t objects, PairList&& pairs, uint64_t changed,
                                                    PairList& finished) {
    Slot& slot = slots_[next_];
    slot.pairs = std::move(pairs);
    slot.plan = FramePlan{objects, changed, frame_.sweep_plan(objects, slot.pairs), slot.pairs.data()};
    FramePhases phases;
    const bool finishing = sequence_.submit(slot.plan, read_back_, phases);
    if (finishing) finished.swap(slots_[1 - next_].pairs);
    next_ = 1 - next_;
    if (!finishing) return std::nullopt;
    return phases;
}

std::optional<FramePhases> AnalyticPipeline::finish(PairList& finished) {
    if (!sequence_.in_flight()) return std::nullopt;
    FramePhases phases;
    sequence_.finish(read_back_, phases);
    finished.swap(slots_[1 - next_].pairs);
    return phases;
}

}  // namespace cdvp
