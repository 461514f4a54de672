// Energy per frame end to end: the report's parts add up frame by frame and
// in the summary, they follow the clock as the model says, the software's is
// its host time at the stated package power; the multi-threaded baseline
// finds the board's pairs; a host with a stated idle power sleeps on the
// interrupt; and the present-day presets refuse nothing the paper's set-up
// runs (docs/energy.md).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliEnergy : public Cli {
protected:
    json report(const std::string& args) {
        const Result r = run("run --scene spheres --frames 4 --warmup 1 --quiet --report r.json " + args);
        EXPECT_EQ(r.status, 0) << r.err;
        return report_of(dir_ / "r.json");
    }
};

double parts(const json& j, const std::string& prefix) {
    return j[prefix + "static_j"].get<double>() + j[prefix + "dynamic_j"].get<double>() +
           j[prefix + "bus_j"].get<double>() + j[prefix + "host_j"].get<double>();
}

TEST_F(CliEnergy, ThePartsAddUpInEveryFrameAndInTheSummary) {
    const json r = report("--board adm-xrc-ii --objects 300 --baseline sap");
    for (const json& frame : r["frames"]) {
        EXPECT_NEAR(frame["energy_j"].get<double>(), parts(frame, "energy_"), 1e-15);
        for (const char* part : {"energy_static_j", "energy_dynamic_j", "energy_bus_j", "energy_host_j"}) {
            EXPECT_GT(frame[part].get<double>(), 0) << part;
        }
        // Static and host energy are their powers x the frame's time (docs/energy.md).
        EXPECT_NEAR(frame["energy_static_j"].get<double>(), 0.115 * frame["total_ns"].get<double>() * 1e-9, 1e-15);
        EXPECT_NEAR(frame["energy_host_j"].get<double>(), 66.1 * frame["total_ns"].get<double>() * 1e-9, 1e-12);
    }
    const json& s = r["summary"];
    EXPECT_NEAR(s["mean_energy_j"].get<double>(), parts(s, "mean_energy_"), 1e-15);
    EXPECT_NEAR(s["mean_energy_per_pair_j"].get<double>() * r["frames"][3]["pairs"].get<double>(),
                s["mean_energy_j"].get<double>(), s["mean_energy_j"].get<double>() * 0.5)
        << "a pair's share, the spheres' pairs about steady";
    EXPECT_EQ(s["host_package_w"].get<double>(), 66.1);
    const json& sap = s["baselines"]["sap"];
    EXPECT_NEAR(sap["energy_j"].get<double>(), 66.1 * sap["mean_host_ns"].get<double>() * 1e-9, 1e-12);
    EXPECT_NEAR(sap["energy_ratio"].get<double>(), sap["energy_j"].get<double>() / s["mean_energy_j"].get<double>(),
                1e-9);
    EXPECT_TRUE(sap["energy_source"] == "stated" || sap["energy_source"] == "rapl") << sap["energy_source"];
}

TEST_F(CliEnergy, TwiceTheClockLeavesTheSwitchingAndShortensTheRest) {
    const json slow = report("--board adm-xrc-ii --objects 300 --clock-mhz 33");
    const json fast = report("--board adm-xrc-ii --objects 300 --clock-mhz 66");
    const json& a = slow["summary"];
    const json& b = fast["summary"];
    EXPECT_NEAR(b["mean_energy_dynamic_j"].get<double>(), a["mean_energy_dynamic_j"].get<double>(), 1e-15);
    EXPECT_LT(b["mean_energy_static_j"].get<double>(), a["mean_energy_static_j"].get<double>());
    EXPECT_LT(b["mean_energy_host_j"].get<double>(), a["mean_energy_host_j"].get<double>());
    EXPECT_NEAR(b["mean_energy_static_j"].get<double>() / a["mean_energy_static_j"].get<double>(),
                b["mean_total_ns"].get<double>() / a["mean_total_ns"].get<double>(), 1e-9);
}

TEST_F(CliEnergy, ToggleRateScalesTheLogicAndNothingElse) {
    const json base = report("--board adm-xrc-ii --objects 300");
    const json busy = report("--board adm-xrc-ii --objects 300 -c device.toggle_percent=25");
    // The logic and the pins switch twice as often; the block RAMs' accesses stay.
    EXPECT_GT(busy["summary"]["mean_energy_dynamic_j"].get<double>(),
              1.2 * base["summary"]["mean_energy_dynamic_j"].get<double>());
    EXPECT_LT(busy["summary"]["mean_energy_dynamic_j"].get<double>(),
              2.0 * base["summary"]["mean_energy_dynamic_j"].get<double>());
    EXPECT_EQ(busy["summary"]["mean_energy_static_j"], base["summary"]["mean_energy_static_j"]);
    EXPECT_EQ(busy["summary"]["mean_energy_bus_j"], base["summary"]["mean_energy_bus_j"]);
}

TEST_F(CliEnergy, WithoutAPresetNoPowerIsStatedAndNoEnergyCounted) {
    const json r = report("--objects 100");
    EXPECT_EQ(r["summary"]["mean_energy_j"].get<double>(), 0);
}

TEST_F(CliEnergy, TheMultiThreadedBaselineFindsTheBoardsPairsOnEveryThreadCount) {
    for (const char* threads : {"1", "2", "3"}) {
        const json r = report(std::string("--board pcie-gen3-x8 --objects 800 --baseline sap_mt,sap --threads ") + threads);
        const json& mt = r["frames"][1]["baselines"]["sap_mt"];
        EXPECT_GT(mt["native_ns"].get<double>(), 0);
        if (std::string(threads) != "1") {
            // Timed by the wall clock; the threads' CPU time beside it.
            EXPECT_EQ(mt["native_ns"], mt["wall_native_ns"]);
            EXPECT_GT(mt["threads_cpu_native_ns"].get<double>(), 0);
        }
    }
}

// A host that states its idle power (alveo-u250.json) sleeps on the board's
// interrupt: its part of a frame is its package power for the frame less the
// sweep and the interrupt, its idle power for those. Polling, it never sleeps.
TEST_F(CliEnergy, AHostWithAStatedIdlePowerSleepsOnTheInterruptAndNotWhilePolling) {
    const json preset = json::parse(slurp(CDVP_SOURCE_DIR "/platform/boards/alveo-u250.json"));
    const double load_w = preset["host"]["package_w"]["value"].get<double>();
    const double idle_w = preset["host"]["idle_w"]["value"].get<double>();
    ASSERT_GT(idle_w, 0);
    ASSERT_LT(idle_w, load_w);
    const json irq = report("--board alveo-u250 --objects 2000 --m 32 --wait irq");
    const json poll = report("--board alveo-u250 --objects 2000 --m 32 --wait poll");
    for (const json& frame : irq["frames"]) {
        const double total = frame["total_ns"].get<double>();
        const double wait = frame["compute_ns"].get<double>() + frame["irq_ns"].get<double>();
        ASSERT_GT(wait, 0);
        EXPECT_NEAR(frame["energy_host_j"].get<double>(), (load_w * (total - wait) + idle_w * wait) * 1e-9, 1e-12);
        EXPECT_NEAR(frame["energy_j"].get<double>(), parts(frame, "energy_"), 1e-15);
    }
    for (const json& frame : poll["frames"]) {
        EXPECT_NEAR(frame["energy_host_j"].get<double>(), load_w * frame["total_ns"].get<double>() * 1e-9, 1e-12);
    }
}

// Whatever the paper's set-up runs, each present-day one runs too: a grid of
// the user's choices (m, format, objects, transfer, wait, upload, box banks),
// on the all-pairs board, and on the grid board at the choices it takes.
TEST_F(CliEnergy, ThePresentDayPresetsRefuseNothingThePapersSetUpRuns) {
    int runs = 0;
    for (const char* algorithm : {"all_pairs", "grid"}) {
        for (const char* m : {"1", "24"}) {
            for (const char* format : {"float32", "fixed16"}) {
                for (const char* objects : {"500", "3000"}) {
                    for (const char* io : {"--transfer dma --wait irq", "--transfer pio --wait poll --upload delta"}) {
                        for (const char* banks : {"1", "2"}) {
                            const std::string args = std::string("run --scene spheres --frames 2 --quiet --fidelity analytic") +
                                                     " -c board.algorithm=" + algorithm + " --m " + m + " --format " +
                                                     format + " --objects " + objects + " " + io + " --box-banks " + banks +
                                                     " --board ";
                            const Result paper = run(args + "adm-xrc-ii");
                            if (paper.status != 0) continue;
                            ++runs;
                            for (const char* today : {"pcie-gen3-x8", "alveo-u250"}) {
                                const Result r = run(args + today);
                                EXPECT_EQ(r.status, 0) << args << today << ": " << r.err;
                            }
                        }
                    }
                }
            }
        }
    }
    EXPECT_GE(runs, 12) << "the paper's set-up runs the grid but where m = 24 does not fit 3000 boxes, and the grid "
                           "board where its choices allow";
}

}  // namespace
}  // namespace cdvp::test
