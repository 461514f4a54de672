// Fault injection: which faults the bus and board models inject, and when.
// Plain C++ so every model can consult it; the platform parses the user's
// KIND@WHERE specs (platform/fault_injection.h) and tells the plan which
// frame runs. docs/faults.md describes every kind.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cdvp {

enum class FaultKind : uint8_t {
    kTargetAbort,  // the board target-aborts the bridge's next local-bus access of a DMA
    kMasterAbort,  // no host memory claims the bridge's next bus-master access of a DMA
    kRetry,        // the next DMA transaction is retried once (completes, costs a second transaction)
    kDisconnect,   // the next DMA transaction is cut after half its data (completes in two)
    kLostIrq,      // the next interrupt never reaches the driver
    kDmaHang,      // the next DMA never completes
    kBoardError,   // the board reports an error status instead of starting the next sweep
};
constexpr FaultKind kAllFaultKinds[] = {FaultKind::kTargetAbort, FaultKind::kMasterAbort, FaultKind::kRetry,
                                        FaultKind::kDisconnect,  FaultKind::kLostIrq,     FaultKind::kDmaHang,
                                        FaultKind::kBoardError};

// The kind's spelling in a spec, e.g. "target-abort".
const char* fault_kind_name(FaultKind kind);

// Inject count faults of kind in the frame numbered frame.
struct FaultSpec {
    FaultKind kind;
    uint64_t frame = 0;
    uint32_t count = 1;
    bool operator==(const FaultSpec& o) const { return kind == o.kind && frame == o.frame && count == o.count; }
};

// The specs of a run, consulted by the models at their injection points.
class FaultPlan {
public:
    explicit FaultPlan(std::vector<FaultSpec> specs = {});

    // Arms the specs of this frame (and disarms what an earlier frame left).
    void begin_frame(uint64_t frame);
    // True when a fault of this kind is due now; it then counts as injected.
    bool fire(FaultKind kind);
    uint64_t injected(FaultKind kind) const { return injected_[static_cast<int>(kind)]; }
    bool empty() const { return specs_.empty(); }

private:
    std::vector<FaultSpec> specs_;
    uint32_t armed_[std::size(kAllFaultKinds)] = {};
    uint64_t injected_[std::size(kAllFaultKinds)] = {};
};

// A plan consulted through a possibly null pointer: no plan, no faults.
inline bool fault_due(FaultPlan* plan, FaultKind kind) { return plan != nullptr && plan->fire(kind); }

}  // namespace cdvp
