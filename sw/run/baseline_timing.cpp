#include "sw/run/baseline_timing.h"

#include "sw/run/best_software.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "models/common/user_text.h"
#include "sw/baselines/worker_pool.h"
#include "sw/run/machine_speed.h"
#include "sw/scene/conversion.h"

namespace cdvp {

namespace {

// FNV-1a over the sorted pairs: enough to tell a later run's pairs from the
// board's without keeping every frame's pairs.
uint64_t pairs_digest(const PairList& sorted_pairs) {
    uint64_t hash = 14695981039346656037ull;
    const auto mix = [&hash](uint64_t value) {
        for (int byte = 0; byte < 8; ++byte) {
            hash ^= (value >> (8 * byte)) & 0xff;
            hash *= 1099511628211ull;
        }
    };
    mix(sorted_pairs.size());
    for (const IndexPair& p : sorted_pairs) mix((static_cast<uint64_t>(p.first) << 32) | p.second);
    return hash;
}

std::runtime_error mismatch(const std::string& name, std::size_t found, uint64_t frame, const std::string& expected) {
    return std::runtime_error("baseline " + name + " found " + std::to_string(found) + " pairs in frame " +
                              std::to_string(frame) + ", " + expected);
}

}  // namespace

unsigned baseline_threads(uint32_t run_threads, uint32_t host_cores) {
    if (run_threads > 0) return run_threads;
    return host_cores > 0 ? std::min(machine_threads(), host_cores) : machine_threads();
}

BaselineTimer::BaselineTimer(const std::vector<std::string>& names, HostTiming host, uint32_t max_tries,
                             const std::string& label, BaselineOptions options)
    : host_(std::move(host)), options_(options), max_tries_(max_tries) {
    for (const std::string& name : names) {
        // Each is timed once a frame; a repeat would be run twice and reported once.
        for (const std::string& earlier : names_) {
            if (earlier == name) throw InputError(label + ": '" + excerpt(name) + "' given twice");
        }
        try {
            first_run_.push_back(make_broad_phase(name, options_));
        } catch (const std::invalid_argument& e) {
            // "best" never reaches here: the run resolves it (sw/run/best_software.h).
            throw InputError(label + ": " + e.what() + ", or " + kBestSoftware);
        } catch (const ThreadsUnavailable& e) {
            throw SystemError(options_.threads_from + ": " + e.what());
        }
        names_.push_back(first_run_.back()->name());
    }
    disturbed_.assign(names_.size(), std::vector<Disturbed>(1));
    probes_.assign(names_.size(), std::vector<std::vector<float>>(1));
    counts_.assign(names_.size(), Counts{});
}

void BaselineTimer::set_pair_budget(PairBudget budget) {
    budget_ = budget;
    for (auto& baseline : first_run_) baseline->set_pair_budget(budget);
}

// A baseline on several threads is timed by the wall clock: they run side by
// side, so that is what a user pays (their CPU time together stays beside it).
CallTiming time_find_pairs(BroadPhase& baseline, const std::vector<FloatBox>& boxes, PairList& found) {
    CallTiming timing = CallTimer::time([&] { baseline.find_pairs(boxes, found); });
    if (baseline.threads() > 1) timing.cpu_ns = timing.wall_ns;
    found = sorted(std::move(found));
    return timing;
}

CallTiming BaselineTimer::probed(BroadPhase& baseline, const std::vector<FloatBox>& boxes, PairList& found,
                                double& probe_ns) {
    const double before = probe_.time_ns();
    const double joules_before = rapl_.available() ? rapl_.joules() : 0;
    const CallTiming timing = time_find_pairs(baseline, boxes, found);
    last_energy_j_ = rapl_.available() ? rapl_.joules_since(joules_before) : -1;
    probe_ns = std::max(before, probe_.time_ns());
    return timing;
}

double BaselineTimer::mark_slowed(uint64_t warmup) {
    const std::size_t first = first_measured(board_digests_.size(), warmup);
    std::vector<double> all;
    for (const auto& runs : probes_) {
        for (const auto& run : runs) {
            for (std::size_t k = first; k < run.size(); ++k) all.push_back(run[k]);
        }
    }
    probe_reference_ns_ = probe_reference_ns(host_.probe_reference_ns, all);
    const double limit = probe_reference_ns_ * (1 + kProbeTolerance);
    for (std::size_t b = 0; b < names_.size(); ++b) {
        for (std::size_t run = 0; run < probes_[b].size(); ++run) {
            for (std::size_t k = first; k < probes_[b][run].size(); ++k) {
                if (probes_[b][run][k] <= limit || disturbed_[b][run][k]) continue;
                disturbed_[b][run][k] = true;
                ++counts_[b].slowed;
            }
        }
    }
    return limit;
}

std::vector<std::unique_ptr<BroadPhase>> BaselineTimer::fresh(const std::vector<std::size_t>& which) const {
    std::vector<std::unique_ptr<BroadPhase>> instances;
    for (const std::size_t b : which) {
        try {
            instances.push_back(make_broad_phase(names_[b], options_));
        } catch (const ThreadsUnavailable& e) {
            throw SystemError(options_.threads_from + ": " + e.what());
        }
        instances.back()->set_pair_budget(budget_);
    }
    return instances;
}

std::map<std::string, BaselineTime> BaselineTimer::time_frame(const std::vector<FloatBox>& boxes,
                                                              const PairList& board_pairs, uint64_t frame) {
    std::map<std::string, BaselineTime> times;
    PairList found;
    for (std::size_t b = 0; b < first_run_.size(); ++b) {
        BroadPhase& baseline = *first_run_[b];
        double probe = 0;
        const CallTiming t = probed(baseline, boxes, found, probe);
        probes_[b].back().push_back(static_cast<float>(probe));
        times[baseline.name()] = {t.cpu_ns, t.wall_ns, t.cpu_ns * host_.factor(baseline.name()),
                                  t.involuntary_switches, t.migrated, probe, last_energy_j_,
                                  baseline.threads() > 1 ? t.process_cpu_ns : 0};
        disturbed_[b].back().push_back(t.disturbed());
        if (found != board_pairs) {
            throw mismatch(baseline.name(), found.size(), frame, "the board " + std::to_string(board_pairs.size()));
        }
    }
    board_digests_.push_back(pairs_digest(board_pairs));
    return times;
}

void BaselineTimer::repeat(FrameSource& source, uint32_t runs, RunTotals& totals,
                           const std::function<void()>& frame_done) {
    first_run_.clear();  // its memory is not the later runs' to reuse
    std::vector<std::size_t> all(names_.size());
    for (std::size_t b = 0; b < all.size(); ++b) all[b] = b;
    for (uint32_t run = 2; run <= runs; ++run) {
        const std::vector<std::unique_ptr<BroadPhase>> instances = fresh(all);
        for (std::size_t b = 0; b < names_.size(); ++b) {
            totals.baseline_samples(names_[b]).start_run();
            totals.baseline_wall_samples(names_[b]).start_run();
            disturbed_[b].emplace_back();
            probes_[b].emplace_back();
        }
        source.rewind();
        std::size_t index = 0;
        PairList found;
        while (std::optional<Frame> frame = source.next()) {
            const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
            for (std::size_t b = 0; b < instances.size(); ++b) {
                double probe = 0;
                const CallTiming t = probed(*instances[b], boxes, found, probe);
                probes_[b].back().push_back(static_cast<float>(probe));
                totals.baseline_samples(names_[b]).add(t.cpu_ns);
                totals.baseline_wall_samples(names_[b]).add(t.wall_ns);
                disturbed_[b].back().push_back(t.disturbed());
                if (index >= board_digests_.size() || pairs_digest(found) != board_digests_[index]) {
                    throw mismatch(names_[b], found.size(), frame->number,
                                   "run " + std::to_string(run) + ": not the pairs the board found");
                }
            }
            source.feed(found);
            ++index;
            frame_done();
        }
    }
}

void BaselineTimer::retime(FrameSource& source, RunTotals& totals) {
    first_run_.clear();
    const std::size_t frames = board_digests_.size();
    const std::size_t first = first_measured(frames, totals.warmup_frames());
    const double limit = mark_slowed(totals.warmup_frames());
    for (uint32_t pass = 0; pass < max_tries_; ++pass) {
        bool any = false;
        for (std::size_t run = 0; run < (disturbed_.empty() ? 0 : disturbed_[0].size()); ++run) {
            // The baselines with a measured frame still disturbed in this run, and the last such frame.
            std::vector<std::size_t> which;
            std::size_t last = 0;
            for (std::size_t b = 0; b < names_.size(); ++b) {
                const Disturbed& flags = disturbed_[b][run];
                for (std::size_t k = first; k < flags.size(); ++k) {
                    if (!flags[k]) continue;
                    if (which.empty() || which.back() != b) which.push_back(b);
                    last = std::max(last, k);
                }
            }
            if (which.empty()) continue;
            any = true;
            // Fresh instances reach each disturbed frame in the state the
            // timed one had: every frame before it, untimed.
            const std::vector<std::unique_ptr<BroadPhase>> instances = fresh(which);
            source.rewind();
            PairList found;
            for (std::size_t index = 0; index <= last; ++index) {
                std::optional<Frame> frame = source.next();
                if (!frame) break;
                const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
                for (std::size_t i = 0; i < which.size(); ++i) {
                    const std::size_t b = which[i];
                    std::vector<bool>::reference flag = disturbed_[b][run][index];
                    if (index >= first && flag) {
                        double probe = 0;
                        const CallTiming t = probed(*instances[i], boxes, found, probe);
                        ++counts_[b].tries;
                        if (!t.disturbed() && probe <= limit) {
                            totals.baseline_samples(names_[b]).replace(run, index, t.cpu_ns);
                            totals.baseline_wall_samples(names_[b]).replace(run, index, t.wall_ns);
                            flag = false;
                            ++counts_[b].retimed;
                            retimed_[names_[b]].push_back(
                                {static_cast<double>(run), static_cast<double>(index), t.cpu_ns});
                        }
                    } else {
                        instances[i]->find_pairs(boxes, found);
                        found = sorted(std::move(found));
                    }
                    if (pairs_digest(found) != board_digests_[index]) {
                        throw mismatch(names_[b], found.size(), frame->number, "timed again: not the pairs the board found");
                    }
                }
                source.feed(found);
            }
        }
        if (!any) break;
    }
}

std::map<std::string, TimingQuality> BaselineTimer::quality(const RunTotals& totals) const {
    std::map<std::string, TimingQuality> out;
    const std::map<std::string, TimingFigures> figures = totals.baseline_figures();
    const std::size_t first = first_measured(board_digests_.size(), totals.warmup_frames());
    for (std::size_t b = 0; b < names_.size(); ++b) {
        TimingQuality q;
        for (const Disturbed& flags : disturbed_[b]) {
            for (std::size_t k = first; k < flags.size(); ++k) {
                ++q.frames_timed;
                q.never_clean += flags[k] ? 1 : 0;
            }
        }
        q.frames_retimed = counts_[b].retimed;
        q.frames_slowed = counts_[b].slowed;
        q.probe_ns = probe_reference_ns_;
        q.frames_disturbed = q.frames_retimed + q.never_clean;
        q.tries = counts_[b].tries;
        q.runs = static_cast<uint32_t>(disturbed_[b].size());
        if (const auto it = figures.find(names_[b]); it != figures.end()) q.repeat_spread = repeat_spread_of(it->second.run_means);
        out[names_[b]] = q;
    }
    return out;
}

}  // namespace cdvp
