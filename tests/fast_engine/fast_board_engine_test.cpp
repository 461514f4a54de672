// The fast engine behind the board's engine seam against the clocked engine:
// every BoardEngine query, segment by segment, and abort.
#include "models/fast_engine/fast_board_engine.h"

#include <gtest/gtest.h>

#include <random>

#include "models/clocked_engine/clocked_engine.h"
#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

BoardConfig small_board(uint32_t m, uint32_t buffer) {
    BoardConfig config;
    config.m = m;
    config.collector.fifo_depth = 2 * m - 1;
    config.collector.buffer_depth = buffer;
    return config;
}

// Both engines through the seam, with the clocked one asked first at each
// edge (it steps there) and the fast one after.
void expect_same_engines(const BoardConfig& config, const testing::WordScene& scene, std::mt19937& rng) {
    ClockedEngine clocked(config, scene.size());
    FastBoardEngine fast(config);
    testing::expect_same_engines(clocked, fast, scene, rng);
}

TEST(FastBoardEngine, AnswersAsTheClockedEngine) {
    std::mt19937 rng(21);
    for (uint32_t n : {0u, 1u, 2u, 40u, 513u, 1200u}) {
        const auto scene = testing::random_scene(n, 2.5f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng);
        expect_same_engines(small_board(3, 7), scene, rng);
        expect_same_engines(small_board(16, 262144), scene, rng);
        if (HasFailure()) return;
    }
    expect_same_engines(small_board(2, 5), testing::overlapping_scene(200, rng), rng);
}

TEST(FastBoardEngine, AnswersAsTheClockedEngineInEveryFormat) {
    std::mt19937 rng(23);
    for (uint32_t k : {0u, 8u, 9u, 16u, 18u, 24u, 31u, 32u}) {
        const NumberFormat format = NumberFormat::from_register(k);
        for (uint32_t n : {2u, 300u, 1100u}) {
            BoardConfig config = small_board(3, 7);
            config.format = format;
            expect_same_engines(config, testing::fixed_scene(n, format, 0.2, rng), rng);
            config = small_board(8, 262144);
            config.format = format;
            expect_same_engines(config, testing::fixed_scene(n, format, 0.05, rng), rng);
            if (HasFailure()) return;
        }
    }
}

// ABORT at any edge: the buffer keeps what it held then, in both.
TEST(FastBoardEngine, AbortKeepsTheBufferOfThatEdge) {
    std::mt19937 rng(22);
    const auto scene = testing::overlapping_scene(150, rng);
    const BoardConfig config = small_board(4, 500);
    testing::expect_same_aborts([&] { return std::make_unique<ClockedEngine>(config, scene.size()); },
                                [&] { return std::make_unique<FastBoardEngine>(config); }, scene, rng);
}

}  // namespace
}  // namespace cdvp
