// Fault injection on the whole platform: every kind either recovers with the
// complete pair set or fails its frame loudly (DeviceFault), and the next
// frame runs clean.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "platform/settings/board_preset.h"
#include "tests/support/preset_platform.h"
#include "platform/fault_injection.h"
#include "platform/virtual_board.h"
#include "sw/baselines/brute_force.h"
#include "sw/scene/scene.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

PlatformConfig faulty_paper_platform(const std::string& faults, bool interrupts = true, bool dma = true) {
    PlatformConfig config = testing::preset_platform("adm-xrc-ii");
    config.faults = parse_fault_specs(faults);
    config.board.collector.buffer_depth = 64;  // a few overflow pauses per frame
    config.driver.wait = (interrupts) ? WaitMode::kIrq : WaitMode::kPoll;
    config.driver.transfer = (dma) ? Transfer::kDma : Transfer::kPio;
    return config;
}

std::vector<FloatBox> scene() {
    std::mt19937 rng(7);
    return testing::random_boxes(300, 25.0f, 3.0f, rng);
}

std::string message_of_failed_frame(VirtualBoard& platform, const std::vector<FloatBox>& boxes) {
    try {
        platform.run_frame(boxes);
    } catch (const DeviceFault& e) {
        return e.what();
    }
    ADD_FAILURE() << "the injected fault did not fail the frame";
    return "";
}

// Frames 0 and 2 run clean, frame 1 carries the fault; returns frame 1's result.
FrameResult run_three_frames(VirtualBoard& platform, const std::vector<FloatBox>& boxes, FramePhases& clean) {
    clean = platform.run_frame(boxes).phases;
    const FrameResult injected = platform.run_frame(boxes);
    const FrameResult& after = platform.run_frame(boxes);
    EXPECT_EQ(sorted(after.pairs), reference_pairs(boxes));
    EXPECT_NEAR(after.phases.total_ns, clean.total_ns, 1e-3) << "the fault left nothing behind";
    return injected;
}

TEST(FaultSpecs, ParseKindsFramesAndCounts) {
    const std::vector<FaultSpec> specs = parse_fault_specs("retry@frame=3,n=2; lost-irq@frame=1 board-error@frame=9");
    ASSERT_EQ(specs.size(), 3u);
    EXPECT_EQ(specs[0], (FaultSpec{FaultKind::kRetry, 3, 2}));
    EXPECT_EQ(specs[1], (FaultSpec{FaultKind::kLostIrq, 1, 1}));
    EXPECT_EQ(specs[2], (FaultSpec{FaultKind::kBoardError, 9, 1}));
    EXPECT_EQ(to_string(specs[0]), "retry@frame=3,n=2");
    for (FaultKind kind : kAllFaultKinds) {
        const std::string text = std::string(fault_kind_name(kind)) + "@frame=1";
        EXPECT_EQ(to_string(parse_fault_specs(text).at(0)), text);
    }
}

TEST(FaultSpecs, RejectBadSpecsNamingWhatWasExpected) {
    auto message = [](const std::string& text) {
        try {
            parse_fault_specs(text);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("explode@frame=1"),
              "'explode@frame=1': unknown fault kind 'explode'; expected one of: target-abort, "
              "master-abort, retry, disconnect, lost-irq, dma-hang, board-error");
    EXPECT_EQ(message("retry"), "'retry': expected KIND@frame=N[,n=K]");
    EXPECT_EQ(message("retry@n=2"), "'retry@n=2': expected frame=N after '@'");
    EXPECT_EQ(message("retry@frame=x"),
              "'retry@frame=x': frame: expected an integer from 0 to 18446744073709551615, found 'x'");
    EXPECT_EQ(parse_fault_specs("retry@frame=0")[0].frame, 0u);
    EXPECT_NE(message("retry@frame=-1").find("found '-1'"), std::string::npos);
    EXPECT_NE(message("retry@frame=2.5").find("found '2.5'"), std::string::npos);
    EXPECT_NE(message("retry@frame=99999999999999999999").find("found '99999999999999999999'"), std::string::npos);
    EXPECT_NE(message("retry@frame=1,n=0").find("n: expected an integer from 1 to 1000000"), std::string::npos);
    EXPECT_NE(message("retry@frame=1,frame=2").find("unexpected 'frame=2'"), std::string::npos);
    EXPECT_NE(message("retry@frame=1,when=now").find("unexpected 'when=now'"), std::string::npos);
    EXPECT_NE(message(" ; ").find("expected KIND@frame=N"), std::string::npos);
}

TEST(FaultInjection, RetryAndDisconnectCompleteWithEveryPairAndCostBusTime) {
    // Elaborate every platform before the first one runs.
    VirtualBoard retry("retry", faulty_paper_platform("retry@frame=1,n=3"), 300);
    VirtualBoard disconnect("disconnect", faulty_paper_platform("disconnect@frame=1,n=3"), 300);
    for (VirtualBoard* each : {&retry, &disconnect}) {
        const std::string kind = each->basename();
        SCOPED_TRACE(kind);
        VirtualBoard& platform = *each;
        const auto boxes = scene();
        FramePhases clean;
        const FrameResult injected = run_three_frames(platform, boxes, clean);
        EXPECT_EQ(sorted(injected.pairs), reference_pairs(boxes));
        EXPECT_EQ(platform.bridge().repeated_transactions(), 3u);
        EXPECT_EQ(platform.faults().injected(kind == "retry" ? FaultKind::kRetry : FaultKind::kDisconnect), 3u);
        EXPECT_GT(injected.phases.total_ns, clean.total_ns) << "a repeated transaction costs bus time";
        EXPECT_LT(injected.phases.total_ns, clean.total_ns + 3 * 2000.0) << "no more than three short transactions";
    }
}

TEST(FaultInjection, ALostInterruptIsRecoveredByTheTimeoutsStatusPoll) {
    VirtualBoard platform("platform", faulty_paper_platform("lost-irq@frame=1,n=2"), 300);
    const auto boxes = scene();
    FramePhases clean;
    const FrameResult injected = run_three_frames(platform, boxes, clean);
    EXPECT_EQ(sorted(injected.pairs), reference_pairs(boxes));
    EXPECT_EQ(injected.phases.timeouts_recovered, 2u);
    EXPECT_EQ(clean.timeouts_recovered, 0u);
    EXPECT_GT(injected.phases.total_ns, clean.total_ns + 2 * 100000.0) << "each lost interrupt costs a timeout";
}

TEST(FaultInjection, AbortsHangsAndBoardErrorsFailTheFrameAndTheNextFrameRunsClean) {
    struct Case {
        const char* spec;
        const char* message;
    };
    const Case cases[] = {
        {"target-abort@frame=1", "DMA fault: target abort (the board rejected the address) at address 0x1000000"},
        {"master-abort@frame=1", "DMA fault: descriptor fetch failed (master abort) at address 0x"},
        {"dma-hang@frame=1", "DMA timed out: no completion within "},
        {"board-error@frame=1", "board error status: the board reported an error (injected board-error)"},
    };
    std::vector<std::unique_ptr<VirtualBoard>> platforms;
    for (const Case& c : cases) {
        const std::string name = "platform" + std::to_string(platforms.size());
        platforms.push_back(std::make_unique<VirtualBoard>(name.c_str(), faulty_paper_platform(c.spec), 300));
    }
    for (std::size_t k = 0; k < platforms.size(); ++k) {
        const Case& c = cases[k];
        SCOPED_TRACE(c.spec);
        VirtualBoard& platform = *platforms[k];
        const auto boxes = scene();
        EXPECT_EQ(sorted(platform.run_frame(boxes).pairs), reference_pairs(boxes));
        const std::string message = message_of_failed_frame(platform, boxes);
        EXPECT_EQ(message.rfind(c.message, 0), 0u) << message;
        EXPECT_EQ(sorted(platform.run_frame(boxes).pairs), reference_pairs(boxes)) << "recovered for the next frame";
    }
}

TEST(FaultInjection, AMasterAbortOnTheUploadChainFailsAtItsFirstDescriptor) {
    // The upload chain's first bus-master access is its first descriptor.
    VirtualBoard platform("platform", faulty_paper_platform("master-abort@frame=0"), 300);
    const auto boxes = scene();
    const std::string message = message_of_failed_frame(platform, boxes);
    EXPECT_EQ(message.rfind("DMA fault: descriptor fetch failed (master abort)", 0), 0u) << message;
    EXPECT_EQ(platform.faults().injected(FaultKind::kMasterAbort), 1u);
}

TEST(FaultInjection, PollingDriverIsImmuneToLostInterruptsAndStillTimesOutAHang) {
    VirtualBoard platform("platform", faulty_paper_platform("lost-irq@frame=0; dma-hang@frame=1", false), 300);
    const auto boxes = scene();
    EXPECT_EQ(sorted(platform.run_frame(boxes).pairs), reference_pairs(boxes));
    EXPECT_EQ(message_of_failed_frame(platform, boxes).rfind("DMA timed out", 0), 0u);
    EXPECT_EQ(sorted(platform.run_frame(boxes).pairs), reference_pairs(boxes));
}

TEST(FaultInjection, ATimeoutPastTheSimulatorsClockIsRefused) {
    PlatformConfig config = faulty_paper_platform("retry@frame=99");
    config.driver.timeout_factor = 1e12;
    VirtualBoard platform("platform", config, 300);
    try {
        platform.run_frame(scene());
        ADD_FAILURE() << "accepted";
    } catch (const SimulatedTimeLimit& e) {
        EXPECT_NE(std::string(e.what()).find("of simulated time could last until "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(", past the limit of 9223.372 s (2^63 fs"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace cdvp
