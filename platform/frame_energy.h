// A run's energy per frame: the energy model (models/energy) fed from the
// settings (the presets' power figures), the board's resources (the device
// fit) and each frame's phases and counters (docs/energy.md).
#pragma once

#include "models/energy/energy_model.h"
#include "platform/driver/frame_phases.h"
#include "platform/settings/settings.h"

namespace cdvp {

// The energy model's coefficients from the settings (device.*, bus.active_w, host.package_w).
PowerCoefficients power_coefficients(const Settings& settings);

// What a frame did, from its phases: the lanes active for the sweep's
// cycles less its stalls; the coordinate memories written a local-bus word
// a cycle through the upload; the boxes crossing the device's pins once on
// their way in, the pairs twice (into the off-chip pair buffer, then out
// to the bridge). With run.wait irq the host sleeps through what the frame
// shows of the sweep and the interrupt (host_wait_ns); polling, it works.
// The block RAMs a cycle enables come from the device fit: a compare cycle
// enables what the memories' geometry says (BlockRamGeometry) and the pair
// FIFO's block RAMs, written and read as the lanes find pairs; an upload
// write cycle what the geometry says.
FrameActivity frame_activity(const FramePhases& phases, uint32_t local_bus_width_bits, WaitMode wait,
                             const BoardResources& fit);

// The energy of a run's frames on one board.
class BoardEnergy {
public:
    // fit: the board's resources on its device and its memories' geometry
    // (none without a device family: no dynamic energy).
    BoardEnergy(const Settings& settings, const BoardResources& fit);
    FrameEnergy frame(const FramePhases& phases) const;
    double host_w() const { return power_.host_w; }

private:
    PowerCoefficients power_;
    BoardResources fit_;
    uint32_t local_bus_width_bits_ = 32;
    WaitMode wait_ = WaitMode::kIrq;
};

}  // namespace cdvp
