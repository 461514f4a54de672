#include "sw/cli/calibrate_command.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "models/common/user_text.h"
#include "models/common/number_text.h"
#include "platform/settings/board_preset.h"
#include "sw/run/machine_info.h"
#include "sw/baselines/broad_phase.h"
#include "sw/run/baseline_timing.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/exit_status.h"
#include "sw/run/frame_source.h"
#include "sw/run/host_factor.h"
#include "sw/cli/number_option.h"
#include "sw/run/reference_workload.h"
#include "sw/scene/conversion.h"
#include "sw/output/output_set.h"
#include "sw/timing/frame_samples.h"
#include "sw/timing/speed_probe.h"

namespace po = boost::program_options;

namespace cdvp {


namespace {

constexpr const char* kCalibrateUsage =
    "Usage: cdvp calibrate [--out PROFILE.json] [--repeat R] [--max-spread P] [--time-limit S] [--strict] [-q]\n"
    "\n"
    "Times the reference workload on this machine in the thread's CPU time: the software baselines sap,\n"
    "dbvt, brute, soa and sap_mt (on one thread; the FCL and ODE ones take the overall factor) on the\n"
    "spheres scene of seed 1 at 100, 500 and 2000 objects, 30 frames each, the first 2 left out, with\n"
    "fresh instances each run. It runs the workload again until, for every baseline\n"
    "and size, R runs' means lie within P% of each other (those R are kept; a run a neighbour disturbed\n"
    "falls outside them), or S seconds have passed. Writes a host profile: the machine (CPU model and\n"
    "clock, cores, kernel), the build (compiler, flags, commit), the load average, each baseline's mean\n"
    "frame time at each size with its runs and spread, the runs made and the worst spread, and the factor\n"
    "to each preset's modelled host. A profile whose spread stayed over P% is written marked poor, with a\n"
    "warning naming the load (refused, and nothing written, with --strict); runs that use it say so.\n"
    "Runs read it (--host-profile, or the default location) and scale each baseline's native time by\n"
    "its preset's reference time over this machine's (docs/timing.md).";

struct CalibrateOptions {
    std::string out;
    uint32_t repeat = 5;
    double max_spread_percent = 3;
    double time_limit_s = 120;
    bool strict = false;
    bool quiet = false;
};

// One run of one size: every baseline on each frame in turn (as cdvp run
// times them), the scene stepped on the pairs they agree on; each
// baseline's mean frame time after the warm-up, in CPU time.
std::map<std::string, double> time_run(uint64_t objects, uint64_t& disturbed_frames) {
    namespace w = reference_workload;
    std::map<std::string, FrameSamples> samples;
    std::vector<std::unique_ptr<BroadPhase>> fresh;
    for (const std::string& name : w::baselines()) {
        samples.emplace(name, FrameSamples(w::kWarmup));
        fresh.push_back(make_broad_phase(name, BaselineOptions{w::kCalibrationThreads}));
    }
    BouncingSpheresConfig scene;
    scene.objects = static_cast<std::size_t>(objects);
    scene.seed = w::kSeed;
    const std::unique_ptr<FrameSource> source = spheres_source(scene, static_cast<std::size_t>(w::kFrames));
    PairList first, found;
    while (std::optional<Frame> frame = source->next()) {
        const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
        for (std::size_t b = 0; b < fresh.size(); ++b) {
            const CallTiming t = time_find_pairs(*fresh[b], boxes, b == 0 ? first : found);
            samples.at(fresh[b]->name()).add(t.cpu_ns);
            disturbed_frames += t.disturbed() ? 1 : 0;
            if (b > 0 && found != first) {
                throw std::runtime_error("calibrate: baseline " + fresh[b]->name() + " disagrees with " +
                                         fresh[0]->name() + " on frame " + std::to_string(frame->number));
            }
        }
        source->feed(first);
    }
    std::map<std::string, double> means;
    for (const auto& [name, s] : samples) means[name] = s.figures().spread.mean;
    return means;
}

// The `keep` of `means` that lie closest together (by max/min), ascending;
// all of them when there are no more.
std::vector<double> closest(std::vector<double> means, std::size_t keep) {
    std::sort(means.begin(), means.end());
    if (means.size() <= keep) return means;
    std::size_t best = 0;
    for (std::size_t k = 1; k + keep <= means.size(); ++k) {
        if (means[k + keep - 1] * means[best] < means[best + keep - 1] * means[k]) best = k;
    }
    return {means.begin() + static_cast<std::ptrdiff_t>(best), means.begin() + static_cast<std::ptrdiff_t>(best + keep)};
}

// Runs of the whole workload until every baseline's kept runs agree within
// the target at every size, or the time is up (at least `repeat` runs).
HostProfile measure(const CalibrateOptions& o) {
    namespace w = reference_workload;
    HostProfile profile;
    profile.created = utc_now();
    profile.machine = read_machine_info();
    profile.build = build_info();
    profile.repeat = o.repeat;
    profile.target_spread = o.max_spread_percent / 100;
    profile.load_average_start = load_average();
    for (const std::string& name : w::baselines()) {
        for (const uint64_t objects : w::objects()) profile.reference[name].sizes.push_back({objects, {}, {}, 0});
    }
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    for (uint32_t run = 1;; ++run) {
        for (std::size_t size = 0; size < w::objects().size(); ++size) {
            for (const auto& [name, mean] : time_run(w::objects()[size], profile.disturbed_frames)) {
                ReferenceTiming& t = profile.reference.at(name).sizes[size];
                t.run_means_native_ns.push_back(mean);
                t.kept_means_native_ns = closest(t.run_means_native_ns, o.repeat);
            }
        }
        profile.runs = run;
        profile.spread = 0;
        for (const auto& [name, baseline] : profile.reference) {
            for (const ReferenceTiming& t : baseline.sizes) profile.spread = std::max(profile.spread, t.spread());
        }
        if (!o.quiet && isatty(2)) {
            std::fprintf(stderr, "\rcdvp calibrate: run %u, spread %.1f%% (target %.1f%%)", run, 100 * profile.spread,
                         o.max_spread_percent);
        }
        if (run >= o.repeat && (profile.spread <= profile.target_spread || elapsed() >= o.time_limit_s)) break;
        if (run >= 10000) break;
    }
    if (!o.quiet && isatty(2)) std::fputs("\r\033[K", stderr);
    // The machine's fast speed, which runs hold their frames to.
    SpeedProbe probe;
    std::vector<double> probes;
    for (int k = 0; k < 4000; ++k) probes.push_back(probe.time_ns());
    profile.probe_native_ns = fast_probe_ns(probes);
    profile.seconds = elapsed();
    profile.load_average_end = load_average();
    for (auto& [name, baseline] : profile.reference) {
        std::vector<double> means;
        for (ReferenceTiming& t : baseline.sizes) {
            t.mean_native_ns = quantile(t.kept_means_native_ns, 0.5);
            means.push_back(t.mean_native_ns);
        }
        baseline.reference_native_ns = geometric_mean(means);
    }
    for (const std::string& name : board_preset_names()) {
        profile.factors[name] = derive_factors(load_board_preset(name).applied().settings().host, profile);
    }
    return profile;
}

// The worst baseline and size, for the warning.
std::string worst_words(const HostProfile& p) {
    std::string words;
    double worst = -1;
    for (const auto& [name, baseline] : p.reference) {
        for (const ReferenceTiming& t : baseline.sizes) {
            if (t.spread() > worst) {
                worst = t.spread();
                words = name + " at " + std::to_string(t.objects) + " objects";
            }
        }
    }
    return words;
}

// One line: why this profile is poor, and what to do.
std::string poor_words(const HostProfile& p) {
    const auto [spread, target] = distinct_figures(100 * p.spread, 100 * p.target_spread, 1);
    char line[600];
    std::snprintf(line, sizeof line,
                  "the reference workload's runs stayed %s%% apart (%s), over the %s%% asked for, after %u runs "
                  "in %.0f s at load %.2f to %.2f (%llu frames disturbed)",
                  spread.c_str(), worst_words(p).c_str(), target.c_str(), p.runs, p.seconds,
                  p.load_average_start[0], p.load_average_end[0], static_cast<unsigned long long>(p.disturbed_frames));
    return line;
}

std::string summary(const HostProfile& p, const std::string& out) {
    std::ostringstream text;
    char line[256];
    std::snprintf(line, sizeof line, ", load average %.2f to %.2f:\n", p.load_average_start[0], p.load_average_end[0]);
    text << "host profile of " << printable(p.machine.cpu_model) << " (" << p.machine.cores_allowed << " of "
         << p.machine.cores_online << " cores), " << printable(p.build.compiler) << " " << printable(p.build.flags)
         << line;
    std::snprintf(line, sizeof line, "  thread CPU time; %u runs in %.1f s, the %u closest kept; worst spread %.1f%% (target %.1f%%)\n",
                  p.runs, p.seconds, p.repeat, 100 * p.spread, 100 * p.target_spread);
    text << line;
    text << "  baseline  objects  mean_native_us  spread over the " << p.repeat << " kept runs\n";
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
    if (vm.count("out") != 0 && o.out.empty()) {
        throw InputError("--out: expected a file path, got '' (leave --out out for the default place)");
    }
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
    const HostProfile profile = measure(o);
    if (profile.poor() && o.strict) {
        throw InputError("--strict: " + poor_words(profile) + "; nothing written: calibrate on a quieter machine, or "
                         "give a larger --max-spread or --time-limit");
    }
    files.file(profile_file).stream() << host_profile_json(profile);
    if (!o.quiet) files.set_standard_output(summary(profile, out));
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp calibrate", *failure);
    if (profile.poor()) {
        std::cerr << "cdvp calibrate: warning: " << poor_words(profile)
                  << "; the profile is marked poor and runs that use it say so (docs/timing.md)\n";
    }
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
        ("repeat", number<uint32_t>(&o.repeat, 1, 1000, "R"),
         "runs kept at each size, the R whose means lie closest; each time is the median of their means")
        ("max-spread", number<double>(&o.max_spread_percent, 0.1, 100, "P"),
         "repeat the workload until the kept runs' means lie within P% (max/min - 1) at every size and baseline")
        ("time-limit", number<double>(&o.time_limit_s, 1, 86400, "S"), "stop repeating after S seconds")
        ("strict", po::bool_switch(&o.strict), "refuse, writing nothing, when the spread stays over P%")
        ("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors");
    return run_command_line("cdvp calibrate", argc, argv, kCalibrateUsage, options,
                            [&o](const po::variables_map& vm) { return calibrate(o, vm); });
}

}  // namespace cdvp
