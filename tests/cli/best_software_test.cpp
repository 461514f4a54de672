// "best" among the baselines: what it stands for at each size and thread
// count, how it joins baselines named beside it, and which one is named
// the fastest.
#include <gtest/gtest.h>

#include "sw/run/best_software.h"

namespace cdvp {
namespace {

using Names = std::vector<std::string>;

TEST(BestSoftware, CandidatesFollowTheFramesSizeAndTheThreads) {
    EXPECT_EQ(best_candidates(500, 1), (Names{"prune", "hgrid"}));
    EXPECT_EQ(best_candidates(500, 2), (Names{"prune", "hgrid", "prune_mt", "hgrid_mt"}));
    EXPECT_EQ(best_candidates(kPruneCandidateLimit - 1, 2), (Names{"prune", "hgrid", "prune_mt", "hgrid_mt"}));
    EXPECT_EQ(best_candidates(kPruneCandidateLimit, 2), (Names{"hgrid", "hgrid_mt"}));
    EXPECT_EQ(best_candidates(1000000, 1), (Names{"hgrid"}));
    // Not known yet (a trace before it is read): every candidate.
    EXPECT_EQ(best_candidates(std::nullopt, 2), (Names{"prune", "hgrid", "prune_mt", "hgrid_mt"}));
}

TEST(BestSoftware, ResolvesBesideTheBaselinesNamedOnTheirOwn) {
    EXPECT_EQ(resolve_baselines({"sap", "best", "dbvt"}, 500, 1), (Names{"sap", "prune", "hgrid", "dbvt"}));
    // A candidate also named on its own is timed once, where it was named.
    EXPECT_EQ(resolve_baselines({"best", "hgrid"}, 500, 2), (Names{"prune", "prune_mt", "hgrid_mt", "hgrid"}));
    EXPECT_EQ(resolve_baselines({"sap"}, 500, 2), (Names{"sap"}));
    EXPECT_TRUE(asks_for_best({"sap", "best"}));
    EXPECT_FALSE(asks_for_best({"sap", "hgrid"}));
}

TEST(BestSoftware, TheFastestIsTheLeastMeanOnTheHostAmongThoseTimed) {
    ReportSummary s;
    EXPECT_FALSE(fastest_baseline(s).has_value());
    s.baselines["sap"].host_ns.mean = 300;
    s.baselines["hgrid"].host_ns.mean = 120;
    s.baselines["prune"].host_ns.mean = 0;  // timed no frame
    EXPECT_EQ(fastest_baseline(s), std::optional<std::string>("hgrid"));
    s.baselines["sap"].host_ns.mean = 100;
    EXPECT_EQ(fastest_baseline(s), std::optional<std::string>("sap"));
}

}  // namespace
}  // namespace cdvp
