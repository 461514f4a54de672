#include "platform/platform_settings.h"

namespace cdvp {

PlatformConfig platform_config(const SettingValues& values) {
    const Settings& settings = values.settings();
    values.check_board();
    PlatformConfig platform;
    platform.board = settings.board;
    platform.bus = values.bus();
    platform.driver = settings.driver;  // run.transfer and run.wait bind its fields directly
    platform.fidelity = engine_of(settings.run.fidelity, settings.run.lockstep);
    platform.quantum_ns = settings.run.quantum_ns;
    return platform;
}

}  // namespace cdvp
