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
    const SweepSchedule schedule(config_.m, config_.tiles, objects);
    block_ends_.assign(schedule.blocks().size() + 1, 0);
    for (const IndexPair& p : pairs_) ++block_ends_[schedule.block_of(p.first, p.second) + 1];
    for (std::size_t k = 1; k < block_ends_.size(); ++k) block_ends_[k] += block_ends_[k - 1];
    by_block_.resize(pairs_.size());
    for (const IndexPair& p : pairs_) by_block_[block_ends_[schedule.block_of(p.first, p.second)]++] = p;
    pairs_.swap(by_block_);
}

}  // namespace cdvp
