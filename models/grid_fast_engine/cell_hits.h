// The lane tests of a busy cell of at most 64 boxes (GridSearch::sweep_cell):
// every row against the columns the one-cell rule may keep beside it, a bit
// a column, in three compare widths: 4 columns (BlockTest: SSE2 on any
// x86-64, portable elsewhere), 8 (AVX2) and 16 (AVX-512). The widest the
// running CPU has is chosen at the first call, so a build for plain x86-64
// (no -march) still uses the wider ones. Every width gives the same bits.
#pragma once

#include <cstdint>
#include <vector>

#include "models/fast_engine/box_block.h"

namespace cdvp {

// Columns read past a cell's last box by the widest compare: BoxColumns
// must hold this many entries beyond the cell's boxes.
constexpr uint32_t kCellHitsPadding = 16;

// For each row r < n - 1 of a cell of n boxes (2 <= n <= 64) whose keys are
// `columns` (boxes 0..n-1 in index order): row_hits[r] holds bit c when
// c > r, the one-cell rule may keep (r, c) (on every axis one of the two
// starts in the cell: bit k of starts[a] says box k does on axis a) and the
// lanes find the two boxes overlapping.
using CellHits = void (*)(const BoxColumns& columns, uint32_t n, const uint64_t (&starts)[3], uint64_t* row_hits);

struct CellHitsWidth {
    uint32_t columns;  // columns a compare
    CellHits hits;
    bool runs;  // the running CPU has the instructions
};
// Every width this build has, narrowest first.
std::vector<CellHitsWidth> cell_hits_widths();

// The widest width the running CPU has.
void masked_cell_hits(const BoxColumns& columns, uint32_t n, const uint64_t (&starts)[3], uint64_t* row_hits);

}  // namespace cdvp
