#include "sw/cli/bullet_command.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "platform/board_preset.h"
#include "sw/bullet/board_broadphase.h"
#include "sw/cli/host_factor.h"
#include "sw/cli/number_option.h"
#include "sw/cli/report_provenance.h"
#include "sw/cli/run_command.h"
#include "sw/scene/output_set.h"
#include "sw/timing/frame_samples.h"

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
    "up), and the speed-ups the board gives. Software times are native wall times x the host factor\n"
    "(from the host profile, as for cdvp run: docs/timing.md). The summary gives each time's mean over\n"
    "the frames after the first, which the speed-ups compare, with p50, p99 and the maximum.";

struct BulletOptions {
    SceneOptions scene;
    std::string board_name;
    uint32_t m = 8;
    std::string fidelity = "fast";
    std::string software = "dbvt";
    double host_factor = 1.0;
    std::string host_profile;
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
         "native software time x F = time on the modelled host (default: from the host profile, else the "
         "preset's, else 1)")
        ("host-profile", po::value(&o.host_profile)->value_name("FILE"),
         "host profile from cdvp calibrate (default: host-profile.json in $XDG_CONFIG_HOME/cdvp, else in "
         "~/.config/cdvp, when there)");
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
    // Bullet's times are whole worlds, not the reference workload's
    // baselines: they all take the overall factor.
    HostTiming host;
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
    HostConfig host;
    if (vm.count("board")) {
        const BoardPreset preset = load_board_preset(o.board_name);
        const uint32_t m = setup.platform.board.m;
        setup.platform.board = preset.board;
        setup.platform.board.m = m;
        setup.platform.bus = preset.bus;
        setup.platform.driver = preset.driver;
        setup.board = preset.name;
        host = preset.host;
        const uint64_t needed = setup.platform.board.block_rams(proxies);
        if (needed > preset.block_rams) {
            throw InputError(preset.path + ": device.block_rams: " + std::to_string(preset.block_rams) +
                             " block RAMs are too few for --m " + std::to_string(m) + " at " +
                             std::to_string(proxies) + " proxies (the scene's): they need 6 x m x ceil(N/512) = " +
                             std::to_string(needed));
        }
    }
    if (vm.count("host-factor")) host.speed_factor = o.host_factor;
    host.profile = o.host_profile;
    setup.host = resolve_host_timing(host, vm.count("host-factor") != 0);
    try {
        setup.platform.board.validate();
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    return setup;
}

// One frame's times: board_ns simulated, _host_ns native x the host factor
// (the modelled host), _native_ns as measured here.
struct FrameRow {
    uint64_t frame = 0;
    uint32_t proxies = 0;
    std::size_t pairs = 0;     // overlapping pairs the board found
    std::size_t contacts = 0;  // contact points in the board world
    double board_ns = 0;       // the board's frame (simulated: upload, compute, interrupt, read-back, driver)
    double bookkeeping_host_ns = 0;  // the host's side around it: AABB update and pair-cache upkeep
    double software_host_ns = 0;     // Bullet's broad phase: AABB update and pair search
    double step_host_ns = 0;         // Bullet's whole step with that broad phase
    double simulate_wall_native_ns = 0;  // simulating the board

    double share() const { return step_host_ns > 0 ? software_host_ns / step_host_ns : 0; }
    // Amdahl: a broad phase that cost nothing would speed the step up at most this much.
    double amdahl_bound() const {
        return software_host_ns < step_host_ns ? step_host_ns / (step_host_ns - software_host_ns) : 0;
    }
    double broadphase_speedup() const { return software_host_ns / (board_ns + bookkeeping_host_ns); }
    double step_speedup() const {
        return step_host_ns / (step_host_ns - software_host_ns + board_ns + bookkeeping_host_ns);
    }
};

// The time fields of a frame, by their report names.
const std::vector<std::pair<const char*, double FrameRow::*>>& time_fields() {
    static const std::vector<std::pair<const char*, double FrameRow::*>> fields{
        {"board_ns", &FrameRow::board_ns},
        {"bookkeeping_host_ns", &FrameRow::bookkeeping_host_ns},
        {"software_broadphase_host_ns", &FrameRow::software_host_ns},
        {"software_step_host_ns", &FrameRow::step_host_ns},
        {"simulate_wall_native_ns", &FrameRow::simulate_wall_native_ns}};
    return fields;
}

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
    row.bookkeeping_host_ns = (board_times.aabbs_ns + board.bookkeeping_ns) * factor;
    row.software_host_ns = software_times.broadphase_share_ns() * factor;
    row.step_host_ns = software_times.step_ns * factor;
    row.simulate_wall_native_ns = board.simulate_ns;
    return row;
}

// The ratios of a row: per frame, or of the means.
void add_ratios(nlohmann::json& json, const FrameRow& r) {
    json["broadphase_share"] = r.share();
    json["amdahl_bound"] = r.amdahl_bound();
    json["broadphase_speedup"] = r.broadphase_speedup();
    json["step_speedup"] = r.step_speedup();
}

nlohmann::json to_json(const FrameRow& r) {
    nlohmann::json json = {{"frame", r.frame}, {"proxies", r.proxies}, {"pairs", r.pairs}, {"contact_points", r.contacts}};
    for (const auto& [name, field] : time_fields()) json[name] = r.*field;
    add_ratios(json, r);
    return json;
}

// Frame 0 is left out: the incremental broad phases build their structures
// in it. Each time's mean over the rest is what a simulation pays (dbvt's
// rebuilds, a few frames in many, included), so the gains divide means;
// p50, p99 and the maximum are beside them for real-time budgets.
constexpr uint64_t kBulletWarmupFrames = 1;

struct Summary {
    std::map<std::string, Spread> times;  // by report name
    FrameRow means;                       // each time its mean: the ratios of the means
    uint64_t frames_in_means = 0;
};

Summary summarise(const std::vector<FrameRow>& rows) {
    Summary summary;
    for (const auto& [name, field] : time_fields()) {
        FrameSamples samples(kBulletWarmupFrames);
        for (const FrameRow& row : rows) samples.add(row.*field);
        const TimingFigures figures = samples.figures();
        summary.times[name] = figures.spread;
        summary.means.*field = figures.spread.mean;
        summary.frames_in_means = figures.frames_per_run;
    }
    summary.means.proxies = rows.back().proxies;
    return summary;
}

nlohmann::json to_json(const Summary& summary) {
    nlohmann::json json = {{"frames_in_means", summary.frames_in_means},
                           {"warmup_frames", kBulletWarmupFrames},
                           {"load_average_end", load_json(load_average())}};
    for (const auto& [name, spread] : summary.times) {
        json["mean_" + name] = spread.mean;
        json["p50_" + name] = spread.p50;
        json["p99_" + name] = spread.p99;
        json["max_" + name] = spread.max;
    }
    add_ratios(json, summary.means);
    return json;
}

void print_times(std::ostream& out, const char* label, uint32_t proxies, std::size_t pairs, const FrameRow& r,
                 bool ratios) {
    char line[200];
    std::snprintf(line, sizeof line, "%7s %7u %7zu %9.1f %9.1f %9.1f %9.1f", label, proxies, pairs, r.board_ns * 1e-3,
                  r.bookkeeping_host_ns * 1e-3, r.software_host_ns * 1e-3, r.step_host_ns * 1e-3);
    out << line;
    if (ratios) {
        std::snprintf(line, sizeof line, " %6.1f%% %7.2fx %7.2fx %7.3fx", 100 * r.share(), r.amdahl_bound(),
                      r.broadphase_speedup(), r.step_speedup());
        out << line;
    }
    out << '\n';
}

std::string summary_text(const SceneSpec& spec, const Setup& setup, const std::vector<FrameRow>& rows) {
    std::ostringstream out;
    const char* software = to_string(setup.software);
    out << "bullet " << spec.name << " objects=" << (spec.objects ? spec.objects : default_objects(spec.name))
        << " seed=" << spec.seed << " on " << setup.board << ": m=" << setup.platform.board.m << ", "
        << to_string(setup.platform.fidelity) << " engine; against " << software << " on " << printable(setup.host.host)
        << " (software: " << setup.host.describe() << ")\n";
    out << "  frame proxies   pairs  board_us   bookkeeping_host_us  " << software
        << "_host_us   step_host_us  share  amdahl  bp_gain step_gain\n";
    for (std::size_t k = 0; k < rows.size() && k < 10; ++k) {
        print_times(out, std::to_string(rows[k].frame).c_str(), rows[k].proxies, rows[k].pairs, rows[k], true);
    }
    if (rows.size() > 10) out << "    ... (" << rows.size() - 10 << " more frames in --report)\n";
    const Summary summary = summarise(rows);
    print_times(out, "mean", summary.means.proxies, rows.back().pairs, summary.means, true);
    for (const auto& [label, pick] : {std::pair<const char*, double Spread::*>{"p50", &Spread::p50},
                                      {"p99", &Spread::p99}, {"max", &Spread::max}}) {
        FrameRow row;
        for (const auto& [name, field] : time_fields()) row.*field = summary.times.at(name).*pick;
        print_times(out, label, summary.means.proxies, rows.back().pairs, row, false);
    }
    out << "board_us: the board's simulated frame; bookkeeping: AABB update and pair-cache upkeep around it;\n"
        << "_host_us: native time x the host factor; share: " << software << "'s broad phase in its step;\n"
        << "amdahl: the most a free broad phase would gain; bp_gain, step_gain: what the board gains on the\n"
        << "broad phase and on the step, from the means (frame 0 left out).\n";
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
    const std::array<double, 3> load_start = load_average();
    std::vector<FrameRow> rows;
    nlohmann::json frames = nlohmann::json::array();
    for (uint64_t frame = 0; frame < o.scene.frames; ++frame) {
        rows.push_back(step_both(*board_world, *software_world, setup.host.overall, frame));
        frames.push_back(to_json(rows.back()));
    }
    if (report) {
        nlohmann::json config = {{"scene", spec.name}, {"objects", spec.objects ? spec.objects : default_objects(spec.name)},
                                 {"seed", spec.seed},  {"frames", o.scene.frames},
                                 {"proxies", layout.proxies}, {"board", setup.board},
                                 {"m", setup.platform.board.m}, {"fidelity", to_string(setup.platform.fidelity)},
                                 {"software", to_string(setup.software)}, {"host", setup.host.host},
                                 {"host_factor", setup.host.overall},
                                 {"host_calibration", host_calibration_json(setup.host)},
                                 {"provenance", provenance_json(read_machine_info(), load_start, setup.host)}};
        files.file(*report).stream()
            << nlohmann::json{{"config", config}, {"frames", frames}, {"summary", to_json(summarise(rows))}}.dump(1)
            << '\n';
    }
    if (!o.quiet) files.set_standard_output(summary_text(spec, setup, rows));
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp bullet", *failure);
    const std::string note = uncalibrated_note(setup.host);
    if (!o.quiet && !note.empty()) std::cerr << "cdvp bullet: " << note << '\n';
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
