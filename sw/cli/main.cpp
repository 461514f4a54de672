// The cdvp command line: `cdvp <command> [options]`.
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <systemc>

#include "platform/kernel.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/calibrate_command.h"
#include "sw/cli/fidelity_command.h"
#include "sw/cli/run_command.h"
#include "sw/cli/settings_command.h"
#include "sw/cli/version.h"
#include "sw/cli/sweep_command.h"
#include "sw/scene/output_target.h"
#include "models/common/user_text.h"

namespace {

constexpr const char* kUsage =
    "Usage: cdvp <command> [options]\n"
    "\n"
    "cdvp is a SystemC virtual platform of an FPGA coprocessor board for broad-phase\n"
    "collision detection (all-pairs AABB tests, after Woulfe, Dingliana and Manzke, 2007).\n"
    "\n"
    "Commands:\n"
    "  run       simulate scene frames on the virtual board; write pairs, a report, waveforms\n"
    "  fidelity  run a scene at every modelling level: simulator speed against timing error\n"
    "  settings  list every setting (-c NAME=VALUE, --config FILE, presets) with its range and default\n"
    "  sweep     run a grid of settings, boards and scenes: one CSV row per point, plots; resumable,\n"
    "            parallel (--jobs) and sharded (--shard)\n"
    "  merge     merge the shard directories of one sweep into one\n"
    "  bullet    step a Bullet scene with the board as its broad phase, against Bullet's own\n"
    "  record    write a Bullet scene's AABBs as a trace for 'cdvp run --trace'\n"
    "  calibrate time the reference workload on this machine and write a host profile, from\n"
    "            which runs take their host factors (docs/timing.md)\n"
    "\n"
    "Run 'cdvp <command> --help' for a command's options; 'cdvp --version' prints the version.\n"
    "\n"
    "Exit status: 0 done; 1 internal failure (a cdvp bug); 2 bad input (file, flag, preset or\n"
    "output path), with one line on stderr naming it; 3 the simulated system faulted; 4 the\n"
    "system failed a write (a full disk, an I/O error), with its own words; 128+N killed by\n"
    "signal N (temporary files removed).\n";

}  // namespace

int sc_main(int argc, char** argv) {
    cdvp::configure_kernel();
    if (argc < 2) {
        std::cerr << kUsage;
        return 2;
    }
    if (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
        return cdvp::print_to_stdout("cdvp", kUsage);
    }
    const std::string command = argv[1];
    if (command == "--version") {
        return cdvp::print_to_stdout("cdvp", std::string("cdvp ") + cdvp::kCdvpVersion + "\n");
    }
    if (command == "run") return cdvp::run_command(argc - 1, argv + 1);
    if (command == "fidelity") return cdvp::fidelity_command(argc - 1, argv + 1);
    if (command == "settings") return cdvp::settings_command(argc - 1, argv + 1);
    if (command == "sweep") return cdvp::sweep_command(argc - 1, argv + 1);
    if (command == "merge") return cdvp::merge_command(argc - 1, argv + 1);
    if (command == "bullet") return cdvp::bullet_command(argc - 1, argv + 1);
    if (command == "record") return cdvp::record_command(argc - 1, argv + 1);
    if (command == "calibrate") return cdvp::calibrate_command(argc - 1, argv + 1);
    std::cerr << "cdvp: unknown command '" << cdvp::excerpt(command)
              << "'; expected one of: run, fidelity, settings, sweep, merge, bullet, record, calibrate (see cdvp --help)\n";
    return 2;
}

// Our own entry point so the SystemC banner is off before the kernel starts;
// sc_elab_and_sim then calls sc_main as libsystemc's main would.
int main(int argc, char** argv) {
    cdvp::reserve_standard_descriptors();
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
    const int status = sc_core::sc_elab_and_sim(argc, argv);
    cdvp::after_kernel_returns();
    return status;
}
