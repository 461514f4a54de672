#include "sw/cli/bullet_command.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "platform/board_preset.h"
#include "sw/bullet/board_broadphase.h"
#include "sw/cli/number_option.h"
#include "sw/cli/run_command.h"
#include "sw/scene/output_set.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kUsage =
    "Usage: cdvp bullet --scene NAME [--objects N] [--frames F] [--seed S] [--board B] [--m M]\n"
    "                   [--fidelity fast|cycle] [--software simple|sap|dbvt] [--report R.json] [-q]\n"
    "\n"
    "Steps a Bullet scene (btDiscreteDynamicsWorld) with the virtual board as its broad phase and, in\n"
    "lockstep, the same scene on one of Bullet's broad phases. Per frame: the board's modelled time,\n"
    "Bullet's broad-phase time (AABB update and pair search) and whole step time, the broad phase's\n"
    "share of the step and its Amdahl bound (the most any broad-phase accelerator can speed the step\n"
    "up), and the speed-ups the board gives. Software times are native wall times x the host factor.";

struct BulletOptions {
    SceneOptions scene;
    std::string board_name;
    uint32_t m = 8;
    std::string fidelity = "fast";
    std::string software = "dbvt";
    double host_factor = 1.0;
    std::string report;
    bool quiet = false;
};

po::options_description bullet_options(BulletOptions& o) {
    po::options_description all = scene_options(o.scene);
    po::options_description board("Board and host");
    board.add_options()
        ("board", po::value(&o.board_name)->value_name("NAME"),
         "board preset (adm-xrc-ii, adm-xrc-ii-64, pcie-gen3-x8) or a .json path; without it: the board alone on "
         "an ideal, untimed bus")
        ("m", number<uint32_t>(&o.m, 1, BoardConfig::kMaxM, "M"), "parallelism: 2m-1 comparison lanes")
        ("fidelity", po::value(&o.fidelity)->value_name("fast|cycle")->default_value(o.fidelity),
         "the board's engine (the same pairs and times; fast is quicker to simulate)")
        ("software", po::value(&o.software)->value_name("simple|sap|dbvt")->default_value(o.software),
         "Bullet's broad phase to compare with: btSimpleBroadphase, btAxisSweep3, btDbvtBroadphase")
        ("host-factor", number<double>(&o.host_factor, 0.001, 1000, "F", false),
         "native software time x F = time on the modelled host (default: the preset's, else 1)");
    po::options_description output("Output (written only if the whole run succeeds)");
    output.add_options()
        ("report", po::value(&o.report)->value_name("FILE"), "JSON report: configuration and every frame")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors");
    all.add(board).add(output);
    return all;
}

struct Setup {
    PlatformConfig platform;
    std::string board = "ideal";
    std::string host = "this machine";
    double host_factor = 1.0;
    BroadphaseKind software = BroadphaseKind::kDbvt;
};

Setup make_setup(const BulletOptions& o, const po::variables_map& vm, uint32_t proxies) {
    Setup setup;
    setup.platform.board.m = o.m;
    if (o.fidelity != "fast" && o.fidelity != "cycle") {
        throw InputError("--fidelity: expected fast or cycle, got '" + excerpt(o.fidelity) + "'");
    }
    setup.platform.fidelity = o.fidelity == "fast" ? Fidelity::kFast : Fidelity::kCycle;
    if (o.software == "board" || (o.software != "simple" && o.software != "sap" && o.software != "dbvt")) {
        throw InputError("--software: expected simple, sap or dbvt, got '" + excerpt(o.software) + "'");
    }
    setup.software = broadphase_kind(o.software);
    if (vm.count("board")) {
        const BoardPreset preset = load_board_preset(o.board_name);
        const uint32_t m = setup.platform.board.m;
        setup.platform.board = preset.board;
        setup.platform.board.m = m;
        setup.platform.bus = preset.bus;
        setup.platform.driver = preset.driver;
        setup.board = preset.name;
        setup.host = preset.host.name;
        setup.host_factor = preset.host.speed_factor;
        const uint64_t needed = setup.platform.board.block_rams(proxies);
        if (needed > preset.block_rams) {
            throw InputError(preset.path + ": device.block_rams: " + std::to_string(preset.block_rams) +
                             " block RAMs are too few for --m " + std::to_string(m) + " at " +
                             std::to_string(proxies) + " proxies (the scene's): they need 6 x m x ceil(N/512) = " +
                             std::to_string(needed));
        }
    }
    if (vm.count("host-factor")) setup.host_factor = o.host_factor;
    try {
        setup.platform.board.validate();
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    return setup;
}

// One frame, all times in ns on the modelled host.
struct FrameRow {
    uint64_t frame = 0;
    uint32_t proxies = 0;
    std::size_t pairs = 0;     // overlapping pairs the board found
    std::size_t contacts = 0;  // contact points in the board world
    double board_ns = 0;       // the board's frame (modelled: upload, compute, interrupt, read-back, driver)
    double board_host_ns = 0;  // the host's side around it: AABB update and pair-cache upkeep
    double software_ns = 0;    // Bullet's broad phase: AABB update and pair search
    double step_ns = 0;        // Bullet's whole step with that broad phase
    double simulate_wall_ns = 0;  // simulating the board, native

    double share() const { return step_ns > 0 ? software_ns / step_ns : 0; }
    // Amdahl: a broad phase that cost nothing would speed the step up at most this much.
    double amdahl_bound() const { return software_ns < step_ns ? step_ns / (step_ns - software_ns) : 0; }
    double broadphase_speedup() const { return software_ns / (board_ns + board_host_ns); }
    double step_speedup() const { return step_ns / (step_ns - software_ns + board_ns + board_host_ns); }
};

FrameRow step_both(BulletWorld& board_world, BulletWorld& software_world, double factor, uint64_t frame) {
    const StepTimes board_times = board_world.step();
    const StepTimes software_times = software_world.step();
    const auto& board = dynamic_cast<const BoardBroadphase&>(board_world.broadphase()).last_frame();
    FrameRow row;
    row.frame = frame;
    row.proxies = board.proxies;
    row.pairs = board.board_pairs;
    row.contacts = board_world.contact_points();
    row.board_ns = board.phases.total_ns;
    row.board_host_ns = (board_times.aabbs_ns + board.bookkeeping_ns) * factor;
    row.software_ns = software_times.broadphase_share_ns() * factor;
    row.step_ns = software_times.step_ns * factor;
    row.simulate_wall_ns = board.simulate_ns;
    return row;
}

nlohmann::json to_json(const FrameRow& r) {
    return {{"frame", r.frame},           {"proxies", r.proxies},
            {"pairs", r.pairs},           {"contact_points", r.contacts},
            {"board_ns", r.board_ns},     {"board_host_ns", r.board_host_ns},
            {"software_broadphase_ns", r.software_ns}, {"software_step_ns", r.step_ns},
            {"broadphase_share", r.share()}, {"amdahl_bound", r.amdahl_bound()},
            {"broadphase_speedup", r.broadphase_speedup()}, {"step_speedup", r.step_speedup()},
            {"simulate_wall_ns", r.simulate_wall_ns}};
}

// Medians after the first frame (in which the incremental broad phases build
// their structures): the software times are wall times on a shared machine,
// and a median is not moved by a step the scheduler interrupted.
FrameRow median_after_first(const std::vector<FrameRow>& rows) {
    const std::size_t first = rows.size() > 1 ? 1 : 0;
    auto median = [&](auto field) {
        std::vector<double> values;
        for (std::size_t k = first; k < rows.size(); ++k) values.push_back(static_cast<double>(rows[k].*field));
        std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
        return values[values.size() / 2];
    };
    FrameRow m;
    m.proxies = rows.back().proxies;
    m.pairs = static_cast<std::size_t>(median(&FrameRow::pairs));
    m.contacts = static_cast<std::size_t>(median(&FrameRow::contacts));
    m.board_ns = median(&FrameRow::board_ns);
    m.board_host_ns = median(&FrameRow::board_host_ns);
    m.software_ns = median(&FrameRow::software_ns);
    m.step_ns = median(&FrameRow::step_ns);
    m.simulate_wall_ns = median(&FrameRow::simulate_wall_ns);
    return m;
}

void print_row(std::ostream& out, const char* label, const FrameRow& r) {
    char line[200];
    std::snprintf(line, sizeof line, "%7s %7u %7zu %9.1f %9.1f %9.1f %9.1f %6.1f%% %7.2fx %7.2fx %7.3fx\n", label,
                  r.proxies, r.pairs, r.board_ns * 1e-3, r.board_host_ns * 1e-3, r.software_ns * 1e-3,
                  r.step_ns * 1e-3, 100 * r.share(), r.amdahl_bound(), r.broadphase_speedup(), r.step_speedup());
    out << line;
}

std::string summary(const SceneSpec& spec, const Setup& setup, const std::vector<FrameRow>& rows) {
    std::ostringstream out;
    const char* software = to_string(setup.software);
    out << "bullet " << spec.name << " objects=" << (spec.objects ? spec.objects : default_objects(spec.name))
        << " seed=" << spec.seed << " on " << setup.board << ": m=" << setup.platform.board.m << ", "
        << to_string(setup.platform.fidelity) << " engine; against " << software << " on " << setup.host
        << " (software time x " << setup.host_factor << ")\n";
    out << "  frame proxies   pairs  board_us   host_us  " << software << "_us   step_us  share  amdahl  bp_gain"
        << " step_gain\n";
    for (std::size_t k = 0; k < rows.size() && k < 10; ++k) print_row(out, std::to_string(rows[k].frame).c_str(), rows[k]);
    if (rows.size() > 10) out << "    ... (" << rows.size() - 10 << " more frames in --report)\n";
    print_row(out, "median", median_after_first(rows));
    out << "board_us: the board's modelled frame; host_us: AABB update and pair-cache upkeep around it;\n"
        << "share: " << software << "'s broad phase in its step; amdahl: the most a free broad phase would gain;\n"
        << "bp_gain, step_gain: what the board gains on the broad phase and on the step. Medians leave out frame 0.\n";
    return out.str();
}

int simulate(const BulletOptions& o, const po::variables_map& vm) {
    const SceneSpec spec = scene_spec(o.scene, vm);
    const SceneLayout layout = scene_layout(spec);
    OutputSet files;
    if (vm.count("board") && !o.board_name.empty()) files.add_input("--board", board_preset_path(o.board_name));
    std::optional<std::size_t> report;
    if (vm.count("report")) report = files.add_output("--report", o.report);
    if (!o.quiet) files.add_standard_output("standard output");
    files.open();
    const Setup setup = make_setup(o, vm, layout.proxies);

    LazyVirtualBoard link(setup.platform, layout.proxies);
    auto board_world = make_scene_world(spec, BroadphaseKind::kBoard, &link);
    auto software_world = make_scene_world(spec, setup.software);
    std::vector<FrameRow> rows;
    nlohmann::json frames = nlohmann::json::array();
    for (uint64_t frame = 0; frame < o.scene.frames; ++frame) {
        rows.push_back(step_both(*board_world, *software_world, setup.host_factor, frame));
        frames.push_back(to_json(rows.back()));
    }
    if (report) {
        nlohmann::json config = {{"scene", spec.name}, {"objects", spec.objects ? spec.objects : default_objects(spec.name)},
                                 {"seed", spec.seed},  {"frames", o.scene.frames},
                                 {"proxies", layout.proxies}, {"board", setup.board},
                                 {"m", setup.platform.board.m}, {"fidelity", to_string(setup.platform.fidelity)},
                                 {"software", to_string(setup.software)}, {"host", setup.host},
                                 {"host_factor", setup.host_factor}};
        nlohmann::json median = to_json(median_after_first(rows));
        median.erase("frame");
        files.file(*report).stream() << nlohmann::json{{"config", config}, {"frames", frames}, {"median_after_first", median}}
                                            .dump(1)
                                     << '\n';
    }
    if (!o.quiet) files.set_standard_output(summary(spec, setup, rows));
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp bullet", *failure);
    return kExitDone;
}

}  // namespace

int bullet_command(int argc, char** argv) {
    BulletOptions o;
    const po::options_description options = bullet_options(o);
    return run_command_line("cdvp bullet", argc, argv, kUsage, options,
                            [&o](const po::variables_map& vm) { return simulate(o, vm); });
}

}  // namespace cdvp
