// The seed's comparison unit: 2m-1 lanes of six comparators ANDed, in the
// board's number format (float32 or fixedK).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "models/coordinate_memory/coordinate_memory.h"
#include "models/number_format/number_format.h"

namespace cdvp {

// Coordinate memories in the board's order.
enum Coordinate : uint32_t { kMinX, kMinY, kMinZ, kMaxX, kMaxY, kMaxZ, kCoordinates };
using CoordinateMemories = std::array<CoordinateMemory, kCoordinates>;
// Six memories of `copies` copies (2 x copies ports) and `depth` boxes each,
// in primitives `layout.depth` words deep (NumberFormat::block_ram_layout).
inline CoordinateMemories make_coordinate_memories(uint32_t copies, uint32_t depth,
                                                   const BlockRamLayout& layout = BlockRamLayout{}) {
    const CoordinateMemory memory(copies, depth, layout.depth);
    return {memory, memory, memory, memory, memory, memory};
}
// The primitives of six such memories: each coordinate's cascade of each
// copy, shared by the coordinates that sit side by side in a word.
inline uint32_t block_rams_of(const CoordinateMemories& memories, const BlockRamLayout& layout) {
    return layout.word_groups() * memories[0].block_rams();
}

struct ComparisonUnitConfig {
    // Cycles from the block RAM outputs to the lane results. Default 2, an
    // assumption: the seed does not give its compare core's latency, and 0-2
    // cycles is the plausible range for a Virtex-II -4 float compare core.
    uint32_t latency_cycles = 2;
};

// Lane k (0-based) compares box i on port 0 with box j on port k+1:
// hit = min_i <= max_j && min_j <= max_i on x, y and z (closed intervals).
// In float32 the comparisons are IEEE float32 comparisons: -0 equals +0,
// denormals are compared as they are (the model never flushes to zero),
// infinities are ordinary extremes. In fixedK they are unsigned comparisons
// of the words' low K bits. Lane results form a bit mask (bit k = lane k), so
// a configuration has at most 63 lanes (m <= 32).
class ComparisonUnit {
public:
    static constexpr uint32_t kMaxLanes = 63;

    // The format is the hardware's: fixed at construction, as synthesis fixes it.
    ComparisonUnit(uint32_t lanes, const ComparisonUnitConfig& config, NumberFormat format = NumberFormat::float32());

    uint32_t lanes() const { return lanes_; }
    uint32_t latency_cycles() const { return latency_; }
    NumberFormat format() const { return format_; }

    // The lane results for the current memory outputs; lanes beyond
    // valid_lanes are not evaluated (their bits are 0).
    uint64_t evaluate(const CoordinateMemories& memories, uint32_t valid_lanes) const {
        return evaluate(memories, memories, valid_lanes);
    }
    // A tiled board: box i from port 0 of the row memories, the boxes j from
    // ports 1..valid_lanes of the column memories.
    uint64_t evaluate(const CoordinateMemories& rows, const CoordinateMemories& columns, uint32_t valid_lanes) const {
        // A branch that goes the same way every cycle of a board, so both
        // loops stay inlined in the clocked engine's step.
        return is_float_ ? evaluate_as<float>(rows, columns, valid_lanes)
                         : evaluate_as<uint32_t>(rows, columns, valid_lanes);
    }

    // Six comparators ANDed. Bounds are ordered min_x, min_y, min_z, max_x, max_y, max_z.
    template <typename Bound>
    static bool lane_hit(const Bound* a, const Bound* b) {
        // Bitwise & keeps all six comparators evaluated, as in hardware, and
        // lets the compiler avoid branches.
        return (a[kMinX] <= b[kMaxX]) & (b[kMinX] <= a[kMaxX]) &
               (a[kMinY] <= b[kMaxY]) & (b[kMinY] <= a[kMaxY]) &
               (a[kMinZ] <= b[kMaxZ]) & (b[kMinZ] <= a[kMaxZ]);
    }
    // The lane test of a format on two boxes' stored words.
    static bool lane_hit(NumberFormat format, const uint32_t* a, const uint32_t* b);

    static float as_float(uint32_t bits) {
        float value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }
    static uint32_t as_bits(float value) {
        uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        return bits;
    }

private:
    // One lane test per format: float32 compares floats, fixedK the masked words.
    template <typename Bound>
    uint64_t evaluate_as(const CoordinateMemories& rows, const CoordinateMemories& columns, uint32_t valid_lanes) const {
        Bound i_bounds[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) i_bounds[c] = bound<Bound>(rows[c].output(0));
        uint64_t hits = 0;
        for (uint32_t port = 1; port <= valid_lanes; ++port) {
            Bound j_bounds[kCoordinates];
            for (uint32_t c = 0; c < kCoordinates; ++c) j_bounds[c] = bound<Bound>(columns[c].output(port));
            hits |= static_cast<uint64_t>(lane_hit(i_bounds, j_bounds)) << (port - 1);
        }
        return hits;
    }
    template <typename Bound>
    Bound bound(uint32_t word) const {
        if constexpr (std::is_same_v<Bound, float>) return as_float(word);
        else return word & mask_;
    }

    uint32_t lanes_;
    uint32_t latency_;
    NumberFormat format_;
    uint32_t mask_;
    bool is_float_;
};

}  // namespace cdvp
