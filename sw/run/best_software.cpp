#include "sw/run/best_software.h"

#include <algorithm>

namespace cdvp {

std::vector<std::string> best_candidates(std::optional<std::size_t> objects, unsigned threads) {
    const bool prune = !objects || *objects < kPruneCandidateLimit;
    std::vector<std::string> names;
    if (prune) names.push_back("prune");
    names.push_back("hgrid");
    if (threads > 1) {
        if (prune) names.push_back("prune_mt");
        names.push_back("hgrid_mt");
    }
    return names;
}

bool asks_for_best(const std::vector<std::string>& names) {
    return std::find(names.begin(), names.end(), kBestSoftware) != names.end();
}

std::vector<std::string> resolve_baselines(const std::vector<std::string>& names, std::optional<std::size_t> objects,
                                           unsigned threads) {
    std::vector<std::string> resolved;
    for (const std::string& name : names) {
        if (name != kBestSoftware) {
            resolved.push_back(name);
            continue;
        }
        for (const std::string& candidate : best_candidates(objects, threads)) {
            if (std::find(names.begin(), names.end(), candidate) == names.end() &&
                std::find(resolved.begin(), resolved.end(), candidate) == resolved.end()) {
                resolved.push_back(candidate);
            }
        }
    }
    return resolved;
}

std::optional<std::string> fastest_baseline(const ReportSummary& summary) {
    std::optional<std::string> fastest;
    double least = 0;
    for (const auto& [name, b] : summary.baselines) {
        if (!(b.host_ns.mean > 0)) continue;
        if (!fastest || b.host_ns.mean < least) fastest = name, least = b.host_ns.mean;
    }
    return fastest;
}

}  // namespace cdvp
