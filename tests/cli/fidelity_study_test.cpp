// Fidelity as a study, without processes: the levels, the error of each
// against the reference, and the table and CSV written from the results.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sw/study/fidelity.h"

namespace cdvp {
namespace {

FidelityResult level(double wall_ns, double total_ns, const std::string& pairs) {
    FidelityResult r;
    r.p50_sim_wall_native_ns = wall_ns;
    r.mean_phase_ns.back() = total_ns;
    r.mean_phase_ns[2] = total_ns / 4;  // compute
    r.frames_in_means = 28;
    r.pairs = pairs;
    return r;
}

TEST(FidelityStudy, TheReferenceIsTheClockedEngineAtQuantumZero) {
    const auto& levels = fidelity_levels();
    ASSERT_EQ(levels.size(), 7u);
    EXPECT_STREQ(levels[0].fidelity(), "cycle");
    EXPECT_EQ(levels[0].quantum_ns, 0);
    for (std::size_t k = 1; k + 1 < levels.size(); ++k) EXPECT_STREQ(levels[k].fidelity(), "fast");
    EXPECT_EQ(levels[levels.size() - 2].quantum_ns, 100000);
    EXPECT_STREQ(levels.back().fidelity(), "analytic");
    EXPECT_EQ(levels.back().quantum_ns, 0) << "the analytic level times a host at quantum 0";
}

TEST(FidelityStudy, ErrorsAreInPercentOfTheReferencesMeanFrameAndPairsAreCompared) {
    std::vector<FidelityResult> results{level(1.5e6, 1000, "0,1\n")};
    results.push_back(level(5e4, 1000, "0,1\n"));
    results.push_back(level(5e4, 1100, "0,1\n"));  // 10% off in total, 2.5% in compute
    results.push_back(level(5e4, 1000, "0,2\n"));  // other pairs
    EXPECT_DOUBLE_EQ(fidelity_error_percent(results[1], results[0], ReportSummary::kPhases - 1), 0.0);
    EXPECT_DOUBLE_EQ(fidelity_error_percent(results[2], results[0], ReportSummary::kPhases - 1), 10.0);
    EXPECT_DOUBLE_EQ(fidelity_error_percent(results[2], results[0], 2), 2.5);
    const std::string csv = fidelity_csv(results);
    EXPECT_EQ(csv.rfind("level,fidelity,quantum_ns,frames_in_means,p50_sim_wall_native_ns,mean_upload_ns", 0), 0u);
    EXPECT_NE(csv.find("\n2,fast,100,28,50000,"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",10,yes\n"), std::string::npos) << "level 2: 10 % off in total, same pairs\n" << csv;
    EXPECT_NE(csv.find(",0,no\n"), std::string::npos) << "level 3: other pairs\n" << csv;
    const std::string table = fidelity_table(results);
    EXPECT_NE(table.find("cycle q=0ns"), std::string::npos) << table;
    EXPECT_NE(table.find("DIFFER"), std::string::npos) << table;
}

}  // namespace
}  // namespace cdvp
