// Fidelity as a study, without processes: the levels, the error of each
// against the reference, and the table and CSV written from the results.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "sw/study/fidelity.h"

namespace cdvp {
namespace {

FidelityResult level(double wall_ns, double total_ns, const std::string& pairs) {
    FidelityResult r;
    r.mean_sim_wall_native_ns = wall_ns;
    r.mean_phase_ns.back() = total_ns;
    r.mean_phase_ns[2] = total_ns / 4;  // compute
    r.frames_in_means = 28;
    r.pairs = pairs;
    return r;
}

TEST(FidelityStudy, TheReferenceIsTheClockedEngineOnTheTransactionLevelBusAtQuantumZero) {
    const auto& levels = fidelity_levels();
    ASSERT_EQ(levels.size(), 16u);
    EXPECT_STREQ(levels[0].fidelity(), "cycle");
    EXPECT_STREQ(levels[0].bus_model, "transaction");
    EXPECT_EQ(levels[0].quantum_ns, 0);
    // Every level on both buses, side by side; the fast engine at five quanta.
    std::set<std::string> seen;
    for (std::size_t k = 0; k < levels.size(); k += 2) {
        EXPECT_STREQ(levels[k].bus_model, "transaction") << k;
        EXPECT_STREQ(levels[k + 1].bus_model, "formula") << k;
        EXPECT_STREQ(levels[k].fidelity(), levels[k + 1].fidelity()) << k;
        EXPECT_EQ(levels[k].quantum_ns, levels[k + 1].quantum_ns) << k;
        seen.insert(std::string(levels[k].fidelity()) + " " + std::to_string(levels[k].quantum_ns));
    }
    EXPECT_EQ(seen.size(), 8u) << "no level twice";
    EXPECT_STREQ(levels[2].fidelity(), "rtl") << "the RTL beside the reference";
    EXPECT_STREQ(levels.back().fidelity(), "analytic");
    EXPECT_EQ(levels.back().quantum_ns, 0) << "the analytic level times a host at quantum 0";
    EXPECT_EQ(levels[levels.size() - 3].quantum_ns, 100000);
}

TEST(FidelityStudy, ErrorsAreInPercentOfTheReferencesMeanFrameAndPairsAreCompared) {
    std::vector<FidelityResult> results{level(1.5e6, 1000, "0,1\n")};
    results.push_back(level(5e4, 1000, "0,1\n"));
    results.push_back(level(5e4, 1100, "0,1\n"));  // 10% off in total, 2.5% in compute
    results.push_back(level(5e4, 1000, "0,2\n"));  // other pairs
    FidelityResult skipped;  // a level that did not run on this board
    skipped.not_run = "cdvp fidelity: no Verilator build serves this board";
    results.push_back(skipped);
    EXPECT_DOUBLE_EQ(fidelity_error_percent(results[1], results[0], ReportSummary::kPhases - 1), 0.0);
    EXPECT_DOUBLE_EQ(fidelity_error_percent(results[2], results[0], ReportSummary::kPhases - 1), 10.0);
    EXPECT_DOUBLE_EQ(fidelity_error_percent(results[2], results[0], 2), 2.5);
    const std::string csv = fidelity_csv(results);
    EXPECT_EQ(csv.rfind("level,fidelity,bus_model,quantum_ns,frames_in_means,mean_sim_wall_native_ns,mean_upload_ns", 0), 0u);
    EXPECT_NE(csv.find("\n2,rtl,transaction,0,28,50000,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\n4,fast,transaction,0" + std::string(23, ',') + "not run\n"), std::string::npos) << "level 4: empty figures\n" << csv;
    EXPECT_NE(csv.find(",10,0,0,0,0,0,0,yes\n"), std::string::npos) << "level 2: 10 % off in total, same pairs\n" << csv;
    EXPECT_NE(csv.find(",0,0,0,0,0,0,0,no\n"), std::string::npos) << "level 3: other pairs\n" << csv;
    const std::string table = fidelity_table(results);
    EXPECT_NE(table.find("cycle transaction q=0ns"), std::string::npos) << table;
    EXPECT_NE(table.find("DIFFER"), std::string::npos) << table;
    EXPECT_NE(table.find("not run: cdvp fidelity: no Verilator build serves this board"), std::string::npos) << table;
}

}  // namespace
}  // namespace cdvp
