// The software broad phases side by side on the same frames: each
// baseline's mean time a frame (thread CPU time; wall time for one on
// several threads), the median over repeats, the baselines alternated
// within each repeat so that load falls on all of them alike; every
// baseline's pairs checked against the first's on every frame.
//   software_bench [--objects 500,10000,100000] [--baselines prune,hgrid,...]
//                  [--frames 12] [--warmup 2] [--repeats 3] [--threads T]
//                  [--scenes spheres,pile,heavy,planar,brownian]
//                  [--trace FILE]...   (traces replace the generated scenes)
// The generated scenes at their default settings, seed 1: spheres moving
// freely (sw/scene/spheres.h: the boxes cdvp run --scene spheres starts
// from) and the kinematic families (docs/scenes.md), as cdvp run has them.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/worker_pool.h"
#include "sw/run/baseline_timing.h"
#include "sw/scene/brownian.h"
#include "sw/scene/conversion.h"
#include "sw/scene/heavy.h"
#include "sw/scene/pile.h"
#include "sw/scene/planar.h"
#include "sw/scene/spheres.h"
#include "sw/scene/trace_csv.h"

namespace {

using Frames = std::vector<std::vector<cdvp::FloatBox>>;

struct Options {
    std::vector<std::size_t> objects{500, 10000, 100000};
    std::vector<std::string> baselines{"sap", "dbvt", "sap_mt", "prune", "prune_mt", "hgrid", "hgrid_mt"};
    std::size_t frames = 12, warmup = 2, repeats = 3;
    unsigned threads = 0;
    std::vector<std::string> scenes{"spheres"};
    std::vector<std::string> traces;
};

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
    return parts;
}

[[noreturn]] void usage(const std::string& why) {
    std::fprintf(stderr, "software_bench: %s\n", why.c_str());
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int k = 1; k < argc; ++k) {
        const std::string flag = argv[k];
        if (k + 1 >= argc) usage(flag + ": expected a value");
        const std::string value = argv[++k];
        if (flag == "--objects") {
            o.objects.clear();
            for (const std::string& n : split(value)) o.objects.push_back(std::stoull(n));
        } else if (flag == "--baselines") {
            o.baselines = split(value);
        } else if (flag == "--frames") {
            o.frames = std::stoull(value);
        } else if (flag == "--warmup") {
            o.warmup = std::stoull(value);
        } else if (flag == "--repeats") {
            o.repeats = std::max<std::size_t>(1, std::stoull(value));
        } else if (flag == "--threads") {
            o.threads = unsigned(std::stoul(value));
        } else if (flag == "--scenes") {
            o.scenes = split(value);
        } else if (flag == "--trace") {
            o.traces.push_back(value);
        } else {
            usage("unknown option " + flag);
        }
    }
    if (o.frames <= o.warmup) usage("--frames must exceed --warmup");
    return o;
}

template <typename Scene, typename Config>
Frames generated(std::size_t n, std::size_t frames) {
    Config config;
    config.objects = n;
    Scene scene(config);
    Frames out;
    for (std::size_t f = 0; f < frames; ++f) out.push_back(cdvp::to_float_boxes(scene.next().boxes));
    return out;
}

Frames scene_frames(const std::string& name, std::size_t n, std::size_t frames) {
    if (name == "spheres") return generated<cdvp::SpheresScene, cdvp::SpheresConfig>(n, frames);
    if (name == "pile") return generated<cdvp::PileScene, cdvp::PileConfig>(n, frames);
    if (name == "heavy") return generated<cdvp::HeavyScene, cdvp::HeavyConfig>(n, frames);
    if (name == "planar") return generated<cdvp::PlanarScene, cdvp::PlanarConfig>(n, frames);
    if (name == "brownian") return generated<cdvp::BrownianScene, cdvp::BrownianConfig>(n, frames);
    usage("unknown scene " + name + "; expected spheres, pile, heavy, planar or brownian");
}

Frames trace(const std::string& path, std::size_t frames) {
    std::ifstream in(path);
    if (!in) usage(path + ": cannot open");
    cdvp::TraceReader reader(in, path);
    Frames out;
    while (out.size() < frames) {
        std::optional<cdvp::Frame> frame = reader.next_frame();
        if (!frame) break;
        out.push_back(cdvp::to_float_boxes(frame->boxes));
    }
    return out;
}

// One repeat: every baseline on fresh instances over the frames, one after
// another; the mean over the frames after the warm-up.
std::map<std::string, double> one_repeat(const Options& o, const Frames& frames, std::vector<uint64_t>& pair_counts) {
    std::map<std::string, double> mean_ns;
    for (const std::string& name : o.baselines) {
        auto phase = cdvp::make_broad_phase(name, cdvp::BaselineOptions{o.threads});
        double sum = 0;
        cdvp::PairList pairs;
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const cdvp::CallTiming t = cdvp::time_find_pairs(*phase, frames[f], pairs);
            if (f >= o.warmup) sum += t.cpu_ns;
            if (pair_counts.size() <= f) pair_counts.push_back(pairs.size());
            if (pair_counts[f] != pairs.size()) {
                usage(name + " found " + std::to_string(pairs.size()) + " pairs in frame " + std::to_string(f) +
                      ", the first baseline " + std::to_string(pair_counts[f]));
            }
        }
        mean_ns[name] = sum / double(frames.size() - o.warmup);
    }
    return mean_ns;
}

// One row of the table: every baseline on the frames, the fastest named.
void measure(const Options& o, const std::string& label, const Frames& frames) {
    if (frames.size() <= o.warmup) usage(label + ": fewer frames than --warmup + 1");
    std::map<std::string, std::vector<double>> samples;
    std::vector<uint64_t> pairs;
    for (std::size_t r = 0; r < o.repeats; ++r) {
        for (const auto& [name, ns] : one_repeat(o, frames, pairs)) samples[name].push_back(ns);
    }
    std::printf("%-22s %9zu %10llu", label.c_str(), frames.back().size(), (unsigned long long)pairs.back());
    std::string fastest;
    double least = 0;
    for (const std::string& name : o.baselines) {
        std::vector<double>& s = samples[name];
        std::nth_element(s.begin(), s.begin() + long(s.size() / 2), s.end());
        const double median = s[s.size() / 2];
        std::printf(" %10.3f", median / 1e6);
        if (fastest.empty() || median < least) fastest = name, least = median;
    }
    std::printf("  %s\n", fastest.c_str());
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    const unsigned threads = o.threads == 0 ? cdvp::machine_threads() : o.threads;
    std::printf("mean time a frame (ms) over %zu frames after %zu warm-up, median of %zu repeats; thread CPU time, "
                "wall time on %u threads for _mt\n",
                o.frames - o.warmup, o.warmup, o.repeats, threads);
    std::printf("%-22s %9s %10s", "scene", "boxes", "pairs");
    for (const std::string& name : o.baselines) std::printf(" %10s", name.c_str());
    std::printf("  fastest\n");
    // Each scene's frames made just before they are timed, and let go after.
    for (const std::string& path : o.traces) measure(o, path, trace(path, o.frames));
    if (!o.traces.empty()) return 0;
    for (const std::string& scene : o.scenes) {
        for (const std::size_t n : o.objects) measure(o, scene + " " + std::to_string(n), scene_frames(scene, n, o.frames));
    }
    return 0;
}
