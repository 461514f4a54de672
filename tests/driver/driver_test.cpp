// The driver is host software on its own: here it runs against a port that
// reaches a plain C++ board directly, with no SystemC kernel at all.
#include "platform/driver/board_driver.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "models/address_generator/address_generator.h"
#include "models/board/board_core.h"
#include "sw/baselines/brute_force.h"
#include "tests/driver/direct_port.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using testing::DirectPort;

TEST(DriverWithoutKernel, RunsFramesThroughOverflowPausesByPioAndPolling) {
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 40;
    BoardCore board(config, 300);
    const SimTime period = fs_from_ns(15.0), access = fs_from_ns(100.0);
    DirectPort port(board, period, access);
    DriverConfig driver_config;
    driver_config.transfer = Transfer::kPio;
    driver_config.wait = WaitMode::kPoll;
    BoardDriver driver(port, period, driver_config, nullptr);
    driver.open();
    EXPECT_EQ(driver.capacity(), 300u);

    std::mt19937 rng(4);
    std::vector<FloatBox> boxes;
    for (int frame = 0; frame < 3; ++frame) {
        boxes = testing::random_boxes(300, 12.0f, 3.0f, rng);
        PairList pairs;
        const FramePhases phases = driver.run_frame(boxes, pairs);
        const PairList expected = reference_pairs(boxes);
        ASSERT_GT(expected.size(), 40u) << "the scene must overflow the pair buffer";
        EXPECT_EQ(sorted(pairs), expected);
        EXPECT_EQ(phases.overflow_pauses, (expected.size() - 1) / 40);
        EXPECT_EQ(phases.compute_cycles,
                  AddressGenerator::sweep_cycles(300, config.m) + config.pipeline_latency() + phases.stall_cycles);
        EXPECT_NEAR(phases.upload_ns + phases.start_ns + phases.compute_ns + phases.irq_ns + phases.readback_ns +
                        phases.driver_ns,
                    phases.total_ns, 1e-6 * phases.total_ns);
        // Polling notices the board within one poll (a status read and the gap of one board period).
        EXPECT_LE(phases.irq_ns, (phases.overflow_pauses + 1) * (100.0 + 15.0) + 1e-6);
    }
    for (uint32_t i = 0; i < 300; ++i) {
        ASSERT_EQ(ComparisonUnit::as_float(board.read_coordinate(kMaxZ, i)), boxes[i].max[2]) << "box " << i;
    }
}

// The read-back holds the pair budget for every engine: the clocked board
// pauses at each full buffer, and the driver refuses the buffer that would
// take the frame past its budget, with no pairs handed out.
TEST(DriverWithoutKernel, RefusesTheBufferThatWouldPassThePairBudget) {
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 40;
    BoardCore board(config, 300);
    const SimTime period = fs_from_ns(15.0);
    DirectPort port(board, period, fs_from_ns(100.0));
    std::mt19937 rng(4);
    const std::vector<FloatBox> boxes = testing::random_boxes(300, 12.0f, 3.0f, rng);
    const uint64_t all = reference_pairs(boxes).size();
    ASSERT_GT(all, 200u);
    DriverConfig driver_config;
    driver_config.transfer = Transfer::kPio;
    driver_config.wait = WaitMode::kPoll;
    driver_config.pair_budget = PairBudget(100);
    BoardDriver driver(port, period, driver_config, nullptr);
    driver.open();
    PairList pairs;
    try {
        driver.run_frame(boxes, pairs);
        ADD_FAILURE() << "a frame of " << all << " pairs passed a budget of 100";
    } catch (const PairBudgetExceeded& e) {
        EXPECT_EQ(e.found(), 120u) << "three full buffers of 40";
        EXPECT_EQ(e.budget(), 100u);
    }
    EXPECT_TRUE(pairs.empty());
}

}  // namespace
}  // namespace cdvp
