#include "sw/cli/run_options.h"

#include <sstream>

#include "models/control_registers/control_registers.h"
#include "sw/cli/number_option.h"
#include "models/common/user_text.h"
#include "sw/scene/scene.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

// Frames and objects are bounded by the address map and by a sane count;
// SystemC's simulated time is checked against the whole run elsewhere.
constexpr uint64_t kMaxFrames = 1'000'000'000;

po::options_description run_options(RunOptions& o) {
    po::options_description input("Input (one of)");
    input.add_options()
        ("trace", po::value(&o.trace)->value_name("FILE"), "scene trace CSV (see README: file formats)")
        ("scene", po::value(&o.scene)->value_name("NAME"), "generated scene: spheres")
        ("objects", number<uint64_t>(&o.objects, 0, address_map::kMaxObjects, "N"), "spheres: number of spheres")
        ("frames", number<uint64_t>(&o.frames, 0, kMaxFrames, "F"), "spheres: number of frames")
        ("seed", number<uint64_t>(&o.spheres.seed, 0, UINT64_MAX, "S"),
         "spheres: random seed (same seed, same scene)");
    po::options_description board("Board");
    board.add_options()
        ("board", po::value(&o.board_name)->value_name("NAME"),
         "board preset (adm-xrc-ii, adm-xrc-ii-64, pcie-gen3-x8) from $CDVP_BOARDS, else share/cdvp/boards of the "
         "installed prefix, else the source tree's platform/boards; or a .json path; "
         "without it: the board alone on an ideal, untimed bus")
        ("m", number<uint32_t>(&o.board.m, 1, BoardConfig::kMaxM, "M"),
         "parallelism: 2m-port memories, 2m-1 comparison lanes")
        ("clock-mhz", number<double>(&o.board.clock_mhz, 1, 1000, "F"), "board clock in MHz")
        ("compare-latency", number<uint32_t>(&o.board.compare.latency_cycles, 0, 64, "C"),
         "float compare pipeline depth in cycles")
        ("fifo-depth", number<uint32_t>(&o.board.collector.fifo_depth, 1, 1u << 20, "P"),
         "pair FIFO depth in pairs (at least 2m-1)")
        ("drain-rate", number<uint32_t>(&o.board.collector.drain_per_cycle, 1, 64, "R"),
         "pairs moved from FIFO to pair buffer a cycle")
        ("pair-buffer", number<uint32_t>(&o.board.collector.buffer_depth, 1, address_map::kMaxBufferedPairs, "P"),
         "pair buffer depth in pairs before the host drains it")
        ("fidelity", po::value(&o.fidelity)->value_name("cycle|fast")->default_value(o.fidelity),
         "the board's engine: fast computes pairs and cycles from the schedule, cycle clocks the datapath edge by "
         "edge; the same pairs, cycles and times (--vcd needs cycle, and picks it when --fidelity is not given)");
    po::options_description host("Host, baselines and faults");
    host.add_options()
        ("transfer", po::value(&o.transfer)->value_name("dma|pio")->default_value(o.transfer),
         "how the driver moves boxes and pairs: bridge DMA or programmed I/O")
        ("wait", po::value(&o.wait)->value_name("irq|poll")->default_value(o.wait),
         "how the driver waits for the board: interrupt or polling")
        ("baseline", po::value(&o.baselines)->value_name("LIST"),
         "software broad phases to time on the same frames, comma-separated: sap, dbvt, brute, soa")
        ("warmup", number<uint64_t>(&o.warmup, 0, kMaxFrames, "W"),
         "frames at the start of each run left out of the timing statistics (allocation, first insertion)")
        ("repeat", number<uint32_t>(&o.repeat, 1, 1000, "R"),
         "time the baselines over the frames R times, fresh instances each run; figures are medians over runs "
         "(the board's simulated times are deterministic and simulated once)")
        ("host-factor", number<double>(&o.host_factor, 0.001, 1000, "F", false),
         "host-speed factor: native software time x F = time on the modelled host (default: the board preset's)")
        ("quantum-ns", number<double>(&o.quantum_ns, 0, 1e9, "Q"),
         "host CPU quantum in ns: how far the CPU runs ahead of the board and bus before it synchronises "
         "(0: at every access, exact; larger is faster and loosely timed)")
        ("inject", po::value(&o.inject)->value_name("KIND@frame=N[,n=K]"),
         "inject a bus or board fault into frame N (repeatable): target-abort, master-abort, retry, disconnect, "
         "lost-irq, dma-hang, board-error (docs/faults.md)");
    po::options_description output("Output (written only if the whole run succeeds)");
    output.add_options()
        ("pairs-out", po::value(&o.pairs_out)->value_name("FILE"), "overlapping pairs CSV (frame,a,b)")
        ("report", po::value(&o.report)->value_name("FILE"), "JSON report: configuration and per-frame cycles")
        ("vcd", po::value(&o.vcd)->value_name("FILE"),
         "waveforms of the board, bridge DMA and interrupts (VCD), with a GTKWave save file beside it "
         "(FILE minus .vcd, plus .gtkw) that groups the signals by block")
        ("vcd-frames", po::value(&o.vcd_frames)->value_name("A:B"),
         "trace only frames A to B (as the run numbers them); the others run untraced")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors")
        ("help,h", po::bool_switch(&o.help), "show this help");
    po::options_description all(
        "Usage: cdvp run (--trace FILE | --scene spheres [--objects N] [--frames F] [--seed S]) [options]\n\n"
        "Simulates each frame on the virtual platform and reports its pairs, cycles and time.\n"
        "With --board, the board settings below come from the preset unless given.\n"
        "Options are spelt in full (no abbreviations); numbers show their range and default");
    all.add(input).add(board).add(host).add(output);
    return all;
}

}  // namespace

po::variables_map parse_run_options(int argc, char** argv, RunOptions& options) {
    const po::options_description description = run_options(options);
    const po::parsed_options parsed =
        po::command_line_parser(argc, argv)
            .options(description)
            .style(po::command_line_style::default_style & ~po::command_line_style::allow_guessing)
            .run();
    for (const std::string& stray : po::collect_unrecognized(parsed.options, po::include_positional)) {
        throw InputError("unexpected argument '" + excerpt(stray) + "'");
    }
    po::variables_map vm;
    po::store(parsed, vm);
    po::notify(vm);
    return vm;
}

std::string run_options_help() {
    RunOptions defaults;
    std::ostringstream text;
    text << run_options(defaults);
    return text.str();
}

}  // namespace cdvp
