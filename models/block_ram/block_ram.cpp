#include "models/block_ram/block_ram.h"

#include <stdexcept>
#include <string>

namespace cdvp {

CascadedBlockRam::CascadedBlockRam(uint32_t depth)
    : depth_(depth), bank_(primitives_for(depth)) {}

void CascadedBlockRam::write(uint32_t address, uint32_t word) {
    if (address >= depth_) {
        throw std::out_of_range("block RAM write to address " + std::to_string(address) +
                                " beyond depth " + std::to_string(depth_));
    }
    bank_[address / BlockRam::kWords].write(address, word);
}

}  // namespace cdvp
