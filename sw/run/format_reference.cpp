#include "sw/run/format_reference.h"

#include <algorithm>


namespace cdvp {

FormatReference::Check FormatReference::check(const std::vector<FloatBox>& boxes, const PairList& board_pairs,
                                              const FramePhases& phases) {
    Check result;
    if (format_.is_float()) {
        result.extra.reference_pairs = board_pairs.size();
        return result;
    }
    find_pairs(memo_.get(), float32_, static_cast<uint32_t>(boxes.size()), float32_words(boxes, words_),
               result.reference);
    // The reference comes first index ascending, then second; a tiled board
    // reports its pairs tile block by tile block, so the board's are sorted first.
    const PairList board = sorted(board_pairs);
    const auto before = [](const IndexPair& a, const IndexPair& b) {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
    };
    auto next = board.begin();
    for (const IndexPair& pair : result.reference) {
        next = std::lower_bound(next, board.end(), pair, before);
        if (next == board.end() || !(*next == pair)) {
            result.missing = pair;
            break;
        }
    }
    // What the host keeps: the board's pairs in the board's order, less the extra ones.
    if (!result.missing) {
        result.kept.reserve(result.reference.size());
        for (const IndexPair& pair : board_pairs) {
            if (std::binary_search(result.reference.begin(), result.reference.end(), pair, before)) {
                result.kept.push_back(pair);
            }
        }
    }
    const uint64_t found = board_pairs.size();
    ExtraPairs& extra = result.extra;
    extra.reference_pairs = result.reference.size();
    extra.extra_pairs = found - std::min<uint64_t>(found, extra.reference_pairs);
    if (found > 0) extra.extra_readback_ns = phases.readback_ns * static_cast<double>(extra.extra_pairs) / found;
    extra.extra_driver_ns = ns_per_pair_ * static_cast<double>(extra.extra_pairs);
    return result;
}

std::string lost_pair_message(NumberFormat format, const Frame& frame, const IndexPair& pair) {
    return "the " + format.name() + " board lost the pair (" + std::to_string(frame.ids.at(pair.first)) + ", " +
           std::to_string(frame.ids.at(pair.second)) + ") of the float32 reference";
}

}  // namespace cdvp
