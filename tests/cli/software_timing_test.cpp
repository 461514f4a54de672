// A workload's shared software timing without processes: written once and
// never replaced, read back whole, refused naming the file and field when
// damaged or of another workload; a resume finds a timing its rows used that
// has changed; a merge keeps both timings of a workload two shards timed;
// and a recalibrated host profile is the same input while its reference
// times moved within their recorded spread.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

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
              file + ": baselines.sap.cpu_native_ns: expected times of 0 ns or more");
    EXPECT_EQ(refusal([](json& j) { j["baselines"]["sap"]["timing_quality"].erase("never_clean"); }),
              file + ": baselines.sap: timing_quality: no never_clean (expected a report of cdvp run)");
    std::ofstream(file) << "{";
    std::string sha;
    EXPECT_THROW(read_software_timing(file, timing(90).workload, sha), InputError);
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
