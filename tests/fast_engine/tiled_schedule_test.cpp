// Boards whose boxes sit in SSRAM: the tiled schedule against its closed form
// (written out here independently), the address generator's slot stream, the
// pairs of the reference set in schedule order, and the fast engine against
// the clocked board edge by edge.
#include "models/address_generator/sweep_schedule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <tuple>

#include "models/address_generator/address_generator.h"
#include "models/board/engine_factory.h"
#include "models/clocked_engine/clocked_engine.h"
#include "models/fast_engine/fast_engine.h"
#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

using testing::expect_lockstep;
using testing::WordScene;

uint64_t ceil_div(uint64_t a, uint64_t b) { return (a + b - 1) / b; }

// S(n, m) summed row by row, as the seed's address generator walks it.
uint64_t rows_sum(uint64_t n, uint64_t w) {
    uint64_t s = 0;
    for (uint64_t r = 1; r < n; ++r) s += ceil_div(r, w);
    return s;
}

// docs/tiles.md: slots(N) = load(first) + sum_k max(compute_k, load_{k+1}).
uint64_t closed_form(uint64_t n, uint32_t m, const TileConfig& tiles) {
    if (n < 2) return 0;
    const uint64_t w = 2 * m - 1, t = tiles.boxes, nt = ceil_div(n, t);
    auto size = [&](uint64_t a) { return std::min(n, (a + 1) * t) - a * t; };
    auto load = [&](uint64_t a) { return size(a) * tiles.cycles_per_box + tiles.load_latency_cycles; };
    std::vector<std::pair<uint64_t, uint64_t>> blocks;  // (compute, column tile)
    for (uint64_t a = 0; a < nt; ++a) {
        for (uint64_t b = a; b < nt; ++b) {
            blocks.push_back({a == b ? rows_sum(size(a), w) : size(a) * ceil_div(size(b), w), b});
        }
    }
    uint64_t slots = load(0);
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        slots += std::max(blocks[k].first, k + 1 < blocks.size() ? load(blocks[k + 1].second) : 0);
    }
    return slots;
}

TileConfig tiles_of(uint32_t boxes, uint32_t latency = 2, uint32_t cycles_per_box = 1) {
    TileConfig tiles;
    tiles.boxes = boxes;
    tiles.load_latency_cycles = latency;
    tiles.cycles_per_box = cycles_per_box;
    return tiles;
}

TEST(TiledSchedule, SlotsFollowTheClosedForm) {
    int checked = 0;
    for (uint32_t n : {0u, 1u, 2u, 3u, 10u, 63u, 64u, 65u, 200u, 513u}) {
        for (uint32_t m : {1u, 2u, 5u, 32u}) {
            for (uint32_t t : {1u, 2u, 7u, 16u, 64u, 100u, 512u, 1000u}) {
                if (ceil_div(n, t) > SweepSchedule::kMaxTiles) continue;
                for (auto [latency, per_box] : {std::pair{2u, 1u}, {0u, 1u}, {8u, 2u}}) {
                    const TileConfig tiles = tiles_of(t, latency, per_box);
                    EXPECT_EQ(SweepSchedule(m, tiles, n).slots(), closed_form(n, m, tiles))
                        << "n=" << n << " m=" << m << " T=" << t;
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 800);
}

TEST(TiledSchedule, UntiledIsTheSeedsSweep) {
    for (uint32_t n = 0; n <= 70; ++n) {
        for (uint32_t m = 1; m <= 4; ++m) {
            const SweepSchedule schedule(m, TileConfig{}, n);
            EXPECT_EQ(schedule.slots(), AddressGenerator::sweep_cycles(n, m));
            EXPECT_EQ(schedule.wait_slots(), 0u);
            AddressGenerator seed(m);
            seed.start(n);
            ScheduleWalker walker(schedule);
            for (;;) {
                const ScheduleWalker::Slot slot = walker.next();
                ASSERT_NE(slot.kind, ScheduleWalker::Slot::kWait);
                ASSERT_EQ(slot.kind == ScheduleWalker::Slot::kEnd, seed.exhausted()) << "n=" << n << " m=" << m;
                if (seed.exhausted()) break;
                const PortWindow issue = seed.current();
                EXPECT_EQ(std::tie(slot.window.row, slot.window.first_column, slot.window.valid_lanes),
                          std::tie(issue.row, issue.first_column, issue.valid_lanes));
                seed.advance();
            }
        }
    }
}

// The walker covers every pair once, in block order then row then column,
// in the slot pair_slot names, and waits exactly wait_slots() slots.
TEST(TiledSchedule, TheWalkerIssuesEveryPairOnceInScheduleOrder) {
    for (uint32_t n : {2u, 5u, 33u, 64u, 130u}) {
        for (uint32_t m : {1u, 3u, 8u}) {
            for (uint32_t t : {1u, 4u, 9u, 32u, 64u, 200u}) {
                const SweepSchedule schedule(m, tiles_of(t, 1 + t % 3), n);
                ScheduleWalker walker(schedule);
                PairList issued;
                uint64_t slot = 0, waits = 0;
                for (;; ++slot) {
                    const ScheduleWalker::Slot s = walker.next();
                    if (s.kind == ScheduleWalker::Slot::kEnd) break;
                    if (s.kind == ScheduleWalker::Slot::kWait) {
                        ++waits;
                        continue;
                    }
                    for (uint32_t lane = 0; lane < s.window.valid_lanes; ++lane) {
                        const uint32_t j = s.window.first_column + lane;
                        ASSERT_EQ(schedule.pair_slot(s.window.row, j), slot) << "n=" << n << " m=" << m << " T=" << t;
                        issued.push_back({s.window.row, j});
                    }
                }
                EXPECT_EQ(slot, schedule.slots());
                EXPECT_EQ(waits, schedule.wait_slots());
                PairList expected;
                for (uint32_t i = 0; i < n; ++i) {
                    for (uint32_t j = i + 1; j < n; ++j) expected.push_back({i, j});
                }
                std::stable_sort(expected.begin(), expected.end(), [t](const IndexPair& a, const IndexPair& b) {
                    return std::pair(a.first / t, a.second / t) < std::pair(b.first / t, b.second / t);
                });
                ASSERT_EQ(issued, expected) << "n=" << n << " m=" << m << " T=" << t;
            }
        }
    }
}

TEST(TiledSchedule, TooManyTilesAreRefused) {
    EXPECT_THROW(SweepSchedule(1, tiles_of(1), SweepSchedule::kMaxTiles + 1), std::invalid_argument);
    EXPECT_NO_THROW(SweepSchedule(1, tiles_of(1), SweepSchedule::kMaxTiles));
}

// The tile buffers: a 2m-port column memory and a row memory, each
// double-buffered, six coordinates: 6 x (2m+2) x ceil(min(T,N)/512).
TEST(TiledSchedule, BlockRamsOfTheTileBuffers) {
    for (uint32_t m : {1u, 8u, 11u}) {
        for (auto [t, n] : {std::pair{512u, 65536u}, {513u, 65536u}, {64u, 40u}, {1024u, 700u}}) {
            BoardConfig config;
            config.m = m;
            config.tiles = tiles_of(t);
            const uint64_t expected = 6ull * (2 * m + 2) * ceil_div(std::min(t, n), 512);
            EXPECT_EQ(config.block_rams(n), expected) << "m=" << m << " T=" << t << " N=" << n;
            if (n <= 1000) {
                EXPECT_EQ(ClockedEngine(config, n).block_rams(), expected);
            }
        }
    }
    BoardConfig untiled;
    untiled.m = 8;
    EXPECT_EQ(untiled.block_rams(65536), 6u * 8 * 128);
}

// A tiled board finds the reference set, in the schedule's order.
TEST(TiledFastEngine, PairsAreTheReferenceSetInScheduleOrder) {
    std::mt19937 rng(91);
    for (uint32_t t : {1u, 5u, 16u, 50u, 64u}) {
        const WordScene scene = testing::random_scene(300, 10.0f, 3.0f, rng);
        BoardConfig config;
        config.m = 4;
        config.tiles = tiles_of(t);
        FastEngine engine(config);
        engine.start(scene.size(), scene.view());
        PairList expected = testing::lane_hit_pairs(scene);
        std::stable_sort(expected.begin(), expected.end(), [t](const IndexPair& a, const IndexPair& b) {
            return std::pair(a.first / t, a.second / t) < std::pair(b.first / t, b.second / t);
        });
        ASSERT_GT(expected.size(), 100u);
        EXPECT_EQ(engine.pairs(), expected) << "T=" << t;
    }
}

// CYCLES = the closed form + L + STALLS on both engines, run to done through
// every pause, over a grid of N, m and T.
TEST(TiledFastEngine, CyclesAreTheClosedFormPlusLatencyAndStallsOnBothEngines) {
    std::mt19937 rng(96);
    int runs = 0;
    for (uint32_t n : {0u, 2u, 9u, 40u, 101u}) {
        for (uint32_t m : {1u, 2u, 7u}) {
            for (uint32_t t : {1u, 3u, 8u, 25u, 64u}) {
                BoardConfig config;
                config.m = m;
                config.tiles = tiles_of(t, t % 5, 1 + t % 3);
                config.collector.fifo_depth = 2 * m - 1;
                config.collector.buffer_depth = 1 + (n + t) % 7;
                const WordScene scene = testing::random_scene(n, 4.0f, 2.0f, rng);
                const uint64_t expected = closed_form(n, m, config.tiles) + config.pipeline_latency();
                for (Fidelity fidelity : {Fidelity::kCycle, Fidelity::kFast}) {
                    std::unique_ptr<BoardEngine> engine = make_engine(fidelity, config, std::max(n, 1u));
                    CoordinateStore store;
                    for (uint32_t c = 0; c < kCoordinates; ++c) store[c] = scene.words[c];
                    engine->start(store, n);
                    while (!engine->segment_finishes()) engine->resume();
                    const SweepCounters end = engine->counters_after(engine->segment_edges());
                    EXPECT_EQ(end.cycles, expected + end.stalls)
                        << to_string(fidelity) << " n=" << n << " m=" << m << " T=" << t;
                    ++runs;
                }
            }
        }
    }
    EXPECT_EQ(runs, 150);
}

BoardConfig tiled_config(uint32_t m, uint32_t tile, uint32_t fifo, uint32_t drain, uint32_t buffer) {
    BoardConfig config = testing::collector_config(m, fifo, drain, buffer);
    config.tiles = tiles_of(tile, tile % 4, 1 + tile % 2);
    return config;
}

// Every edge: tiles of 1 to 64 boxes, partial last tiles, up to 20 tiles, the
// smallest FIFO and pair buffers of 1 to 7, so pauses fall at tile borders.
TEST(TiledFastEngine, EveryEdgeAgainstTheClockedBoardWithSmallTiles) {
    std::mt19937 rng(92);
    uint32_t pauses = 0;
    for (uint32_t tile : {1u, 2u, 3u, 5u, 8u, 13u, 21u, 32u, 64u}) {
        for (uint32_t m : {1u, 2u, 5u}) {
            const uint32_t n = std::min(20 * tile, 7 + (tile * 37 + m * 11) % 150);
            const BoardConfig config = tiled_config(m, tile, 2 * m - 1, 1 + tile % 3, 1 + (tile + m) % 7);
            pauses += expect_lockstep(config, testing::random_scene(n, 4.0f, 2.0f, rng), 0, rng) - 1;
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(pauses, 300u);
}

TEST(TiledFastEngine, EveryParallelismFrom1To32) {
    std::mt19937 rng(93);
    for (uint32_t m = 1; m <= 32; ++m) {
        const uint32_t tile = 1 + (m * 7) % 64;
        const WordScene scene = testing::random_scene(std::min(20 * tile, 180u), 10.0f, 4.0f, rng);
        expect_lockstep(tiled_config(m, tile, 2 * m - 1, 1 + m % 4, 1 + m % 7), scene, 200, rng);
        expect_lockstep(tiled_config(m, tile, 2 * m - 1 + m % 5, 1, 262144), scene, 200, rng);
        if (HasFailure()) return;
    }
}

TEST(TiledFastEngine, AllOverlappingAndSpecialValues) {
    std::mt19937 rng(94);
    for (uint32_t m : {1u, 3u, 8u}) {
        WordScene scene = testing::overlapping_scene(120, rng);
        expect_lockstep(tiled_config(m, 17, 2 * m - 1, 1, 262144), scene, 300, rng);
        expect_lockstep(tiled_config(m, 24, 2 * m - 1, 3, 5), scene, 20, rng);
        testing::sprinkle_special_values(scene, 0.2, rng);
        expect_lockstep(tiled_config(m, 7, 2 * m + 3, 2, 3), scene, 20, rng);
        if (HasFailure()) return;
    }
}

// One engine over frames of different sizes and tilings of the same size.
TEST(TiledFastEngine, ReusedOverFramesOfDifferentSizes) {
    std::mt19937 rng(95);
    const BoardConfig config = tiled_config(4, 16, 7, 1, 9);
    FastEngine engine(config);
    for (uint32_t n : {100u, 3u, 0u, 160u, 17u}) {
        const WordScene scene = testing::random_scene(n, 6.0f, 2.0f, rng);
        engine.start(n, scene.view());
        uint64_t pairs = 0;
        for (;;) {
            pairs += engine.observe(engine.segment_cycles()).buffer_count;
            if (engine.phase() == SweepState::kDone) break;
            engine.resume();
        }
        EXPECT_EQ(pairs, testing::lane_hit_pairs(scene).size()) << "n=" << n;
        expect_lockstep(config, scene, 50, rng);
    }
}

}  // namespace
}  // namespace cdvp
