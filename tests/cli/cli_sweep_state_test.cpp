// `cdvp sweep` and `cdvp merge` tried as a hostile user would: files edited
// between runs, a manifest gone or damaged, an input changed, two sweeps into
// one directory, shards with a damaged row or a missing report, a full disk,
// a sweep killed by SIGKILL, values that look like options, --frames 0. In
// every case the command refuses with one line or reruns what it cannot
// trust: it never exits 0 with a wrong row.
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_merge.h"
#include "sw/study/sweep_table.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

const std::string kStateSweep = "sweep --board adm-xrc-ii --set m=1,2 --set objects=20,40 --frames 2 ";

using Rows = std::vector<std::vector<std::string>>;

// Temporaries and staging directories anywhere under 'dir'.
std::vector<std::string> leftovers_of(const fs::path& dir) {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.find(".part-") != std::string::npos || name.find(".merge-") != std::string::npos) {
            found.push_back(entry.path());
        }
    }
    return found;
}

class CliSweepState : public Cli {
protected:
    // A shell command line run in the test's directory.
    Result shell(const std::string& script) {
        const fs::path out = dir_ / ".stdout", err = dir_ / ".stderr";
        const std::string command = "cd '" + dir_.string() + "' && (" + script + ") > '" + out.string() + "' 2> '" +
                                    err.string() + "' < /dev/null";
        const int raw = std::system(command.c_str());
        Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
        fs::remove(out);
        fs::remove(err);
        return r;
    }
    Rows rows(const std::string& dir) { return parse_csv(slurp(dir_ / dir / "sweep.csv"), "sweep.csv"); }
    void write_rows(const std::string& dir, const Rows& table) {
        std::string text;
        for (const auto& fields : table) {
            for (std::size_t c = 0; c < fields.size(); ++c) text += (c ? "," : "") + csv_field(fields[c]);
            text += "\n";
        }
        write(dir + "/sweep.csv", text);
    }
    // The table without its measured columns, for comparing two runs.
    std::vector<std::map<std::string, std::string>> untimed(const std::string& dir) {
        const Rows table = rows(dir);
        std::vector<std::map<std::string, std::string>> out;
        for (std::size_t k = 1; k < table.size(); ++k) {
            std::map<std::string, std::string> row;
            for (std::size_t c = 0; c < table[0].size(); ++c) {
                if (!is_measured_column(table[0][c])) row[table[0][c]] = table[k][c];
            }
            out.push_back(row);
        }
        return out;
    }
    std::string snapshot(const std::string& dir) {
        std::string all;
        for (const auto& entry : fs::recursive_directory_iterator(dir_ / dir)) {
            all += entry.path().string() + "\n" + (entry.is_regular_file() ? slurp(entry.path()) : "") + "\n";
        }
        return all;
    }
};

TEST_F(CliSweepState, AResumeRefusesRowsItDidNotWriteOrRerunsThemWhenAsked) {
    ASSERT_EQ(run(kStateSweep + "--out res -q").status, 0);
    const auto fresh = untimed("res");
    Rows table = rows("res");
    table[2][1] = "0";  // the second row claims the first point's index
    write_rows("res", table);
    expect_refusal(run(kStateSweep + "--out res -q"),
                   "cdvp sweep: res/sweep.csv:3: field 'point': expected 'board-adm-xrc-ii_m-1_objects-20' (point 0)");
    table = rows("res");
    table[3][7] = "4";  // an axis value edited (m)
    table[3][1] = "2";
    write_rows("res", table);
    const Result rerun = run(kStateSweep + "--out res --rerun-invalid");
    ASSERT_EQ(rerun.status, 0) << rerun.err;
    EXPECT_NE(rerun.err.find("cdvp sweep: runs again: res/sweep.csv:3: field 'point'"), std::string::npos) << rerun.err;
    EXPECT_NE(rerun.out.find("(2 run now; "), std::string::npos) << rerun.out;
    EXPECT_EQ(untimed("res"), fresh) << "the points run again, the table is whole and right";
}

// A sweep killed after making its directories but before its manifest was
// committed (a Dask task's, say) left only its own empty directories and a
// temporary: the same command starts there; one point's report there is not
// its own, and is refused.
TEST_F(CliSweepState, ASweepKilledBeforeItsManifestStartsOverWhereItsEmptyDirectoriesAre) {
    fs::create_directories(dir_ / "res" / "points");
    fs::create_directories(dir_ / "res" / "software");
    write("res/sweep.json.part-4242", "{\"format");
    const Result r = run(kStateSweep + "--out res -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "res" / "sweep.json"));
    EXPECT_FALSE(fs::exists(dir_ / "res" / "sweep.json.part-4242")) << "the temporary is removed";

    fs::create_directories(dir_ / "other" / "points");
    write("other/points/p0.json", "{}");
    expect_refusal(run(kStateSweep + "--out other -q"), "cdvp sweep: --out: other holds points but no sweep.json");
}

TEST_F(CliSweepState, ADamagedRowAManifestGoneOrDamagedAndAChangedInputAreRefusedNamingTheFile) {
    ASSERT_EQ(run(kStateSweep + "--out res -q").status, 0);
    const std::string manifest = slurp(dir_ / "res" / "sweep.json");
    write("res/sweep.json", "{\"format\": ");
    expect_refusal(run(kStateSweep + "--out res -q"), "cdvp sweep: res/sweep.json:1:12: not JSON");
    fs::remove(dir_ / "res" / "sweep.json");
    // Another grid would adopt the old rows: refused.
    expect_refusal(run("sweep --board adm-xrc-ii --set m=4,8 --set objects=20,40 --out res -q"),
                   "cdvp sweep: --out: res holds answer-energy.png and 9 more but no sweep.json");
    write("res/sweep.json", manifest);
    Rows table = rows("res");
    table[1].pop_back();
    write_rows("res", table);
    expect_refusal(run(kStateSweep + "--out res -q"), "cdvp sweep: res/sweep.csv:2: expected ");

    write("c.json", "{\"board\": {\"compare_latency_cycles\": 2}}");
    ASSERT_EQ(run(kStateSweep + "--config c.json --out cfg -q").status, 0);
    write("c.json", "{\"board\": {\"compare_latency_cycles\": 3}}");
    expect_refusal(run(kStateSweep + "--config c.json --out cfg -q"),
                   "cdvp sweep: --out: cfg: --config c.json changed since the sweep began");
    write("c.json", "{\"board\": {\"compare_latency_cycles\": 2}}");
    const Result restored = run(kStateSweep + "--config c.json --out cfg");
    EXPECT_EQ(restored.status, 0) << restored.err;
    EXPECT_NE(restored.out.find("(0 run now; "), std::string::npos);
}

TEST_F(CliSweepState, AFailedMergeLeavesOutAsItWas) {
    ASSERT_EQ(run(kStateSweep + "--shard 1/2 --out s1 -q").status, 0);
    ASSERT_EQ(run(kStateSweep + "--shard 2/2 --out s2 -q").status, 0);
    fs::rename(dir_ / "s2/points/board-adm-xrc-ii_m-2_objects-40.json", dir_ / "kept.json");
    expect_refusal(run("merge --out merged s1 s2"), "cdvp merge: s2/sweep.csv:3: the point's report");
    EXPECT_FALSE(fs::exists(dir_ / "merged")) << "a new OUT is not left behind";
    fs::rename(dir_ / "kept.json", dir_ / "s2/points/board-adm-xrc-ii_m-2_objects-40.json");
    const std::string whole = slurp(dir_ / "s2" / "sweep.csv");
    write("s2/sweep.csv", whole + "board-adm-xrc-ii_m-1");  // a shard stopped while it appended a row
    expect_refusal(run("merge --out merged s1 s2"), "cdvp merge: s2/sweep.csv: its last row is cut short");
    EXPECT_FALSE(fs::exists(dir_ / "merged"));
    write("s2/sweep.csv", whole);
    ASSERT_EQ(run("merge --out merged s1 -q").status, 0);
    const std::string before = snapshot("merged");
    Rows table = rows("s2");
    table[1][1] = "0";  // a shard row moved to a point of the other shard
    write_rows("s2", table);
    expect_refusal(run("merge --out merged s2"), "cdvp merge: s2/sweep.csv:2: field 'index': point 0 is not in shard 2/2");
    EXPECT_EQ(snapshot("merged"), before) << "an existing OUT is untouched";
    table[1][1] = "1";
    write_rows("s2", table);
    const Result merged = run("merge merged s2");
    ASSERT_EQ(merged.status, 0) << merged.err;
    EXPECT_NE(merged.out.find("4 of 4 points"), std::string::npos) << merged.out;
    EXPECT_EQ(leftovers_of(dir_), std::vector<std::string>{}) << "no staging directory left";
}

TEST_F(CliSweepState, TheMergeOfNoShardIsRefusedAndLeavesNothing) {
    MergeSpec spec;
    spec.out = (dir_ / "merged").string();
    spec.quiet = true;
    try {
        merge_sweeps(spec);
        ADD_FAILURE() << "a merge of no shard was not refused";
    } catch (const InputError& refused) {
        EXPECT_STREQ(refused.what(), "no shard to merge: give at least one sweep directory");
    }
    EXPECT_FALSE(fs::exists(dir_ / "merged"));
}

TEST_F(CliSweepState, TracesOfOneNameGetIdsOfTheirOwnAndEachRowItsOwnReport) {
    fs::create_directories(dir_ / "a");
    fs::create_directories(dir_ / "b");
    fs::copy_file(trace("small.csv"), dir_ / "a/t.csv");
    fs::copy_file(trace("hard_cases.csv"), dir_ / "b/t.csv");
    fs::copy_file(trace("spellings.csv"), dir_ / "t.1.csv");
    const Result r = run("sweep --trace a/t.csv,b/t.csv,t.1.csv --set m=1,2 --jobs 3 --out res -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const Rows table = rows("res");
    ASSERT_EQ(table.size(), 7u);
    std::set<std::string> ids;
    for (std::size_t k = 1; k < table.size(); ++k) {
        ids.insert(table[k][0]);
        const auto report = nlohmann::json::parse(slurp(dir_ / "res/points" / (table[k][0] + ".json")));
        EXPECT_EQ(report["config"]["source"], "trace " + table[k][6]) << table[k][0];  // the axis after format_version
    }
    EXPECT_EQ(ids.size(), 6u);
}

TEST_F(CliSweepState, ASecondSweepIntoOneDirectoryIsRefusedNamingTheFirst) {
    const std::string slow = "sweep --set m=1:6:+1 --set objects=3000 --frames 3 --fidelity cycle --out res -q";
    const pid_t first = spawn(dir_, {"sweep", "--set", "m=1:6:+1", "--set", "objects=3000", "--frames", "3",
                                     "--fidelity", "cycle", "--out", "res", "-q"});
    for (int k = 0; k < 400 && !fs::exists(dir_ / "res" / "sweep.lock"); ++k) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const Result second = run(slow);
    int status = 0;
    waitpid(first, &status, 0);
    expect_refusal(second, "cdvp sweep: --out: res is in use by another cdvp sweep or merge (pid " +
                               std::to_string(first) + ", holding res/sweep.lock)");
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(rows("res").size(), 7u) << "the first sweep's rows, all of them";
    EXPECT_FALSE(fs::exists(dir_ / "res" / "sweep.lock"));
}

TEST_F(CliSweepState, APointWhoseReportTheSystemCouldNotWriteIsNoRowAndRunsAgain) {
    // A file size limit fails the writes past it (EFBIG) as a full disk would.
    const Result limited = shell("trap '' XFSZ; ulimit -f 16; '" CDVP_BINARY "' " + kStateSweep + "--out res -q");
    EXPECT_EQ(limited.status, 4) << limited.err;
    EXPECT_NE(limited.err.find("File too large"), std::string::npos) << limited.err;
    EXPECT_EQ(limited.err.find("refused"), std::string::npos) << limited.err;
    for (const auto& fields : rows("res")) EXPECT_NE(fields[2], "refused") << fields[0];
    const Result resumed = run(kStateSweep + "--out res");
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_EQ(rows("res").size(), 5u);
    for (std::size_t k = 1; k < 5; ++k) EXPECT_EQ(rows("res")[k][2], "ok");
}

TEST_F(CliSweepState, AKilledSweepLeavesNoRunningPointAndNoScratchFile) {
    fs::create_directories(dir_ / "tmp");
    // Points of several seconds each, so that they are mid-run at the kill.
    const std::string command = "cd '" + dir_.string() + "' && TMPDIR='" + (dir_ / "tmp").string() + "' exec '" CDVP_BINARY
                                "' sweep --set m=1,2 --set objects=20000 --frames 2 --fidelity cycle --jobs 2 "
                                "--out killed-sweep -q";
    const pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    // The points' own command lines name the sweep's directory ('[c]' keeps
    // pgrep from finding its own shell).
    const std::string count = "pgrep -f '[c]dvp run.*killed-sweep' | wc -l";
    for (int k = 0; k < 200 && shell(count).out != "2\n"; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(shell(count).out, "2\n") << "two points running";
    ASSERT_EQ(kill(pid, SIGKILL), 0);
    waitpid(pid, nullptr, 0);
    for (int k = 0; k < 30 && shell(count).out != "0\n"; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(shell(count).out, "0\n") << "no point outlives its sweep";
    EXPECT_TRUE(fs::is_empty(dir_ / "tmp"));
    EXPECT_EQ(leftovers_of(dir_), std::vector<std::string>{}) << "each point removed its temporaries as it ended";
    EXPECT_EQ(rows("killed-sweep").size(), 1u) << "no point finished: the header only";
}

TEST_F(CliSweepState, NoFramesGivesWhatFitsAndFidelityRefusesIt) {
    const Result sweep = run("sweep --board adm-xrc-ii --set m=1,24 --set objects=100,500 --frames 0 --out res");
    ASSERT_EQ(sweep.status, 0) << sweep.err;
    EXPECT_NE(slurp(dir_ / "res" / "fit.csv").find("adm-xrc-ii,500,24,47"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir_ / "res" / "largest-m-adm-xrc-ii.png"));
    EXPECT_FALSE(fs::exists(dir_ / "res" / "time-adm-xrc-ii.png"));
    const Result fidelity = run("fidelity --scene spheres --objects 20 --frames 0 --out fid");
    expect_refusal(fidelity, "cdvp fidelity: the scene has no frames to time (--frames 0");
    EXPECT_FALSE(fs::exists(dir_ / "fid"));
}

TEST_F(CliSweepState, ASweepNeedsNoTemporaryDirectoryAndOneThatDoesNamesIt) {
    const Result sweep = run(kStateSweep + "--out res -q", "TMPDIR=/nonexistent");
    EXPECT_EQ(sweep.status, 0) << sweep.err;
    const Result fidelity = run("fidelity --scene spheres --objects 20 --frames 2 --out fid -q", "TMPDIR=/nonexistent");
    expect_refusal(fidelity, "cdvp fidelity: TMPDIR: /nonexistent: cannot create a temporary file (set TMPDIR to a "
                             "writable directory): No such file or directory");
    const Result piped = shell("cat '" + trace("small.csv") + "' | TMPDIR=/nonexistent '" CDVP_BINARY
                               "' sweep --trace /dev/stdin --set m=1 --out piped -q");
    expect_refusal(piped, "cdvp sweep: /dev/stdin: cannot copy it to a temporary file in TMPDIR /nonexistent (set "
                          "TMPDIR to a writable directory)");
    const Result device = run("run --scene spheres --objects 20 --vcd /dev/null -q", "TMPDIR=/nonexistent");
    expect_refusal(device, "cdvp run: --vcd: /dev/null: cannot make its temporary file in /nonexistent (set TMPDIR");
}

TEST_F(CliSweepState, WithoutPlotsTheDataFilesAreWrittenAll) {
    ASSERT_EQ(run(kStateSweep + "--baseline soa --no-plots --out res -q").status, 0);
    EXPECT_TRUE(fs::exists(dir_ / "res" / "fit.csv"));
    EXPECT_TRUE(fs::exists(dir_ / "res" / "crossover.csv"));
    for (const auto& entry : fs::directory_iterator(dir_ / "res")) EXPECT_NE(entry.path().extension(), ".png");
}

TEST_F(CliSweepState, APipedTraceIsCopiedOnceUnderTheTraceLimitsForEveryPoint) {
    const Result piped = shell("cat '" + trace("small.csv") + "' | '" CDVP_BINARY "' sweep --trace /dev/stdin --set m=1,2 "
                               "--out res -q");
    ASSERT_EQ(piped.status, 0) << piped.err;
    const Rows table = rows("res");
    ASSERT_EQ(table.size(), 3u);
    for (std::size_t k = 1; k < 3; ++k) EXPECT_EQ(table[k][2], "ok") << table[k][0];
    for (const char* command : {"sweep --trace /dev/zero --set m=1,2 --out z", "fidelity --trace /dev/zero --out z"}) {
        const Result zero = run(command);
        EXPECT_EQ(zero.status, 2) << command;
        EXPECT_NE(zero.err.find("/dev/zero:1: line longer than 4096 bytes"), std::string::npos) << zero.err;
        EXPECT_FALSE(fs::exists(dir_ / "z")) << command;
    }
}

// A recalibration whose reference times moved by more than the profile's
// recorded spread is a changed input; one that moved within it (here: the
// same times, the file rewritten) is the same, and the sweep resumes.
TEST_F(CliSweepState, ARecalibratedHostProfileMakesAnotherSweep) {
    fs::create_directories(dir_ / "config" / "cdvp");
    const std::string env = "XDG_CONFIG_HOME='" + (dir_ / "config").string() + "'";
    ASSERT_EQ(run("calibrate --repeat 1 -q", env).status, 0);
    ASSERT_TRUE(fs::exists(dir_ / "config" / "cdvp" / "host-profile.json"));
    ASSERT_EQ(run(kStateSweep + "--out res -q", env).status, 0);
    EXPECT_NE(slurp(dir_ / "res" / "sweep.json").find("\"--host-profile\""), std::string::npos);
    ASSERT_EQ(run("calibrate --repeat 1 -q", env).status, 0);
    expect_refusal(run(kStateSweep + "--out res -q", env),
                   "cdvp sweep: --out: res: --host-profile (its default place) changed since the sweep began");
    // A profile named on the command line is an input too.
    fs::copy_file(dir_ / "config" / "cdvp" / "host-profile.json", dir_ / "named.json");
    ASSERT_EQ(run(kStateSweep + "--host-profile named.json --out named -q").status, 0);
    write("named.json", slurp(dir_ / "named.json") + " ");
    EXPECT_EQ(run(kStateSweep + "--host-profile named.json --out named -q").status, 0) << "the same reference times";
    nlohmann::json moved = report_of(dir_ / "named.json");
    moved["reference"]["sap"]["reference_native_ns"] = 1.5 * moved["reference"]["sap"]["reference_native_ns"].get<double>();
    write("named.json", moved.dump(2));
    expect_refusal(run(kStateSweep + "--host-profile named.json --out named -q"),
                   "cdvp sweep: --out: named: --host-profile named.json changed since the sweep began: sap's reference "
                   "time (ns) moved +50.0% (");
}

TEST_F(CliSweepState, PointsRunAtOnceShareTheDefaultMemoryBudget) {
    ASSERT_EQ(run("sweep --set m=1,2 --objects 20 --jobs 2 --out two -q").status, 0);
    ASSERT_EQ(run("sweep --set m=1,2 --objects 20 --out one -q").status, 0);
    auto budget = [&](const std::string& dir) {
        return nlohmann::json::parse(slurp(dir_ / dir / "points" / "m-1.json"))["config"]["budgets"]["memory_bytes"]
            .get<uint64_t>();
    };
    EXPECT_NEAR(static_cast<double>(budget("two")), static_cast<double>(budget("one")) / 2, 1.0)
        << "two points at once: half the budget each";
}

}  // namespace
}  // namespace cdvp::test
