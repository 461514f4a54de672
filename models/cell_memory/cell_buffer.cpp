#include "models/cell_memory/cell_buffer.h"

#include <stdexcept>

namespace cdvp {

namespace {
CellBuffer::Half make_half(uint32_t m, uint32_t capacity, const BlockRamLayout& layout) {
    std::vector<uint8_t> first(capacity, 0);
    return {make_coordinate_memories(m, capacity, layout), {first, first, first}, std::vector<uint32_t>(capacity, 0), 0};
}
}  // namespace

CellBuffer::CellBuffer(uint32_t m, uint32_t capacity, const GridSlots& slots, NumberFormat format)
    : slots_(slots),
      format_(format),
      layout_(format.block_ram_layout(capacity)),
      halves_{make_half(m, capacity, layout_), make_half(m, capacity, layout_)} {}

void CellBuffer::begin(uint32_t half, const uint32_t* boxes, uint32_t count) {
    if (loading_) throw std::logic_error("cell buffer: a load began during another");
    if (count > halves_[half].index.size()) throw std::logic_error("cell buffer: a load past its depth");
    loading_ = true;
    half_ = half;
    boxes_ = boxes;
    count_ = count;
    slot_ = 0;
    halves_[half].count = count;
}

bool CellBuffer::tick(const Store& store, const GridGeometry& grid) {
    if (!loading_) return false;
    const uint64_t fill = slots_.load(0);  // the latencies before the first box
    const uint64_t q = slots_.cycles_per_box;
    // Box p's last word lands in the load's slot fill + (p + 1) q - 1.
    if (slot_ >= fill && (slot_ - fill + 1) % q == 0) {
        const auto p = static_cast<uint32_t>((slot_ - fill + 1) / q - 1);
        Half& h = halves_[half_];
        const uint32_t box = boxes_[p];
        for (uint32_t c = 0; c < kCoordinates; ++c) h.boxes[c].write(p, store[c][box]);
        for (uint32_t a = 0; a < 3; ++a) h.first[a][p] = static_cast<uint8_t>(grid.cell(a, format_.key(store[a][box])));
        h.index[p] = box;
    }
    ++slot_;
    if (slot_ < slots_.load(count_)) return false;
    loading_ = false;
    return true;
}

}  // namespace cdvp
