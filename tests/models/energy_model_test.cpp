#include "models/energy/energy_model.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace cdvp {
namespace {

// The XC2V6000's coefficients as adm-xrc-ii.json states them, round.
PowerCoefficients virtex2() {
    PowerCoefficients p;
    p.static_w = 0.115;
    p.clb_uw_per_mhz = 5.9;
    p.block_ram_uw_per_mhz = 73;
    p.io_pj_per_toggle = 54;
    p.bus_w = 1.5;
    p.host_w = 66;
    return p;
}

Resources board(double luts, double flip_flops, double block_rams) {
    Resources r;
    r.luts = luts;
    r.flip_flops = flip_flops;
    r.block_rams = block_rams;
    return r;
}

FrameActivity frame(double frame_ns, uint64_t active_cycles) {
    FrameActivity a;
    a.frame_ns = frame_ns;
    a.transfer_ns = frame_ns / 4;
    a.active_cycles = active_cycles;
    a.memory_write_cycles = 3000;
    a.block_rams_read = 72;  // m = 12 copies of six coordinates, one block deep
    a.block_rams_written = 72;
    a.io_bits = 96000;
    return a;
}

// A host that states its idle power draws it while it sleeps on the
// interrupt and its package power the rest of the frame; one that does not
// draws its package power throughout. Only the host's part changes.
TEST(EnergyModel, AStatedIdlePowerIsDrawnWhileTheHostWaitsAndOnlyThen) {
    FrameActivity a = frame(400000, 10000);
    a.host_wait_ns = 300000;
    const FrameEnergy unstated = board_frame_energy(virtex2(), board(8000, 4000, 72), a);
    EXPECT_DOUBLE_EQ(unstated.host_j, 66 * 400e-6);
    PowerCoefficients sleeping = virtex2();
    sleeping.host_idle_w = 6;
    const FrameEnergy e = board_frame_energy(sleeping, board(8000, 4000, 72), a);
    EXPECT_DOUBLE_EQ(e.host_j, 66 * 100e-6 + 6 * 300e-6);
    EXPECT_DOUBLE_EQ(e.static_j, unstated.static_j);
    EXPECT_DOUBLE_EQ(e.dynamic_j, unstated.dynamic_j);
    EXPECT_DOUBLE_EQ(e.bus_j, unstated.bus_j);
    a.host_wait_ns = 0;  // polling: no wait, the package power throughout
    EXPECT_DOUBLE_EQ(board_frame_energy(sleeping, board(8000, 4000, 72), a).host_j, 66 * 400e-6);
    a.host_wait_ns = 400001;
    EXPECT_THROW(board_frame_energy(sleeping, board(8000, 4000, 72), a), std::invalid_argument);
}

TEST(EnergyModel, PartsAddUpToTheTotalAndEachIsWorkedOutFromItsCoefficient) {
    const FrameEnergy e = board_frame_energy(virtex2(), board(8000, 4000, 72), frame(400000, 10000));
    EXPECT_DOUBLE_EQ(e.static_j, 0.115 * 400e-6);
    EXPECT_DOUBLE_EQ(e.bus_j, 1.5 * 100e-6);
    EXPECT_DOUBLE_EQ(e.host_j, 66 * 400e-6);
    // 1000 CLBs x 5.9 pJ x 10,000 cycles; 72 block RAMs x 73 pJ x 13,000
    // cycles; 96,000 bits x 12.5% x 54 pJ.
    EXPECT_NEAR(e.dynamic_j, (1000 * 5.9 * 10000 + 72 * 73 * 13000 + 96000 * 0.125 * 54) * 1e-12, 1e-15);
    // The block RAMs a cycle enables are charged, not those the board holds:
    // the same 72 enabled of a memory 20 blocks deep cost the same.
    EXPECT_DOUBLE_EQ(board_frame_energy(virtex2(), board(8000, 4000, 72 * 20), frame(400000, 10000)).dynamic_j,
                     e.dynamic_j);
    EXPECT_DOUBLE_EQ(e.total_j(), e.static_j + e.dynamic_j + e.bus_j + e.host_j);
    FrameEnergy sum;
    sum += e;
    sum += e;
    EXPECT_DOUBLE_EQ(sum.total_j(), 2 * e.total_j());
}

TEST(EnergyModel, ClbsAreTheLargerShareOfLutsAndFlipFlops) {
    PowerCoefficients p = virtex2();
    p.flip_flops_per_clb = 16;  // an UltraScale+ CLB
    EXPECT_DOUBLE_EQ(clbs_used(board(800, 800, 0), p), 100);
    EXPECT_DOUBLE_EQ(clbs_used(board(800, 3200, 0), p), 200);
}

TEST(EnergyModel, AFasterClockLeavesDynamicEnergyAndShrinksStaticAndHostWithTheFrame) {
    // The same sweep (cycles) at twice the clock: half the compute time.
    const FrameEnergy slow = board_frame_energy(virtex2(), board(8000, 4000, 72), frame(400000, 10000));
    const FrameEnergy fast = board_frame_energy(virtex2(), board(8000, 4000, 72), frame(200000, 10000));
    EXPECT_DOUBLE_EQ(fast.dynamic_j, slow.dynamic_j);
    EXPECT_DOUBLE_EQ(fast.static_j, slow.static_j / 2);
    EXPECT_DOUBLE_EQ(fast.host_j, slow.host_j / 2);
    EXPECT_LT(fast.total_j(), slow.total_j());
}

TEST(EnergyModel, LogicEnergyFollowsTheResourcesAndTheActivity) {
    PowerCoefficients p = virtex2();
    p.block_ram_uw_per_mhz = 0;
    p.io_pj_per_toggle = 0;
    const FrameEnergy base = board_frame_energy(p, board(8000, 4000, 72), frame(400000, 10000));
    // Twice the lanes (about twice the LUTs at twice m) and half the cycles: the same logic energy.
    const FrameEnergy wider = board_frame_energy(p, board(16000, 8000, 144), frame(400000, 5000));
    EXPECT_DOUBLE_EQ(wider.dynamic_j, base.dynamic_j);
    // Twice the toggle rate, twice the switching.
    p.toggle_rate = 0.25;
    EXPECT_DOUBLE_EQ(board_frame_energy(p, board(8000, 4000, 72), frame(400000, 10000)).dynamic_j, 2 * base.dynamic_j);
    // Stalled cycles compare nothing.
    p.toggle_rate = kPublishedToggleRate;
    EXPECT_DOUBLE_EQ(board_frame_energy(p, board(8000, 4000, 72), frame(400000, 2500)).dynamic_j, base.dynamic_j / 4);
}

TEST(EnergyModel, SoftwareEnergyIsPackagePowerTimesItsTime) {
    EXPECT_DOUBLE_EQ(software_frame_energy_j(66, 360470), 66 * 360470e-9);
    EXPECT_THROW(software_frame_energy_j(-1, 10), std::invalid_argument);
}

TEST(EnergyModel, RefusesNegativeOrNonFiniteInputsNamingThem) {
    PowerCoefficients p = virtex2();
    p.static_w = std::numeric_limits<double>::quiet_NaN();
    try {
        board_frame_energy(p, board(1, 1, 72), frame(1, 1));
        FAIL() << "a NaN static power was taken";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("static power"), std::string::npos) << e.what();
    }
    EXPECT_THROW(board_frame_energy(virtex2(), board(1, 1, 72), frame(-5, 1)), std::invalid_argument);
    p = virtex2();
    p.luts_per_clb = 0;
    EXPECT_THROW(board_frame_energy(p, board(1, 1, 72), frame(1, 1)), std::invalid_argument);
    // A cycle cannot enable more block RAMs than the board holds.
    try {
        board_frame_energy(virtex2(), board(1, 1, 71), frame(1, 1));
        FAIL() << "72 block RAMs enabled of 71 were taken";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("block RAMs"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace cdvp
