// The cdvp command line: `cdvp <command> [options]`.
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <systemc>

#include "platform/kernel.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/calibrate_command.h"
#include "sw/cli/fidelity_command.h"
#include "sw/cli/rtl_variants_command.h"
#include "sw/cli/run_command.h"
#include "sw/cli/settings_command.h"
#include "sw/run/version.h"
#include "sw/cli/sweep_command.h"
#include "sw/output/output_target.h"
#include "models/common/user_text.h"
#include "models/rtl_engine/rtl_model_cache.h"

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
    "  rtl-variants  list the board RTL's parameter sets built in for --fidelity rtl (docs/rtl.md)\n"
    "\n"
    "Run 'cdvp <command> --help' (or 'cdvp help <command>') for a command's options; 'cdvp --version'\n"
    "prints the version.\n"
    "\n"
    "Exit status: 0 done; 1 internal failure (a cdvp bug); 2 bad input (file, flag, preset or\n"
    "output path, or a run past its memory, pair, time or input budgets), with one line on\n"
    "stderr naming it; 3 the simulated system faulted; 4 the system failed a write (a full\n"
    "disk, an I/O error), with its own words; 128+N killed by signal N (temporary files\n"
    "removed).\n";

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
    std::string command = argv[1];
    if (command == "--version") {
        return cdvp::print_to_stdout("cdvp", std::string("cdvp ") + cdvp::kCdvpVersion + "\n");
    }
    // The command's own argv: its name, then its arguments; "cdvp help
    // COMMAND" is "cdvp COMMAND --help".
    int command_argc = argc - 1;
    char** command_argv = argv + 1;
    char help_flag[] = "--help";
    char* help_argv[] = {nullptr, help_flag, nullptr};
    if (command == "help") {
        if (argc > 3) {
            std::cerr << "cdvp help: unexpected argument '" << cdvp::excerpt(argv[3]) << "' (see cdvp --help)\n";
            return 2;
        }
        if (argc == 2) return cdvp::print_to_stdout("cdvp", kUsage);
        command = argv[2];
        help_argv[0] = argv[2];
        command_argc = 2;
        command_argv = help_argv;
    }
    using Command = int (*)(int, char**);
    const std::pair<const char*, Command> commands[] = {
        {"run", cdvp::run_command},       {"fidelity", cdvp::fidelity_command}, {"settings", cdvp::settings_command},
        {"sweep", cdvp::sweep_command},   {"merge", cdvp::merge_command},       {"bullet", cdvp::bullet_command},
        {"record", cdvp::record_command}, {"calibrate", cdvp::calibrate_command},
        {"rtl-variants", cdvp::rtl_variants_command}};
    for (const auto& [name, run] : commands) {
        if (command == name) {
            cdvp::set_rtl_notice_program("cdvp " + command);  // names the RTL's compile on first use
            return run(command_argc, command_argv);
        }
    }
    std::cerr << "cdvp: unknown command '" << cdvp::excerpt(command)
              << "'; expected one of: run, fidelity, settings, sweep, merge, bullet, record, calibrate, rtl-variants, help (see cdvp --help)\n";
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
