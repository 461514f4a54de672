// `cdvp run --fidelity analytic`: the board's pairs found without the SystemC
// kernel and the frame timed from closed forms; exact where docs/analytic.md
// says so, and what it cannot model refused.
#include <cmath>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

TEST_F(Cli, AnalyticFindsTheBoardsPairsAndTimesTheBusExactly) {
    // Fixed point too: the pairs are the format's, not float32's.
    for (const std::string format : {"float32", "fixed16"}) {
        const std::string scene = "run --trace " + trace("hard_cases.csv") + " --board adm-xrc-ii --m 3 -q -c board.format=" +
                                  format + " ";
        ASSERT_EQ(run(scene + "--pairs-out fast.csv --report fast.json").status, 0) << format;
        const Result r = run(scene + "--fidelity analytic --pairs-out analytic.csv --report analytic.json");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(slurp(dir_ / "analytic.csv"), slurp(dir_ / "fast.csv")) << format;
        const auto fast = report_of(dir_ / "fast.json"), analytic = report_of(dir_ / "analytic.json");
        EXPECT_EQ(analytic["config"]["fidelity"], "analytic");
        ASSERT_EQ(fast["frames"].size(), analytic["frames"].size());
        ASSERT_GT(fast["frames"].size(), 0u);
        for (std::size_t k = 0; k < fast["frames"].size(); ++k) {
            for (const char* field : {"pairs", "upload_ns", "start_ns", "readback_ns", "driver_ns"}) {
                EXPECT_NEAR(analytic["frames"][k][field].get<double>(), fast["frames"][k][field].get<double>(), 1e-6)
                    << format << " frame " << k << " " << field;
            }
            const double total = fast["frames"][k]["total_ns"].get<double>();
            EXPECT_LT(std::abs(analytic["frames"][k]["total_ns"].get<double>() - total), 0.05 * total) << k;
        }
    }
}

TEST_F(Cli, AnalyticRefusesWhatItCannotModel) {
    const std::string scene = "run --scene spheres --objects 40 --frames 2 --board adm-xrc-ii --fidelity analytic ";
    expect_refusal(run(scene + "--inject dma-hang@frame=0"),
                   "cdvp run: --inject: the analytic level (--fidelity) has no engine to inject faults into");
    expect_refusal(run(scene + "--quantum-ns 100"),
                   "cdvp run: --quantum-ns: the analytic level (--fidelity) times a host that synchronises at every "
                   "access; expected 0");
    expect_refusal(run(scene + "--vcd w.vcd"), "cdvp run: --vcd: waveforms need the clocked engine or the RTL; --fidelity asks for "
                                               "analytic");
    expect_refusal(run("bullet --scene stack --frames 2 --fidelity analytic"),
                   "cdvp bullet: --fidelity analytic: cdvp bullet runs Bullet's world on the platform's engines");
    EXPECT_FALSE(fs::exists(dir_ / "w.vcd"));
}

TEST_F(Cli, AutoTakesTheAnalyticLevelWhereItsErrorIsBoundedOrMeasuredWithinTheLimit) {
    // Sparse: every frame's pairs fit the FIFO, so the analytic level is exact by bound, and is the fast engine's.
    const std::string sparse = "run --board adm-xrc-ii --scene spheres --objects 100 --frames 4 ";
    ASSERT_EQ(run(sparse + "--report fast.json -q").status, 0);
    const Result bounded = run(sparse + "--fidelity auto --report auto.json");
    ASSERT_EQ(bounded.status, 0) << bounded.err;
    EXPECT_NE(bounded.out.find("auto: analytic level on 4 of 4 frames (4 exact by bound)\n"), std::string::npos)
        << bounded.out;
    const auto fast = report_of(dir_ / "fast.json"), chosen = report_of(dir_ / "auto.json");
    EXPECT_EQ(chosen["config"]["fidelity"], "auto");
    EXPECT_EQ(chosen["fidelity_choice"]["exact_by_bound_frames"], 4);
    for (std::size_t k = 0; k < 4; ++k) {
        for (const char* field : {"upload_ns", "start_ns", "compute_ns", "irq_ns", "readback_ns", "total_ns"}) {
            EXPECT_NEAR(chosen["frames"][k][field].get<double>(), fast["frames"][k][field].get<double>(), 1e-6)
                << "frame " << k << " " << field;
        }
    }
    // Polling with pair-buffer pauses: each pause placed by its pair's slot, the first frame measures exact.
    const Result paused = run("run --board adm-xrc-ii --scene spheres --objects 700 --frames 4 --pair-buffer 100 "
                              "--wait poll --fidelity auto --max-error 0.01");
    ASSERT_EQ(paused.status, 0) << paused.err;
    EXPECT_NE(paused.out.find("auto: analytic level on 3 of 4 frames (0 exact by bound); measured on frame 0 against "
                              "the fast engine: total off by 0%, within --max-error 0.01%\n"),
              std::string::npos)
        << paused.out;
    // A pyramid's contacts come in bursts a 7-pair FIFO cannot take: the stalls are estimated.
    const std::string bursts = "run --board adm-xrc-ii --scene pyramid --frames 4 --m 4 --fifo-depth 7 --fidelity auto ";
    const Result within = run(bursts + "--max-error 5");
    ASSERT_EQ(within.status, 0) << within.err;
    EXPECT_NE(within.out.find("auto: analytic level on 3 of 4 frames (0 exact by bound); measured on frame 0 against "
                              "the fast engine: total off by 1.2%, within --max-error 5%\n"),
              std::string::npos)
        << within.out;
    const Result beyond = run(bursts + "--max-error 0.5 --report beyond.json");
    ASSERT_EQ(beyond.status, 0) << beyond.err;
    EXPECT_NE(beyond.out.find("analytic level on 0 of 4 frames (0 exact by bound); measured on frame 0 against the fast "
                              "engine: total off by 1.2%, beyond --max-error 0.5%; the fast engine on the rest\n"),
              std::string::npos)
        << beyond.out;
    EXPECT_EQ(report_of(dir_ / "beyond.json")["fidelity_choice"]["fast_frames"], 4);
    expect_refusal(run(sparse + "--max-error 2"),
                   "cdvp run: --max-error: only --fidelity auto picks a level by its error; give --fidelity auto");
}

}  // namespace
}  // namespace cdvp::test
