// Scenes as the host writes them into the coordinate memories (float32 bit
// patterns), and a lock-step run of BoardCore beside the fast engine.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "models/board_spec/board_config.h"
#include "models/board_spec/board_engine.h"
#include "models/fast_engine/pair_finder.h"

namespace cdvp::testing {

struct WordScene {
    std::array<std::vector<uint32_t>, kCoordinates> words;

    uint32_t size() const { return static_cast<uint32_t>(words[0].size()); }
    CoordinateWords view() const;
    static WordScene from_boxes(const std::vector<FloatBox>& boxes);
};

// Boxes with corners uniform in [0, extent)^3 and sides uniform in [0, size).
WordScene random_scene(uint32_t n, float extent, float size, std::mt19937& rng);
// Dense clumps: boxes scattered tightly around a few centres far apart.
WordScene clustered_scene(uint32_t n, uint32_t clusters, std::mt19937& rng);
// Every box contains the origin: every pair meets.
WordScene overlapping_scene(uint32_t n, std::mt19937& rng);
// Coordinates that are multiples of the smallest denormal, of either sign.
WordScene denormal_scene(uint32_t n, std::mt19937& rng);
// Replaces about `fraction` of the words with NaNs (quiet, signalling,
// negative), zeros of both signs, infinities, denormals and FLT_MAX, and
// inverts about as many boxes (min above max).
void sprinkle_special_values(WordScene& scene, double fraction, std::mt19937& rng);

// Fixed-point boxes of a format: corners uniform over its codes, sides up to
// size_share of the range, random junk above the format's K bits.
WordScene fixed_scene(uint32_t n, NumberFormat format, double size_share, std::mt19937& rng);

// A board of 2m-1 lanes with this pair FIFO (depth, drain a cycle) and pair
// buffer; float32, untiled, the other settings at their defaults.
BoardConfig collector_config(uint32_t m, uint32_t fifo, uint32_t drain, uint32_t buffer);

// All pairs by the comparison unit's own test, in BoardCore's order.
PairList lane_hit_pairs(const WordScene& scene, NumberFormat format = NumberFormat::float32());

// Runs BoardCore edge by edge beside FastEngine on the same scene and
// compares, in every segment, the registers after each probed edge, the edge
// at which the segment ends, the phase and the whole pair buffer; then every
// pair. probes_per_segment = 0 probes every edge, k > 0 k random edges.
// Returns the number of segments (pauses + 1); failures are gtest failures.
uint32_t expect_lockstep(const BoardConfig& config, const WordScene& scene, uint32_t probes_per_segment,
                         std::mt19937& rng);

// The scene as the board's coordinate memories hold it.
CoordinateStore store_of(const WordScene& scene);
// The buffer's valid entries after `edges` edges of the segment.
PairList buffer_of(BoardEngine& engine, uint64_t edges);
// Two engines of one board through the seam, segment by segment: at
// `probes` random edges whether the segment has ended and the counters,
// then its end, how it ends, the counters past it and the whole buffer.
// The reference is asked first at each edge (a clocked one steps there).
void expect_same_engines(BoardEngine& reference, BoardEngine& other, const WordScene& scene, std::mt19937& rng,
                         int probes = 40);

// ABORT at a random edge of the first or the second segment, over `trials`
// pairs of engines made afresh: the buffer and the counters at that edge agree.
using MakeEngine = std::function<std::unique_ptr<BoardEngine>()>;
void expect_same_aborts(const MakeEngine& reference, const MakeEngine& other, const WordScene& scene,
                        std::mt19937& rng, int trials = 20);

}  // namespace cdvp::testing
