#include "platform/frame_energy.h"

#include <algorithm>

namespace cdvp {

PowerCoefficients power_coefficients(const Settings& s) {
    PowerCoefficients p;
    p.static_w = s.power.static_w;
    p.clb_uw_per_mhz = s.power.clb_uw_per_mhz;
    p.luts_per_clb = s.power.luts_per_clb;
    p.flip_flops_per_clb = s.power.flip_flops_per_clb;
    p.block_ram_uw_per_mhz = s.power.block_ram_uw_per_mhz;
    p.io_pj_per_toggle = s.power.io_pj_per_toggle;
    p.toggle_rate = s.power.toggle_percent / 100.0;
    p.bus_w = s.power.bus_w;
    p.host_w = s.power.host_w;
    p.host_idle_w = s.power.host_idle_w;
    return p;
}

FrameActivity frame_activity(const FramePhases& p, uint32_t local_bus_width_bits, WaitMode wait,
                             const BoardResources& fit) {
    FrameActivity a;
    a.frame_ns = p.total_ns;
    a.transfer_ns = p.upload_ns + p.start_ns + p.readback_ns;
    if (wait == WaitMode::kIrq) {
        // What of the sweep and the interrupt the host's frame shows (two box
        // banks hide some of the sweep behind its work on the frames beside it).
        a.host_wait_ns = std::clamp(p.compute_ns + p.irq_ns - p.overlap_ns, 0.0, p.total_ns);
    }
    a.active_cycles = p.compute_cycles - std::min(p.stall_cycles, p.compute_cycles);
    const uint64_t upload_bits = p.upload_bytes * 8;
    const uint64_t width = std::max<uint32_t>(local_bus_width_bits, 1);
    a.memory_write_cycles = (upload_bits + width - 1) / width;
    a.block_rams_read = double(fit.memory_geometry.read_enabled()) + fit.pair_collector.block_rams;
    a.block_rams_written = double(fit.memory_geometry.write_enabled());
    a.io_bits = upload_bits + 2 * p.readback_bytes * 8;
    return a;
}

BoardEnergy::BoardEnergy(const Settings& settings, const BoardResources& fit)
    : power_(power_coefficients(settings)),
      fit_(fit),
      wait_(settings.driver.wait) {
    if (settings.bus_type == BusType::kPci) local_bus_width_bits_ = settings.pci.local_bus.width_bits;
    if (settings.bus_type == BusType::kPcie) local_bus_width_bits_ = settings.pcie.local_bus.width_bits;
}

FrameEnergy BoardEnergy::frame(const FramePhases& phases) const {
    return board_frame_energy(power_, fit_.total(), frame_activity(phases, local_bus_width_bits_, wait_, fit_));
}

}  // namespace cdvp
