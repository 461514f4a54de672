// The fast engine against BoardCore stepped edge by edge: pairs, buffer
// contents, and the registers at every probed edge of every segment.
#include "models/fast_engine/fast_engine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "models/address_generator/address_generator.h"
#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

using testing::collector_config;
using testing::expect_lockstep;
using testing::WordScene;

// Every edge of every segment, over small dense scenes: the smallest legal
// FIFO, drains of 1 to 3, buffers of 1 to 7 pairs (a pause every few pairs).
TEST(FastEngine, EveryEdgeOfSmallScenesWithTinyFifoAndBuffer) {
    std::mt19937 rng(1);
    uint32_t pauses = 0;
    for (uint32_t m = 1; m <= 6; ++m) {
        for (uint32_t n = 0; n <= 40; ++n) {
            const BoardConfig config = collector_config(m, 2 * m - 1, 1 + n % 3, 1 + n % 7);
            pauses += expect_lockstep(config, testing::random_scene(n, 4.0f, 2.0f, rng), 0, rng) - 1;
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(pauses, 1000u);
}

TEST(FastEngine, EveryParallelismFrom1To32) {
    std::mt19937 rng(2);
    for (uint32_t m = 1; m <= 32; ++m) {
        const uint32_t lanes = 2 * m - 1;
        const WordScene scene = testing::random_scene(150, 12.0f, 4.0f, rng);
        expect_lockstep(collector_config(m, lanes, 1 + m % 4, 1 + m % 7), scene, 200, rng);
        expect_lockstep(collector_config(m, lanes + m % 5, 1, 262144), scene, 200, rng);
        if (HasFailure()) return;
    }
}

// Around the block RAM's 512 words, with back-pressure and overflow pauses.
TEST(FastEngine, AroundOneBlockRam) {
    std::mt19937 rng(3);
    for (uint32_t n : {511u, 512u, 513u}) {
        for (uint32_t m : {1u, 4u, 24u}) {
            const WordScene scene = testing::random_scene(n, 30.0f, 3.0f, rng);
            expect_lockstep(collector_config(m, 2 * m - 1, 1, 7), scene, 20, rng);
            expect_lockstep(collector_config(m, 64, 2, 262144), scene, 200, rng);
            if (HasFailure()) return;
        }
    }
}

// Every pair meets: the FIFO is always full, the pipeline holds most edges.
TEST(FastEngine, AllOverlappingScenes) {
    std::mt19937 rng(4);
    for (uint32_t m : {1u, 3u, 8u, 32u}) {
        const WordScene scene = testing::overlapping_scene(300, rng);
        expect_lockstep(collector_config(m, 2 * m - 1, 1, 262144), scene, 500, rng);
        expect_lockstep(collector_config(m, 2 * m - 1, 3, 5), scene, 10, rng);
        expect_lockstep(collector_config(m, 512, 1 + m % 3, 1000), scene, 100, rng);
        if (HasFailure()) return;
    }
}

TEST(FastEngine, ClusteredScenes) {
    std::mt19937 rng(5);
    for (uint32_t m : {2u, 8u, 24u}) {
        const WordScene scene = testing::clustered_scene(1200, 6, rng);
        expect_lockstep(collector_config(m, 2 * m - 1, 1, 262144), scene, 500, rng);
        expect_lockstep(collector_config(m, 2 * m + 3, 2, 97), scene, 5, rng);
        if (HasFailure()) return;
    }
}

TEST(FastEngine, LargeRandomScenes) {
    std::mt19937 rng(6);
    for (uint32_t n : {2000u, 3000u}) {
        const WordScene scene = testing::random_scene(n, 4.0f * std::cbrt(static_cast<float>(n)), 2.0f, rng);
        expect_lockstep(collector_config(32, 63, 1, 262144), scene, 1000, rng);
        expect_lockstep(collector_config(8, 15, 2, 6), scene, 5, rng);
        if (HasFailure()) return;
    }
}

TEST(FastEngine, NanZerosInfinitiesAndDenormals) {
    std::mt19937 rng(7);
    for (uint32_t n : {60u, 700u}) {
        WordScene special = testing::random_scene(n, 10.0f, 3.0f, rng);
        testing::sprinkle_special_values(special, 0.05, rng);
        expect_lockstep(collector_config(4, 7, 1, 3), special, 50, rng);
        expect_lockstep(collector_config(5, 9, 1, 262144), testing::denormal_scene(n, rng), 200, rng);
        if (HasFailure()) return;
    }
}

// Draining more pairs a cycle than there are lanes: no back-pressure ever,
// only the end-of-sweep drain and overflow pauses.
TEST(FastEngine, DrainFasterThanTheLanes) {
    std::mt19937 rng(11);
    const WordScene scene = testing::overlapping_scene(120, rng);
    for (uint32_t m : {1u, 4u, 31u}) {
        expect_lockstep(collector_config(m, 2 * m - 1, 64, 262144), scene, 0, rng);
        expect_lockstep(collector_config(m, 2 * m + 10, 2 * m + 1, 5), scene, 0, rng);
        if (HasFailure()) return;
    }
}

TEST(FastEngine, CompareLatencyAndDefaults) {
    std::mt19937 rng(8);
    const WordScene scene = testing::random_scene(400, 15.0f, 3.0f, rng);
    for (uint32_t latency : {0u, 1u, 5u, 64u}) {
        BoardConfig config = collector_config(3, 5, 1, 4);
        config.compare.latency_cycles = latency;
        expect_lockstep(config, scene, 20, rng);
    }
    expect_lockstep(BoardConfig{}, scene, 300, rng);
}

TEST(FastEngine, ObservingPastTheSegmentSeesItsEnd) {
    std::mt19937 rng(9);
    const WordScene scene = testing::overlapping_scene(20, rng);
    FastEngine engine(collector_config(2, 3, 1, 50));
    EXPECT_EQ(engine.phase(), SweepState::kIdle);
    EXPECT_THROW(engine.resume(), std::logic_error);
    engine.start(scene.size(), scene.view());
    ASSERT_EQ(engine.phase(), SweepState::kPaused);
    const BoardObservation end = engine.observe(engine.segment_cycles());
    const BoardObservation later = engine.observe(engine.segment_cycles() + 1000);
    EXPECT_EQ(later.cycles, end.cycles);
    EXPECT_EQ(later.phase, SweepState::kPaused);
    EXPECT_EQ(end.buffer_count, 50u);
    EXPECT_EQ(engine.observe(0).cycles, 0u);
    EXPECT_EQ(engine.observe(0).phase, SweepState::kRunning);
    engine.resume();
    EXPECT_EQ(engine.observe(0).cycles, end.cycles) << "cycles count from START, not from RESUME";
    EXPECT_EQ(engine.observe(0).buffer_count, 0u);
    while (engine.phase() == SweepState::kPaused) engine.resume();
    EXPECT_EQ(engine.phase(), SweepState::kDone);
    EXPECT_EQ(engine.pairs().size(), 190u);
    EXPECT_THROW(engine.resume(), std::logic_error);
}

// One engine over many frames (as a shell would keep it): each frame as a fresh engine sees it.
TEST(FastEngine, ReusedAcrossFramesOfAnySize) {
    std::mt19937 rng(12);
    const BoardConfig config = collector_config(6, 11, 2, 40);
    FastEngine reused(config);
    for (uint32_t n : {3000u, 5u, 700u, 0u, 1500u, 2u}) {
        const WordScene scene = testing::random_scene(n, 3.0f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng);
        FastEngine fresh(config);
        reused.start(n, scene.view());
        fresh.start(n, scene.view());
        for (;;) {
            const BoardObservation a = reused.observe(reused.segment_cycles()), b = fresh.observe(fresh.segment_cycles());
            ASSERT_EQ(reused.segment_cycles(), fresh.segment_cycles()) << n;
            ASSERT_EQ(a.cycles, b.cycles) << n;
            ASSERT_EQ(a.stalls, b.stalls) << n;
            ASSERT_EQ(a.buffer_count, b.buffer_count) << n;
            ASSERT_EQ(reused.phase(), fresh.phase()) << n;
            if (reused.phase() == SweepState::kDone) break;
            reused.resume();
            fresh.resume();
        }
        EXPECT_EQ(reused.pairs(), testing::lane_hit_pairs(scene)) << n;
    }
}

// Beyond 65,536 boxes, where the board itself is too slow to step here: the
// cycle identity and the pairs of the all-pairs search.
TEST(FastEngine, BeyondSixtyFiveThousandBoxes) {
    std::mt19937 rng(10);
    const uint32_t n = 70000;
    const WordScene scene = testing::random_scene(n, 4.0f * std::cbrt(static_cast<float>(n)), 2.0f, rng);
    const BoardConfig config = collector_config(16, 31, 1, 1024);
    FastEngine engine(config);
    engine.start(n, scene.view());
    uint64_t segments = 1;
    for (; engine.phase() == SweepState::kPaused; ++segments) engine.resume();
    const BoardObservation end = engine.observe(engine.segment_cycles());
    EXPECT_EQ(end.total_pairs, engine.pairs().size());
    EXPECT_EQ(segments, (engine.pairs().size() + 1023) / 1024);
    EXPECT_EQ(end.cycles, AddressGenerator::sweep_cycles(n, 16) + config.pipeline_latency() + end.stalls);
    // Every pair found meets, and 300 random rows hold every pair they should.
    const PairList& pairs = engine.pairs();
    EXPECT_GT(pairs.size(), 3000u);
    EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
    auto meet = [&](uint32_t i, uint32_t j) {
        float a[kCoordinates], b[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            a[c] = ComparisonUnit::as_float(scene.words[c][i]);
            b[c] = ComparisonUnit::as_float(scene.words[c][j]);
        }
        return ComparisonUnit::lane_hit(a, b);
    };
    EXPECT_TRUE(std::all_of(pairs.begin(), pairs.end(), [&](const IndexPair& p) { return meet(p.first, p.second); }));
    for (int sample = 0; sample < 300; ++sample) {
        const uint32_t i = static_cast<uint32_t>(rng() % n);
        PairList row;
        for (uint32_t j = i + 1; j < n; ++j) {
            if (meet(i, j)) row.push_back({i, j});
        }
        const auto first = std::lower_bound(pairs.begin(), pairs.end(), IndexPair{i, 0});
        const auto last = std::lower_bound(pairs.begin(), pairs.end(), IndexPair{i + 1, 0});
        ASSERT_EQ(PairList(first, last), row) << "row " << i;
    }
}

}  // namespace
}  // namespace cdvp
