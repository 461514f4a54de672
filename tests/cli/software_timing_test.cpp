// A workload's shared software timing without processes: written once and
// never replaced, read back whole, refused naming the file and field when
// damaged or of another workload; a resume finds a timing its rows used that
// has changed; a merge keeps both timings of a workload two shards timed;
// and a recalibrated host profile is the same input while its reference
// times moved within their recorded spread.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/run/software_timing.h"
#include "sw/study/sweep_software_timings.h"
#include "sw/study/sweep_manifest.h"
#include "sw/study/sweep_table.h"

namespace cdvp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class SoftwareTimingDir : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = (fs::temp_directory_path() / ("cdvp-timing-" + std::to_string(getpid()) + "-" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name()))
                   .string();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static SoftwareTiming timing(double sap_ns) {
        SoftwareTiming t;
        t.workload = {{"scene", "spheres"}, {"scene_settings", {{"scene.objects", 500}}}, {"baselines", {"sap"}}};
        t.retime_tries = 3;
        SoftwareTiming::Baseline& b = t.baselines["sap"];
        b.cpu_ns = {{2000, sap_ns, sap_ns}, {1900, sap_ns, sap_ns * 1.01}};
        b.wall_ns = {{2100, sap_ns + 5, sap_ns + 5}, {2000, sap_ns + 5, sap_ns + 6}};
        b.quality.frames_timed = 4;
        b.quality.runs = 2;
        return t;
    }
    std::string path(const SoftwareTiming& t) const { return software_timing_path(dir_, software_timing_key(t.workload)); }
    std::string refusal(const std::function<void(json&)>& change) {
        const SoftwareTiming t = timing(90);
        json j = json::parse(software_timing_text(t));
        change(j);
        std::ofstream(path(t)) << j.dump();
        std::string sha;
        try {
            read_software_timing(path(t), t.workload, sha);
        } catch (const InputError& e) {
            return e.what();
        }
        ADD_FAILURE() << "accepted: " << j.dump();
        return {};
    }
    std::string dir_;
};

TEST_F(SoftwareTimingDir, IsWrittenOnceReadBackWholeAndNeverReplaced) {
    const SoftwareTiming first = timing(90);
    std::string sha;
    EXPECT_FALSE(read_software_timing(path(first), first.workload, sha).has_value()) << "none yet";
    const std::optional<std::string> added = publish_software_timing(dir_, first);
    ASSERT_TRUE(added.has_value());
    EXPECT_EQ(added->size(), 64u);
    EXPECT_FALSE(publish_software_timing(dir_, timing(120)).has_value()) << "a second timing of the workload is not added";
    const std::optional<SoftwareTiming> read = read_software_timing(path(first), first.workload, sha);
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(sha, *added);
    EXPECT_EQ(read->baselines.at("sap").cpu_ns, first.baselines.at("sap").cpu_ns) << "the first one stays";
    EXPECT_EQ(read->baselines.at("sap").wall_ns, first.baselines.at("sap").wall_ns);
    EXPECT_EQ(read->baselines.at("sap").quality.frames_timed, 4u);
    EXPECT_EQ(read->retime_tries, 3u);
    EXPECT_EQ(software_timing_id(software_timing_key(first.workload), sha).size(), 16u + 1 + 8);
    for (const auto& entry : fs::directory_iterator(dir_)) {
        EXPECT_EQ(entry.path().filename().string().find(".part-"), std::string::npos) << "no temporary left";
    }
}

TEST_F(SoftwareTimingDir, TheKeyIsTheWorkloadsAndNothingElse) {
    SoftwareTiming a = timing(90), b = timing(200);
    EXPECT_EQ(software_timing_key(a.workload), software_timing_key(b.workload)) << "the times are not the workload";
    b.workload["scene_settings"]["scene.objects"] = 400;
    EXPECT_NE(software_timing_key(a.workload), software_timing_key(b.workload));
    EXPECT_EQ(software_timing_key(a.workload).size(), 16u);
}

TEST_F(SoftwareTimingDir, ADamagedOrForeignTimingIsRefusedNamingFileAndField) {
    const std::string file = path(timing(90));
    EXPECT_EQ(refusal([](json& j) { j["format"] = "x"; }), file + ": format: expected \"cdvp software timing\"");
    EXPECT_EQ(refusal([](json& j) { j["workload"]["scene"] = "stack"; }).rfind(file + ": workload: another workload's", 0), 0u);
    EXPECT_EQ(refusal([](json& j) { j["baselines"]["sap"]["cpu_native_ns"][1] = {1, 2}; }),
              file + ": baselines.sap.cpu_native_ns: expected as many frames in every run");
    EXPECT_EQ(refusal([](json& j) { j["baselines"]["sap"]["cpu_native_ns"][0][1] = -1; }),
              file + ": baselines.sap.cpu_native_ns: expected a time from 0 to 1e+15 ns, got -1");
    EXPECT_EQ(refusal([](json& j) { j["baselines"]["sap"]["timing_quality"].erase("never_clean"); }),
              file + ": baselines.sap.timing_quality.never_clean: expected a count from 0 to 18446744073709551615, "
                     "got nothing");
    EXPECT_EQ(refusal([](json& j) { j["format_version"] = "1"; }), file + ": format_version: expected 1")
        << "a string where a number belongs is refused, not a JSON library's error";
    std::ofstream(file) << "{";
    std::string sha;
    EXPECT_THROW(read_software_timing(file, timing(90).workload, sha), InputError);
}

// Every number is checked against what it means before it is used: a time
// of 1e308 ns made the host time inf (an internal error) or the report's mean
// null (exit 0); a count of -5 became 18446744073709551611 in the report.
TEST_F(SoftwareTimingDir, ANumberOutsideWhatItMeansIsRefusedNamingFileFieldAndRange) {
    const std::string file = path(timing(90));
    const std::string sap = file + ": baselines.sap.";
    const std::vector<std::pair<std::function<void(json&)>, std::string>> cases{
        {[](json& j) { j["baselines"]["sap"]["cpu_native_ns"][0][2] = 1e308; },
         sap + "cpu_native_ns: expected a time from 0 to 1e+15 ns, got 1e+308"},
        {[](json& j) { j["baselines"]["sap"]["wall_native_ns"][1][0] = 1e308; },
         sap + "wall_native_ns: expected a time from 0 to 1e+15 ns, got 1e+308"},
        {[](json& j) { j["baselines"]["sap"]["wall_native_ns"][1][0] = "7"; },
         sap + "wall_native_ns: expected a time from 0 to 1e+15 ns, got \"7\""},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["frames_timed"] = -5; },
         sap + "timing_quality.frames_timed: expected a count from 0 to 18446744073709551615, got -5"},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["tries"] = 2.5; },
         sap + "timing_quality.tries: expected a count from 0 to 18446744073709551615, got 2.5"},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["runs"] = 0; },
         sap + "timing_quality.runs: expected a count from 1 to 4294967295, got 0"},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["probe_native_ns"] = 1e300; },
         sap + "timing_quality.probe_native_ns: expected a time from 0 to 1e+15 ns, got 1e+300"},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["repeat_spread"] = -0.5; },
         sap + "timing_quality.repeat_spread: expected a spread of 0 or more, got -0.5"},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["load_average_end"] = {0.5, -1, 0}; },
         sap + "timing_quality.load_average_end[1]: expected a load average of 0 or more, got -1"},
        {[](json& j) { j["baselines"]["sap"]["timing_quality"]["load_average_end"] = {0.5}; },
         sap + "timing_quality.load_average_end: expected the 1, 5 and 15 minute load averages, got [0.5]"},
        {[](json& j) { j["retime_tries"] = 1099511627776; },
         file + ": retime_tries: expected a count from 0 to 4294967295, got 1099511627776"},
    };
    for (const auto& [change, why] : cases) EXPECT_EQ(refusal(change), why);
}

// A timing file is read as every input file is: a FIFO (which held a resume
// forever), a link to /dev/zero (read without limit) or a file larger than a
// timing of its shape is refused unread, naming it; the alarm fails a test
// that hangs.
TEST_F(SoftwareTimingDir, ATimingThatIsNoRegularFileOrTooBigIsRefusedUnread) {
    alarm(60);
    const SoftwareTiming t = timing(90);
    const std::string file = path(t);
    std::string sha;
    ASSERT_EQ(mkfifo(file.c_str(), 0600), 0);
    try {
        read_software_timing(file, t.workload, sha);
        ADD_FAILURE() << "a FIFO was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), file + ": cannot open: not a regular file; expected a software timing cdvp wrote");
    }
    // A resume's check of the timings its rows used reads them the same way.
    const Grid grid(std::vector<Axis>{{"m", {"1"}}});
    SweepTable table(grid);
    PointRow row = failed_row(grid, grid.point(0), PointStatus::kOk, "", 0.1);
    row.values["sap_timing_id"] = software_timing_id(software_timing_key(t.workload), std::string(64, 'a'));
    table.add(0, row);
    EXPECT_THROW(check_software_timings(dir_, table), InputError);
    fs::remove(file);
    fs::create_symlink("/dev/zero", file);
    EXPECT_THROW(read_software_timing(file, t.workload, sha), InputError);
    fs::remove(file);
    std::ofstream(file) << software_timing_text(t) << std::string(4096, ' ');
    const std::size_t bound = software_timing_text(t).size() + 100;
    try {
        read_software_timing(file, t.workload, sha, bound);
        ADD_FAILURE() << "a file past its bound was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  file + ": larger than " + std::to_string(bound) + " bytes; not a software timing cdvp wrote");
    }
    EXPECT_GT(software_timing_max_bytes(2, 3, 1), software_timing_text(t).size()) << "what cdvp writes fits";
    EXPECT_EQ(software_timing_max_bytes(1000, 1000000000, 8), kMaxSoftwareTimingBytes);
    alarm(0);
}

TEST_F(SoftwareTimingDir, AResumeFindsATimingItsRowsUsedThatChangedOrWentAway) {
    const SoftwareTiming t = timing(90);
    const std::string sha = *publish_software_timing(dir_, t);
    const Grid grid(std::vector<Axis>{{"m", {"1", "2"}}});
    SweepTable table(grid);
    for (std::size_t k = 0; k < 2; ++k) {
        PointRow row = failed_row(grid, grid.point(k), PointStatus::kOk, "", 0.1);
        row.values["sap_timing_id"] = software_timing_id(software_timing_key(t.workload), sha);
        table.add(k, row);
    }
    EXPECT_EQ(check_software_timings(dir_, table), std::nullopt);
    std::ofstream(path(t), std::ios::app) << " ";
    const std::optional<std::string> changed = check_software_timings(dir_, table);
    ASSERT_TRUE(changed.has_value());
    EXPECT_EQ(changed->rfind(path(t) + ": changed (sha256 ", 0), 0u) << *changed;
    EXPECT_NE(changed->find("but point m-1's sap_timing_id is "), std::string::npos) << *changed;
    fs::remove(path(t));
    EXPECT_EQ(check_software_timings(dir_, table)->rfind(path(t) + ": missing, but point", 0), 0u);
}

TEST_F(SoftwareTimingDir, AMergeKeepsBothTimingsOfAWorkloadTwoShardsTimed) {
    fs::create_directories(dir_ + "/a");
    fs::create_directories(dir_ + "/b");
    const std::string sha_a = *publish_software_timing(dir_ + "/a", timing(90));
    const std::string sha_b = *publish_software_timing(dir_ + "/b", timing(95));
    const std::string into = dir_ + "/merged";
    EXPECT_TRUE(merge_software_timings(dir_ + "/a", into).empty());
    EXPECT_TRUE(merge_software_timings(dir_ + "/a", into).empty()) << "the same timing twice is one";
    const std::vector<std::string> notes = merge_software_timings(dir_ + "/b", into);
    ASSERT_EQ(notes.size(), 1u);
    const std::string key = software_timing_key(timing(90).workload);
    EXPECT_NE(notes[0].find("was timed by more than one shard"), std::string::npos) << notes[0];
    EXPECT_TRUE(fs::exists(into + "/" + key + ".json"));
    EXPECT_TRUE(fs::exists(into + "/" + software_timing_id(key, sha_b) + ".json"));
    // Rows of either shard find their timing in the merge.
    const Grid grid(std::vector<Axis>{{"m", {"1", "2"}}});
    SweepTable table(grid);
    const std::string ids[] = {software_timing_id(key, sha_a), software_timing_id(key, sha_b)};
    for (std::size_t k = 0; k < 2; ++k) {
        PointRow row = failed_row(grid, grid.point(k), PointStatus::kOk, "", 0.1);
        row.values["sap_timing_id"] = ids[k];
        table.add(k, row);
    }
    EXPECT_EQ(check_software_timings(into, table), std::nullopt);
}

TEST(SweepManifest, ARecalibratedProfileIsTheSameInputWhileItsTimesMovedWithinTheirSpread) {
    const auto profile = [](double sap_ns, double spread) {
        SweepInput input{"--host-profile", "p.json", "p.json", std::string(64, sap_ns > 100 ? 'b' : 'a'), 100, nullptr};
        input.facts = {{"values", {{"sap's reference time (ns)", sap_ns}}},
                       {"tolerance", {{"sap's reference time (ns)", spread}}}};
        return input;
    };
    Manifest then, now;
    then.axes = now.axes = {{"m", {"1"}, "board.m", "m"}};
    then.cdvp_version = now.cdvp_version = "1";
    then.inputs = {profile(100, 0.02)};
    now.inputs = {profile(101.5, 0.01)};
    EXPECT_EQ(difference(then, now), std::nullopt) << "1.5% within the 2% it may move";
    now.inputs = {profile(104, 0.01)};
    const std::optional<SweepDifference> moved = difference(then, now);
    ASSERT_TRUE(moved.has_value());
    EXPECT_TRUE(moved->input_changed);
    EXPECT_EQ(moved->what, "--host-profile p.json changed since the sweep began: sap's reference time (ns) moved +4.0% "
                           "(100 then, 104 now), more than the 2.0% it may (its recorded spread)");
    now.inputs[0].facts = nullptr;
    ASSERT_TRUE(difference(then, now).has_value()) << "without facts any change is a change";
    EXPECT_NE(difference(then, now)->what.find("changed since the sweep began (100 bytes"), std::string::npos);
}

}  // namespace
}  // namespace cdvp
