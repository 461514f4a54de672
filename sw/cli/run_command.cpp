#include "sw/cli/run_command.h"

#include <unistd.h>

#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <boost/program_options.hpp>

#include "models/address_generator/address_generator.h"
#include "models/control_registers/control_registers.h"
#include "platform/virtual_board.h"
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
    SpheresConfig spheres;
    // Signed, so that a negative count is reported instead of wrapping around.
    int64_t objects = 500;
    int64_t frames = 1;
    BoardConfig board;
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
    po::options_description output("Output");
    output.add_options()
        ("pairs-out", po::value(&o.pairs_out)->value_name("FILE"), "overlapping pairs CSV (frame,a,b)")
        ("report", po::value(&o.report)->value_name("FILE"), "JSON report: configuration and per-frame cycles")
        ("vcd", po::value(&o.vcd)->value_name("FILE"), "board waveforms (VCD, opens in GTKWave)")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors")
        ("help,h", "show this help");
    po::options_description all("Usage: cdvp run (--trace FILE | --scene spheres [--objects N] [--frames F] "
                                "[--seed S]) [options]\n\nSimulates each frame on the cycle-level board "
                                "and reports its pairs and cycles");
    all.add(input).add(board).add(output);
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
    SpheresConfig spheres = o.spheres;
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

int simulate(const RunOptions& o, FrameSource& source, Outputs& out) {
    RunSummary run;
    run.config = o.board;
    run.source = source.describe();
    run.capacity = static_cast<uint32_t>(source.max_objects());
    VirtualBoard platform("platform", o.board, run.capacity, out.vcd_base());
    run.block_rams = platform.board().core().block_rams();
    if (out.pairs) write_pairs_header(out.pairs->stream());

    Progress progress(source.frame_count(), !o.quiet);
    const auto wall_start = std::chrono::steady_clock::now();
    while (std::optional<Frame> frame = source.next()) {
        const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
        const FrameResult& result = platform.run_frame(boxes);
        if (out.pairs) write_frame_pairs(out.pairs->stream(), frame->number, to_id_pairs(*frame, result.pairs));
        run.frames.push_back({frame->number, boxes.size(), result.pairs.size(),
                              AddressGenerator::sweep_cycles(boxes.size(), o.board.m), result.phases.compute_cycles,
                              result.phases.stall_cycles, result.phases.overflow_pauses});
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
        Outputs out;
        if (!o.pairs_out.empty()) out.pairs.emplace(o.pairs_out);
        if (!o.report.empty()) out.report.emplace(o.report);
        if (!o.vcd.empty()) out.vcd.emplace(o.vcd, ".vcd", false);
        return simulate(o, *source, out);
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
