// How the pair buffer reads back over the bus (the PAIR_FORMAT register): the
// read port's encoder between the buffer and the bus, and the host's decoder.
// The buffer itself, and so the board's stalls and pauses, are the same in
// every format; only the words the host moves differ (docs/communication.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp {

enum class PairFormat : uint8_t {
    // Two words a pair, (first, second), in board order: 8 bytes a pair.
    kList = 0,
    // Each run of pairs sharing a first index: that index, the run's length
    // k, then the k second indices: 4 bytes a pair and 8 a run. The sweep
    // emits a row's pairs together, so a run is a row (a tile's part of a
    // row on a tiled board).
    kCounted = 1,
    // The first row r0 and the row count R of the rows the buffer's pairs
    // span, then R rows of ceil(N/32) words: bit j of row i - r0 is pair
    // (i, j). Independent of the pair count; the host reads rows in order,
    // so within a read-back the pairs come sorted by (first, second).
    kBitmap = 2,
};

constexpr uint32_t kPairFormats = 3;

// The read-back window's words for these buffered pairs of a sweep of
// `objects` boxes.
uint64_t encoded_words(PairFormat format, const IndexPair* pairs, uint64_t count, uint32_t objects);
// Appends the encoding to out.
void encode_pairs(PairFormat format, const IndexPair* pairs, uint64_t count, uint32_t objects,
                  std::vector<uint32_t>& out);
// The most words `pairs` buffered pairs of a sweep of `objects` boxes can
// take, when a row's pairs come in at most `row_pieces` runs (1 in block
// RAM; a tiled board's column tiles); 0 row_pieces: any number.
uint64_t worst_encoded_words(PairFormat format, uint64_t pairs, uint32_t objects, uint64_t row_pieces = 0);

// Decodes `count` words of a read-back of a sweep of `objects` boxes,
// appending the pairs. Returns an empty string, or what is wrong with the
// words (a run past the words, an index out of range, a stray bit).
std::string decode_pairs(PairFormat format, const uint32_t* words, uint64_t count, uint32_t objects,
                         PairList& out);

}  // namespace cdvp
