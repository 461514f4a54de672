// Frames pipelined from the command line (--box-banks 2): a recorded
// scene's trace gives the same pairs file as one frame at a time, on both
// engines and at the analytic level (whose times equal the fast engine's on
// this scene); the report gives each frame's overlap and latency, and the
// host's time a frame falls; a closed-loop scene or a Bullet world is
// refused on one line naming the setting; auto measures the first frame.
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

TEST_F(Cli, TwoBoxBanksPipelineATraceToTheSamePairsInLessHostTime) {
    ASSERT_EQ(run("record --scene bullet-spheres --objects 300 --frames 5 --out trace.csv -q").status, 0);
    const std::string trace = "run --trace trace.csv --board adm-xrc-ii --m 4 -q ";
    ASSERT_EQ(run(trace + "--pairs-out one.csv --report one.json").status, 0);
    nlohmann::json fast;
    for (const std::string fidelity : {"fast", "cycle", "analytic"}) {
        const Result r = run(trace + "--box-banks 2 --fidelity " + fidelity + " --pairs-out two.csv --report two.json");
        ASSERT_EQ(r.status, 0) << fidelity << ": " << r.err;
        EXPECT_EQ(slurp(dir_ / "one.csv"), slurp(dir_ / "two.csv")) << fidelity << ": the same pairs, frame by frame";
        const auto one = report_of(dir_ / "one.json")["frames"], two = report_of(dir_ / "two.json")["frames"];
        ASSERT_EQ(two.size(), 5u);
        double one_total = 0, two_total = 0;
        for (std::size_t k = 0; k < two.size(); ++k) {
            EXPECT_EQ(two[k]["frame"], one[k]["frame"]);
            EXPECT_EQ(two[k]["pairs"], one[k]["pairs"]) << k;
            EXPECT_EQ(two[k]["compute_cycles"], one[k]["compute_cycles"]) << k;
            EXPECT_EQ(one[k]["overlap_ns"], 0.0) << k;
            EXPECT_EQ(one[k]["latency_ns"], one[k]["total_ns"]) << k;
            EXPECT_GE(two[k]["latency_ns"].get<double>(), two[k]["total_ns"].get<double>()) << k;
            one_total += one[k]["total_ns"].get<double>();
            two_total += two[k]["total_ns"].get<double>();
        }
        EXPECT_GT(two[0]["overlap_ns"].get<double>(), 0.0) << "frame 0 sweeps while frame 1 uploads";
        EXPECT_LT(two_total, one_total) << fidelity;
        if (fidelity == "fast") fast = two;
        for (std::size_t k = 0; fidelity == "analytic" && k < two.size(); ++k) {
            for (const char* field : {"upload_ns", "compute_ns", "irq_ns", "readback_ns", "total_ns", "latency_ns",
                                      "overlap_ns"}) {
                const double exact = fast[k][field].get<double>();
                EXPECT_NEAR(two[k][field].get<double>(), exact, 1e-6 * std::max(1.0, exact)) << k << " " << field;
            }
        }
    }
    const Result summary = run("run --trace trace.csv --board adm-xrc-ii --m 4 --box-banks 2");
    ASSERT_EQ(summary.status, 0) << summary.err;
    EXPECT_NE(summary.out.find("pipelined (two box banks)"), std::string::npos) << summary.out;
}

TEST_F(Cli, PipeliningWhatCannotBePipelinedIsRefused) {
    const Result scene = run("run --scene spheres --objects 50 --box-banks 2 -q");
    EXPECT_EQ(scene.status, 2);
    EXPECT_NE(scene.err.find("--box-banks"), std::string::npos) << scene.err;
    EXPECT_NE(scene.err.find("--trace"), std::string::npos) << scene.err;
    const Result bullet = run("bullet --scene pyramid --objects 20 --frames 2 --box-banks 2 -q");
    EXPECT_EQ(bullet.status, 2);
    EXPECT_NE(bullet.err.find("Bullet world"), std::string::npos) << bullet.err;
    ASSERT_EQ(run("record --scene bullet-spheres --objects 40 --frames 2 --out t.csv -q").status, 0);
    const Result banks_refused = run("run --trace t.csv --box-banks 3 -q");
    EXPECT_EQ(banks_refused.status, 2);
    EXPECT_NE(banks_refused.err.find("--box-banks"), std::string::npos) << banks_refused.err;
}

// --fidelity auto pipelined: both levels run until the first frame finishes,
// which is measured (pipelined frames have no bound); within --max-error
// the analytic level times the rest, else the fast engine does. The pairs
// are the fast engine's either way.
TEST_F(Cli, AutoMeasuresThePipelinesFirstFrameAndKeepsTheLevelWithinTheError) {
    ASSERT_EQ(run("record --scene bullet-spheres --objects 300 --frames 6 --out t.csv -q").status, 0);
    const std::string trace = "run --trace t.csv --board adm-xrc-ii --box-banks 2 ";
    ASSERT_EQ(run(trace + "--m 4 --fidelity fast --pairs-out fast.csv -q").status, 0);
    const Result chosen = run(trace + "--m 4 --fidelity auto --report r.json --pairs-out auto.csv");
    ASSERT_EQ(chosen.status, 0) << chosen.err;
    EXPECT_NE(chosen.out.find("auto: analytic level on 5 of 6 pipelined frames"), std::string::npos) << chosen.out;
    EXPECT_EQ(slurp(dir_ / "auto.csv"), slurp(dir_ / "fast.csv"));
    const auto choice = report_of(dir_ / "r.json")["fidelity_choice"];
    EXPECT_EQ(choice["pipelined"], true);
    EXPECT_EQ(choice["measured_frame"], 0);
    EXPECT_EQ(choice["fast_frames"], 1);
    EXPECT_EQ(choice["analytic_frames"], 5);
    // Pausing every 50 pairs: each pause placed by its pair's slot, the frame is exact.
    const Result exact = run(trace + "--m 2 -c board.pair_buffer_depth=50 --fidelity auto --max-error 0.1 -q --report p.json");
    ASSERT_EQ(exact.status, 0) << exact.err;
    const auto paused = report_of(dir_ / "p.json")["fidelity_choice"];
    EXPECT_EQ(paused["measured_error_percent"].get<double>(), 0.0) << paused.dump();
    EXPECT_EQ(paused["analytic_frames"], 5);
    // A pyramid's rows of contacts come in bursts a 7-pair FIFO cannot take: its
    // stalls are estimated, the sweep outlasts the upload, and 0.1% is too tight.
    ASSERT_EQ(run("record --scene pyramid --objects 1500 --frames 3 --out pyramid.csv -q").status, 0);
    const Result fast = run("run --trace pyramid.csv --board adm-xrc-ii --box-banks 2 --m 4 --fifo-depth 7 "
                            "--fidelity auto --max-error 0.1 -q --report b.json");
    ASSERT_EQ(fast.status, 0) << fast.err;
    const auto bursts = report_of(dir_ / "b.json")["fidelity_choice"];
    EXPECT_GT(bursts["measured_error_percent"].get<double>(), 0.1) << bursts.dump();
    EXPECT_LT(bursts["measured_error_percent"].get<double>(), 5.0) << bursts.dump();
    EXPECT_EQ(bursts["analytic_frames"], 0);
    EXPECT_EQ(bursts["fast_frames"], 3);
}

}  // namespace
}  // namespace cdvp::test
