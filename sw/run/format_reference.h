// A fixed-point board against the float32 reference: the board must find
// every pair the float32 comparators find (the quantiser rounds outward);
// what it finds beyond them are extra pairs, with a cost downstream.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/common/aabb.h"
#include "models/fast_engine/pair_finder.h"
#include "models/fast_engine/pair_memo.h"
#include "models/number_format/number_format.h"
#include "sw/run/extra_pairs.h"
#include "platform/driver/board_driver.h"
#include "sw/scene/scene.h"

namespace cdvp {

class FormatReference {
public:
    // The float32 reference finds at most `budget` pairs (PairBudgetExceeded past it).
    // With `memo`, the reference's pairs come from it when it holds them.
    FormatReference(NumberFormat format, double ns_per_pair, PairBudget budget = {},
                    std::shared_ptr<PairMemo> memo = nullptr)
        : format_(format), ns_per_pair_(ns_per_pair), float32_(NumberFormat::float32(), budget), memo_(std::move(memo)) {}

    struct Check {
        PairList reference;              // the float32 pairs, first index ascending (empty under float32)
        PairList kept;                   // the board's pairs less the extra ones, in the board's order (ditto)
        ExtraPairs extra;
        std::optional<IndexPair> missing;  // a reference pair the board did not find: a fault
    };
    // board_pairs in any order. Under float32 the board is the reference
    // (both engines are proven equal to its comparators): nothing is recomputed.
    Check check(const std::vector<FloatBox>& boxes, const PairList& board_pairs, const FramePhases& phases);
    // The pairs the host keeps, in the board's order: the board's less the
    // extra ones (all of the board's under float32).
    const PairList& kept(const Check& check, const PairList& board_pairs) const {
        return format_.is_float() ? board_pairs : check.kept;
    }

private:
    NumberFormat format_;
    double ns_per_pair_;
    PairFinder float32_;
    std::shared_ptr<PairMemo> memo_;
    std::vector<uint32_t> words_[kCoordinates];
};

// "the fixed16 board lost the pair (ID, ID) of the float32 reference", by the frame's ids.
std::string lost_pair_message(NumberFormat format, const Frame& frame, const IndexPair& pair);

}  // namespace cdvp
