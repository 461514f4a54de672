// The board's datapath against the plain C++ reference, without a kernel.
#include "models/board/board_core.h"
#include "models/address_generator/address_generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "sw/baselines/brute_force.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using testing::CoreRun;
using testing::random_boxes;
using testing::run_core;


void expect_cycle_identity(const CoreRun& run, uint64_t n, const BoardConfig& config) {
    EXPECT_EQ(run.cycles, AddressGenerator::sweep_cycles(n, config.m) + config.pipeline_latency() + run.stalls)
        << "compute_cycles = S(N,m) + L + stalls, N=" << n << " m=" << config.m;
}

TEST(BoardCore, EqualsReferenceOnRandomScenes) {
    std::mt19937 rng(2026);
    for (uint32_t m : {1u, 2u, 3u, 8u, 16u}) {
        for (std::size_t n : {0u, 1u, 2u, 3u, 29u, 512u, 513u, 1100u, 2000u}) {
            if (m == 1 && n > 1100) continue;  // covered by the larger m; keeps the test quick
            BoardConfig config;
            config.m = m;
            BoardCore core(config, static_cast<uint32_t>(n));
            // Extent scaled so each box meets a few others on average.
            const auto boxes = random_boxes(n, 10.0f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng);
            const CoreRun run = run_core(core, boxes);
            ASSERT_EQ(sorted(run.pairs), reference_pairs(boxes)) << "n=" << n << " m=" << m;
            expect_cycle_identity(run, n, config);
        }
    }
}

TEST(BoardCore, CascadedBlockRamsBeyond512Boxes) {
    BoardConfig config;
    config.m = 4;
    BoardCore core(config, 1500);
    EXPECT_EQ(core.block_rams(), 6u * 4u * 3u);
    std::mt19937 rng(5);
    // Make box 1499 (in the third primitive) overlap box 3 (in the first) only.
    auto boxes = random_boxes(1500, 1000.0f, 0.5f, rng);
    boxes[1499] = boxes[3];
    const PairList pairs = sorted(run_core(core, boxes).pairs);
    EXPECT_EQ(pairs, reference_pairs(boxes));
    EXPECT_TRUE(std::binary_search(pairs.begin(), pairs.end(), IndexPair{3, 1499}));
}

// Every box overlaps every other: 2m-1 hits a cycle against a drain of one a
// cycle. The FIFO fills, the pipeline holds, and still no pair is lost.
TEST(BoardCore, BackPressureLosesNoPair) {
    const uint32_t n = 300;
    for (uint32_t fifo : {15u, 16u, 64u}) {
        BoardConfig config;
        config.m = 8;
        config.collector.fifo_depth = fifo;
        BoardCore core(config, n);
        const std::vector<FloatBox> boxes(n, FloatBox{{0, 0, 0}, {1, 1, 1}});
        const CoreRun run = run_core(core, boxes);
        EXPECT_EQ(run.pairs.size(), n * (n - 1) / 2);
        EXPECT_EQ(std::set<IndexPair>(run.pairs.begin(), run.pairs.end()).size(), run.pairs.size()) << "duplicates";
        EXPECT_EQ(sorted(run.pairs), reference_pairs(boxes));
        EXPECT_GT(run.stalls, 0u);
        expect_cycle_identity(run, n, config);
        // With one pair drained a cycle, the sweep cannot beat the pair count.
        EXPECT_GE(run.cycles, run.pairs.size());
    }
}

TEST(BoardCore, FasterDrainStallsLess) {
    const uint32_t n = 300;
    uint64_t previous = UINT64_MAX;
    for (uint32_t drain : {1u, 4u, 15u}) {
        BoardConfig config;
        config.m = 8;
        config.collector.fifo_depth = 32;
        config.collector.drain_per_cycle = drain;
        BoardCore core(config, n);
        const CoreRun run = run_core(core, std::vector<FloatBox>(n, FloatBox{{0, 0, 0}, {1, 1, 1}}));
        EXPECT_EQ(run.pairs.size(), n * (n - 1) / 2);
        expect_cycle_identity(run, n, config);
        EXPECT_LT(run.stalls, previous) << "drain " << drain;
        previous = run.stalls;
    }
    EXPECT_EQ(previous, 0u) << "draining 2m-1 a cycle never stalls";
}

// A pair buffer far smaller than the pair set: the board pauses, the host
// drains and resumes, and every pair arrives exactly once.
TEST(BoardCore, PairBufferOverflowPausesAndResumes) {
    std::mt19937 rng(11);
    for (uint32_t depth : {1u, 7u, 100u}) {
        BoardConfig config;
        config.m = 4;
        config.collector.buffer_depth = depth;
        config.collector.drain_per_cycle = 3;
        BoardCore core(config, 400);
        const auto boxes = random_boxes(400, 10.0f, 4.0f, rng);
        const CoreRun run = run_core(core, boxes);
        const PairList expected = reference_pairs(boxes);
        ASSERT_GT(expected.size(), 10u * depth);
        EXPECT_EQ(sorted(run.pairs), expected) << "depth " << depth;
        EXPECT_GE(run.pauses, expected.size() / depth - 1);
        expect_cycle_identity(run, 400, config);
    }
}

TEST(BoardCore, LatencyIsBlockRamPlusComparePlusCollector) {
    std::mt19937 rng(3);
    const auto boxes = random_boxes(50, 10.0f, 3.0f, rng);
    for (uint32_t latency : {0u, 1u, 2u, 5u}) {
        BoardConfig config;
        config.m = 2;
        config.compare.latency_cycles = latency;
        EXPECT_EQ(config.pipeline_latency(), latency + 2);
        BoardCore core(config, 50);
        const CoreRun run = run_core(core, boxes);
        EXPECT_EQ(sorted(run.pairs), reference_pairs(boxes));
        expect_cycle_identity(run, 50, config);
    }
}

// Small N against many m, with a FIFO of exactly 2m-1, over dense scenes.
TEST(BoardCore, CycleIdentityOverSmallScenes) {
    std::mt19937 rng(17);
    for (uint32_t m = 1; m <= 6; ++m) {
        for (uint32_t n = 0; n <= 40; ++n) {
            BoardConfig config;
            config.m = m;
            config.collector.fifo_depth = 2 * m - 1;
            config.collector.buffer_depth = 16;
            BoardCore core(config, n);
            const auto boxes = random_boxes(n, 4.0f, 2.0f, rng);
            const CoreRun run = run_core(core, boxes);
            ASSERT_EQ(sorted(run.pairs), reference_pairs(boxes)) << n << " " << m;
            expect_cycle_identity(run, n, config);
        }
    }
}

TEST(BoardCore, RegistersAndRefusedCommands) {
    BoardConfig config;
    config.m = 2;
    BoardCore core(config, 10);
    uint32_t value = 0;
    ASSERT_TRUE(core.read_register(ControlRegisters::kId, value));
    EXPECT_EQ(value, ControlRegisters::kIdValue);
    ASSERT_TRUE(core.read_register(ControlRegisters::kCapacity, value));
    EXPECT_EQ(value, 10u);
    ASSERT_TRUE(core.read_register(ControlRegisters::kParallelism, value));
    EXPECT_EQ(value, 2u);
    EXPECT_FALSE(core.read_register(0x3FC, value)) << "unmapped";
    using Write = RegisterResult;
    EXPECT_EQ(core.write_register(0x3FC, 1), Write::kUnmapped);
    EXPECT_EQ(core.write_coordinate(kMinX, 10, 0), Write::kUnmapped) << "past capacity";

    core.write_register(ControlRegisters::kObjectCount, 11);
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
    EXPECT_TRUE(core.status().error) << "more objects than the memories hold";
    EXPECT_EQ(core.status().error_cause, ControlRegisters::kTooManyObjects);
    EXPECT_TRUE(core.interrupt()) << "an error interrupts like done";
    EXPECT_FALSE(core.running());

    core.write_register(ControlRegisters::kObjectCount, 10);
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
    EXPECT_FALSE(core.status().error);
    EXPECT_TRUE(core.running());
    ASSERT_TRUE(core.read_register(ControlRegisters::kStatus, value));
    EXPECT_EQ(value, uint32_t{ControlRegisters::kBusy});
    EXPECT_EQ(core.write_coordinate(kMinX, 0, 0), Write::kRefused) << "memories are locked while busy";
    EXPECT_EQ(core.status().error_cause, ControlRegisters::kWriteWhileBusy);
    EXPECT_EQ(core.write_register(ControlRegisters::kObjectCount, 3), Write::kRefused) << "the sweep's count is fixed";
    ASSERT_TRUE(core.read_register(ControlRegisters::kObjectCount, value));
    EXPECT_EQ(value, 10u) << "read-back equals the count the sweep uses";
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
    EXPECT_TRUE(core.status().error) << "start while busy";
    EXPECT_EQ(core.status().error_cause, ControlRegisters::kStartWhileBusy);
    while (core.running()) core.step();
    EXPECT_EQ(core.phase(), SweepState::kDone);
    EXPECT_TRUE(core.interrupt());
    core.write_register(ControlRegisters::kControl, ControlRegisters::kAcknowledge);
    EXPECT_FALSE(core.interrupt()) << "acknowledged: the shared line may fall";
    EXPECT_TRUE(core.status().done) << "acknowledging keeps the status";
    ASSERT_TRUE(core.read_register(ControlRegisters::kCyclesLo, value));
    EXPECT_EQ(value, AddressGenerator::sweep_cycles(10, 2) + config.pipeline_latency() + core.counters().stalls);
    core.write_register(ControlRegisters::kControl, ControlRegisters::kResume);
    EXPECT_TRUE(core.status().error) << "resume without a pause";
    EXPECT_EQ(core.status().error_cause, ControlRegisters::kResumeNotPaused);
}

TEST(BoardCore, AbortStopsASweepAndClearsEveryStatusBit) {
    BoardConfig config;
    config.m = 1;
    BoardCore core(config, 50);
    core.write_register(ControlRegisters::kObjectCount, 50);
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
    core.step();
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
    ASSERT_TRUE(core.status().error);
    core.write_register(ControlRegisters::kControl, ControlRegisters::kAbort);
    EXPECT_EQ(core.phase(), SweepState::kIdle);
    EXPECT_EQ(core.status().bits(), 0u);
    EXPECT_EQ(core.status().error_cause, ControlRegisters::kNoError);
    EXPECT_FALSE(core.interrupt());
    EXPECT_EQ(core.write_register(ControlRegisters::kObjectCount, 4), RegisterResult::kDone) << "idle again";
}

TEST(BoardCore, FormatRegisterAndMemoriesAsWideAsTheFormat) {
    for (uint32_t k : {0u, 8u, 16u, 32u}) {
        BoardConfig config;
        config.format = NumberFormat::from_register(k);
        BoardCore core(config, 4);
        uint32_t value = 99;
        ASSERT_TRUE(core.read_register(ControlRegisters::kFormat, value));
        EXPECT_EQ(value, k);
        core.write_register(ControlRegisters::kFormat, 12);  // read-only: ignored
        ASSERT_TRUE(core.read_register(ControlRegisters::kFormat, value));
        EXPECT_EQ(value, k);
        core.write_coordinate(kMinX, 0, 0xDEAD'BEEFu);
        EXPECT_EQ(core.read_coordinate(kMinX, 0), 0xDEAD'BEEFu & config.format.word_mask()) << k;
        const unsigned char words[8] = {0xFF, 0xFF, 0xFF, 0xFF, 0x34, 0x12, 0xCD, 0xAB};
        core.write_coordinates(kMaxY, 1, words, 2);
        EXPECT_EQ(core.read_coordinate(kMaxY, 1), 0xFFFF'FFFFu & config.format.word_mask());
        EXPECT_EQ(core.read_coordinate(kMaxY, 2), 0xABCD'1234u & config.format.word_mask());
    }
}

TEST(BoardConfig, RejectsAbsurdSettings) {
    auto invalid = [](auto change) {
        BoardConfig config;
        change(config);
        EXPECT_THROW(config.validate(), std::invalid_argument);
    };
    invalid([](BoardConfig& c) { c.m = 0; });
    invalid([](BoardConfig& c) { c.m = 33; });
    invalid([](BoardConfig& c) { c.clock_mhz = 0; });
    invalid([](BoardConfig& c) { c.clock_mhz = std::nan(""); });
    invalid([](BoardConfig& c) { c.collector.fifo_depth = 14; });  // < 2m-1 for m=8
    invalid([](BoardConfig& c) { c.collector.drain_per_cycle = 0; });
    invalid([](BoardConfig& c) { c.collector.buffer_depth = 0; });
    invalid([](BoardConfig& c) { c.compare.latency_cycles = 65; });
    BoardConfig ok;
    EXPECT_NO_THROW(ok.validate());
    EXPECT_EQ(ok.pipeline_latency(), 4u);
}

}  // namespace
}  // namespace cdvp

namespace cdvp {
namespace {

void load(BoardCore& core, const std::vector<FloatBox>& boxes) {
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            const float v = c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3];
            core.write_coordinate(static_cast<Coordinate>(c), i, ComparisonUnit::as_bits(v));
        }
    }
    core.write_register(ControlRegisters::kObjectCount, static_cast<uint32_t>(boxes.size()));
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
}

// A board whose engine computed each segment ahead answers, at every edge,
// exactly what a board stepped edge by edge shows: the host may look at any time.
TEST(BoardCore, ASegmentComputedAheadAnswersForEveryEdge) {
    std::mt19937 rng(23);
    for (uint32_t depth : {1u, 5u, 64u}) {
        BoardConfig config;
        config.m = 3;
        config.collector.fifo_depth = 5;
        config.collector.buffer_depth = depth;
        const auto boxes = random_boxes(90, 6.0f, 3.0f, rng);
        BoardCore stepped(config, 90), ahead(config, 90);
        load(stepped, boxes);
        load(ahead, boxes);
        uint32_t segments = 0;
        for (;;) {
            ++segments;
            const uint64_t edges = ahead.segment_edges();
            for (uint64_t e = 1; e <= edges; ++e) {
                stepped.step();
                ahead.advance_to(e);
                ASSERT_EQ(ahead.counters(), stepped.counters()) << "edge " << e << " of segment " << segments;
                ASSERT_EQ(ahead.status().bits(), stepped.status().bits()) << "edge " << e;
            }
            ASSERT_FALSE(stepped.running()) << "the stepped board ends its segment at the same edge";
            ASSERT_EQ(ahead.buffered_pairs(), stepped.buffered_pairs());
            for (uint32_t k = 0; k < ahead.buffered_pairs(); ++k) {
                ASSERT_EQ(ahead.buffered_pair(k), stepped.buffered_pair(k));
            }
            if (stepped.phase() == SweepState::kDone) break;
            stepped.write_register(ControlRegisters::kControl, ControlRegisters::kResume);
            ahead.write_register(ControlRegisters::kControl, ControlRegisters::kResume);
        }
        if (depth < 64) {
            EXPECT_GT(segments, 10u) << "many overflow pauses";
        }
    }
}

// A burst read of the pair buffer copies the words the host would read pair
// by pair (first, then second), from an even or an odd word, on both engines.
TEST(BoardCore, BufferedWordsAreThePairsFirstThenSecond) {
    std::mt19937 rng(31);
    const auto boxes = random_boxes(200, 8.0f, 3.0f, rng);
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 37;  // pauses with a full buffer
    for (Fidelity fidelity : {Fidelity::kCycle, Fidelity::kFast}) {
        BoardCore core(config, 200, fidelity);
        load(core, boxes);
        core.advance_to(core.segment_edges());
        const uint32_t buffered = core.buffered_pairs();
        ASSERT_EQ(buffered, 37u) << to_string(fidelity);
        std::vector<uint32_t> expected;
        for (uint32_t k = 0; k < buffered; ++k) {
            expected.push_back(core.buffered_pair(k).first);
            expected.push_back(core.buffered_pair(k).second);
        }
        for (uint64_t first : {0u, 1u, 9u}) {
            const uint64_t count = expected.size() - first;
            std::vector<uint32_t> words(count);
            core.copy_window_words(first, count, reinterpret_cast<unsigned char*>(words.data()));
            EXPECT_TRUE(std::equal(words.begin(), words.end(), expected.begin() + first)) << to_string(fidelity) << " from word " << first;
        }
    }
}

// ABORT in the middle of a segment computed ahead keeps what the buffer held then.
TEST(BoardCore, AbortAfterComputingAheadKeepsTheBufferOfThatEdge) {
    BoardConfig config;
    config.m = 2;
    const std::vector<FloatBox> boxes(60, FloatBox{{0, 0, 0}, {1, 1, 1}});
    BoardCore stepped(config, 60), ahead(config, 60);
    load(stepped, boxes);
    load(ahead, boxes);
    ASSERT_GT(ahead.segment_edges(), 500u);
    for (int e = 0; e < 400; ++e) stepped.step();
    ahead.advance_to(400);
    const SweepCounters before = stepped.counters();
    ahead.write_register(ControlRegisters::kControl, ControlRegisters::kAbort);
    stepped.write_register(ControlRegisters::kControl, ControlRegisters::kAbort);
    EXPECT_EQ(ahead.phase(), SweepState::kIdle);
    EXPECT_EQ(ahead.counters(), before);
    ASSERT_EQ(ahead.buffered_pairs(), before.buffered);
    for (uint32_t k = 0; k < before.buffered; ++k) EXPECT_EQ(ahead.buffered_pair(k), stepped.buffered_pair(k));
}

// The driver bounds a sweep by what these registers say, not by a copy of the
// board's configuration.
TEST(BoardCore, TileRegistersDescribeTheMemoryTheBoardWasBuiltWith) {
    auto read = [](BoardCore& core, uint32_t offset) {
        uint32_t value = 0xFFFF'FFFFu;
        EXPECT_TRUE(core.read_register(offset, value));
        return value;
    };
    BoardConfig block_ram;
    BoardCore untiled(block_ram, 64);
    EXPECT_EQ(read(untiled, ControlRegisters::kTileBoxes), 0u);
    EXPECT_EQ(read(untiled, ControlRegisters::kTileTiming), 0u);

    BoardConfig ssram;
    ssram.tiles.boxes = 96;
    ssram.tiles.load_latency_cycles = 5;
    ssram.tiles.cycles_per_box = 3;
    BoardCore tiled(ssram, 1000);
    EXPECT_EQ(read(tiled, ControlRegisters::kTileBoxes), 96u);
    const uint32_t timing = read(tiled, ControlRegisters::kTileTiming);
    EXPECT_EQ(timing & ControlRegisters::kTileTimingLatencyMask, 5u);
    EXPECT_EQ(timing >> ControlRegisters::kTileTimingCyclesShift, 3u);
    tiled.write_register(ControlRegisters::kTileBoxes, 7);  // read-only: ignored
    EXPECT_EQ(read(tiled, ControlRegisters::kTileBoxes), 96u);
}

}  // namespace
}  // namespace cdvp
