// cdvp bullet and cdvp record, end to end.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using Bullet = Cli;

TEST_F(Bullet, HelpAndRefusals) {
    const Result help = run("bullet --help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("Usage: cdvp bullet --scene NAME"), std::string::npos);
    EXPECT_NE(help.out.find("--software simple|sap|dbvt"), std::string::npos);
    expect_refusal(run("bullet --scene nope"), "cdvp bullet: --scene: expected one of pyramid");
    expect_refusal(run("bullet"), "cdvp bullet: --scene: expected one of pyramid");
    expect_refusal(run("bullet --scene stack --m 0"), "cdvp bullet: --m: expected an integer from 1 to 32");
    expect_refusal(run("bullet --scene stack --frames 0"), "cdvp bullet: --frames: expected an integer");
    expect_refusal(run("bullet --scene stack --software board"), "cdvp bullet: --software: expected simple");
    expect_refusal(run("bullet --scene stack --fidelity exact"), "cdvp bullet: --fidelity: expected fast or cycle");
    expect_refusal(run("bullet --scene stack extra"), "cdvp bullet: unexpected argument 'extra'");
    expect_refusal(run("bullet --scene boxes --board adm-xrc-ii --m 30"), "cdvp bullet: " + preset("adm-xrc-ii") + ": device.block_rams");
    expect_refusal(run("record --scene stack"), "cdvp record: --out: expected");
    expect_refusal(run("record --scene stack --out missing/t.csv"), "cdvp record: --out");
    EXPECT_EQ(files(), std::vector<std::string>{});
}

nlohmann::json report(const fs::path& path) { return nlohmann::json::parse(slurp(path)); }

TEST_F(Bullet, ReportsEveryFrameWithTheAmdahlBound) {
    const Result r = run("bullet --scene stack --objects 20 --frames 6 --board adm-xrc-ii --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\n   mean "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n    p99 "), std::string::npos) << r.out;
    const nlohmann::json j = report(dir_ / "r.json");
    EXPECT_EQ(j["config"]["board"], "adm-xrc-ii");
    EXPECT_EQ(j["config"]["proxies"], 21);
    ASSERT_EQ(j["frames"].size(), 6u);
    for (const auto& frame : j["frames"]) {
        EXPECT_GT(frame["board_ns"].get<double>(), 20000.0) << "a PCI frame costs tens of microseconds";
        EXPECT_GE(frame["amdahl_bound"].get<double>(), 1.0);
        EXPECT_GT(frame["pairs"].get<int>(), 0);
    }
    // The summary's means leave frame 0 out, and the gains divide means.
    const nlohmann::json& summary = j["summary"];
    EXPECT_EQ(summary["frames_in_means"], 5);
    double software = 0, board = 0, bookkeeping = 0, largest = 0;
    for (std::size_t k = 1; k < 6; ++k) {
        software += j["frames"][k]["software_broadphase_host_ns"].get<double>() / 5;
        board += j["frames"][k]["board_ns"].get<double>() / 5;
        bookkeeping += j["frames"][k]["bookkeeping_host_ns"].get<double>() / 5;
        largest = std::max(largest, j["frames"][k]["software_broadphase_host_ns"].get<double>());
    }
    EXPECT_NEAR(summary["mean_software_broadphase_host_ns"].get<double>(), software, 1e-6 * software);
    EXPECT_DOUBLE_EQ(summary["max_software_broadphase_host_ns"].get<double>(), largest);
    EXPECT_NEAR(summary["broadphase_speedup"].get<double>(), software / (board + bookkeeping), 1e-6);
    EXPECT_EQ(j["config"]["host_calibration"]["basis"], "uncalibrated");
    EXPECT_EQ(j["config"]["provenance"]["host_profile"], "uncalibrated");
}

TEST_F(Bullet, BothEnginesGiveTheSamePairsAndBoardTimes) {
    ASSERT_EQ(run("bullet --scene pyramid --objects 15 --frames 5 -q --fidelity fast --report fast.json").status, 0);
    ASSERT_EQ(run("bullet --scene pyramid --objects 15 --frames 5 -q --fidelity cycle --report cycle.json").status, 0);
    const nlohmann::json fast = report(dir_ / "fast.json"), cycle = report(dir_ / "cycle.json");
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_EQ(fast["frames"][k]["pairs"], cycle["frames"][k]["pairs"]);
        EXPECT_EQ(fast["frames"][k]["board_ns"], cycle["frames"][k]["board_ns"]);
    }
}

// The checked-in trace is what `cdvp record` writes for its scene, and `cdvp run` replays it.
TEST_F(Bullet, RecordWritesTheCheckedInTraceAndRunReplaysIt) {
    const Result r = run("record --scene pyramid --objects 28 --frames 20 --out t.csv -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "t.csv"), slurp(trace("bullet_pyramid.csv")));
    const Result replay = run("run --trace t.csv --pairs-out pairs.csv -q");
    ASSERT_EQ(replay.status, 0) << replay.err;
    const std::string pairs = slurp(dir_ / "pairs.csv");
    EXPECT_GT(std::count(pairs.begin(), pairs.end(), '\n'), 20 * 28) << "every box rests on the ground at least";
}

}  // namespace
}  // namespace cdvp::test
