#include "models/board/engine_factory.h"

#include <stdexcept>

#include "models/clocked_engine/clocked_engine.h"
#include "models/fast_engine/fast_board_engine.h"
#include "models/grid_clocked_engine/grid_clocked_engine.h"
#include "models/grid_fast_engine/grid_fast_board_engine.h"
#include "models/rtl_engine/lockstep_engine.h"
#include "models/rtl_engine/rtl_engine.h"

namespace cdvp {

std::unique_ptr<BoardEngine> make_engine(Fidelity fidelity, const BoardConfig& config, uint32_t capacity,
                                         PairBudget budget) {
    if (config.grid_board()) {
        if (fidelity == Fidelity::kFast) return std::make_unique<GridFastBoardEngine>(config, budget);
        if (fidelity == Fidelity::kCycle) return std::make_unique<GridClockedEngine>(config, capacity);
    }
    switch (fidelity) {
        case Fidelity::kCycle: return std::make_unique<ClockedEngine>(config, capacity);
        case Fidelity::kFast: return std::make_unique<FastBoardEngine>(config, budget);
        case Fidelity::kRtl: return std::make_unique<RtlEngine>(config, capacity);
        case Fidelity::kLockstep: return std::make_unique<LockstepEngine>(config, capacity);
    }
    throw std::invalid_argument("unknown fidelity");
}

}  // namespace cdvp
