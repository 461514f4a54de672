#include "models/block_ram/block_ram.h"

#include <stdexcept>
#include <string>

namespace cdvp {

namespace {
uint32_t checked_aspect(uint32_t words) {
    if (words == 0 || (words & (words - 1)) != 0) {
        throw std::invalid_argument("a block RAM aspect's depth is a power of two, not " + std::to_string(words));
    }
    return words;
}
}  // namespace

CascadedBlockRam::CascadedBlockRam(uint32_t depth, uint32_t words_per_primitive)
    : depth_(depth),
      shift_(static_cast<uint32_t>(__builtin_ctz(checked_aspect(words_per_primitive)))),
      bank_(primitives_for(depth, words_per_primitive), BlockRam(words_per_primitive)) {}

void CascadedBlockRam::write(uint32_t address, uint32_t word) {
    if (address >= depth_) {
        throw std::out_of_range("block RAM write to address " + std::to_string(address) +
                                " beyond depth " + std::to_string(depth_));
    }
    bank_[address >> shift_].write(address, word);
}

}  // namespace cdvp
