// The grid board's fast engine behind the board's engine seam.
#pragma once

#include "models/fast_engine/result_board_engine.h"
#include "models/grid_fast_engine/grid_fast_engine.h"

namespace cdvp {

class GridFastBoardEngine : public ResultBoardEngine<GridFastEngine> {
public:
    explicit GridFastBoardEngine(const BoardConfig& config, PairBudget budget = {})
        : ResultBoardEngine(config, budget) {}
    GridSweepStats grid_stats() const override { return engine_.stats(); }
};

}  // namespace cdvp
