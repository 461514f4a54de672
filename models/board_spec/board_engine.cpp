#include "models/board_spec/board_engine.h"

namespace cdvp {

const char* to_string(Fidelity fidelity) {
    switch (fidelity) {
        case Fidelity::kCycle: return "cycle";
        case Fidelity::kFast: return "fast";
    }
    return "unknown";
}

}  // namespace cdvp
