// The engine a board runs: which implementation of BoardEngine computes its
// sweeps. Above the engines, so the vocabulary below them names none.
#pragma once

#include <cstdint>
#include <memory>

#include "models/board_spec/board_config.h"
#include "models/board_spec/board_engine.h"
#include "models/common/pair_budget.h"

namespace cdvp {

// The engine of a board with this configuration and coordinate-memory depth.
// A fast engine finds a sweep's pairs at START and throws PairBudgetExceeded
// there when they outgrow `budget`; the clocked one holds no more pairs than
// its pair buffer (the driver's read-back holds the budget for it).
std::unique_ptr<BoardEngine> make_engine(Fidelity fidelity, const BoardConfig& config, uint32_t capacity,
                                         PairBudget budget = {});

}  // namespace cdvp
