// cdvp bullet and cdvp record, end to end: Bullet's worlds on the board with
// run's settings, checks and report, and Bullet's scenes in cdvp run.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "sw/study/sweep_table.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using Bullet = Cli;

nlohmann::json report(const fs::path& path) { return report_of(path); }

// Bullet's settings as the report gives them: value and origin.
const nlohmann::json& setting(const nlohmann::json& report, const std::string& name) {
    return report.at("config").at("settings").at(name);
}

TEST_F(Bullet, HelpAndRefusals) {
    const Result help = run("bullet --help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("Usage: cdvp bullet --scene NAME"), std::string::npos);
    EXPECT_NE(help.out.find("--software simple|sap|dbvt"), std::string::npos);
    EXPECT_NE(help.out.find("boxes 3000"), std::string::npos) << "each scene's own object count";
    expect_refusal(run("bullet --scene nope"), "cdvp bullet: --scene: expected one of pyramid");
    expect_refusal(run("bullet"), "cdvp bullet: --scene: expected one of pyramid");
    expect_refusal(run("bullet --scene spheres"), "cdvp bullet: --scene: 'spheres' is cdvp run's scene");
    expect_refusal(run("bullet --scene stack --frames 0"), "cdvp bullet: --frames: expected at least 1 frame");
    expect_refusal(run("bullet --scene stack --objects 0"), "cdvp bullet: --objects: expected 1 to 1000000 objects");
    expect_refusal(run("bullet --scene stack --software board"), "cdvp bullet: --software: expected simple");
    expect_refusal(run("bullet --scene stack extra"), "cdvp bullet: unexpected argument 'extra'");
    // The options of a run that a Bullet world has no use for.
    for (const char* only_run : {"--max-trace-size 5", "--baseline sap", "--trace t.csv", "--pairs-out p.csv"}) {
        expect_refusal(run(std::string("bullet --scene stack ") + only_run), "cdvp bullet: unrecognised option", only_run);
    }
    expect_refusal(run("bullet --scene boxes --board adm-xrc-ii --m 30"),
                   "cdvp bullet: " + preset("adm-xrc-ii") + ": device.block_rams: 144 block RAMs are too few for --m 30 "
                   "at 3001 boxes (the collision objects of --scene boxes at 3000 objects (the default of --objects))");
    expect_refusal(run("record --scene stack"), "cdvp record: --out: expected");
    expect_refusal(run("record --scene stack --out missing/t.csv"), "cdvp record: --out");
    EXPECT_EQ(files(), std::vector<std::string>{});
}

// Every dedicated flag of a setting that bullet takes is accepted, lands in
// the report's config with its origin, and a bad value is refused on one
// line naming the flag, as cdvp run refuses it.
TEST_F(Bullet, EverySettingsFlagIsAcceptedWithItsOriginAndABadValueRefused) {
    const nlohmann::json table = nlohmann::json::parse(run("settings --json").out);
    const std::string help = run("bullet --help").out;
    std::size_t tried = 0;
    for (const auto& s : table) {
        const std::string flag = s["flag"].is_string() ? s["flag"].get<std::string>().substr(2) : "";
        if (flag.empty() || help.find("  --" + flag + " ") == std::string::npos) continue;
        // A small, quick scene, but for the flag under test.
        std::string scene = "bullet --scene stack --board adm-xrc-ii -q ";
        if (flag != "objects") scene += "--objects 10 ";
        const std::string name = s["name"].get<std::string>();
        const bool is_switch = s["type"] == "choice" && s["choices"] == nlohmann::json{"no", "yes"};
        if (name == "run.lockstep") {  // the rtl level's alone
            expect_refusal(run(scene + "--lockstep"), "cdvp bullet: --lockstep: compares the RTL with the clocked engine");
            scene += "--fidelity rtl ";
        }
        if (name == "run.max_error_percent") {  // bounds --fidelity auto, which cdvp bullet does not run
            expect_refusal(run(scene + "--max-error 1"), "cdvp bullet: --max-error: only --fidelity auto picks a level");
            ++tried;
            continue;
        }
        if (name != "host.profile") {  // a profile must exist: CliCalibrate gives bullet one
            // The preset's own value where it gives one, so the run stays the same board.
            const std::string value = name == "host.speed_factor" ? "4" : is_switch ? "" : s["default"].dump();
            const std::string shown = value.size() > 1 && value.front() == '"' ? value.substr(1, value.size() - 2) : value;
            const Result r = run(scene + "--" + flag + " " + shown + " --report r.json");
            ASSERT_EQ(r.status, 0) << flag << ": " << r.err;
            const nlohmann::json given = setting(report(dir_ / "r.json"), name);
            EXPECT_EQ(given["origin"], "flag --" + flag) << name;
            if (is_switch) {
                EXPECT_EQ(given["value"], "yes") << name;
            }
        }
        if (!is_switch) expect_refusal(run(scene + "--" + flag + " nonsense"), "cdvp bullet: --" + flag + ": ", flag);
        ++tried;
    }
    // board (m, format, clock-mhz, compare-latency, fifo-depth, drain-rate,
    // pair-buffer, box-banks at its default, memory, tile-boxes, algorithm), scene (objects, frames, seed), host
    // (host-factor, host-profile) and run (transfer, wait, fidelity,
    // quantum-ns, max-error, warmup, repeat, retime-tries, pin-cpu, ignore-capacity, ignore-timing, lockstep,
    // max-memory, max-pairs),
    // the driver's communication (upload, pair-format, interrupts) and the
    // spheres scene's moving share (its default only: Bullet's scenes refuse another).
    EXPECT_EQ(tried, 35u) << "the flags bullet shares with run";
}

TEST_F(Bullet, LayersPresetThenConfigThenOverridesThenFlagsAsRunDoes) {
    write("c.toml", "[board]\nm = 2\nclock_mhz = 50\n[run]\nwarmup = 1\n");
    const Result r = run("bullet --scene stack --objects 10 --frames 4 --board adm-xrc-ii --config c.toml "
                         "-c run.warmup=0 -c bus.interrupt_ns=5000 --m 3 -q --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = report(dir_ / "r.json");
    EXPECT_EQ(setting(j, "board.m"), (nlohmann::json{{"value", 3}, {"origin", "flag --m"}}));
    EXPECT_EQ(setting(j, "board.clock_mhz"), (nlohmann::json{{"value", 50.0}, {"origin", "config c.toml:3"}}));
    EXPECT_EQ(setting(j, "run.warmup"), (nlohmann::json{{"value", 0}, {"origin", "-c"}}));
    EXPECT_EQ(setting(j, "bus.interrupt_ns")["origin"], "-c");
    EXPECT_EQ(setting(j, "bus.width_bits")["origin"], "preset " + preset("adm-xrc-ii"));
    EXPECT_EQ(j["config"]["m"], 3);
    EXPECT_EQ(j["summary"]["warmup_frames"], 0);
    for (const auto& frame : j["frames"]) EXPECT_EQ(frame["irq_ns"], 5000.0) << "the override reached the bus";
    expect_refusal(run("bullet --scene stack --board adm-xrc-ii --config c.toml -c board.fifo_depth=2"),
                   "cdvp bullet: -c board.fifo_depth: ");
    write("bad.json", R"({"board": {"m": 40}})");
    expect_refusal(run("bullet --scene stack --config bad.json"), "cdvp bullet: bad.json");
}

// The 3,000 falling boxes at m = 8 on the paper's board: past its block
// RAMs, so the boxes move to SSRAM tiles, as they do for cdvp run.
TEST_F(Bullet, TheBoxesAtEightRunInSsramTilesAsRunsDo) {
    const std::string board = " --scene boxes --board adm-xrc-ii --m 8 -q";
    ASSERT_EQ(run("bullet" + board + " --frames 3 --report b.json").status, 0);
    ASSERT_EQ(run("run" + board + " --frames 3 --report r.json").status, 0);
    const nlohmann::json b = report(dir_ / "b.json"), r = report(dir_ / "r.json");
    EXPECT_EQ(b["config"]["memory"], "SSRAM");
    EXPECT_EQ(b["config"]["tiles"], 6);
    EXPECT_EQ(b["config"]["capacity"], 3001);
    EXPECT_EQ(b["config"]["resources"]["fits"], true);
    for (const char* key : {"memory", "tiles", "tile_boxes", "block_rams", "load_wait_slots"}) {
        EXPECT_EQ(b["config"][key], r["config"][key]) << key;
    }
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(b["frames"][k]["compute_cycles"], r["frames"][k]["compute_cycles"]);
        EXPECT_GT(b["frames"][k]["load_wait_slots"].get<uint64_t>(), 0u) << "tiles load from SSRAM";
    }
    expect_refusal(run("bullet" + board + " --memory block_ram"), "cdvp bullet: " + preset("adm-xrc-ii") +
                   ": device.block_rams: 144 block RAMs are too few for --m 8");
    const Result anyway = run("bullet" + board + " --memory block_ram --ignore-capacity --report i.json");
    ASSERT_EQ(anyway.status, 0) << anyway.err;
    const nlohmann::json i = report(dir_ / "i.json");
    EXPECT_EQ(i["config"]["memory"], "block RAM");
    EXPECT_EQ(i["config"]["resources"]["fits"], false);
    EXPECT_EQ(setting(i, "run.ignore_capacity"), (nlohmann::json{{"value", "yes"}, {"origin", "flag --ignore-capacity"}}));
}

// Bullet's board is refused as a run's is: fixed16's tile buffers by the
// format's own layout (three word groups a box, not float32's six).
TEST_F(Bullet, AFixedPointTileRefusalCountsTheFormatsBlockRams) {
    const Result r = run("bullet --scene pyramid --frames 1 -q --board adm-xrc-ii --m 24 -c board.memory=ssram "
                         "--format fixed16");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("in tiles of 122 boxes: they need 3 x (2m+2) x ceil(T/512) = 150 (largest m that fits: 23;"),
              std::string::npos)
        << r.err;
}

TEST_F(Bullet, ReportsEveryFrameWithTheAmdahlBound) {
    const Result r = run("bullet --scene stack --objects 20 --frames 6 --board adm-xrc-ii --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\n   mean "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n    p99 "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("total: 6 frames"), std::string::npos) << "the board's summary, as run prints it";
    const nlohmann::json j = report(dir_ / "r.json");
    EXPECT_EQ(j["config"]["board"], "adm-xrc-ii");
    const nlohmann::json& bullet = j["bullet"];
    EXPECT_EQ(bullet["proxies"], 21);
    EXPECT_EQ(bullet["software"], "dbvt");
    ASSERT_EQ(j["frames"].size(), 6u);
    ASSERT_EQ(bullet["frames"].size(), 6u);
    for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_GT(j["frames"][k]["total_ns"].get<double>(), 20000.0) << "a PCI frame costs tens of microseconds";
        EXPECT_GT(j["frames"][k]["pairs"].get<int>(), 0);
        EXPECT_GE(bullet["frames"][k]["amdahl_bound"].get<double>(), 1.0);
    }
    // The means leave the warm-up frames out (--warmup, 2), and the gains divide means.
    EXPECT_EQ(j["summary"]["frames_in_means"], 4);
    const nlohmann::json& summary = bullet["summary"];
    double software = 0, board = 0, bookkeeping = 0, largest = 0;
    for (std::size_t k = 2; k < 6; ++k) {
        software += bullet["frames"][k]["software_broadphase_host_ns"].get<double>() / 4;
        board += j["frames"][k]["total_ns"].get<double>() / 4;
        bookkeeping += bullet["frames"][k]["bookkeeping_host_ns"].get<double>() / 4;
        largest = std::max(largest, bullet["frames"][k]["software_broadphase_host_ns"].get<double>());
    }
    EXPECT_NEAR(j["summary"]["mean_total_ns"].get<double>(), board, 1e-9 * board);
    EXPECT_NEAR(summary["mean_software_broadphase_host_ns"].get<double>(), software, 1e-6 * software);
    EXPECT_DOUBLE_EQ(summary["max_software_broadphase_host_ns"].get<double>(), largest);
    EXPECT_NEAR(summary["broadphase_speedup"].get<double>(), software / (board + bookkeeping), 1e-6);
    EXPECT_EQ(j["config"]["host_calibration"]["basis"], "uncalibrated");
    EXPECT_EQ(j["config"]["provenance"]["host_profile"], "uncalibrated");
}

// --repeat steps fresh software worlds from the same start; each time's mean
// is the median of the runs' means.
TEST_F(Bullet, RepeatsTheSoftwareWorldAndTakesTheMedianOfItsMeans) {
    ASSERT_EQ(run("bullet --scene stack --objects 10 --frames 5 --warmup 1 --repeat 3 -q --report r.json").status, 0);
    const nlohmann::json j = report(dir_ / "r.json");
    EXPECT_EQ(setting(j, "run.repeat"), (nlohmann::json{{"value", 3}, {"origin", "flag --repeat"}}));
    EXPECT_EQ(j["summary"]["frames_in_means"], 4);
    const nlohmann::json& summary = j["bullet"]["summary"];
    EXPECT_EQ(summary["software_runs"], 3);
    for (const char* time : {"software_broadphase_host_ns", "software_step_host_ns"}) {
        std::vector<double> means = summary[std::string("run_means_") + time].get<std::vector<double>>();
        ASSERT_EQ(means.size(), 3u) << time;
        double first = 0;
        for (std::size_t k = 1; k < 5; ++k) first += j["bullet"]["frames"][k][time].get<double>() / 4;
        EXPECT_NEAR(means[0], first, 1e-6 * first) << "the first run is the one beside the board";
        std::sort(means.begin(), means.end());
        EXPECT_DOUBLE_EQ(summary[std::string("mean_") + time].get<double>(), means[1]) << time;
    }
    EXPECT_EQ(report(dir_ / "r.json")["config"]["baseline_runs"], 3);
}

TEST_F(Bullet, BothEnginesGiveTheSamePairsAndBoardTimes) {
    ASSERT_EQ(run("bullet --scene pyramid --objects 15 --frames 5 -q --fidelity fast --report fast.json").status, 0);
    ASSERT_EQ(run("bullet --scene pyramid --objects 15 --frames 5 -q --fidelity cycle --report cycle.json").status, 0);
    const nlohmann::json fast = report(dir_ / "fast.json"), cycle = report(dir_ / "cycle.json");
    EXPECT_EQ(cycle["config"]["fidelity"], "cycle");
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_EQ(fast["frames"][k]["pairs"], cycle["frames"][k]["pairs"]);
        EXPECT_EQ(fast["frames"][k]["total_ns"], cycle["frames"][k]["total_ns"]);
    }
}

// One reader for both reports: the sweep's row builder reads a bullet
// report and a run report of the same scene and board, and every column they
// share but the measured ones holds the same value.
TEST_F(Bullet, ARunReportAndABulletReportReadAlike) {
    const std::string scene = " --scene stack --objects 10 --frames 4 --board adm-xrc-ii --m 4 -q --report ";
    ASSERT_EQ(run("run" + scene + "r.json").status, 0);
    ASSERT_EQ(run("bullet" + scene + "b.json").status, 0);
    const Grid grid(std::vector<Axis>{{"scene", {"stack"}}});
    const Row from_run = report_row(grid, grid.point(0), slurp(dir_ / "r.json"), 0).values;
    const Row from_bullet = report_row(grid, grid.point(0), slurp(dir_ / "b.json"), 0).values;
    std::size_t compared = 0;
    for (const auto& [column, value] : from_run) {
        ASSERT_EQ(from_bullet.count(column), 1u) << column << " is not in the bullet report's row";
        if (is_measured_column(column)) continue;
        EXPECT_EQ(from_bullet.at(column), value) << column;
        ++compared;
    }
    EXPECT_EQ(from_bullet.size(), from_run.size()) << "no column of one reader's that the other lacks";
    EXPECT_GT(compared, 100u) << "the settings, the board, every frame's medians and the summary";
    EXPECT_EQ(from_bullet.at("median_pairs"), from_run.at("median_pairs"));
    EXPECT_EQ(from_bullet.at("config.source"), "stack objects=10 seed=1");
}

// `cdvp run --scene boxes` simulates what `cdvp record` records, and `cdvp
// bullet` gives its board the same boxes: the same pairs and board time
// every frame.
TEST_F(Bullet, RunsSceneIsRecordsTraceAndBulletsBoxes) {
    const std::string scene = "--scene boxes --objects 300 --frames 40 --board adm-xrc-ii";
    ASSERT_EQ(run("record " + scene.substr(0, scene.find(" --board")) + " --out t.csv -q").status, 0);
    ASSERT_EQ(run("run --trace t.csv --board adm-xrc-ii -q --pairs-out a.csv --report a.json").status, 0);
    ASSERT_EQ(run("run " + scene + " -q --pairs-out b.csv --report b.json").status, 0);
    ASSERT_EQ(run("bullet " + scene + " -q --report c.json").status, 0);
    EXPECT_EQ(slurp(dir_ / "a.csv"), slurp(dir_ / "b.csv")) << "the scene is its recorded trace";
    const nlohmann::json traced = report(dir_ / "a.json"), generated = report(dir_ / "b.json"),
                         bullet = report(dir_ / "c.json");
    EXPECT_EQ(generated["config"]["source"], "boxes objects=300 seed=1");
    EXPECT_EQ(setting(generated, "scene.objects"), (nlohmann::json{{"value", 300}, {"origin", "flag --objects"}}));
    ASSERT_EQ(generated["frames"].size(), 40u);
    uint64_t most = 0;
    for (std::size_t k = 0; k < 40; ++k) {
        for (const char* key : {"objects", "pairs", "compute_cycles", "total_ns"}) {
            EXPECT_EQ(generated["frames"][k][key], traced["frames"][k][key]) << "frame " << k << " " << key;
            EXPECT_EQ(bullet["frames"][k][key], generated["frames"][k][key]) << "frame " << k << " " << key;
        }
        most = std::max(most, generated["frames"][k]["pairs"].get<uint64_t>());
    }
    EXPECT_GT(most, 300u) << "the boxes land on the ground and on each other";
    // Left at its default, the count is the scene's own, not the spheres' 500.
    ASSERT_EQ(run("run --scene pyramid --frames 1 -q --report p.json").status, 0);
    EXPECT_EQ(setting(report(dir_ / "p.json"), "scene.objects"), (nlohmann::json{{"value", 120}, {"origin", "default"}}));
    expect_refusal(run("run --scene boxes --objects 0"), "cdvp run: --objects: expected 1 to 1000000 objects");
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
