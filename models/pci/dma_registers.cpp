#include "models/pci/dma_registers.h"

namespace cdvp {

const char* describe(DmaFault fault) {
    switch (fault) {
        case DmaFault::kNone: return "no fault";
        case DmaFault::kBadLength: return "bad length (zero, not a multiple of 4, or above 16 MiB)";
        case DmaFault::kMisaligned: return "misaligned address";
        case DmaFault::kMasterAbort: return "master abort (no host memory claimed the address)";
        case DmaFault::kTargetAbort: return "target abort (the board rejected the address)";
        case DmaFault::kBoardRefused: return "the board refused the access";
        case DmaFault::kDescriptorFault: return "descriptor fetch failed (master abort)";
        case DmaFault::kChainLoop: return "descriptor chain loops";
        case DmaFault::kChainTooLong: return "descriptor chain longer than 1024";
        case DmaFault::kStartWhileBusy: return "START while a transfer was under way";
    }
    return "unknown fault";
}

}  // namespace cdvp
