// HostPort's contract (platform/driver/host_port.h) held where the driver can
// see it: a port that breaks a rule gets a one-line error naming the rule,
// not a hang or wrong times; the same port keeping the rule runs the frames.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "models/board/board_core.h"
#include "platform/driver/board_driver.h"
#include "sw/baselines/brute_force.h"
#include "tests/driver/direct_port.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using testing::DirectPort;

std::vector<std::vector<FloatBox>> scenes(int frames) {
    std::mt19937 rng(9);
    std::vector<std::vector<FloatBox>> boxes;
    for (int k = 0; k < frames; ++k) boxes.push_back(testing::random_boxes(200, 12.0f, 3.0f, rng));
    return boxes;
}

// Polls that pause a gap of 700.0001 ns: 700,000,100 fs, which a clock of
// whole picoseconds rounds.
DriverConfig polling_with_an_odd_gap() {
    DriverConfig config;
    config.transfer = Transfer::kPio;
    config.wait = WaitMode::kPoll;
    config.poll_gap_ns = 700.0001;
    return config;
}

// Runs `frames` one at a time; returns the first error's text, empty when every frame matched.
std::string run_frames(DirectPort::Fault fault) {
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 500;  // its pair area fits the port's 1 MiB
    BoardCore board(config, 200, Fidelity::kFast);
    const SimTime period = fs_from_ns(15.0);
    DirectPort port(board, period, fs_from_ns(100.0), DirectPort::kNoInterrupt, fault);
    BoardDriver driver(port, period, polling_with_an_odd_gap(), nullptr);
    driver.open();
    try {
        for (const std::vector<FloatBox>& boxes : scenes(3)) {
            PairList pairs;
            driver.run_frame(boxes, pairs);
            if (sorted(pairs) != reference_pairs(boxes)) return "pairs differ";
        }
    } catch (const PortContractError& e) {
        return e.what();
    }
    return "";
}

TEST(HostPortContract, AClockOfWholePicosecondsIsRefusedAtItsFirstRoundedWait) {
    EXPECT_EQ(run_frames(DirectPort::Fault::kNone), "");
    const std::string error = run_frames(DirectPort::Fault::kPicosecondClock);
    EXPECT_EQ(error,
              "the host port's clock moved 700000000 fs on a wait of 700000100 fs: a HostPort keeps time in whole "
              "femtoseconds (platform/driver/host_port.h)");
    EXPECT_EQ(error.find('\n'), std::string::npos);
}

// Frames pipelined on an untimed bus with interrupts: the driver reads the
// board's status before each wait (the sweep may have ended during the
// upload) and, no time having passed, asks for an interrupt since then. A
// port that returns at once for a handler it returned before would hold it
// in that loop for ever.
std::string submit_frames(DirectPort::Fault fault, int& finished) {
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 500;
    config.box_banks = 2;
    BoardCore board(config, 200, Fidelity::kFast);
    const SimTime period = fs_from_ns(15.0);
    DirectPort port(board, period, 0, fs_from_ns(1000.0), fault);
    DriverConfig driver_config;
    driver_config.transfer = Transfer::kPio;
    driver_config.wait = WaitMode::kIrq;
    BoardDriver driver(port, period, driver_config, nullptr);
    driver.open();
    const std::vector<std::vector<FloatBox>> frames = scenes(4);
    finished = 0;
    try {
        std::size_t next_result = 0;
        for (const std::vector<FloatBox>& boxes : frames) {
            PairList pairs;
            FramePhases phases;
            if (!driver.submit(boxes, pairs, phases)) continue;
            if (sorted(pairs) != reference_pairs(frames[next_result++])) return "pairs differ";
            ++finished;
        }
        PairList pairs;
        FramePhases phases;
        if (driver.finish(pairs, phases)) {
            if (sorted(pairs) != reference_pairs(frames[next_result])) return "pairs differ";
            ++finished;
        }
    } catch (const PortContractError& e) {
        return e.what();
    }
    return "";
}

TEST(HostPortContract, APortThatReturnsAnInterruptAgainIsRefusedInsteadOfLoopingForEver) {
    int finished = 0;
    EXPECT_EQ(submit_frames(DirectPort::Fault::kNone, finished), "");
    EXPECT_EQ(finished, 4);
    const std::string error = submit_frames(DirectPort::Fault::kInterruptTakenAgain, finished);
    EXPECT_NE(error.find("the host port returned at once twice for the interrupt at "), std::string::npos) << error;
    EXPECT_NE(error.find(": a HostPort takes each interrupt once (platform/driver/host_port.h)"), std::string::npos)
        << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace cdvp
