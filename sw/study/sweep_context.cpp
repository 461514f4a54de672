// The words a figure's title takes from the rows it draws: the board and its
// bus, the engine and frames behind each point, and what the software's
// times rest on (the modelled host, its factor, and whether a host profile
// calibrated it), so a figure read alone says how it was made.
#include <algorithm>
#include <cmath>
#include <map>

#include "sw/study/sweep_samples.h"

namespace cdvp::sweep_figures {

namespace {

// "30", or "12-30" when the points differ: the values of 'value' over them.
template <class Value>
std::string range_of(const std::vector<const Sample*>& points, Value value) {
    double low = NAN, high = NAN;
    for (const Sample* s : points) {
        const double v = value(*s);
        if (std::isnan(v)) continue;
        low = std::isnan(low) ? v : std::min(low, v);
        high = std::isnan(high) ? v : std::max(high, v);
    }
    if (std::isnan(low)) return "";
    return low == high ? short_number(low) : short_number(low) + "-" + short_number(high);
}

std::string range_words(const std::vector<const Sample*>& points, const std::string& column) {
    return range_of(points, [&](const Sample& s) { return number(s.row, column); });
}

// The distinct values of a text column, in the order first met.
std::vector<std::string> distinct(const std::vector<const Sample*>& points, const std::string& column) {
    std::vector<std::string> values;
    for (const Sample* s : points) {
        const std::string v = text(s->row, column);
        if (!v.empty() && std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
    }
    return values;
}

std::string joined(const std::vector<std::string>& words, const std::string& between = ", ") {
    std::string all;
    for (const std::string& w : words) all += (all.empty() ? "" : between) + w;
    return all;
}

// What the factors rest on, from the rows' host calibration (or, in a
// table from before it, their provenance).
std::string basis_words(const std::vector<const Sample*>& points) {
    std::vector<std::string> bases = distinct(points, "config.host_calibration.basis");
    if (bases.empty() && !distinct(points, "config.provenance.host_profile.path").empty()) bases = {"calibrated"};
    if (bases.empty() && !distinct(points, "config.provenance.host_profile").empty()) bases = {"uncalibrated"};
    std::vector<std::string> words;
    for (const std::string& basis : bases) {
        if (basis == "calibrated") {
            const std::vector<std::string> machines = distinct(points, "config.host_calibration.profile_machine");
            words.push_back(machines.empty() ? "factors calibrated by a host profile"
                                             : "factors calibrated by the host profile of " + joined(machines, "; "));
        } else if (basis == "uncalibrated") {
            words.push_back("factors uncalibrated: the preset's estimate (cdvp calibrate measures this machine)");
        } else if (basis == "overridden") {
            words.push_back("factors set by --host-factor");
        }
    }
    return joined(words, "; ");
}

}  // namespace

std::vector<const Sample*> on_board(const Samples& samples, const std::string& board) {
    std::vector<const Sample*> points;
    for (const Sample& s : samples.all) {
        if (s.board == board) points.push_back(&s);
    }
    return points;
}

std::string board_words(const std::vector<const Sample*>& points) {
    std::vector<std::string> boards;
    for (const Sample* s : points) {
        if (std::find(boards.begin(), boards.end(), s->board) == boards.end()) boards.push_back(s->board);
    }
    std::vector<std::string> each;
    for (const std::string& board : boards) {
        std::vector<const Sample*> its;
        for (const Sample* s : points) {
            if (s->board == board) its.push_back(s);
        }
        const std::vector<std::string> buses = distinct(its, "config.bus");
        each.push_back(buses.empty() ? board : board + " (" + joined(buses) + ")");
    }
    return joined(each);
}

std::string run_words(const std::vector<const Sample*>& points) {
    std::vector<std::string> engines;
    for (const std::string& engine : distinct(points, "config.fidelity")) engines.push_back(engine + " engine");
    const std::string frames = range_words(points, "report_frames");
    const std::string timed = range_words(points, "frames_in_medians");
    // The warm-up is what the means leave out (it may be an axis of its own).
    const std::string warmup = range_of(points, [](const Sample& s) {
        return number(s.row, "report_frames") - number(s.row, "frames_in_medians");
    });
    std::string words = "board simulated" + (engines.empty() ? std::string() : " on the " + joined(engines, " and "));
    if (!frames.empty()) {
        words += "; " + frames + (frames == "1" ? " frame" : " frames") + " a point";
        if (!timed.empty() && !warmup.empty()) {
            words += ", means of the " + timed + " after " + warmup + " warm-up";
        }
    }
    return words;
}

std::string software_words(const std::vector<const Sample*>& points, const std::vector<std::string>& baselines) {
    // host -> factor text -> the baselines timed with it
    std::map<std::string, std::map<std::string, std::vector<std::string>>> factors;
    std::vector<std::string> hosts;
    for (const std::string& host : distinct(points, "config.host")) {
        std::vector<const Sample*> its;
        for (const Sample* s : points) {
            if (text(s->row, "config.host") == host) its.push_back(s);
        }
        for (const std::string& baseline : baselines) {
            std::string factor = range_words(its, baseline + "_host_factor");
            if (factor.empty()) factor = range_words(its, "config.host_factor");
            if (!factor.empty()) factors[host][factor].push_back(baseline);
        }
        hosts.push_back(host);
    }
    std::vector<std::string> each;
    for (const std::string& host : hosts) {
        std::vector<std::string> parts;
        for (const auto& [factor, named] : factors[host]) parts.push_back("x " + factor + " (" + joined(named) + ")");
        each.push_back(host + ": native " + joined(parts));
    }
    std::string words = (hosts.size() > 1 ? "software on the modelled hosts " : "software on the modelled host ") +
                        joined(each, "; ");
    const std::string basis = basis_words(points);
    return basis.empty() ? words : words + "\n" + basis;
}

std::string baseline_words(const std::string& baseline) {
    static const std::map<std::string, std::string> kWhat{{"sap", "Bullet's sweep and prune"},
                                                          {"dbvt", "Bullet's dynamic AABB tree"},
                                                          {"brute", "brute force"},
                                                          {"soa", "all pairs over structure of arrays"},
                                                          {"sap_mt", "sweep and prune on several threads"},
                                                          {"prune", "box pruning, radix sort and SIMD"},
                                                          {"prune_mt", "box pruning on several threads"},
                                                          {"hgrid", "hierarchical grid"},
                                                          {"hgrid_mt", "hierarchical grid on several threads"},
                                                          {"fcl_tree", "FCL's dynamic AABB tree"},
                                                          {"fcl_sap", "FCL's sweep and prune"},
                                                          {"fcl_interval", "FCL's interval manager"},
                                                          {"fcl_hash", "FCL's spatial hash"},
                                                          {"ode_hash", "ODE's hash space"},
                                                          {"ode_quadtree", "ODE's quadtree space"},
                                                          {"ode_sap", "ODE's sweep and prune space"},
                                                          {"best", "the fastest software timed at each point"}};
    const auto at = kWhat.find(baseline);
    return at == kWhat.end() ? baseline : baseline + " (" + at->second + ")";
}

}  // namespace cdvp::sweep_figures
