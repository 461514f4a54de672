// The software's time end to end: every report carries what its timing can be
// trusted for; a frame on a slowed CPU is timed again up to run.retime_tries
// and, never clean, makes the timing disturbed on the summary's line, in the
// report and in the sweep's rows; --pin-cpu; a sweep times each workload once
// and every point of it divides by that timing; a resume refuses a timing its
// rows used that changed; cdvp calibrate repeats to a spread, says when it
// could not get there, and runs on a poor profile say so.
#include <sys/stat.h>

#include <functional>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "tests/cli/sweep_rows.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliTimingQuality : public Cli {
protected:
    json read_json(const std::string& name) { return report_of(dir_ / name); }
    // A profile whose fast speed no probe reaches: every frame is on a slowed CPU.
    void write_unreachable_profile() {
        ASSERT_EQ(run("calibrate --repeat 1 --max-spread 100 -q --out p.json").status, 0);
        json p = read_json("p.json");
        p["calibration"]["probe_native_ns"] = 1;
        write("p.json", p.dump(2));
    }
    const std::string kRun = "run --board adm-xrc-ii --scene spheres --objects 60 --frames 6 --m 4 --baseline sap,soa ";
};

TEST_F(CliTimingQuality, EveryReportSaysItsClockAndWhatItsTimingCanBeTrustedFor) {
    const Result r = run(kRun + "--repeat 2 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("software timing (thread CPU time): "), std::string::npos) << r.out;
    const json j = read_json("r.json");
    for (const json& frame : j["frames"]) {
        for (const char* name : {"sap", "soa"}) {
            const json& b = frame["baselines"][name];
            EXPECT_GT(b["wall_native_ns"].get<double>(), 0);
            EXPECT_GT(b["probe_native_ns"].get<double>(), 0);
            EXPECT_TRUE(b["migrated"].is_boolean());
        }
    }
    const json& q = j["summary"]["timing_quality"];
    EXPECT_EQ(q["frames_timed"], 2 * 2 * 4) << "two baselines, two runs, four frames after the warm-up";
    EXPECT_EQ(q["runs"], 2);
    EXPECT_EQ(q["frames_disturbed"], q["frames_retimed"].get<uint64_t>() + q["never_clean"].get<uint64_t>());
    EXPECT_TRUE(q["verdict"] == "clean" || q["verdict"] == "disturbed");
    EXPECT_EQ(j["summary"]["retime_tries"], 3);
    EXPECT_EQ(j["summary"]["baselines"]["sap"]["timing_quality"]["frames_timed"], 8);
}

TEST_F(CliTimingQuality, AFrameOnASlowedCpuIsTimedAgainAndNeverCleanIsLoud) {
    write_unreachable_profile();
    const Result r = run(kRun + "--host-profile p.json --retime-tries 2 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("software timing (thread CPU time): disturbed: 8 of 8 frames never came clean after 2 tries"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("; sap, soa's speedup may not hold (docs/timing.md)\n  to time it clean: "), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("--retime-tries 6\n"), std::string::npos) << r.out;
    const json j = read_json("r.json");
    const json& q = j["summary"]["timing_quality"];
    EXPECT_EQ(q["verdict"], "disturbed");
    EXPECT_EQ(q["never_clean"], 8);
    EXPECT_EQ(q["frames_slowed"], 8);
    EXPECT_EQ(q["tries"], 16) << "each of the 8 frames timed again twice, on fresh instances stepped to it";
    EXPECT_DOUBLE_EQ(q["probe_native_ns"].get<double>(), 1);
    const Result none = run(kRun + "--host-profile p.json --retime-tries 0 --report n.json -q");
    ASSERT_EQ(none.status, 0) << none.err;
    EXPECT_EQ(read_json("n.json")["summary"]["timing_quality"]["tries"], 0);
    EXPECT_EQ(read_json("n.json")["summary"]["timing_quality"]["never_clean"], 8);
}

// Without a host profile a run's frames are held to the fastest this CPU
// model has shown, kept between runs in the user's cache: a run slow from
// its first probe to its last is not held to its own slow speed. A damaged
// record is written anew, one of another CPU model ignored.
TEST_F(CliTimingQuality, ARunSlowThroughoutIsHeldToTheSpeedTheMachineShowedBefore) {
    const Result first = run(kRun + "--report r.json -q");
    ASSERT_EQ(first.status, 0) << first.err;
    const fs::path kept = cache_ / "cdvp/speed-probe.json";
    ASSERT_TRUE(fs::exists(kept));
    json record = report_of(kept);
    EXPECT_DOUBLE_EQ(record["probe_native_ns"].get<double>(),
                     read_json("r.json")["summary"]["timing_quality"]["probe_native_ns"].get<double>())
        << "the first run is held to its own speed, and keeps it";
    record["probe_native_ns"] = 1;  // a speed no probe reaches: as if this run were slowed throughout
    std::ofstream(kept) << record.dump();
    const Result slowed = run(kRun + "--retime-tries 1 --report s.json -q");
    ASSERT_EQ(slowed.status, 0) << slowed.err;
    const json report = read_json("s.json");
    const json& q = report["summary"]["timing_quality"];
    EXPECT_EQ(q["verdict"], "disturbed");
    EXPECT_EQ(q["never_clean"], 8);
    EXPECT_DOUBLE_EQ(q["probe_native_ns"].get<double>(), 1);
    EXPECT_DOUBLE_EQ(report_of(kept)["probe_native_ns"].get<double>(), 1) << "a slower run keeps the faster speed";
    for (const std::string& other : {std::string("{\"cpu_model\": \"another CPU\", \"probe_native_ns\": 1}"),
                                     std::string("not json"), std::string(100000, 'x')}) {
        std::ofstream(kept) << other;
        const Result r = run(kRun + "--retime-tries 0 --report o.json -q");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_GT(read_json("o.json")["summary"]["timing_quality"]["probe_native_ns"].get<double>(), 1) << other.substr(0, 40);
        EXPECT_NE(report_of(kept)["probe_native_ns"].get<double>(), 1) << "written anew: " << other.substr(0, 40);
    }
}

TEST_F(CliTimingQuality, ReTimingFindsTheSamePairsAndKeepsTheFiguresTheReportsFramesGive) {
    // --warmup 0: the first frame (allocation, first insertion) is timed again too.
    const Result r = run(kRun + "--warmup 0 --repeat 2 --report r.json -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = read_json("r.json");
    for (const char* name : {"sap", "soa"}) {
        std::vector<double> first;
        for (const json& f : j["frames"]) first.push_back(f["baselines"][name]["native_ns"].get<double>());
        for (const json& again : j["summary"]["baselines"][name]["retimed"]) {
            ASSERT_EQ(again.size(), 3u);
            if (again[0] == 0) first.at(again[1].get<std::size_t>()) = again[2].get<double>();
        }
        double sum = 0;
        for (const double v : first) sum += v;
        const std::vector<double> means = j["summary"]["baselines"][name]["run_means_native_ns"];
        ASSERT_EQ(means.size(), 2u);
        EXPECT_NEAR(means[0], sum / static_cast<double>(first.size()), 1e-6 * means[0]) << name;
    }
}

TEST_F(CliTimingQuality, PinCpuPinsOrIsRefusedOnOneLine) {
    expect_refusal(run(kRun + "--pin-cpu 1023"), "cdvp run: --pin-cpu: CPU 1023 is not one this process may run on (");
    expect_refusal(run(kRun + "--pin-cpu abc"), "cdvp run: --pin-cpu: ");
    expect_refusal(run(kRun + "-c run.pin_cpu=-1"), "cdvp run: -c run.pin_cpu: ");
    const Result pinned = run(kRun + "--pin-cpu 0 --report r.json -q");
    ASSERT_EQ(pinned.status, 0) << pinned.err;
    EXPECT_EQ(read_json("r.json")["config"]["settings"]["run.pin_cpu"]["value"], "0");
}

TEST_F(CliTimingQuality, ASweepTimesEachWorkloadOnceAndEveryPointOfItDividesByIt) {
    const std::string grid = "sweep --board adm-xrc-ii,pcie-gen3-x8 --set m=1,4 --set objects=40,80 --frames 4 "
                             "--baseline sap --no-plots -q ";
    ASSERT_EQ(run(grid + "--out s").status, 0);
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "s" / "software")) files += entry.path().extension() == ".json";
    EXPECT_EQ(files, 2u) << "two workloads (40 and 80 objects) for eight points";
    std::map<std::string, std::set<std::string>> ids, natives;
    for (const auto& row : sweep_rows(slurp(dir_ / "s" / "sweep.csv"), false)) {
        ids[row.at("objects")].insert(row.at("sap_timing_id"));
        const double factor = std::stod(row.at("sap_host_factor"));
        char native[32];
        std::snprintf(native, sizeof native, "%.6g", std::stod(row.at("sap_mean_host_ns")) / factor);
        natives[row.at("objects")].insert(native);
        EXPECT_TRUE(row.at("sap_timing_quality") == "clean" || row.at("sap_timing_quality") == "disturbed");
    }
    for (const auto& [objects, used] : ids) {
        EXPECT_EQ(used.size(), 1u) << objects << " objects: one timing for every board and m";
        EXPECT_EQ(used.begin()->find('@'), 16u) << *used.begin();
        EXPECT_EQ(natives[objects].size(), 1u) << objects << " objects: one native mean";
    }
    // A resume holds the rows to the timings they used.
    const std::string file = (dir_ / "s" / "software" / (ids["40"].begin()->substr(0, 16) + ".json")).string();
    std::string text = slurp(file);
    write("s/software/" + ids["40"].begin()->substr(0, 16) + ".json", text + " ");
    expect_refusal(run(grid + "--out s"), "cdvp sweep: s/software/" + ids["40"].begin()->substr(0, 16) + ".json: changed");
    write("s/software/" + ids["40"].begin()->substr(0, 16) + ".json", text);
    EXPECT_EQ(run(grid + "--out s").status, 0);
    expect_refusal(run(grid + "--out s --software-timings none"),
                   "cdvp sweep: --out: s holds another sweep (software timings shared through 'OUT/software', not ''");
    // Each point its own timing.
    ASSERT_EQ(run(grid + "--out own --software-timings none").status, 0);
    EXPECT_FALSE(fs::exists(dir_ / "own" / "software"));
    for (const auto& row : sweep_rows(slurp(dir_ / "own" / "sweep.csv"), false)) EXPECT_EQ(row.at("sap_timing_id"), "own");
}

TEST_F(CliTimingQuality, ShardsGivenOneTimingsDirectoryShareItAndTheirMergeEqualsTheWhole) {
    const std::string grid = "sweep --board adm-xrc-ii --set m=1,2,4 --set objects=40 --frames 4 --baseline soa "
                             "--no-plots -q --software-timings shared ";
    ASSERT_EQ(run(grid + "--out a --shard 1/2").status, 0);
    ASSERT_EQ(run(grid + "--out b --shard 2/2").status, 0);
    ASSERT_EQ(run("merge -q --out m a b").status, 0);
    std::set<std::string> ids;
    for (const auto& row : sweep_rows(slurp(dir_ / "m" / "sweep.csv"), false)) ids.insert(row.at("soa_timing_id"));
    EXPECT_EQ(ids.size(), 1u) << "both shards divided by one timing";
}

// A shared timing is an input file like any other: one out of range (a time
// of 1e308 ns, a count of -5) or that is no regular file (a FIFO held the run
// forever, a link to /dev/zero was read without limit) is refused in one line
// naming the file, field and range, exit 2, and the run writes nothing. The
// timeout fails a run that hangs.
TEST_F(CliTimingQuality, ASharedTimingOutOfRangeOrNoRegularFileIsRefusedAndNothingIsWritten) {
    const std::string share = "run --board adm-xrc-ii --scene spheres --objects 20 --frames 4 --baseline sap -q "
                              "--software-timings shared ";
    fs::create_directory(dir_ / "shared");
    ASSERT_EQ(run(share + "--m 1").status, 0);
    std::vector<std::string> timings;
    for (const auto& entry : fs::directory_iterator(dir_ / "shared")) timings.push_back(entry.path().filename().string());
    ASSERT_EQ(timings.size(), 1u);
    const std::string name = "shared/" + timings[0];
    const json good = json::parse(slurp(dir_ / name));
    const auto refused = [&](const std::string& start) {
        const Result r = run(share + "--m 2 --report r.json --pairs-out p.csv", "timeout 60");
        expect_refusal(r, "cdvp run: " + name + start);
        EXPECT_FALSE(fs::exists(dir_ / "r.json")) << start;
        EXPECT_FALSE(fs::exists(dir_ / "p.csv")) << start;
    };
    const std::vector<std::pair<std::function<void(json&)>, std::string>> edits{
        {[](json& j) { j["baselines"]["sap"]["cpu_native_ns"][0][3] = 1e308; },
         ": baselines.sap.cpu_native_ns: expected a time from 0 to 1e+15 ns, got 1e+308\n"},
        {[](json& j) { j["baselines"]["sap"]["wall_native_ns"][0][3] = 1e308; },
         ": baselines.sap.wall_native_ns: expected a time from 0 to 1e+15 ns, got 1e+308\n"},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["frames_timed"] = -5; },
         ": baselines.sap.timing_quality.frames_timed: expected a count from 0 to 18446744073709551615, got -5\n"},
    };
    for (const auto& [edit, start] : edits) {
        json bad = good;
        edit(bad);
        write(name, bad.dump(1));
        refused(start);
    }
    fs::remove(dir_ / name);
    ASSERT_EQ(mkfifo((dir_ / name).c_str(), 0600), 0);
    refused(": cannot open: not a regular file; expected a software timing cdvp wrote\n");
    fs::remove(dir_ / name);
    fs::create_symlink("/dev/zero", dir_ / name);
    refused(": cannot open: not a regular file; expected a software timing cdvp wrote\n");
    // A sweep's points refuse it alike, and the sweep leaves nothing.
    const Result sweep = run("sweep --board adm-xrc-ii --scene spheres --set m=2,4 --objects 20 --frames 4 --baseline sap "
                             "-q --no-plots --software-timings shared --out s",
                             "timeout 60");
    expect_refusal(sweep, "cdvp sweep: every point was refused; the first, ");
    EXPECT_NE(sweep.err.find(name + ": cannot open: not a regular file"), std::string::npos) << sweep.err;
    EXPECT_FALSE(fs::exists(dir_ / "s"));
}

// A run makes its --software-timings directory as a sweep does (mkdir -p)
// and adds its timing there; one that names a file or cannot be made is
// refused in one line naming it, exit 2, and nothing is written; a run that
// fails after making it leaves none of the directories it made.
TEST_F(CliTimingQuality, ARunMakesItsSoftwareTimingsDirectoryOrRefusesNamingIt) {
    const std::string share = "run --board adm-xrc-ii --scene spheres --objects 20 --frames 3 --baseline sap -q "
                              "--report r.json --software-timings ";
    const auto timings = [this](const std::string& dir) {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_ / dir)) names.push_back(entry.path().filename().string());
        return names;
    };
    const Result made = run(share + "new/timings");
    ASSERT_EQ(made.status, 0) << made.err;
    const std::vector<std::string> added = timings("new/timings");
    ASSERT_EQ(added.size(), 1u);
    EXPECT_EQ(fs::path(added[0]).extension(), ".json");
    ASSERT_EQ(run(share + "new/timings/").status, 0);
    EXPECT_EQ(timings("new/timings"), added) << "the second run takes the first one's timing";
    fs::remove(dir_ / "r.json");
    write("file", "not a directory\n");
    expect_refusal(run(share + "file"), "cdvp run: --software-timings: file: expected a directory\n");
    expect_refusal(run(share + "file/timings"), "cdvp run: --software-timings: file/timings: cannot create: ");
    EXPECT_FALSE(fs::exists(dir_ / "r.json")) << "a refused run writes nothing";
    const Result fault = run(share + "gone/timings --inject board-error@frame=1");
    EXPECT_EQ(fault.status, 3) << fault.err;
    EXPECT_FALSE(fs::exists(dir_ / "gone")) << "made for the run, removed with it";
    EXPECT_FALSE(fs::exists(dir_ / "r.json"));
}

TEST_F(CliTimingQuality, CalibrateSaysWhenItsRunsCouldNotAgreeAndARunOnThatProfileSaysSo) {
    const Result strict = run("calibrate --repeat 2 --max-spread 0.1 --time-limit 1 --strict --out strict.json");
    if (strict.status == 0) GTEST_SKIP() << "this machine got within 0.1%: " << strict.out;
    expect_refusal(strict, "cdvp calibrate: --strict: the reference workload's runs stayed ");
    EXPECT_FALSE(fs::exists(dir_ / "strict.json")) << "a refused calibration writes nothing";
    const Result poor = run("calibrate --repeat 2 --max-spread 0.1 --time-limit 1 -q --out poor.json");
    ASSERT_EQ(poor.status, 0) << poor.err;
    EXPECT_EQ(poor.err.rfind("cdvp calibrate: warning: the reference workload's runs stayed ", 0), 0u) << poor.err;
    EXPECT_NE(poor.err.find(" at load "), std::string::npos) << "names the load: " << poor.err;
    const json p = read_json("poor.json");
    EXPECT_EQ(p["calibration"]["quality"], "poor");
    // It repeats for the spread until its time limit; a slow build (sanitizers) may reach the limit at 2 runs.
    const int runs = p["calibration"]["runs"].get<int>();
    EXPECT_GE(runs, 2);
    EXPECT_TRUE(runs > 2 || p["calibration"]["seconds"].get<double>() >= 1.0)
        << "it stopped at " << runs << " runs before its time limit: " << p["calibration"].dump();
    const Result r = run(kRun + "--host-profile poor.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.rfind("cdvp run: host factors rest on a poor profile, poor.json: its runs stayed ", 0), 0u) << r.err;
}

TEST_F(CliTimingQuality, BulletReportsItsSoftwareWorldsTimingQuality) {
    const Result r = run("bullet --scene stack --objects 20 --frames 5 --board adm-xrc-ii --m 2 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("software world's timing (thread CPU time): "), std::string::npos) << r.out;
    const json report = read_json("r.json");
    const json& q = report["bullet"]["summary"]["timing_quality"];
    EXPECT_EQ(q["frames_timed"], 3) << "five steps, two of them warm-up";
    EXPECT_EQ(q["frames_disturbed"], q["frames_retimed"].get<uint64_t>() + q["never_clean"].get<uint64_t>());
}

}  // namespace
}  // namespace cdvp::test
