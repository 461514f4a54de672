// The software broad phases side by side on the same frames: each
// baseline's mean time a frame (thread CPU time; wall time for one on
// several threads), the median over repeats, the baselines alternated
// within each repeat so that load falls on all of them alike; every
// baseline's pairs checked against the first's on every frame.
//   software_bench [--objects 500,10000,100000] [--baselines prune,hgrid,...]
//                  [--frames 12] [--warmup 2] [--repeats 3] [--threads T]
//                  [--trace FILE]...   (a trace replaces the generated scene)
// The generated scene is the spheres scene (sw/scene/spheres.h, seed 1), the
// boxes cdvp run --scene spheres starts from, moving freely.
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
#include "sw/scene/conversion.h"
#include "sw/scene/spheres.h"
#include "sw/scene/trace_csv.h"

namespace {

using Frames = std::vector<std::vector<cdvp::FloatBox>>;

struct Options {
    std::vector<std::size_t> objects{500, 10000, 100000};
    std::vector<std::string> baselines{"sap", "dbvt", "sap_mt", "prune", "prune_mt", "hgrid", "hgrid_mt"};
    std::size_t frames = 12, warmup = 2, repeats = 3;
    unsigned threads = 0;
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
        } else if (flag == "--trace") {
            o.traces.push_back(value);
        } else {
            usage("unknown option " + flag);
        }
    }
    if (o.frames <= o.warmup) usage("--frames must exceed --warmup");
    return o;
}

Frames spheres(std::size_t n, std::size_t frames) {
    cdvp::SpheresConfig config;
    config.objects = n;
    cdvp::SpheresScene scene(config);
    Frames out;
    for (std::size_t f = 0; f < frames; ++f) out.push_back(cdvp::to_float_boxes(scene.next().boxes));
    return out;
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

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    std::vector<std::pair<std::string, Frames>> scenes;
    for (const std::string& path : o.traces) scenes.emplace_back(path, trace(path, o.frames));
    if (o.traces.empty()) {
        for (const std::size_t n : o.objects) scenes.emplace_back("spheres " + std::to_string(n), spheres(n, o.frames));
    }
    const unsigned threads = o.threads == 0 ? cdvp::machine_threads() : o.threads;
    std::printf("mean time a frame (ms) over %zu frames after %zu warm-up, median of %zu repeats; thread CPU time, "
                "wall time on %u threads for _mt\n",
                o.frames - o.warmup, o.warmup, o.repeats, threads);
    std::printf("%-28s %9s %10s", "scene", "boxes", "pairs");
    for (const std::string& name : o.baselines) std::printf(" %10s", name.c_str());
    std::printf("  fastest\n");
    for (const auto& [label, frames] : scenes) {
        if (frames.size() <= o.warmup) usage(label + ": fewer frames than --warmup + 1");
        std::map<std::string, std::vector<double>> samples;
        std::vector<uint64_t> pairs;
        for (std::size_t r = 0; r < o.repeats; ++r) {
            for (const auto& [name, ns] : one_repeat(o, frames, pairs)) samples[name].push_back(ns);
        }
        std::printf("%-28s %9zu %10llu", label.c_str(), frames.back().size(), (unsigned long long)pairs.back());
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
    return 0;
}
