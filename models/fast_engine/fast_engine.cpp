#include "models/fast_engine/fast_engine.h"

#include "models/address_generator/sweep_schedule.h"

namespace cdvp {

FastEngine::FastEngine(const BoardConfig& config, PairBudget budget)
    : config_(config), finder_(config.format, budget), timeline_(config) {}

void FastEngine::start(uint32_t objects, const CoordinateWords& words) {
    finder_.find(objects, words, pairs_);
    if (config_.tiles.tiled() && objects > config_.tiles.boxes) order_by_block(objects);
    timeline_.start(objects, pairs_);
}

void FastEngine::resume() { timeline_.resume(); }

void FastEngine::order_by_block(uint32_t objects) {
    SweepSchedule(config_.m, config_.tiles, objects).order_by_block(pairs_, by_block_, block_ends_);
}

}  // namespace cdvp
