// run_configuration, the study's entry point for one run: the command's
// report typed, its refusals as RunFailed with the command's status and line,
// and a run at the analytic level in this process giving what a child gives.
#include "sw/study/study_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "models/common/user_text.h"
#include "sw/run/run_arguments.h"

namespace cdvp {
namespace {

RunRequest request(RunSpec spec) {
    RunRequest r;
    r.spec = std::move(spec);
    r.cdvp_binary = CDVP_BINARY;
    return r;
}

// The paper's board on the spheres: objects and frames given typed.
RunSpec spheres(uint64_t objects, uint64_t frames) {
    RunSpec spec;
    spec.settings.board = "adm-xrc-ii";
    spec.frames = SceneFrames{"spheres"};
    set_input(spec, "scene.objects", std::to_string(objects), true);
    set_input(spec, "scene.frames", std::to_string(frames), true);
    return spec;
}

TEST(StudyRun, ReturnsTheRunsReportTypedAndItsPairs) {
    RunRequest r = request(spheres(60, 3));
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

TEST(StudyRun, AnAnalyticRunInThisProcessGivesTheChildsFramesAndPairs) {
    RunSpec spec = spheres(200, 4);
    set_input(spec, "run.fidelity", "analytic", true);
    RunRequest child = request(spec), here = request(spec);
    child.pairs = here.pairs = true;
    here.in_process = true;
    RunResult a = run_configuration(child), b = run_configuration(here);
    // What the simulator's own wall time was, and the words a setting's origin
    // is named in (the child's command line says "flag --objects"), differ.
    for (RunResult* r : {&a, &b}) {
        for (auto& frame : r->report.at("frames")) frame.erase("sim_wall_native_ns");
        for (auto& [name, setting] : r->report.at("config").at("settings").items()) setting.erase("origin");
    }
    EXPECT_EQ(a.report.at("frames"), b.report.at("frames"));
    EXPECT_EQ(a.pairs_csv, b.pairs_csv);
    EXPECT_EQ(a.report.at("config").at("settings"), b.report.at("config").at("settings"));
}

TEST(StudyRun, ARefusedOrFaultingRunIsRunFailedWithTheCommandsStatusAndLine) {
    RunSpec too_wide = spheres(60, 3);
    too_wide.settings.overrides.push_back("board.m=99");
    try {
        run_configuration(request(too_wide));
        FAIL() << "not refused";
    } catch (const RunFailed& e) {
        EXPECT_EQ(e.status(), 2);
        EXPECT_EQ(std::string(e.what()).rfind("cdvp run: -c board.m: expected", 0), 0u) << e.what();
    }
    RunSpec faulty = spheres(60, 2);
    faulty.faults = {"dma-hang@frame=1"};
    try {
        run_configuration(request(faulty));
        FAIL() << "no fault";
    } catch (const RunFailed& e) {
        EXPECT_EQ(e.status(), 3) << e.what();
        EXPECT_NE(std::string(e.what()).find("DMA timed out"), std::string::npos) << e.what();
    }
}

TEST(StudyRun, TheStudysOwnOutputsAreRefusedBeforeAnyRun) {
    RunSpec with_report = spheres(60, 1);
    with_report.outputs.report = "r.json";
    EXPECT_THROW(run_configuration(request(with_report)), InputError);
    RunSpec with_pairs = spheres(60, 1);
    with_pairs.outputs.pairs_csv = "p.csv";
    EXPECT_THROW(run_configuration(request(with_pairs)), InputError);
}

}  // namespace
}  // namespace cdvp
