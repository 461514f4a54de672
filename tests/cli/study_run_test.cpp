// run_configuration, the study's entry point for one run: the command's
// report typed, and its refusals as RunFailed with the command's status and line.
#include "sw/study/study_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "models/common/user_text.h"

namespace cdvp {
namespace {

RunRequest request(std::vector<std::string> options) {
    RunRequest r;
    r.options = std::move(options);
    r.cdvp_binary = CDVP_BINARY;
    return r;
}

TEST(StudyRun, ReturnsTheRunsReportTypedAndItsPairs) {
    RunRequest r = request({"--board", "adm-xrc-ii", "--scene", "spheres", "--objects", "60", "--frames", "3"});
    r.pairs = true;
    const RunResult result = run_configuration(r);
    EXPECT_EQ(result.summary.frames, 3u);
    EXPECT_EQ(result.report.at("frames").size(), 3u);
    uint64_t pairs = 0;
    for (const auto& frame : result.report.at("frames")) pairs += frame.at("pairs").get<uint64_t>();
    EXPECT_EQ(result.summary.pairs, pairs);
    EXPECT_GT(result.summary.mean_phase_ns.back(), 0.0);
    EXPECT_EQ(result.report.at("config").at("board"), "adm-xrc-ii");
    // The pairs CSV: a header, then one line a pair.
    EXPECT_EQ(static_cast<uint64_t>(std::count(result.pairs_csv.begin(), result.pairs_csv.end(), '\n')), pairs + 1);
}

TEST(StudyRun, ARefusedOrFaultingRunIsRunFailedWithTheCommandsStatusAndLine) {
    try {
        run_configuration(request({"--scene", "spheres", "--objects", "lots"}));
        FAIL() << "not refused";
    } catch (const RunFailed& e) {
        EXPECT_EQ(e.status(), 2);
        EXPECT_EQ(std::string(e.what()).rfind("cdvp run: --objects: expected an integer", 0), 0u) << e.what();
    }
    try {
        run_configuration(request({"--scene", "spheres", "--frames", "2", "--inject", "dma-hang@frame=1"}));
        FAIL() << "no fault";
    } catch (const RunFailed& e) {
        EXPECT_EQ(e.status(), 3) << e.what();
        EXPECT_NE(std::string(e.what()).find("DMA timed out"), std::string::npos) << e.what();
    }
}

TEST(StudyRun, TheStudysOwnOptionsAndNulCharactersAreRefusedBeforeAnyRun) {
    EXPECT_THROW(run_configuration(request({"--scene", "spheres", "--report", "r.json"})), InputError);
    EXPECT_THROW(run_configuration(request({"--scene", "spheres", "--pairs-out=p.csv"})), InputError);
    EXPECT_THROW(run_configuration(request({"--scene", "spheres", "--objects", std::string("5\0--m", 5)})), InputError);
}

}  // namespace
}  // namespace cdvp
