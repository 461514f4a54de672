// Energy per frame beside its time: the board's static and dynamic energy,
// the bus's and the host's (docs/energy.md). Plain numbers in, joules out:
// the coefficients come from the device and host presets (each with its
// source), the resources from the synthesis-backed resource model, the
// activity from the frame's own phases and counters.
#pragma once

#include <cstdint>

#include "models/resources/resource_model.h"

namespace cdvp {

// The toggle rate the published per-CLB figure is read at: Xilinx Power
// Estimator's default, 12.5% (a signal changes on one clock edge in eight).
constexpr double kPublishedToggleRate = 0.125;

// What the board, its bus and its host draw.
struct PowerCoefficients {
    double static_w = 0;             // the device's quiescent power, drawn the whole frame
    double clb_uw_per_mhz = 0;       // dynamic power of a CLB in use, at kPublishedToggleRate
    double luts_per_clb = 8;         // how many LUTs and flip-flops a CLB holds: the
    double flip_flops_per_clb = 8;   // board's CLBs are the larger of its LUTs' and flip-flops' share
    double block_ram_uw_per_mhz = 0; // an 18-Kbit block RAM read or written every cycle
    double io_pj_per_toggle = 0;     // one output pin's transition (1/2 C V^2 of its load)
    double toggle_rate = kPublishedToggleRate;  // logic and I/O activity: transitions a clock
    double bus_w = 0;                // the bus and its bridges while they move data
    double host_w = 0;               // the host's package, for as long as the frame takes it
    // The package while its cores sleep on the board's interrupt; 0: not
    // stated, the package draws host_w through the wait too.
    double host_idle_w = 0;
};

// What a frame did, from its phases and counters.
struct FrameActivity {
    double frame_ns = 0;             // the host's time on the frame (the board powered throughout)
    double transfer_ns = 0;          // the bus moving data or commands: upload, start, read-back
    double host_wait_ns = 0;         // of frame_ns, the host asleep on the board's interrupt (at most frame_ns)
    uint64_t active_cycles = 0;      // board cycles the lanes compare (the sweep less its stalls)
    uint64_t memory_write_cycles = 0;  // board cycles the coordinate memories are written (upload)
    // Block RAMs a cycle enables (BlockRamGeometry): a compare cycle and an
    // upload write cycle. One block of each cascade, not its depth.
    double block_rams_read = 0;
    double block_rams_written = 0;
    uint64_t io_bits = 0;            // bits through the device's pins: boxes in, pairs out
};

// A frame's energy in joules, by part.
struct FrameEnergy {
    double static_j = 0;   // quiescent power x frame time
    double dynamic_j = 0;  // logic, block RAM and I/O switching at the run's activity
    double bus_j = 0;      // bus power x its transfer time
    double host_j = 0;     // host package power x frame time (its idle power while it sleeps, where stated)
    double total_j() const { return static_j + dynamic_j + bus_j + host_j; }
    FrameEnergy& operator+=(const FrameEnergy& other);
};

// The CLBs a board's resources occupy.
double clbs_used(const Resources& used, const PowerCoefficients& power);

// A frame on the board. Dynamic energy a cycle does not depend on the
// clock, so a sweep of fixed cycles costs the same dynamic energy at any
// clock, while the static and host parts follow the frame's time.
// Throws std::invalid_argument for a negative or non-finite input, or for
// more block RAMs enabled a cycle than the board holds.
FrameEnergy board_frame_energy(const PowerCoefficients& power, const Resources& used, const FrameActivity& activity);

// Software on the host: its package power x its time on the frame.
double software_frame_energy_j(double host_w, double host_ns);

}  // namespace cdvp
