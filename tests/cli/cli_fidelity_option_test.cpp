// `cdvp run --fidelity` and `--quantum-ns`: the engine chosen, the same
// results either way, waveforms only from the clocked engine.
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

TEST_F(Cli, FidelityDefaultsToFastAndGivesTheClockedEnginesResults) {
    const std::string scene = "--trace " + trace("hard_cases.csv") + " --board adm-xrc-ii --m 3 --pair-buffer 5 -q";
    ASSERT_EQ(run("run " + scene + " --pairs-out fast.csv --report fast.json").status, 0);
    ASSERT_EQ(run("run " + scene + " --fidelity cycle --pairs-out cycle.csv --report cycle.json").status, 0);
    ASSERT_EQ(run("run " + scene + " --quantum-ns 10000 --pairs-out loose.csv --report loose.json").status, 0);
    EXPECT_EQ(slurp(dir_ / "fast.csv"), slurp(trace("hard_cases.expected.csv")));
    EXPECT_EQ(slurp(dir_ / "cycle.csv"), slurp(dir_ / "fast.csv"));
    EXPECT_EQ(slurp(dir_ / "loose.csv"), slurp(dir_ / "fast.csv"));
    const auto fast = report_of(dir_ / "fast.json"), cycle = report_of(dir_ / "cycle.json"),
               loose = report_of(dir_ / "loose.json");
    EXPECT_EQ(fast["config"]["fidelity"], "fast");
    EXPECT_EQ(cycle["config"]["fidelity"], "cycle");
    EXPECT_EQ(loose["config"]["quantum_ns"], 10000.0);
    ASSERT_EQ(fast["frames"].size(), cycle["frames"].size());
    for (std::size_t k = 0; k < fast["frames"].size(); ++k) {
        for (const char* field : {"pairs", "compute_cycles", "stall_cycles", "overflow_pauses", "upload_ns",
                                  "compute_ns", "irq_ns", "readback_ns", "total_ns"}) {
            EXPECT_EQ(fast["frames"][k][field], cycle["frames"][k][field]) << "frame " << k << " " << field;
            EXPECT_EQ(loose["frames"][k][field], cycle["frames"][k][field]) << "frame " << k << " " << field;
        }
        EXPECT_GT(fast["frames"][k]["sim_wall_native_ns"].get<double>(), 0.0);
    }
}

TEST_F(Cli, WaveformsTakeTheClockedEngine) {
    const Result r = run("run --scene spheres --objects 30 --vcd w.vcd --report r.json -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(report_of(dir_ / "r.json")["config"]["fidelity"], "cycle") << "--vcd alone picks the clocked engine";
    EXPECT_NE(slurp(dir_ / "w.vcd").find("lane_hit"), std::string::npos);
}

TEST_F(Cli, FidelityAndQuantumRefuseWhatTheyCannotDo) {
    struct Case {
        const char* args;
        const char* message;
    } cases[] = {
        {"--fidelity fast --vcd w.vcd", "cdvp run: --vcd: waveforms need the clocked engine or the RTL"},
        {"--fidelity exact", "cdvp run: --fidelity: expected rtl, cycle, fast, analytic or auto, got 'exact'"},
        {"--quantum-ns -1", "cdvp run: --quantum-ns: expected"},
        {"--quantum-ns 2e9", "cdvp run: --quantum-ns: expected"},
    };
    for (const Case& c : cases) {
        expect_refusal(run(std::string("run --scene spheres --objects 10 ") + c.args), c.message, c.args);
        EXPECT_FALSE(fs::exists(dir_ / "w.vcd")) << c.args;
    }
}

}  // namespace
}  // namespace cdvp::test
