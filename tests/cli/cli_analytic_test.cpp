// `cdvp run --fidelity analytic`: the board's pairs found without the SystemC
// kernel and the frame timed from closed forms; exact where docs/analytic.md
// says so, and what it cannot model refused.
#include <cmath>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

nlohmann::json report_of(const fs::path& path) { return nlohmann::json::parse(slurp(path)); }

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
    expect_refusal(run(scene + "--vcd w.vcd"), "cdvp run: --vcd: waveforms need the clocked engine; --fidelity asks for "
                                               "analytic");
    expect_refusal(run("bullet --scene stack --frames 2 --fidelity analytic"),
                   "cdvp bullet: --fidelity analytic: cdvp bullet runs Bullet's world on the platform's engines");
    EXPECT_FALSE(fs::exists(dir_ / "w.vcd"));
}

}  // namespace
}  // namespace cdvp::test
