// The pairs output: "frame,a,b" with one overlapping pair of ids a line.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "models/common/aabb.h"
#include "sw/scene/scene.h"

namespace cdvp {

// A pair of overlapping boxes named by their ids, a < b.
struct IdPair {
    uint64_t a;
    uint64_t b;
    friend bool operator==(const IdPair& x, const IdPair& y) {
        return x.a == y.a && x.b == y.b;
    }
    friend bool operator<(const IdPair& x, const IdPair& y) {
        return x.a != y.a ? x.a < y.a : x.b < y.b;
    }
};

// Maps box indices (positions in frame.boxes) to the frame's ids, orders
// each pair so a < b and sorts by (a, b). Throws std::out_of_range for an
// index outside the frame.
std::vector<IdPair> to_id_pairs(const Frame& frame, const PairList& pairs);

// Writes "frame,a,b\n".
void write_pairs_header(std::ostream& out);

// Writes one line "frame,a,b" per pair, in the given order.
void write_frame_pairs(std::ostream& out, uint64_t frame, const std::vector<IdPair>& pairs);

// Reads a pairs file back as (frame, pair) in file order. Checks the header,
// the field count, the integers and a < b; InputError "PATH:LINE: message".
std::vector<std::pair<uint64_t, IdPair>> read_pairs_csv(const std::string& path);

}  // namespace cdvp
