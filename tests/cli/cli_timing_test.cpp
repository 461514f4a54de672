// Baseline timing statistics of `cdvp run`: warm-up frames, means with p50,
// p99 and the maximum, --repeat, and the note on too few frames. The tests check which
// frames the figures rest on and how they combine, never how fast anything is.
#include <algorithm>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

double mean(const std::vector<double>& v) {
    double sum = 0;
    for (const double x : v) sum += x;
    return sum / static_cast<double>(v.size());
}

// Type-7 quantile (docs: the report's definition), computed independently here.
double quantile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    const double h = (static_cast<double>(v.size()) - 1) * p;
    const std::size_t k = static_cast<std::size_t>(h);
    return k + 1 < v.size() ? v[k] + (h - static_cast<double>(k)) * (v[k + 1] - v[k]) : v.back();
}

// A baseline's first-run frames as its figures took them: the report's
// frames, with those the run timed again (summary ... retimed) replaced.
std::vector<double> per_frame(const json& report, const std::string& baseline, std::size_t from) {
    std::vector<double> all;
    for (const json& f : report["frames"]) {
        all.push_back(baseline.empty() ? f["total_ns"].get<double>() : f["baselines"][baseline]["native_ns"].get<double>());
    }
    if (!baseline.empty()) {
        for (const json& again : report["summary"]["baselines"][baseline]["retimed"]) {
            if (again[0].get<double>() == 0) all.at(static_cast<std::size_t>(again[1].get<double>())) = again[2].get<double>();
        }
    }
    return {all.begin() + static_cast<std::ptrdiff_t>(std::min(from, all.size())), all.end()};
}

class CliTiming : public Cli {
protected:
    json report_of(const std::string& args) {
        const Result r = run("run --scene spheres --objects 60 --m 2 --board adm-xrc-ii -q --report r.json " + args);
        EXPECT_EQ(r.status, 0) << r.err;
        return json::parse(slurp(dir_ / "r.json"));
    }
};

TEST_F(CliTiming, WarmUpFramesAreLeftOutOfMeansAndQuantiles) {
    const json report = report_of("--frames 8 --warmup 3 --baseline sap,soa");
    const json& summary = report["summary"];
    EXPECT_EQ(summary["warmup_frames"], 3);
    EXPECT_EQ(summary["frames_in_means"], 5);
    for (const char* name : {"sap", "soa"}) {
        const std::vector<double> measured = per_frame(report, name, 3);
        const json& b = summary["baselines"][name];
        EXPECT_DOUBLE_EQ(b["mean_native_ns"].get<double>(), mean(measured)) << name;
        EXPECT_DOUBLE_EQ(b["p50_native_ns"].get<double>(), quantile(measured, 0.5)) << name;
        EXPECT_DOUBLE_EQ(b["p99_native_ns"].get<double>(), quantile(measured, 0.99)) << name;
        EXPECT_DOUBLE_EQ(b["max_native_ns"].get<double>(), quantile(measured, 1)) << name;
        EXPECT_EQ(b["run_means_native_ns"].size(), 1u);
    }
    EXPECT_DOUBLE_EQ(summary["mean_total_ns"].get<double>(), mean(per_frame(report, "", 3)));
    EXPECT_DOUBLE_EQ(summary["p99_total_ns"].get<double>(), quantile(per_frame(report, "", 3), 0.99));
    EXPECT_TRUE(summary["too_few_frames"].get<bool>());
}

TEST_F(CliTiming, WarmUpZeroMeasuresTheFirstFrameToo) {
    const json report = report_of("--frames 5 --warmup 0 --baseline sap");
    EXPECT_EQ(report["summary"]["frames_in_means"], 5);
    EXPECT_DOUBLE_EQ(report["summary"]["baselines"]["sap"]["max_native_ns"].get<double>(),
                     quantile(per_frame(report, "sap", 0), 1));
}

TEST_F(CliTiming, ARunNoLongerThanItsWarmUpSaysSoAndUsesItsFrames) {
    const Result r = run("run --scene spheres --objects 30 --frames 2 --warmup 5 --baseline brute --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("2 frames, all warm-up frames"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("note: these figures rest on 2 frames, fewer than 10"), std::string::npos) << r.out;
    const json report = json::parse(slurp(dir_ / "r.json"));
    EXPECT_DOUBLE_EQ(report["summary"]["baselines"]["brute"]["mean_native_ns"].get<double>(),
                     mean(per_frame(report, "brute", 0)));
}

// One measured frame is counted in the singular; a run at the default frames
// measures enough that it carries no note at all.
TEST_F(CliTiming, TheNoteCountsOneFrameAsOneAndTheDefaultFramesNeedNone) {
    const Result one = run("run --scene spheres --objects 30 --frames 3 --baseline sap");
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_NE(one.out.find("note: these figures rest on 1 frame, fewer than 10"), std::string::npos) << one.out;
    EXPECT_NE(one.out.find("total: 3 frames, "), std::string::npos) << one.out;
    const Result defaults = run("run --scene spheres --objects 30 --baseline sap");
    ASSERT_EQ(defaults.status, 0) << defaults.err;
    EXPECT_EQ(defaults.out.find("note:"), std::string::npos) << defaults.out;
    EXPECT_NE(defaults.out.find("total: 12 frames, "), std::string::npos) << defaults.out;
}

TEST_F(CliTiming, RepeatTakesTheMedianOfEachRunsMeanAndTheSpeedupAsARatioOfMeans) {
    const Result r = run("run --scene spheres --objects 60 --m 2 --board adm-xrc-ii --frames 14 --repeat 3 "
                         "--baseline sap,brute --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.find("note:"), std::string::npos) << "12 measured frames are enough: " << r.out;
    EXPECT_NE(r.out.find("timed in 3 runs (median of their means)"), std::string::npos) << r.out;
    const json report = json::parse(slurp(dir_ / "r.json"));
    EXPECT_EQ(report["config"]["baseline_runs"], 3);
    EXPECT_EQ(report["frames"].size(), 14u) << "the frames are simulated and reported once";
    const json& summary = report["summary"];
    EXPECT_FALSE(summary["too_few_frames"].get<bool>());
    for (const char* name : {"sap", "brute"}) {
        const json& b = summary["baselines"][name];
        const std::vector<double> runs = b["run_means_native_ns"].get<std::vector<double>>();
        ASSERT_EQ(runs.size(), 3u) << name;
        EXPECT_DOUBLE_EQ(runs[0], mean(per_frame(report, name, 2))) << "the first run is the one reported";
        EXPECT_DOUBLE_EQ(b["mean_native_ns"].get<double>(), quantile(runs, 0.5)) << name;
        EXPECT_LE(b["p50_native_ns"].get<double>(), b["p99_native_ns"].get<double>()) << name;
        EXPECT_LE(b["p99_native_ns"].get<double>(), b["max_native_ns"].get<double>()) << name;
        EXPECT_DOUBLE_EQ(b["mean_host_ns"].get<double>(), b["host_factor"].get<double>() * b["mean_native_ns"].get<double>());
        EXPECT_NEAR(b["speedup"].get<double>(),
                    b["mean_host_ns"].get<double>() / summary["mean_total_ns"].get<double>(), 1e-9);
    }
}

TEST_F(CliTiming, RepeatRereadsATraceAndChecksEveryRunsPairs) {
    const Result r = run("run --trace " + trace("hard_cases.csv") + " --m 3 --repeat 2 --baseline sap,dbvt,brute,soa "
                         "--report r.json -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const json report = json::parse(slurp(dir_ / "r.json"));
    for (const char* name : {"sap", "dbvt", "brute", "soa"}) {
        EXPECT_EQ(report["summary"]["baselines"][name]["run_means_native_ns"].size(), 2u) << name;
    }
}

TEST_F(CliTiming, RepeatRereadsATraceFromAPipeFromItsCopy) {
    const std::string command = "cd '" + dir_.string() + "' && cat '" + trace("hard_cases.csv") + "' | '" CDVP_BINARY
                                "' run --trace /dev/stdin --m 3 --repeat 3 --baseline sap,brute -q --report r.json";
    ASSERT_EQ(std::system(command.c_str()), 0);
    const json report = json::parse(slurp(dir_ / "r.json"));
    EXPECT_EQ(report["summary"]["baselines"]["sap"]["run_means_native_ns"].size(), 3u);
    EXPECT_EQ(report["summary"]["baselines"]["brute"]["run_means_native_ns"].size(), 3u);
}

TEST_F(CliTiming, RepeatWithoutABaselineAndOutOfRangeCountsAreRefused) {
    expect_refusal(run("run --scene spheres --frames 3 --repeat 2"), "cdvp run: --repeat: reruns the software");
    expect_refusal(run("run --scene spheres --frames 3 --baseline sap --repeat 0"), "cdvp run: --repeat: expected");
    expect_refusal(run("run --scene spheres --frames 3 --baseline sap --warmup -1"), "cdvp run: --warmup: expected");
    expect_refusal(run("run --scene spheres --frames 3 --baseline sap --warmup 1.5"), "cdvp run: --warmup: expected");
    EXPECT_TRUE(files().empty()) << "a refused run writes nothing";
}

}  // namespace
}  // namespace cdvp::test
