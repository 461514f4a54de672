// The fast engine behind the board's engine seam (BoardEngine), so that
// BoardCore and its SystemC shell can run on it instead of the clocked datapath.
#pragma once

#include "models/fast_engine/fast_engine.h"
#include "models/fast_engine/result_board_engine.h"

namespace cdvp {

// Answers every BoardEngine query as ClockedEngine does: the same segment
// ends, counters after any edge, buffer contents and abort.
class FastBoardEngine : public ResultBoardEngine<FastEngine> {
public:
    explicit FastBoardEngine(const BoardConfig& config, PairBudget budget = {}) : ResultBoardEngine(config, budget) {}
};

}  // namespace cdvp
