// What a process running many analytic runs keeps between them (a sweep's
// points, the Python module's runs): the pairs the board found, by the six
// memories' words, and the scenes generated, by every setting of the scene.
// None changes a result: a hit is the same words or the same scene settings.
#pragma once

#include <memory>

#include "models/fast_engine/pair_memo.h"
#include "sw/run/scene_memo.h"

namespace cdvp {

struct RunMemo {
    std::shared_ptr<PairMemo> pairs = std::make_shared<PairMemo>();
    SceneMemo scenes;
};

}  // namespace cdvp
