#include "models/common/fault_plan.h"

#include <utility>

namespace cdvp {

const char* fault_kind_name(FaultKind kind) {
    switch (kind) {
        case FaultKind::kTargetAbort: return "target-abort";
        case FaultKind::kMasterAbort: return "master-abort";
        case FaultKind::kRetry: return "retry";
        case FaultKind::kDisconnect: return "disconnect";
        case FaultKind::kLostIrq: return "lost-irq";
        case FaultKind::kDmaHang: return "dma-hang";
        case FaultKind::kBoardError: return "board-error";
    }
    return "unknown";
}

FaultPlan::FaultPlan(std::vector<FaultSpec> specs) : specs_(std::move(specs)) {}

void FaultPlan::begin_frame(uint64_t frame) {
    for (uint32_t& armed : armed_) armed = 0;
    for (const FaultSpec& spec : specs_) {
        if (spec.frame == frame) armed_[static_cast<int>(spec.kind)] += spec.count;
    }
}

bool FaultPlan::fire(FaultKind kind) {
    uint32_t& armed = armed_[static_cast<int>(kind)];
    if (armed == 0) return false;
    --armed;
    ++injected_[static_cast<int>(kind)];
    return true;
}

}  // namespace cdvp
