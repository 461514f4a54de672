#include "models/board/board_engine.h"

#include <stdexcept>

#include "models/board/clocked_engine.h"
#include "models/fast_engine/fast_board_engine.h"

namespace cdvp {

const char* to_string(Fidelity fidelity) {
    switch (fidelity) {
        case Fidelity::kCycle: return "cycle";
        case Fidelity::kFast: return "fast";
    }
    return "unknown";
}

std::unique_ptr<BoardEngine> make_engine(Fidelity fidelity, const BoardConfig& config, uint32_t capacity,
                                         PairBudget budget) {
    switch (fidelity) {
        case Fidelity::kCycle: return std::make_unique<ClockedEngine>(config, capacity);
        case Fidelity::kFast: return std::make_unique<FastBoardEngine>(config, budget);
    }
    throw std::invalid_argument("unknown fidelity");
}

}  // namespace cdvp
