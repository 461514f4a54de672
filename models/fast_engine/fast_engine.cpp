#include "models/fast_engine/fast_engine.h"

namespace cdvp {

FastEngine::FastEngine(const BoardConfig& config) : config_(config), finder_(config.format), timeline_(config) {}

void FastEngine::start(uint32_t objects, const CoordinateWords& words) {
    finder_.find(objects, words, pairs_);
    timeline_.start(objects, pairs_);
}

void FastEngine::resume() { timeline_.resume(); }

}  // namespace cdvp
