#include "sw/cli/run_command.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <boost/program_options.hpp>

#include "models/address_generator/address_generator.h"
#include "models/control_registers/control_registers.h"
#include "models/block_ram/block_ram.h"
#include "platform/board_preset.h"
#include "platform/virtual_board.h"
#include "sw/baselines/broad_phase.h"
#include "sw/cli/frame_source.h"
#include "sw/cli/run_report.h"
#include "sw/scene/conversion.h"
#include "sw/scene/output_file.h"
#include "sw/scene/pairs_csv.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

struct RunOptions {
    std::string trace;
    std::string scene;
    BouncingSpheresConfig spheres;
    // Signed, so that a negative count is reported instead of wrapping around.
    int64_t objects = 500;
    int64_t frames = 1;
    BoardConfig board;
    std::string board_name;
    std::string transfer = "dma";
    std::string wait = "irq";
    std::string baselines;
    double host_factor = 0;  // 0: the preset's
    std::string pairs_out, report, vcd;
    bool quiet = false;
};

po::options_description run_options(RunOptions& o) {
    po::options_description input("Input (one of)");
    input.add_options()
        ("trace", po::value(&o.trace)->value_name("FILE"), "scene trace CSV (see README: file formats)")
        ("scene", po::value(&o.scene)->value_name("NAME"), "generated scene: spheres")
        ("objects", po::value(&o.objects)->value_name("N")->default_value(o.objects),
         "spheres: number of spheres")
        ("frames", po::value(&o.frames)->value_name("F")->default_value(o.frames), "spheres: number of frames")
        ("seed", po::value(&o.spheres.seed)->value_name("S")->default_value(o.spheres.seed),
         "spheres: random seed (same seed, same scene)");
    po::options_description board("Board");
    board.add_options()
        ("board", po::value(&o.board_name)->value_name("NAME"),
         "board preset from platform/boards (adm-xrc-ii, adm-xrc-ii-64, pcie-gen3-x8) or a .json path; "
         "without it: the board alone on an ideal, untimed bus")
        ("m", po::value(&o.board.m)->value_name("M")->default_value(o.board.m),
         "parallelism: 2m-port memories, 2m-1 comparison lanes (1..32)")
        ("clock-mhz", po::value(&o.board.clock_mhz)->value_name("F")->default_value(o.board.clock_mhz, "66"),
         "board clock in MHz")
        ("compare-latency", po::value(&o.board.compare.latency_cycles)->value_name("C")
             ->default_value(o.board.compare.latency_cycles), "float compare pipeline depth in cycles")
        ("fifo-depth", po::value(&o.board.collector.fifo_depth)->value_name("P")
             ->default_value(o.board.collector.fifo_depth), "pair FIFO depth in pairs (>= 2m-1)")
        ("drain-rate", po::value(&o.board.collector.drain_per_cycle)->value_name("R")
             ->default_value(o.board.collector.drain_per_cycle), "pairs moved from FIFO to pair buffer a cycle")
        ("pair-buffer", po::value(&o.board.collector.buffer_depth)->value_name("P")
             ->default_value(o.board.collector.buffer_depth), "pair buffer depth in pairs before the host drains it");
    po::options_description host("Host and baselines");
    host.add_options()
        ("transfer", po::value(&o.transfer)->value_name("dma|pio")->default_value(o.transfer),
         "how the driver moves boxes and pairs: bridge DMA or programmed I/O")
        ("wait", po::value(&o.wait)->value_name("irq|poll")->default_value(o.wait),
         "how the driver waits for the board: interrupt or polling")
        ("baseline", po::value(&o.baselines)->value_name("LIST"),
         "software broad phases to time on the same frames, comma-separated: sap, dbvt, brute, soa")
        ("host-factor", po::value(&o.host_factor)->value_name("F"),
         "host-speed factor: native software time x F = time on the modelled host (default: the board preset's)");
    po::options_description output("Output");
    output.add_options()
        ("pairs-out", po::value(&o.pairs_out)->value_name("FILE"), "overlapping pairs CSV (frame,a,b)")
        ("report", po::value(&o.report)->value_name("FILE"), "JSON report: configuration and per-frame cycles")
        ("vcd", po::value(&o.vcd)->value_name("FILE"), "board waveforms (VCD, opens in GTKWave)")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors")
        ("help,h", "show this help");
    po::options_description all("Usage: cdvp run (--trace FILE | --scene spheres [--objects N] [--frames F] "
                                "[--seed S]) [options]\n\nSimulates each frame on the virtual platform "
                                "and reports its pairs, cycles and time.\nWith --board, the board settings "
                                "below come from the preset unless given");
    all.add(input).add(board).add(host).add(output);
    return all;
}

// The output files, created as temporaries up front (an unwritable path
// fails before the simulation) and renamed into place only at the end.
struct Outputs {
    std::optional<OutputFile> pairs, report, vcd;
    std::string vcd_base() const {
        if (!vcd) return {};
        const std::string& t = vcd->temp_path();
        return t.substr(0, t.size() - 4);  // SystemC appends ".vcd"
    }
};

// Board settings are checked by the model; its message names the setting as
// the report does, which is mapped to the flag that sets it.
void validate_board(const BoardConfig& config) {
    try {
        config.validate();
    } catch (const std::invalid_argument& e) {
        static const std::pair<const char*, const char*> kFlags[] = {
            {"m:", "--m"}, {"clock_mhz:", "--clock-mhz"}, {"compare_latency_cycles:", "--compare-latency"},
            {"fifo_depth:", "--fifo-depth"}, {"drain_per_cycle:", "--drain-rate"},
            {"pair_buffer_depth:", "--pair-buffer"}};
        std::string message = e.what();
        for (const auto& [setting, flag] : kFlags) {
            if (message.rfind(setting, 0) == 0) message = std::string(flag) + message.substr(std::strlen(setting) - 1);
        }
        throw InputError(message);
    }
}

std::unique_ptr<FrameSource> open_source(const RunOptions& o, const po::variables_map& vm) {
    if (o.trace.empty() == o.scene.empty()) throw InputError("give exactly one of --trace FILE or --scene spheres");
    if (!o.trace.empty()) {
        for (const char* flag : {"objects", "frames", "seed"}) {
            if (!vm[flag].defaulted()) throw InputError(std::string("--") + flag + " goes with --scene, not --trace");
        }
        return trace_source(o.trace);
    }
    if (o.scene != "spheres") throw InputError("--scene: expected 'spheres', found '" + o.scene + "'");
    if (o.objects < 0 || o.objects > address_map::kMaxObjects) {
        throw InputError("--objects: expected 0 to " + std::to_string(address_map::kMaxObjects) + ", found " +
                         std::to_string(o.objects));
    }
    if (o.frames < 0) throw InputError("--frames: expected a non-negative count, found " + std::to_string(o.frames));
    BouncingSpheresConfig spheres = o.spheres;
    spheres.objects = static_cast<std::size_t>(o.objects);
    return spheres_source(spheres, static_cast<std::size_t>(o.frames));
}

class Progress {
public:
    Progress(std::size_t total, bool enabled) : total_(total), enabled_(enabled && total > 1 && isatty(2)) {}
    void update(std::size_t done) {
        if (!enabled_) return;
        const auto now = std::chrono::steady_clock::now();
        if (done < total_ && now - last_ < std::chrono::milliseconds(200)) return;
        last_ = now;
        std::cerr << "\rcdvp run: frame " << done << "/" << total_ << std::flush;
        if (done == total_) std::cerr << "\r\033[K" << std::flush;
    }

private:
    std::size_t total_;
    bool enabled_;
    std::chrono::steady_clock::time_point last_{};
};

// What the run simulates on: the board (from a preset or the flags), its bus
// and host, and the software baselines to time beside it.
struct Setup {
    PlatformConfig platform;
    std::string board = "ideal";
    std::string host = "this machine";
    double host_factor = 1.0;
    uint32_t block_rams = 0;  // the FPGA's; 0: unbounded
    std::vector<std::unique_ptr<BroadPhase>> baselines;
};

Setup make_setup(const RunOptions& o, const po::variables_map& vm, std::size_t max_objects) {
    Setup setup;
    setup.platform.board = o.board;
    if (!o.board_name.empty()) {
        const BoardPreset preset = load_board_preset(o.board_name);
        BoardConfig& b = setup.platform.board;
        // The preset's numbers, unless a flag sets them.
        if (vm["clock-mhz"].defaulted()) b.clock_mhz = preset.board.clock_mhz;
        if (vm["compare-latency"].defaulted()) b.compare = preset.board.compare;
        if (vm["fifo-depth"].defaulted()) b.collector.fifo_depth = preset.board.collector.fifo_depth;
        if (vm["drain-rate"].defaulted()) b.collector.drain_per_cycle = preset.board.collector.drain_per_cycle;
        if (vm["pair-buffer"].defaulted()) b.collector.buffer_depth = preset.board.collector.buffer_depth;
        setup.platform.bus = preset.bus;
        setup.platform.driver = preset.driver;
        setup.board = preset.name;
        setup.host = preset.host.name;
        setup.host_factor = preset.host.speed_factor;
        setup.block_rams = preset.block_rams;
    }
    validate_board(setup.platform.board);
    const uint64_t needed = uint64_t{kCoordinates} * setup.platform.board.m *
                            CascadedBlockRam::primitives_for(static_cast<uint32_t>(max_objects));
    if (setup.block_rams != 0 && needed > setup.block_rams) {
        const uint64_t per_m = uint64_t{kCoordinates} * std::max<uint32_t>(1, CascadedBlockRam::primitives_for(
                                                                                   static_cast<uint32_t>(max_objects)));
        throw InputError("--m: m=" + std::to_string(setup.platform.board.m) + " needs " + std::to_string(needed) +
                         " block RAMs for " + std::to_string(max_objects) + " objects; " + setup.board + " has " +
                         std::to_string(setup.block_rams) + " (largest m that fits: " +
                         std::to_string(setup.block_rams / per_m) + ")");
    }
    if (o.transfer != "dma" && o.transfer != "pio") throw InputError("--transfer: expected dma or pio, found '" + o.transfer + "'");
    if (o.wait != "irq" && o.wait != "poll") throw InputError("--wait: expected irq or poll, found '" + o.wait + "'");
    setup.platform.driver.use_dma = o.transfer == "dma";
    setup.platform.driver.use_interrupts = o.wait == "irq";
    if (vm.count("host-factor")) {
        if (!(o.host_factor > 0)) throw InputError("--host-factor: expected a positive number");
        setup.host_factor = o.host_factor;
    }
    std::stringstream names(o.baselines);
    for (std::string name; std::getline(names, name, ',');) {
        try {
            setup.baselines.push_back(make_broad_phase(name));
        } catch (const std::invalid_argument& e) {
            throw InputError(std::string("--baseline: ") + e.what());
        }
    }
    return setup;
}


// Times each baseline natively on the frame and checks it finds the board's pairs.
std::map<std::string, BaselineTime> run_baselines(Setup& setup, const std::vector<FloatBox>& boxes,
                                                  const PairList& board_pairs, uint64_t frame) {
    std::map<std::string, BaselineTime> times;
    PairList found;
    for (auto& baseline : setup.baselines) {
        const auto start = std::chrono::steady_clock::now();
        baseline->find_pairs(boxes, found);
        const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
        times[baseline->name()] = {ns, ns * setup.host_factor};
        if (sorted(found) != board_pairs) {
            throw std::runtime_error("baseline " + baseline->name() + " found " + std::to_string(found.size()) +
                                     " pairs in frame " + std::to_string(frame) + ", the board " +
                                     std::to_string(board_pairs.size()));
        }
    }
    return times;
}

int simulate(const RunOptions& o, FrameSource& source, Setup& setup, Outputs& out) {
    RunSummary run;
    run.config = setup.platform.board;
    run.source = source.describe();
    run.capacity = static_cast<uint32_t>(source.max_objects());
    run.board = setup.board;
    run.host = setup.host;
    run.host_factor = setup.host_factor;
    run.dma = setup.platform.driver.use_dma;
    run.interrupts = setup.platform.driver.use_interrupts;
    for (const auto& b : setup.baselines) run.baseline_names.push_back(b->name());
    VirtualBoard platform("platform", setup.platform, run.capacity, out.vcd_base());
    run.block_rams = platform.board().core().block_rams();
    run.bus = platform.bus_timing().describe();
    if (out.pairs) write_pairs_header(out.pairs->stream());

    Progress progress(source.frame_count(), !o.quiet);
    const auto wall_start = std::chrono::steady_clock::now();
    while (std::optional<Frame> frame = source.next()) {
        const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
        const FrameResult& result = platform.run_frame(boxes);
        if (out.pairs) write_frame_pairs(out.pairs->stream(), frame->number, to_id_pairs(*frame, result.pairs));
        FrameStats stats{frame->number, boxes.size(), result.pairs.size(),
                         AddressGenerator::sweep_cycles(boxes.size(), run.config.m), result.phases, {}};
        if (!setup.baselines.empty()) stats.baselines = run_baselines(setup, boxes, sorted(result.pairs), frame->number);
        run.frames.push_back(std::move(stats));
        source.feed(result.pairs);
        progress.update(run.frames.size());
    }
    run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    platform.close_trace();

    if (out.report) out.report->stream() << report_json(run).dump(2) << '\n';
    for (auto* file : {&out.pairs, &out.report, &out.vcd}) {
        if (*file) (*file)->commit();
    }
    if (!o.quiet) print_summary(std::cout, run);
    return 0;
}

}  // namespace

int run_command(int argc, char** argv) {
    RunOptions o;
    const po::options_description options = run_options(o);
    try {
        po::variables_map vm;
        po::store(po::command_line_parser(argc, argv).options(options).run(), vm);
        if (vm.count("help")) {
            std::cout << options << '\n';
            return 0;
        }
        po::notify(vm);
        validate_board(o.board);
        std::unique_ptr<FrameSource> source = open_source(o, vm);
        Setup setup = make_setup(o, vm, source->max_objects());
        Outputs out;
        if (!o.pairs_out.empty()) out.pairs.emplace(o.pairs_out);
        if (!o.report.empty()) out.report.emplace(o.report);
        if (!o.vcd.empty()) out.vcd.emplace(o.vcd, ".vcd", false);
        return simulate(o, *source, setup, out);
    } catch (const po::error& e) {
        std::cerr << "cdvp run: " << e.what() << " (see cdvp run --help)\n";
        return 2;
    } catch (const InputError& e) {
        std::cerr << "cdvp run: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "cdvp run: simulation failed: " << e.what() << '\n';
        return 1;
    }
}

}  // namespace cdvp
