#include "models/energy/energy_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cdvp {

namespace {

// 1 uW/MHz is 1 pJ a cycle.
constexpr double kJoulesPerPicojoule = 1e-12;
constexpr double kSecondsPerNs = 1e-9;

void check(double value, const char* what) {
    if (!std::isfinite(value) || value < 0) {
        throw std::invalid_argument(std::string("energy model: ") + what + " is " + std::to_string(value) +
                                    " (expected a finite number at least 0)");
    }
}

void check(const PowerCoefficients& p) {
    check(p.static_w, "static power");
    check(p.clb_uw_per_mhz, "CLB power");
    check(p.block_ram_uw_per_mhz, "block RAM power");
    check(p.io_pj_per_toggle, "I/O energy a toggle");
    check(p.toggle_rate, "toggle rate");
    check(p.bus_w, "bus power");
    check(p.host_w, "host power");
    check(p.host_idle_w, "host idle power");
    if (!(p.luts_per_clb > 0) || !(p.flip_flops_per_clb > 0)) {
        throw std::invalid_argument("energy model: a CLB must hold LUTs and flip-flops (expected more than 0 of each)");
    }
}

}  // namespace

FrameEnergy& FrameEnergy::operator+=(const FrameEnergy& other) {
    static_j += other.static_j;
    dynamic_j += other.dynamic_j;
    bus_j += other.bus_j;
    host_j += other.host_j;
    return *this;
}

double clbs_used(const Resources& used, const PowerCoefficients& power) {
    return std::max(used.luts / power.luts_per_clb, used.flip_flops / power.flip_flops_per_clb);
}

FrameEnergy board_frame_energy(const PowerCoefficients& power, const Resources& used, const FrameActivity& a) {
    check(power);
    check(a.frame_ns, "frame time");
    check(a.transfer_ns, "transfer time");
    check(a.host_wait_ns, "host wait");
    if (a.host_wait_ns > a.frame_ns) {
        throw std::invalid_argument("energy model: the host waits " + std::to_string(a.host_wait_ns) +
                                    " ns of a frame of " + std::to_string(a.frame_ns) + " ns (expected at most the frame)");
    }
    check(used.luts, "LUTs");
    check(used.flip_flops, "flip-flops");
    check(used.block_rams, "block RAMs");
    check(a.block_rams_read, "block RAMs a compare cycle enables");
    check(a.block_rams_written, "block RAMs a write cycle enables");
    if (std::max(a.block_rams_read, a.block_rams_written) > used.block_rams) {
        throw std::invalid_argument("energy model: a cycle enables " +
                                    std::to_string(std::max(a.block_rams_read, a.block_rams_written)) +
                                    " block RAMs of the " + std::to_string(used.block_rams) +
                                    " the board holds (expected at most those)");
    }
    const double activity = power.toggle_rate / kPublishedToggleRate;
    const double logic_pj = clbs_used(used, power) * power.clb_uw_per_mhz * activity * double(a.active_cycles);
    // Only the block RAMs a cycle enables switch: one block of each cascade
    // a read, every copy a write (BlockRamGeometry).
    const double memory_pj = power.block_ram_uw_per_mhz * (a.block_rams_read * double(a.active_cycles) +
                                                           a.block_rams_written * double(a.memory_write_cycles));
    const double io_pj = double(a.io_bits) * power.toggle_rate * power.io_pj_per_toggle;
    FrameEnergy e;
    e.static_j = power.static_w * a.frame_ns * kSecondsPerNs;
    e.dynamic_j = (logic_pj + memory_pj + io_pj) * kJoulesPerPicojoule;
    e.bus_j = power.bus_w * a.transfer_ns * kSecondsPerNs;
    // A host that states its idle power sleeps through the wait on the interrupt.
    e.host_j = power.host_idle_w > 0 ? (power.host_w * (a.frame_ns - a.host_wait_ns) + power.host_idle_w * a.host_wait_ns) *
                                           kSecondsPerNs
                                     : power.host_w * a.frame_ns * kSecondsPerNs;
    return e;
}

double software_frame_energy_j(double host_w, double host_ns) {
    check(host_w, "host power");
    check(host_ns, "host time");
    return host_w * host_ns * kSecondsPerNs;
}

}  // namespace cdvp
