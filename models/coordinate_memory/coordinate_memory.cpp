#include "models/coordinate_memory/coordinate_memory.h"

#include <stdexcept>

namespace cdvp {

CoordinateMemory::CoordinateMemory(uint32_t copies, uint32_t depth, uint32_t words_per_primitive)
    : depth_(depth), copies_(copies, CascadedBlockRam(depth, words_per_primitive)) {
    if (copies == 0) throw std::invalid_argument("a coordinate memory needs at least one block RAM copy");
}

void CoordinateMemory::write(uint32_t address, uint32_t word) {
    for (auto& copy : copies_) copy.write(address, word);
}

}  // namespace cdvp
