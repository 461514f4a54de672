#include "sw/cli/calibrate_command.h"

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "models/common/user_text.h"
#include "platform/board_preset.h"
#include "sw/baselines/broad_phase.h"
#include "sw/cli/baseline_timing.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/frame_source.h"
#include "sw/cli/host_factor.h"
#include "sw/cli/number_option.h"
#include "sw/cli/reference_workload.h"
#include "sw/scene/conversion.h"
#include "sw/study/output/output_set.h"
#include "sw/timing/frame_samples.h"

namespace po = boost::program_options;

namespace cdvp {


namespace {

constexpr const char* kUsage =
    "Usage: cdvp calibrate [--out PROFILE.json] [--repeat R] [-q]\n"
    "\n"
    "Times the reference workload on this machine: every software baseline (sap, dbvt, brute, soa) on\n"
    "the spheres scene of seed 1 at 100, 500 and 2000 objects, 30 frames each, the first 2 left out,\n"
    "R times over with fresh instances. Writes a host profile: the machine (CPU model and clock,\n"
    "cores, kernel), the build (compiler, flags, commit), the load average, each baseline's mean frame\n"
    "time at each size with its spread over the R runs, and the factor to each preset's modelled host.\n"
    "Runs read it (--host-profile, or the default location) and scale each baseline's native time by\n"
    "its preset's reference time over this machine's (docs/timing.md). Run it on an otherwise idle\n"
    "machine, with the build the runs will use.";

struct CalibrateOptions {
    std::string out;
    uint32_t repeat = 5;
    bool quiet = false;
};

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm parts{};
    gmtime_r(&now, &parts);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
    return text;
}

// One size of the workload, 'repeat' times: every baseline on each frame in
// turn (as cdvp run times them), the scene stepped on the pairs they agree on.
std::map<std::string, TimingFigures> time_size(uint64_t objects, uint32_t repeat) {
    namespace w = reference_workload;
    std::map<std::string, FrameSamples> samples;
    for (const std::string& name : w::baselines()) samples.emplace(name, FrameSamples(w::kWarmup));
    BouncingSpheresConfig scene;
    scene.objects = static_cast<std::size_t>(objects);
    scene.seed = w::kSeed;
    for (uint32_t run = 0; run < repeat; ++run) {
        std::vector<std::unique_ptr<BroadPhase>> fresh;
        for (const std::string& name : w::baselines()) {
            fresh.push_back(make_broad_phase(name));
            samples.at(name).start_run();
        }
        const std::unique_ptr<FrameSource> source = spheres_source(scene, static_cast<std::size_t>(w::kFrames));
        PairList first, found;
        while (std::optional<Frame> frame = source->next()) {
            const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
            for (std::size_t b = 0; b < fresh.size(); ++b) {
                samples.at(fresh[b]->name()).add(time_find_pairs(*fresh[b], boxes, b == 0 ? first : found));
                if (b > 0 && found != first) {
                    throw std::runtime_error("calibrate: baseline " + fresh[b]->name() + " disagrees with " +
                                             fresh[0]->name() + " on frame " + std::to_string(frame->number));
                }
            }
            source->feed(first);
        }
    }
    std::map<std::string, TimingFigures> figures;
    for (const auto& [name, s] : samples) figures[name] = s.figures();
    return figures;
}

HostProfile measure(uint32_t repeat, bool quiet) {
    HostProfile profile;
    profile.created = utc_now();
    profile.machine = read_machine_info();
    profile.build = build_info();
    profile.repeat = repeat;
    profile.load_average_start = load_average();
    for (const uint64_t objects : reference_workload::objects()) {
        if (!quiet) std::cerr << "cdvp calibrate: timing " << objects << " objects\n";
        for (const auto& [name, figures] : time_size(objects, repeat)) {
            profile.reference[name].sizes.push_back({objects, figures.run_means, figures.spread.mean});
        }
    }
    profile.load_average_end = load_average();
    for (auto& [name, baseline] : profile.reference) {
        std::vector<double> means;
        for (const ReferenceTiming& t : baseline.sizes) means.push_back(t.mean_native_ns);
        baseline.reference_native_ns = geometric_mean(means);
    }
    for (const std::string& name : board_preset_names()) {
        profile.factors[name] = derive_factors(load_board_preset(name).applied().settings().host, profile);
    }
    return profile;
}

std::string summary(const HostProfile& p, const std::string& out) {
    std::ostringstream text;
    char line[256];
    std::snprintf(line, sizeof line, ", load average %.2f to %.2f:\n", p.load_average_start[0], p.load_average_end[0]);
    text << "host profile of " << printable(p.machine.cpu_model) << " (" << p.machine.cores_allowed << " of "
         << p.machine.cores_online << " cores), " << printable(p.build.compiler) << " " << printable(p.build.flags)
         << line;
    text << "  baseline  objects  mean_native_us  spread over " << p.repeat << " runs\n";
    for (const auto& [name, baseline] : p.reference) {
        for (const ReferenceTiming& t : baseline.sizes) {
            std::snprintf(line, sizeof line, "  %-8s %8llu %15.1f %8.1f%%\n", name.c_str(),
                          static_cast<unsigned long long>(t.objects), t.mean_native_ns / 1e3, 100 * t.spread());
            text << line;
        }
    }
    for (const auto& [preset, factors] : p.factors) {
        if (factors.empty()) continue;
        text << "  factor to " << preset << "'s host:";
        for (const auto& [name, factor] : factors) {
            std::snprintf(line, sizeof line, " %s %.3g", name.c_str(), factor);
            text << line;
        }
        text << '\n';
    }
    text << "written to " << printable(out) << '\n';
    return text.str();
}

int calibrate(const CalibrateOptions& o, const po::variables_map& vm) {
    const std::string out = vm.count("out") ? o.out : default_host_profile_path();
    if (out.empty()) throw InputError("--out: no default location ($XDG_CONFIG_HOME and $HOME unset); give --out");
    if (vm.count("out") == 0) {
        // The default location's directory is made; a path the user gave must lead somewhere already.
        std::error_code ignored;
        std::filesystem::create_directories(std::filesystem::path(out).parent_path(), ignored);
    }
    OutputSet files;
    const std::size_t profile_file = files.add_output("--out", out);
    if (!o.quiet) files.add_standard_output("standard output");
    files.open();
    const HostProfile profile = measure(o.repeat, o.quiet);
    files.file(profile_file).stream() << host_profile_json(profile);
    if (!o.quiet) files.set_standard_output(summary(profile, out));
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp calibrate", *failure);
    return kExitDone;
}

}  // namespace

int calibrate_command(int argc, char** argv) {
    CalibrateOptions o;
    po::options_description options("Options");
    options.add_options()
        ("out", po::value(&o.out)->value_name("PROFILE.json"),
         "the profile to write (default: host-profile.json in $XDG_CONFIG_HOME/cdvp, else in ~/.config/cdvp, "
         "where runs look for it)")
        ("repeat", number<uint32_t>(&o.repeat, 1, 1000, "R"), "runs of the workload; each time is the median of their means")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors");
    return run_command_line("cdvp calibrate", argc, argv, kUsage, options,
                            [&o](const po::variables_map& vm) { return calibrate(o, vm); });
}

}  // namespace cdvp
