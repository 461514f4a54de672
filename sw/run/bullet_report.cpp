#include "sw/run/bullet_report.h"

#include "sw/run/report_summary.h"
#include "sw/timing/spread.h"

#include <cstdio>
#include <sstream>

#include "models/common/user_text.h"
#include "sw/run/machine_info.h"

namespace cdvp {

namespace {

// The times only Bullet has, by their report names (the board's frame is the
// run report's total_ns).
struct TimeField {
    const char* name;
    double BulletFrame::*field;
};
constexpr TimeField kBulletTimes[] = {
    {"bookkeeping_host_ns", &BulletFrame::bookkeeping_host_ns},
    {"software_broadphase_host_ns", &BulletFrame::software_broadphase_host_ns},
    {"software_step_host_ns", &BulletFrame::software_step_host_ns}};

// The ratios of a frame, or of a frame of means.
void add_ratios(nlohmann::json& json, const BulletFrame& f) {
    json["broadphase_share"] = f.share();
    json["amdahl_bound"] = f.amdahl_bound();
    json["broadphase_speedup"] = f.broadphase_speedup();
    json["step_speedup"] = f.step_speedup();
}

nlohmann::json frame_json(const BulletFrame& f) {
    nlohmann::json json = {{"frame", f.frame}, {"contact_points", f.contacts}};
    for (const TimeField& time : kBulletTimes) json[time.name] = f.*time.field;
    add_ratios(json, f);
    return json;
}

void print_row(std::ostream& out, const std::string& label, uint32_t proxies, std::size_t pairs, const BulletFrame& f,
               bool ratios) {
    char line[200];
    std::snprintf(line, sizeof line, "%7s %7u %7zu %9.1f %9.1f %9.1f %9.1f", label.c_str(), proxies, pairs,
                  f.board_ns * 1e-3, f.bookkeeping_host_ns * 1e-3, f.software_broadphase_host_ns * 1e-3,
                  f.software_step_host_ns * 1e-3);
    out << line;
    if (ratios) {
        std::snprintf(line, sizeof line, " %6.1f%% %7.2fx %7.2fx %7.3fx", 100 * f.share(), f.amdahl_bound(),
                      f.broadphase_speedup(), f.step_speedup());
        out << line;
    }
    out << '\n';
}

}  // namespace

double BulletFrame::share() const { return finite_ratio(software_broadphase_host_ns, software_step_host_ns); }

double BulletFrame::amdahl_bound() const {
    return finite_ratio(software_step_host_ns, software_step_host_ns - software_broadphase_host_ns);
}

double BulletFrame::broadphase_speedup() const {
    return finite_ratio(software_broadphase_host_ns, board_ns + bookkeeping_host_ns);
}

double BulletFrame::step_speedup() const {
    return finite_ratio(software_step_host_ns,
                        software_step_host_ns - software_broadphase_host_ns + board_ns + bookkeeping_host_ns);
}

BulletTimes::BulletTimes(uint64_t warmup_frames)
    : warmup_frames_(warmup_frames),
      board_(warmup_frames),
      bookkeeping_(warmup_frames),
      broadphase_(warmup_frames),
      step_(warmup_frames) {}

void BulletTimes::add(const BulletFrame& frame) {
    frames_.push_back(frame);
    board_.add(frame.board_ns);
    bookkeeping_.add(frame.bookkeeping_host_ns);
    add_software(frame.software_broadphase_host_ns, frame.software_step_host_ns);
}

void BulletTimes::start_software_run() {
    broadphase_.start_run();
    step_.start_run();
}

void BulletTimes::add_software(double broadphase_host_ns, double step_host_ns) {
    broadphase_.add(broadphase_host_ns);
    step_.add(step_host_ns);
}

void BulletTimes::replace_software(std::size_t run, std::size_t frame, double broadphase_host_ns, double step_host_ns) {
    broadphase_.replace(run, frame, broadphase_host_ns);
    step_.replace(run, frame, step_host_ns);
    if (run == 0 && frame < frames_.size()) {
        frames_[frame].software_broadphase_host_ns = broadphase_host_ns;
        frames_[frame].software_step_host_ns = step_host_ns;
    }
}

void BulletTimes::set_quality(const TimingQuality& quality, uint32_t tries, bool pinned) {
    quality_ = quality;
    tries_ = tries;
    pinned_ = pinned;
}

TimingFigures BulletTimes::figures(double BulletFrame::*time) const {
    if (time == &BulletFrame::board_ns) return board_.figures();
    if (time == &BulletFrame::bookkeeping_host_ns) return bookkeeping_.figures();
    if (time == &BulletFrame::software_broadphase_host_ns) return broadphase_.figures();
    return step_.figures();
}

BulletFrame BulletTimes::means() const {
    BulletFrame means;
    means.board_ns = board_.figures().spread.mean;
    for (const TimeField& time : kBulletTimes) means.*time.field = figures(time.field).spread.mean;
    return means;
}

nlohmann::json BulletTimes::section(const SceneSpec& spec, BroadphaseKind software) const {
    nlohmann::json frames = nlohmann::json::array();
    for (const BulletFrame& f : frames_) frames.push_back(frame_json(f));
    // The frames the figures rest on are the run summary's (warmup_frames, frames_in_means).
    nlohmann::json summary = {{"software_runs", broadphase_.runs()}};
    for (const TimeField& time : kBulletTimes) {
        const TimingFigures figures = this->figures(time.field);
        const std::string name = time.name;
        summary["mean_" + name] = figures.spread.mean;
        summary["p50_" + name] = figures.spread.p50;
        summary["p99_" + name] = figures.spread.p99;
        summary["max_" + name] = figures.spread.max;
        summary["run_means_" + name] = figures.run_means;
    }
    add_ratios(summary, means());
    summary["timing_quality"] = to_json(quality_);
    summary["retime_tries"] = tries_;
    return {{"scene", spec.name},
            {"objects", spec.objects},
            {"seed", spec.seed},
            {"proxies", frames_.empty() ? 0 : frames_.back().proxies},
            {"software", to_string(software)},
            {"frames", frames},
            {"summary", summary}};
}

std::string BulletTimes::table(BroadphaseKind software, const std::string& host, const std::string& factor,
                               bool has_report) const {
    std::ostringstream out;
    const std::string name = to_string(software);
    out << "\nagainst Bullet's " << name << " on host " << printable(host) << " (software: " << factor;
    if (broadphase_.runs() > 1) out << ", timed in " << broadphase_.runs() << " runs (median of their means)";
    out << "):\n";
    out << "  frame proxies   pairs  board_us   bookkeeping_host_us  " << name
        << "_host_us   step_host_us  share  amdahl  bp_gain step_gain\n";
    constexpr std::size_t kRowsShown = 10;
    for (std::size_t k = 0; k < frames_.size() && k < kRowsShown; ++k) {
        print_row(out, std::to_string(frames_[k].frame), frames_[k].proxies, frames_[k].pairs, frames_[k], true);
    }
    if (frames_.size() > kRowsShown) {
        out << "    ... (" << frames_.size() - kRowsShown << " more frames"
            << (has_report ? " in the report)\n" : "; --report FILE lists every frame)\n");
    }
    if (frames_.empty()) return out.str();
    const uint32_t proxies = frames_.back().proxies;
    const std::size_t pairs = frames_.back().pairs;
    print_row(out, "mean", proxies, pairs, means(), true);
    for (const auto& [label, pick] : {std::pair<const char*, double Spread::*>{"p50", &Spread::p50},
                                      {"p99", &Spread::p99}, {"max", &Spread::max}}) {
        BulletFrame row;
        row.board_ns = board_.figures().spread.*pick;
        for (const TimeField& time : kBulletTimes) row.*time.field = figures(time.field).spread.*pick;
        print_row(out, label, proxies, pairs, row, false);
    }
    out << "board_us: the board's simulated frame; bookkeeping: AABB update and pair-cache upkeep around it;\n"
        << "_host_us: native time x the host factor; share: " << name << "'s broad phase in its step;\n"
        << "amdahl: the most a free broad phase would gain; bp_gain, step_gain: what the board gains on the\n"
        << "broad phase and on the step, from the means (the first " << warmup_frames_
        << " frames left out: --warmup).\n";
    out << "software world's timing (thread CPU time): " << quality_.describe(tries_);
    if (!quality_.clean()) out << "; the gains may not hold (docs/timing.md)";
    out << '\n';
    const std::string advice = quality_.advice(tries_, pinned_, read_machine_info().cores_online);
    if (!advice.empty()) out << "  " << advice << '\n';
    return out.str();
}

}  // namespace cdvp
