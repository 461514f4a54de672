// The report's summary, typed: what the run writes is what sweep and
// fidelity read back, and a summary that lacks a key is refused naming it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "sw/run/report_summary.h"

namespace cdvp {
namespace {

ReportSummary example() {
    ReportSummary s;
    s.frames = 30;
    s.warmup_frames = 2;
    s.frames_in_means = 28;
    s.too_few_frames = false;
    s.pairs = 12940;
    s.load_average_end = {1.5, 1.25, 1.0};
    s.extra = {100, 7, 12.5, 3.25};
    s.total_ns = {267500, 266400, 277000, 277100};
    s.sim_wall_native_ns = {57000, 56000, 72000, 74000};
    for (std::size_t k = 0; k < ReportSummary::kPhases; ++k) s.mean_phase_ns[k] = 1000.0 * static_cast<double>(k + 1);
    BaselineSummary& sap = s.baselines["sap"];
    sap.native_ns = {90, 88, 120, 130};
    sap.host_ns = sap.native_ns.scaled(4.25);
    sap.run_means_native_ns = {91, 90, 89};
    sap.host_factor = 4.25;
    sap.speedup = 1.43;
    BaselineSummary& hgrid = s.baselines["hgrid"];
    hgrid.native_ns = {30, 29, 40, 41};
    hgrid.host_ns = hgrid.native_ns.scaled(4.0);
    hgrid.host_factor = 4.0;
    hgrid.speedup = 0.45;
    s.best_software = "hgrid";
    return s;
}

TEST(ReportSummary, ReadsBackEveryFieldItWrites) {
    const ReportSummary written = example();
    const nlohmann::json json = to_json(written);
    const ReportSummary read = summary_from_json(nlohmann::json::parse(json.dump()), "r.json");
    EXPECT_EQ(to_json(read), json);
    EXPECT_EQ(read.frames_in_means, 28u);
    EXPECT_EQ(read.extra.extra_pairs, 7u);
    EXPECT_DOUBLE_EQ(read.sim_wall_native_ns.p50, 56000);
    EXPECT_DOUBLE_EQ(read.baselines.at("sap").host_ns.p99, 120 * 4.25);
    EXPECT_EQ(read.baselines.at("sap").run_means_native_ns.size(), 3u);
    // The frame time's mean is the phases' (summed as they come), written last.
    EXPECT_DOUBLE_EQ(json.at("mean_total_ns").get<double>(), 7000.0);
    EXPECT_DOUBLE_EQ(json.at("extra_share").get<double>(), 7.0 / 107.0);
}

// The fastest software is named as written; a report from before it was
// written names the fastest of its baselines; a name that is none of them
// is refused.
TEST(ReportSummary, NamesTheFastestSoftware) {
    nlohmann::json json = to_json(example());
    EXPECT_EQ(json.at("best_software"), "hgrid");
    json.erase("best_software");
    EXPECT_EQ(summary_from_json(json, "r.json").best_software, "hgrid");
    json["best_software"] = "sap_mt";
    try {
        summary_from_json(json, "r.json");
        ADD_FAILURE() << "a best_software of no baseline was taken";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "r.json: summary: best_software: 'sap_mt' is none of the summary's baselines");
    }
    ReportSummary none = example();
    none.baselines.clear();
    none.best_software.clear();
    EXPECT_FALSE(to_json(none).contains("best_software"));
}

TEST(ReportSummary, RefusesASummaryLackingAKeyOrOfTheWrongTypeNamingIt) {
    const nlohmann::json json = to_json(example());
    struct Case {
        const char* key;
        nlohmann::json value;  // null: removed
        const char* message;
    };
    for (const Case& c : {Case{"frames_in_means", nullptr, "r.json: summary: no frames_in_means"},
                          Case{"p50_sim_wall_native_ns", "fast", "r.json: summary: p50_sim_wall_native_ns is string"},
                          Case{"baselines", 3, "r.json: summary: no baselines section"}}) {
        nlohmann::json damaged = json;
        if (c.value.is_null()) damaged.erase(c.key);
        else damaged[c.key] = c.value;
        try {
            summary_from_json(damaged, "r.json");
            ADD_FAILURE() << c.key << " was taken";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(c.message, 0), 0u) << e.what();
        }
    }
    nlohmann::json no_speedup = json;
    no_speedup["baselines"]["sap"].erase("speedup");
    EXPECT_THROW(summary_from_json(no_speedup, "r.json"), InputError);
    EXPECT_THROW(summary_from_json(nlohmann::json::array(), "r.json"), InputError);
}

}  // namespace
}  // namespace cdvp
