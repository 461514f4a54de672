// The whole platform (host thread + board) against the reference.
#include "platform/virtual_board.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "sw/baselines/brute_force.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using namespace sc_core;


TEST(VirtualBoard, FramesEqualTheReferenceAndTimeIsOnlyComputeTime) {
    BoardConfig config;
    config.m = 8;
    config.collector.buffer_depth = 64;  // the larger frames overflow it
    VirtualBoard platform("platform", config, 2000);
    std::mt19937 rng(99);
    sc_time board_time = SC_ZERO_TIME;
    uint32_t pauses = 0;
    for (std::size_t n : {2000u, 0u, 1u, 513u, 7u, 1200u}) {
        const auto boxes = testing::random_boxes(n, 6.0f * std::cbrt(static_cast<float>(n) + 1), 2.5f, rng);
        const FrameResult& r = platform.run_frame(boxes);
        ASSERT_EQ(sorted(r.pairs), reference_pairs(boxes)) << "n=" << n;
        EXPECT_EQ(r.phases.compute_cycles, AddressGenerator::sweep_cycles(n, 8) + config.pipeline_latency() + r.phases.stall_cycles);
        board_time += platform.board().period() * static_cast<double>(r.phases.compute_cycles);
        pauses += r.phases.overflow_pauses;
        EXPECT_FALSE(sc_pending_activity()) << "nothing may tick between frames";
    }
    EXPECT_GT(pauses, 0u) << "the scene should exercise the overflow path";
    // The host is untimed here, so simulated time is the board's compute time:
    // the clock never ran while the board was idle.
    EXPECT_EQ(sc_time_stamp(), board_time);
}

TEST(VirtualBoard, RefusesAFrameBeyondCapacity) {
    VirtualBoard platform("platform", BoardConfig{}, 10);
    EXPECT_THROW(platform.run_frame(std::vector<FloatBox>(11)), std::invalid_argument);
    EXPECT_EQ(platform.run_frame(std::vector<FloatBox>(10, FloatBox{{0, 0, 0}, {1, 1, 1}})).pairs.size(), 45u);
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(VirtualBoard, WaveformsOpenInGtkwaveTools) {
    char dir[] = "/tmp/cdvp-vcd-XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    const std::string base = std::string(dir) + "/waves";
    {
        BoardConfig config;
        config.m = 2;
        config.collector.fifo_depth = 3;
        VirtualBoard platform("platform", config, 40, base);
        const FrameResult& r = platform.run_frame(std::vector<FloatBox>(40, FloatBox{{0, 0, 0}, {1, 1, 1}}));
        EXPECT_EQ(r.pairs.size(), 780u);
        EXPECT_GT(r.phases.stall_cycles, 0u);
        platform.close_trace();
    }
    const std::string vcd = slurp(base + ".vcd");
    for (const char* name : {"clk", "state", "address_0", "address_3", "lane_valid", "lane_hit", "fifo_level",
                             "stall", "done", "pair_count", "irq"}) {
        EXPECT_NE(vcd.find(std::string(" ") + name + " "), std::string::npos) << name;
    }
    const std::string command = "vcd2fst '" + base + ".vcd' '" + base + ".fst' > /dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream fst(base + ".fst", std::ios::binary | std::ios::ate);
    EXPECT_GT(static_cast<long>(fst.tellg()), 100L);
    std::remove((base + ".vcd").c_str());
    std::remove((base + ".fst").c_str());
    rmdir(dir);
}

}  // namespace
}  // namespace cdvp
