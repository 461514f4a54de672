#include "sw/cli/baseline_timing.h"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "models/common/user_text.h"
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

BaselineTimer::BaselineTimer(const std::string& names, HostTiming host) : host_(std::move(host)) {
    std::stringstream list(names);
    for (std::string name; std::getline(list, name, ',');) {
        // Each is timed once a frame; a repeat would be run twice and reported once.
        for (const std::string& earlier : names_) {
            if (earlier == name) throw InputError("--baseline: '" + excerpt(name) + "' given twice");
        }
        try {
            first_run_.push_back(make_broad_phase(name));
        } catch (const std::invalid_argument& e) {
            throw InputError(std::string("--baseline: ") + e.what());
        }
        names_.push_back(first_run_.back()->name());
    }
}

void BaselineTimer::set_pair_budget(PairBudget budget) {
    budget_ = budget;
    for (auto& baseline : first_run_) baseline->set_pair_budget(budget);
}

double time_find_pairs(BroadPhase& baseline, const std::vector<FloatBox>& boxes, PairList& found) {
    const auto start = std::chrono::steady_clock::now();
    baseline.find_pairs(boxes, found);
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    found = sorted(std::move(found));
    return ns;
}

std::map<std::string, BaselineTime> BaselineTimer::time_frame(const std::vector<FloatBox>& boxes,
                                                              const PairList& board_pairs, uint64_t frame) {
    std::map<std::string, BaselineTime> times;
    PairList found;
    for (auto& baseline : first_run_) {
        const double ns = time_find_pairs(*baseline, boxes, found);
        times[baseline->name()] = {ns, ns * host_.factor(baseline->name())};
        if (found != board_pairs) {
            throw mismatch(baseline->name(), found.size(), frame, "the board " + std::to_string(board_pairs.size()));
        }
    }
    board_digests_.push_back(pairs_digest(board_pairs));
    return times;
}

void BaselineTimer::repeat(FrameSource& source, uint32_t runs, RunTotals& totals,
                           const std::function<void()>& frame_done) {
    first_run_.clear();  // its memory is not the later runs' to reuse
    for (uint32_t run = 2; run <= runs; ++run) {
        std::vector<std::unique_ptr<BroadPhase>> fresh;
        for (const std::string& name : names_) {
            fresh.push_back(make_broad_phase(name));
            fresh.back()->set_pair_budget(budget_);
            totals.baseline_samples(name).start_run();
        }
        source.rewind();
        std::size_t index = 0;
        PairList found;
        while (std::optional<Frame> frame = source.next()) {
            const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
            for (auto& baseline : fresh) {
                totals.baseline_samples(baseline->name()).add(time_find_pairs(*baseline, boxes, found));
                if (index >= board_digests_.size() || pairs_digest(found) != board_digests_[index]) {
                    throw mismatch(baseline->name(), found.size(), frame->number,
                                   "run " + std::to_string(run) + ": not the pairs the board found");
                }
            }
            source.feed(found);
            ++index;
            frame_done();
        }
    }
}

}  // namespace cdvp
