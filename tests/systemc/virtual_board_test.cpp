// The whole platform (host thread + board) against the reference.
#include "platform/virtual_board.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "platform/settings/board_preset.h"
#include "tests/support/preset_platform.h"
#include "sw/baselines/brute_force.h"
#include "tests/support/core_driver.h"
#include "tests/support/vcd_reader.h"

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

// --vcd-frames: outside the window no signal moves, the bus's, the bridge's
// and the interrupts' no more than the board's; inside it every block does.
TEST(VirtualBoard, AWindowOfFramesHoldsEverySignalOutsideIt) {
    char dir[] = "/tmp/cdvp-window-XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    const std::string base = std::string(dir) + "/waves";
    std::vector<sc_time> frame_ends;
    {
        VirtualBoard platform("platform", testing::preset_platform("adm-xrc-ii"), 60, base);
        platform.set_trace_window(1, 1);
        std::mt19937 rng(5);
        for (int frame = 0; frame < 3; ++frame) {
            platform.run_frame(testing::random_boxes(60, 8.0f, 2.0f, rng));
            frame_ends.push_back(sc_time_stamp());
        }
        platform.close_trace();
    }
    // The kernel's resolution and the VCD's unit are both 1 fs.
    const uint64_t window_begin = frame_ends[0].value(), window_end = frame_ends[1].value();
    const test::Vcd vcd = test::read_vcd_text(slurp(base + ".vcd"));
    std::map<std::string, int> moves_inside;  // by the signal's block
    for (const test::VcdChange& change : vcd.changes) {
        if (change.time == 0) continue;  // the initial values
        EXPECT_GE(change.time, window_begin) << change.id << " moved before the window";
        EXPECT_LE(change.time, window_end) << change.id << " moved after the window";
        for (const auto& [name, id] : vcd.id_of) {
            if (id == change.id) ++moves_inside[name.substr(0, name.rfind('.'))];
        }
    }
    for (const char* block : {"SystemC.platform", "SystemC.platform.pci", "SystemC.platform.bridge.dma",
                              "SystemC.platform.board.control"}) {
        EXPECT_GT(moves_inside[block], 0) << block << " is traced in the window";
    }
    std::remove((base + ".vcd").c_str());
    rmdir(dir);
}

}  // namespace
}  // namespace cdvp
