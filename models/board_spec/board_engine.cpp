#include "models/board_spec/board_engine.h"

namespace cdvp {

const char* to_string(Fidelity fidelity) {
    switch (fidelity) {
        case Fidelity::kCycle: return "cycle";
        case Fidelity::kFast: return "fast";
        case Fidelity::kRtl: return "rtl";
        case Fidelity::kLockstep: return "rtl-lockstep";
    }
    return "unknown";
}

}  // namespace cdvp
