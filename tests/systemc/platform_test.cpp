// The whole platform on a timed bus: driver, PCI bus, bridge DMA, board.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>

#include "platform/settings/board_preset.h"
#include "tests/support/preset_platform.h"
#include "platform/virtual_board.h"
#include "sw/baselines/brute_force.h"
#include "sw/scene/scene.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {


PlatformConfig paper_platform(bool dma = true, bool interrupts = true) {
    PlatformConfig config = testing::preset_platform("adm-xrc-ii");
    config.driver.transfer = (dma) ? Transfer::kDma : Transfer::kPio;
    config.driver.wait = (interrupts) ? WaitMode::kIrq : WaitMode::kPoll;
    return config;
}

std::vector<FloatBox> scene(std::size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    return testing::random_boxes(n, 5.0f * std::cbrt(static_cast<float>(n)), 2.0f, rng);
}

void expect_phases_add_up(const FramePhases& p) {
    const double sum = p.upload_ns + p.start_ns + p.compute_ns + p.irq_ns + p.readback_ns + p.driver_ns;
    EXPECT_NEAR(sum, p.total_ns, 1e-6 * p.total_ns + 1e-3);
    for (double phase : {p.upload_ns, p.start_ns, p.compute_ns, p.irq_ns, p.readback_ns, p.driver_ns}) {
        EXPECT_GE(phase, -1e-6);
    }
}

TEST(Platform, PhasesAddUpAndComputeIsCyclesTimesPeriod) {
    const PlatformConfig config = paper_platform();
    VirtualBoard platform("platform", config, 300);
    const auto boxes = scene(300, 1);
    const FrameResult& r = platform.run_frame(boxes);
    EXPECT_EQ(sorted(r.pairs), reference_pairs(boxes));
    expect_phases_add_up(r.phases);
    EXPECT_NEAR(r.phases.compute_ns, r.phases.compute_cycles * platform.board().period().to_seconds() * 1e9, 1e-6);
    EXPECT_NEAR(r.phases.irq_ns, platform.bus_timing().interrupt_ns(), 1e-6) << "one interrupt, no overflow";
    EXPECT_GT(r.phases.upload_ns, 0);
    EXPECT_GT(r.phases.readback_ns, 0);
    EXPECT_GT(r.phases.driver_ns, 0);
    EXPECT_EQ(platform.bridge().dma_transfers(), 2u) << "one chain up, the pairs back";
    EXPECT_EQ(platform.bridge().dma_segments(), 7u) << "six coordinate arrays up, the pairs back";
}

// Two platforms in one elaboration: one moves data by DMA, the other by PIO.
TEST(Platform, DmaWinsForLargeTransfersAndLosesForTinyOnes) {
    VirtualBoard dma("dma", paper_platform(true), 1000);
    VirtualBoard pio("pio", paper_platform(false), 1000);
    for (std::size_t n : {4u, 1000u}) {
        const auto boxes = scene(n, 2);
        const FramePhases by_dma = dma.run_frame(boxes).phases;
        const FrameResult& by_pio = pio.run_frame(boxes);
        EXPECT_EQ(sorted(by_pio.pairs), reference_pairs(boxes));
        expect_phases_add_up(by_pio.phases);
        if (n == 4) EXPECT_LT(by_pio.phases.upload_ns, by_dma.upload_ns) << "DMA set-up and interrupts dominate";
        else EXPECT_GT(by_pio.phases.upload_ns, 2 * by_dma.upload_ns) << "bursts beat single words";
    }
    EXPECT_EQ(pio.bridge().dma_transfers(), 0u);
}

TEST(Platform, PollingNoticesSoonerThanTheInterrupt) {
    VirtualBoard irq("irq", paper_platform(true, true), 400);
    VirtualBoard poll("poll", paper_platform(true, false), 400);
    const auto boxes = scene(400, 3);
    const FramePhases by_irq = irq.run_frame(boxes).phases;
    const FrameResult& by_poll = poll.run_frame(boxes);
    EXPECT_EQ(sorted(by_poll.pairs), reference_pairs(boxes));
    expect_phases_add_up(by_poll.phases);
    EXPECT_EQ(by_poll.phases.compute_cycles, by_irq.compute_cycles);
    // A poll loop notices within one status read; the interrupt takes its latency.
    EXPECT_LE(by_poll.phases.irq_ns, poll.bus_timing().pio_read_ns() + 1e-6);
    EXPECT_LT(by_poll.phases.total_ns, by_irq.total_ns);
}

TEST(Platform, OverflowIsDrainedAndResumedByTheDriver) {
    PlatformConfig config = paper_platform();
    config.board.collector.buffer_depth = 50;
    VirtualBoard platform("platform", config, 200);
    const std::vector<FloatBox> boxes(200, FloatBox{{0, 0, 0}, {1, 1, 1}});  // 19,900 pairs
    const FrameResult& r = platform.run_frame(boxes);
    EXPECT_EQ(r.pairs.size(), 19900u);
    EXPECT_EQ(sorted(r.pairs), reference_pairs(boxes));
    EXPECT_EQ(r.phases.overflow_pauses, 19900u / 50 - 1) << "every full buffer but the last";
    expect_phases_add_up(r.phases);
    // Every pause costs an interrupt.
    EXPECT_NEAR(r.phases.irq_ns, (r.phases.overflow_pauses + 1) * platform.bus_timing().interrupt_ns(), 1e-3);
}

TEST(Platform, PcieWhatIfUploadsFasterThanPci) {
    VirtualBoard fast("fast", testing::preset_platform("pcie-gen3-x8"), 2000);
    VirtualBoard paper("paper", paper_platform(), 2000);
    const auto boxes = scene(2000, 4);
    const FramePhases on_pci = paper.run_frame(boxes).phases;
    const FrameResult& on_pcie = fast.run_frame(boxes);
    EXPECT_EQ(sorted(on_pcie.pairs), reference_pairs(boxes));
    EXPECT_LT(on_pcie.phases.upload_ns * 5, on_pci.upload_ns);
    EXPECT_LT(on_pcie.phases.total_ns, on_pci.total_ns);
}

TEST(BoardPreset, EveryPresetLoadsWithSourcedNumbers) {
    const std::vector<std::string> names = board_preset_names();
    EXPECT_EQ(names, (std::vector<std::string>{"adm-xrc-ii", "adm-xrc-ii-64", "alveo-u250", "pcie-gen3-x8"}));
    for (const std::string& name : names) {
        const BoardPreset p = load_board_preset(name);
        EXPECT_EQ(p.name, name);
        const SettingValues values = p.applied();
        EXPECT_NO_THROW(values.settings().board.validate());
        EXPECT_GT(values.settings().host.speed_factor, 0);
        EXPECT_GT(values.settings().device.block_rams, 0u);
    }
    EXPECT_EQ(load_board_preset("adm-xrc-ii").applied().bus()->describe(), "PCI 32-bit/33.3 MHz");
    EXPECT_EQ(load_board_preset("adm-xrc-ii-64").applied().bus()->describe(), "PCI 64-bit/66.7 MHz");
}

TEST(BoardPreset, RejectsUnsourcedNumbersAndUnknownNames) {
    char path[] = "/tmp/cdvp-preset-XXXXXX.json";
    const int fd = mkstemps(path, 5);
    ASSERT_GE(fd, 0);
    close(fd);
    std::ifstream in(boards_directory() + "/adm-xrc-ii.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string sourced = "\"wait_states\": {\"value\": 0, \"source\":";
    ASSERT_NE(text.find(sourced), std::string::npos);
    text.replace(text.find(sourced), sourced.size(), "\"wait_states\": {\"value\": 0, \"note\":");
    std::ofstream(path) << text;
    try {
        load_board_preset(path);
        ADD_FAILURE() << "a number without a source was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(std::string(path) + ": bus.wait_states: expected"), std::string::npos)
            << e.what();
    }
    std::remove(path);
    try {
        load_board_preset("nope");
        ADD_FAILURE() << "an unknown board was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("expected one of: adm-xrc-ii, adm-xrc-ii-64, alveo-u250, pcie-gen3-x8"),
                  std::string::npos);
    }
}

}  // namespace
}  // namespace cdvp

namespace cdvp {
namespace {

// A loosely-timed host CPU: the board answers for each access's annotated
// time and the bridge synchronises, so every mode gives the pairs and the
// per-phase times of a CPU that synchronises at every access.
TEST(Platform, AHostQuantumKeepsPairsAndPhases) {
    std::mt19937 rng(8);
    const auto boxes = testing::random_boxes(300, 12.0f, 3.0f, rng);
    // Elaborate every platform before the first frame runs.
    std::vector<std::unique_ptr<VirtualBoard>> exact, loose;
    for (const auto& [dma, irq] : {std::pair{true, true}, std::pair{true, false}, std::pair{false, false}}) {
        PlatformConfig config = paper_platform(dma, irq);
        config.board.collector.buffer_depth = 16;  // overflow pauses too
        exact.push_back(std::make_unique<VirtualBoard>(("exact" + std::to_string(exact.size())).c_str(), config, 300));
        config.quantum_ns = 10000;
        loose.push_back(std::make_unique<VirtualBoard>(("loose" + std::to_string(loose.size())).c_str(), config, 300));
    }
    for (std::size_t mode = 0; mode < exact.size(); ++mode) {
        for (int frame = 0; frame < 2; ++frame) {
            const FrameResult a = exact[mode]->run_frame(boxes);
            const FrameResult& b = loose[mode]->run_frame(boxes);
            ASSERT_EQ(b.pairs, a.pairs) << "mode " << mode;
            EXPECT_GT(a.phases.overflow_pauses, 0u);
            EXPECT_EQ(b.phases.compute_cycles, a.phases.compute_cycles);
            EXPECT_NEAR(b.phases.total_ns, a.phases.total_ns, 1e-9 * a.phases.total_ns) << "mode " << mode;
            EXPECT_NEAR(b.phases.irq_ns, a.phases.irq_ns, 1e-6) << "mode " << mode;
            EXPECT_NEAR(b.phases.readback_ns, a.phases.readback_ns, 1e-6) << "mode " << mode;
        }
    }
}

}  // namespace
}  // namespace cdvp
