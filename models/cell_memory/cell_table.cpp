#include "models/cell_memory/cell_table.h"

#include <stdexcept>

namespace cdvp {

void CellTable::reset(uint64_t cells, uint32_t capacity, uint64_t entry_capacity) {
    cells_ = cells;
    capacity_ = capacity;
    entry_capacity_ = entry_capacity;
    entries_ = 0;
    counts_.assign(cells, 0);
    busy_.clear();
}

void CellTable::begin_scan() {
    // Entries are 32-bit word addresses, as on the board's address map.
    if (entries_ > UINT32_MAX) throw std::length_error("more than 2^32 cell entries");
    scanned_ = 0;
    busy_.clear();
    entries_list_.resize(entries_);
}

}  // namespace cdvp
