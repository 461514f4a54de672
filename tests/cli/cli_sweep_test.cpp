// `cdvp sweep` and `cdvp merge` end to end: rows for every point (refused
// ones too), resuming, shards merged into what one run gives, --jobs, and
// an interrupted sweep that leaves complete points and no temporaries.
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_table.h"
#include "tests/cli/cli_support.h"
#include "tests/cli/sweep_rows.h"

namespace cdvp::test {
namespace {

// A quick grid: 2 x 2 points of 20 and 40 spheres, 2 frames each.
const std::string kGrid = "sweep --board adm-xrc-ii --set m=1,2 --set objects=20:40:x2 --frames 2 --baseline soa ";

// The CSV as rows of column -> value, timing columns left out.
std::vector<std::map<std::string, std::string>> untimed_rows(const std::string& csv) { return sweep_rows(csv, true); }

std::vector<std::string> leftovers(const fs::path& dir) {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (entry.path().filename().string().find(".part-") != std::string::npos) found.push_back(entry.path());
    }
    return found;
}

TEST_F(Cli, SweepWritesARowPerPointAndARowWithItsReasonForAPointThatDoesNotFit) {
    // m = 32 needs 6 x 32 block RAMs; the XC2V6000 has 144.
    const Result r = run("sweep --board adm-xrc-ii --set m=2,32 --set objects=20,40 --frames 2 --baseline soa --out res");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("4 points in res/sweep.csv: 2 ok, 2 refused, 0 faulted"), std::string::npos) << r.out;
    const auto lines = parse_csv(slurp(dir_ / "res" / "sweep.csv"), "sweep.csv");
    ASSERT_EQ(lines.size(), 5u);
    const auto& header = lines[0];
    auto at = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    };
    const std::vector<std::string> expected_status{"ok", "ok", "refused", "refused"};
    for (std::size_t k = 1; k < lines.size(); ++k) {
        const auto& row = lines[k];
        EXPECT_EQ(row[at("status")], expected_status[k - 1]) << row[at("point")];
        EXPECT_EQ(row[at("index")], std::to_string(k - 1));
        const bool ok = row[at("status")] == "ok";
        EXPECT_EQ(fs::exists(dir_ / "res" / "points" / (row[at("point")] + ".json")), ok) << row[at("point")];
        if (ok) {
            EXPECT_EQ(row[at("config.m")], row[at("m")]);
            EXPECT_EQ(row[at("config.block_rams")], "12");
            EXPECT_GT(std::stod(row[at("median_total_ns")]), 0.0);
            EXPECT_GT(std::stod(row[at("soa_speedup")]), 0.0);
        } else {
            EXPECT_NE(row[at("reason")].find("block RAM"), std::string::npos) << row[at("reason")];
            EXPECT_EQ(row[at("median_total_ns")], "");
        }
    }
    EXPECT_EQ(lines[1][at("point")], "board-adm-xrc-ii_m-2_objects-20");
    for (const char* png : {"time-adm-xrc-ii.png", "speedup-adm-xrc-ii-soa.png", "phases-adm-xrc-ii.png"}) {
        EXPECT_EQ(slurp(dir_ / "res" / png).substr(1, 3), "PNG") << png;
    }
    EXPECT_TRUE(fs::exists(dir_ / "res" / "crossover.csv"));
    EXPECT_EQ(leftovers(dir_), std::vector<std::string>{});
}

TEST_F(Cli, SweepDrawsEveryKindOfFigureFromItsTemplate) {
    // Two formats (a variant), two m and two N, where the board loses to
    // brute force at 50 boxes and wins at 400: every template is drawn.
    const Result r = run("sweep --board adm-xrc-ii --set format=float32,fixed16 --set m=8,24 --set objects=50,400 "
                         "--frames 3 --baseline brute --out res -q");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* png : {"time-adm-xrc-ii.png", "speedup-adm-xrc-ii-brute.png", "crossover-brute.png",
                            "phases-adm-xrc-ii.png", "largest-m-adm-xrc-ii.png", "lanes-extra-adm-xrc-ii.png"}) {
        const std::string picture = slurp(dir_ / "res" / png);
        EXPECT_EQ(picture.substr(1, 3), "PNG") << png;
        EXPECT_GT(picture.size(), 10000u) << png << " is too small to hold a plot";
    }
}

TEST_F(Cli, SweepRecordsAPointWhoseSystemFaultsAsARowAndGoesOn) {
    const Result r = run("sweep --board adm-xrc-ii --set m=1,2 --set objects=20 --frames 2 "
                         "--inject board-error@frame=1 --out res");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = untimed_rows(slurp(dir_ / "res" / "sweep.csv"));
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(r.err, "cdvp sweep: no plots: no point of the sweep ran\n") << "a skipped plot is said on stderr";
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("status"), "fault");
        EXPECT_EQ(row.at("reason").rfind("frame 1: ", 0), 0u) << row.at("reason");
        EXPECT_NE(row.at("reason").find("injected board-error"), std::string::npos) << row.at("reason");
    }
}

TEST_F(Cli, SweepWhoseEveryPointIsRefusedExitsTwoWithTheFirstReasonAndLeavesNothing) {
    const Result r = run("sweep --board adm-xrc-ii --set m=28,32 --set objects=20 --memory block_ram --out res");
    expect_refusal(r, "cdvp sweep: every point was refused; the first, board-adm-xrc-ii_m-28_objects-20: ");
    EXPECT_NE(r.err.find("block RAMs are too few for --m 28"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "res"));
    // A misspelt option is refused before any point runs.
    expect_refusal(run("sweep --set m=1,2 --frmes 3 --out res"),
                   "cdvp sweep: unrecognised option '--frmes'; did you mean '--frames'? (see cdvp sweep --help)\n");
    EXPECT_FALSE(fs::exists(dir_ / "res"));
}

TEST_F(Cli, SweepRefusesBadAxesAndOptionsBeforeAnyPointRuns) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"sweep --set m=1:8:x1 --out res", "cdvp sweep: --set m: '1:8:x1': a geometric range needs"},
        {"sweep --set m=1,,2 --out res", "cdvp sweep: --set m: '1,,2': an empty value"},
        {"sweep --set m --out res", "cdvp sweep: --set: 'm': expected NAME=LIST"},
        {"sweep --set m=1 --set m=2 --out res", "cdvp sweep: --set m: the axis is given twice"},
        {"sweep --set m=1,2 --m 4 --out res", "cdvp sweep: --m: board.m is an axis of the sweep (m); give it once"},
        {"sweep --set board.m=1,2 --m 4 --out res",
         "cdvp sweep: --m: board.m is an axis of the sweep (board.m); give it once"},
        {"sweep --set m=1,2 -c board.m=4 --out res", "cdvp sweep: -c: board.m is an axis of the sweep (m)"},
        {"sweep --set bus.interrupt_ns=1,2 -c bus.interrupt_ns=4 --out res",
         "cdvp sweep: -c: bus.interrupt_ns is an axis of the sweep"},
        {"sweep --set bus.interrupt_ns=1,2 -cbus.interrupt_ns=4 --out res",
         "cdvp sweep: -cbus.interrupt_ns=4: bus.interrupt_ns is an axis of the sweep"},
        {"sweep --set scene.objects=10,20 --set objects=30 --out res",
         "cdvp sweep: --set objects: the same setting as the axis scene.objects; give it once"},
        {"sweep --set m=1,01 --out res", "cdvp sweep: --set m: '01' is the same value as '1'; give each value once"},
        {"sweep --set quantum-ns=1000,1e3 --out res", "cdvp sweep: --set quantum-ns: '1e3' is the same value as '1000'"},
        {"sweep --set objects=50,--help --out res",
         "cdvp sweep: --set objects: expected an integer from 0 to 4194304, got '--help'"},
        {"sweep --set m=0,1 --out res", "cdvp sweep: --set m: expected an integer from 1 to 32, got '0'"},
        {"sweep --fidelity fast,slow --out res", "cdvp sweep: --fidelity: expected rtl, cycle, fast, analytic or auto, got 'slow'"},
        {"sweep --board adm-xrc-ii,nosuch --out res", "cdvp sweep: --board: "},
        {"sweep --set m=1 --frames 2 --frames 3 --out res", "cdvp sweep: option '--frames' cannot be specified more"},
        {"sweep --set m=1 --out res -- --frames 2", "cdvp sweep: unexpected argument '--frames'"},
        {"sweep --set m=1 --scene spheres --trace t.csv --out res", "cdvp sweep: --scene and --trace: give one of them"},
        {"sweep --set m=1,2", "cdvp sweep: --out DIR is required"},
        {"sweep --set m=1 --jobs 0 --out res", "cdvp sweep: --jobs: expected a whole number from 1 to 24"},
        {"sweep --set m=1 --jobs 25 --out res", "cdvp sweep: --jobs: expected a whole number from 1 to 24"},
        {"sweep --set m=1 --shard 3/2 --out res", "cdvp sweep: --shard: '3/2': expected K/N"},
        {"sweep --set m=1 --report r.json --out res", "cdvp sweep: --report: set by cdvp sweep"},
        {"sweep --out res", "cdvp sweep: a sweep needs at least one axis"},
        {"sweep --set objcts=1,2 --out res", "cdvp sweep: --set objcts: no flag of cdvp run or setting has this name; "
                                             "the nearest is 'objects'"},
        {"sweep --set bus.interupt_ns=1,2 --out res", "cdvp sweep: --set bus.interupt_ns: no flag of cdvp run or "
                                                      "setting has this name; the nearest is 'bus.interrupt_ns'"},
        // The grid's size before any value is read by its setting (m=0 would be
        // refused by it): no work a value or a point costs comes first.
        {"sweep --set seed=1:100000:+1 --set m=0:31:+1 --out res",
         "cdvp sweep: the grid has 3200000 points, more than 1000000\n"},
    };
    for (const auto& [args, start] : cases) {
        expect_refusal(run(args), start, args);
        EXPECT_FALSE(fs::exists(dir_ / "res")) << args;
    }
    write("file", "x");
    expect_refusal(run("sweep --set m=1 --out file"), "cdvp sweep: --out: file: expected a directory");
    EXPECT_EQ(slurp(dir_ / "file"), "x");
}

TEST_F(Cli, SweepResumesWithoutRerunningTheRecordedPointsAndRefusesAnotherGrid) {
    ASSERT_EQ(run(kGrid + "--out res -q").status, 0);
    // As if interrupted after three points: the last row goes.
    const fs::path csv = dir_ / "res" / "sweep.csv";
    std::string text = slurp(csv);
    text.erase(text.rfind('\n', text.size() - 2) + 1);
    std::ofstream(csv, std::ios::binary) << text;
    std::map<std::string, fs::file_time_type> before;
    for (const auto& entry : fs::directory_iterator(dir_ / "res" / "points")) before[entry.path()] = entry.last_write_time();
    ASSERT_EQ(before.size(), 4u);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));

    const Result again = run(kGrid + "--out res");
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.out.find("4 points in res/sweep.csv: 4 ok, 0 refused, 0 faulted (1 run now; "), std::string::npos)
        << again.out;
    std::size_t rerun = 0;
    for (const auto& [path, time] : before) rerun += fs::last_write_time(path) != time;
    EXPECT_EQ(rerun, 1u) << "only the point missing from the CSV ran again";
    EXPECT_EQ(untimed_rows(slurp(csv)).size(), 4u);

    expect_refusal(run("sweep --board adm-xrc-ii --set m=1,4 --set objects=20:40:x2 --frames 2 --baseline soa --out res"),
                   "cdvp sweep: --out: res holds another sweep (other values of m)");
    expect_refusal(run("sweep --board adm-xrc-ii --set m=1,2 --set objects=20:40:x2 --frames 3 --baseline soa --out res"),
                   "cdvp sweep: --out: res holds another sweep (other options given to every point)");
    expect_refusal(run(kGrid + "--shard 1/2 --out res"), "cdvp sweep: --out: res holds shard 1/1 of this sweep, not 1/2");
}

TEST_F(Cli, MergedShardsEqualOneWholeSweepButForTheTimings) {
    ASSERT_EQ(run(kGrid + "--out whole -q").status, 0);
    ASSERT_EQ(run(kGrid + "--shard 1/3 --out s1 -q").status, 0);
    ASSERT_EQ(run(kGrid + "--shard 2/3 --out s2 -q").status, 0);
    ASSERT_EQ(run(kGrid + "--shard 3/3 --out s3 -q").status, 0);
    EXPECT_EQ(untimed_rows(slurp(dir_ / "s1" / "sweep.csv")).size(), 2u) << "points 0 and 3";
    const Result merged = run("merge merged s3 s1 s2");
    ASSERT_EQ(merged.status, 0) << merged.err;
    EXPECT_NE(merged.out.find("4 of 4 points"), std::string::npos) << merged.out;
    const auto whole = untimed_rows(slurp(dir_ / "whole" / "sweep.csv"));
    ASSERT_EQ(whole.size(), 4u);
    EXPECT_EQ(untimed_rows(slurp(dir_ / "merged" / "sweep.csv")), whole);
    EXPECT_EQ(parse_csv(slurp(dir_ / "merged" / "sweep.csv"), "m")[0], parse_csv(slurp(dir_ / "whole" / "sweep.csv"), "w")[0])
        << "the same columns in the same order";
    for (const auto& entry : fs::directory_iterator(dir_ / "whole" / "points")) {
        EXPECT_TRUE(fs::exists(dir_ / "merged" / "points" / entry.path().filename())) << entry.path();
    }
    // The merged directory is the whole sweep: resuming it runs nothing.
    const Result resumed = run(kGrid + "--out merged");
    EXPECT_NE(resumed.out.find("(0 run now; "), std::string::npos) << resumed.out << resumed.err;

    ASSERT_EQ(run("sweep --board adm-xrc-ii --set m=1,4 --set objects=20 --frames 2 --shard 1/2 --out other -q").status, 0);
    expect_refusal(run("merge m2 s1 other"), "cdvp merge: other: a shard of another sweep than s1");
    expect_refusal(run("merge m3 s1 s1"), "cdvp merge: s1: shard 1/3 is given twice");
    write("junk", "");
    expect_refusal(run("merge . s1"), "cdvp merge: --out: .: expected a new or empty directory");
    EXPECT_FALSE(fs::exists(dir_ / "m2"));
}

TEST_F(Cli, SweepInTwoJobsGivesTheSameTableAsInOne) {
    ASSERT_EQ(run(kGrid + "--out one -q").status, 0);
    ASSERT_EQ(run(kGrid + "--jobs 2 --out two -q").status, 0);
    const auto one = untimed_rows(slurp(dir_ / "one" / "sweep.csv"));
    ASSERT_EQ(one.size(), 4u);
    EXPECT_EQ(untimed_rows(slurp(dir_ / "two" / "sweep.csv")), one);
}

TEST_F(Cli, InterruptedSweepLeavesOnlyCompletePointsAndNoTemporaries) {
    // Enough points that the signal lands mid-sweep.
    const pid_t pid = spawn(dir_, {"sweep", "--set", "m=1:12:+1", "--set", "objects=200,300", "--frames", "20",
                                   "--jobs", "2", "--out", "res", "-q"});
    const fs::path csv = dir_ / "res" / "sweep.csv";
    auto rows_written = [&] { return fs::exists(csv) ? parse_csv(slurp(csv), "sweep.csv").size() - 1 : 0; };
    for (int k = 0; k < 400 && rows_written() == 0; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_GE(rows_written(), 1u) << "no point finished in 4 s";
    ASSERT_EQ(kill(pid, SIGINT), 0);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
    EXPECT_EQ(WTERMSIG(status), SIGINT);
    EXPECT_EQ(leftovers(dir_), std::vector<std::string>{});
    const auto rows = untimed_rows(slurp(csv));
    EXPECT_GE(rows.size(), 1u);
    EXPECT_LT(rows.size(), 24u) << "interrupted before the end";
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("status"), "ok");
        EXPECT_TRUE(fs::exists(dir_ / "res" / "points" / (row.at("point") + ".json"))) << row.at("point");
    }
    // Resuming completes the rest.
    const Result resumed = run("sweep --set m=1:12:+1 --set objects=200,300 --frames 20 --jobs 2 --out res");
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_EQ(untimed_rows(slurp(csv)).size(), 24u);
}

// A misspelt flag is told the flag it may mean, in every command that takes
// flags, as a misspelt -c key is; one far from every flag gets no guess.
TEST_F(Cli, AMisspeltFlagIsToldTheNearestOne) {
    const std::vector<std::pair<std::string, std::string>> typos{
        {"run --frmaes 3", "cdvp run: unrecognised option '--frmaes'; did you mean '--frames'?"},
        {"run --baslien sap", "cdvp run: unrecognised option '--baslien'; did you mean '--baseline'?"},
        {"run --frmaes=3", "cdvp run: unrecognised option '--frmaes=3'; did you mean '--frames'?"},
        {"bullet --scnee boxes", "cdvp bullet: unrecognised option '--scnee'; did you mean '--scene'?"},
        {"sweep --jbos 2 --out o", "cdvp sweep: unrecognised option '--jbos'; did you mean '--jobs'?"},
        {"fidelity --otu o", "cdvp fidelity: unrecognised option '--otu'; did you mean '--out'?"},
        {"calibrate --repat 2", "cdvp calibrate: unrecognised option '--repat'; did you mean '--repeat'?"}};
    for (const auto& [words, line] : typos) expect_refusal(run(words), line, words);
    const Result far = run("run --zzzzzzzz 1");
    expect_refusal(far, "cdvp run: unrecognised option '--zzzzzzzz' (see cdvp run --help)\n");
    EXPECT_FALSE(fs::exists(dir_ / "o"));
}

}  // namespace
}  // namespace cdvp::test
