// How a board configuration sits on its FPGA (the device.* settings), costed
// by the synthesis-backed resource model and timed by the synthesis-backed
// timing model (models/resources).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "models/resources/resource_model.h"
#include "models/resources/timing_model.h"
#include "platform/settings/setting_values.h"
#include "platform/settings/settings.h"

namespace cdvp {

// The device's speed grade: the number after the last '-' of device.name
// (XC2V6000-4: 4), else the family's slowest grade in the timing table.
struct SpeedGrade {
    uint32_t grade = 0;
    bool named = false;  // false: not in the name, the slowest assumed
};
// Throws std::invalid_argument when the name gives a grade the family's
// timing table has no rows for ("... the xc2v timing has -4, -5 or -6").
SpeedGrade speed_grade_of(const DeviceSettings& device);

struct DeviceFit {
    DeviceCapacity device;     // unbounded resources as infinity
    BoardResources resources;  // for the settings' m and number format (lanes, block RAM depth)
    Utilisation use;           // over the device; overflow names the first resource that does not fit
    uint32_t largest_m = 0;    // the largest m (1 to BoardConfig::kMaxM) that fits; 0: none does
    SpeedGrade speed_grade;
    BoardTiming timing;        // each piece's longest path at that grade (BoardTiming::limiting sets the Fmax)
    double clock_mhz = 0;      // the board clock the settings ask for
};

// Whether a device family is set, so that resources can be costed.
bool has_device_family(const Settings& settings);
// The fit of settings.board on settings.device for boards of 'capacity'
// boxes, in the memory plan_memory picks at each m (block RAM or SSRAM
// tiles); only with has_device_family(settings).
DeviceFit fit_on_device(const Settings& settings, uint64_t capacity);

// The board clock against the estimated Fmax of the fit (every piece and the
// whole board as one design): a clock beyond it is refused in one line naming
// where the clock came from, the estimate and the piece or path that limits
// it; with run.ignore_timing that line is returned instead (the run's
// warning, for its summary, report and sweep row) and the run goes on.
// Nothing without a device family. Throws InputError (also for a speed grade
// the timing table lacks).
std::optional<std::string> check_clock(const SettingValues& values, uint64_t capacity);

// The fit's timing for the run report (config.resources.timing) and for the
// fit line cdvp run prints ("Fmax about 71.4 MHz at speed grade -4 (its whole
// board as one design (...), 14.01 ns)"; on a board with no whole-board row
// "...; from the pieces alone: no whole-board timing of ...").
nlohmann::json timing_json(const DeviceFit& fit);
std::string timing_summary(const DeviceFit& fit);

}  // namespace cdvp
