// A board clock its device cannot reach, end to end through cdvp run: refused
// in one line naming where the clock came from, the estimated Fmax and the
// piece or path that limits it, with no report left behind; --ignore-timing
// runs it with a warning on standard error, in the summary, in the report and
// in every sweep row; every preset runs at its own clock; the fit line and the
// report carry the estimate.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <regex>

#include <nlohmann/json.hpp>

#include "models/common/number_text.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliClock : public Cli {
protected:
    static std::string spheres(const std::string& board) {
        return "run --scene spheres --objects 200 --frames 1 --board " + board + " ";
    }
    json timing() const { return report_of(dir_ / "r.json")["config"]["resources"]["timing"]; }
    static std::string mhz(double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f MHz", value);
        return text;
    }
};

TEST_F(CliClock, AClockBeyondTheEstimateIsRefusedNamingItsOriginTheEstimateAndThePiece) {
    ASSERT_EQ(run(spheres("adm-xrc-ii") + "--quiet --report r.json").status, 0);
    const json estimate = timing();
    const double fmax = estimate["fmax_mhz"];
    const std::string limit = estimate["limited_by"];
    std::filesystem::remove(dir_ / "r.json");

    const Result r = run(spheres("adm-xrc-ii") + "--clock-mhz 500 --report r.json --pairs-out p.csv");
    expect_refusal(r, "cdvp run: --clock-mhz: 500.0 MHz is beyond the " + mhz(fmax) +
                          " the board reaches on the XC2V6000-4 (speed grade -4): its " + limit + " takes ");
    EXPECT_NE(r.err.find("a cycle (synthesis timing for xc2v); --ignore-timing runs it anyway\n"), std::string::npos)
        << r.err;
    EXPECT_EQ(files(), std::vector<std::string>{}) << "a refused run leaves no file";

    // Where the clock came from: a preset's own clock is named by its file and key.
    json fast = json::parse(slurp(preset("adm-xrc-ii")));
    fast["board"]["clock_mhz"]["value"] = 400;
    write("fast.json", fast.dump());
    expect_refusal(run(spheres("fast.json") + "--quiet"),
                   "cdvp run: fast.json: board.clock_mhz: 400.0 MHz is beyond the ");
}

TEST_F(CliClock, TheEstimateItselfIsTheBoundary) {
    ASSERT_EQ(run(spheres("adm-xrc-ii") + "--quiet --report r.json").status, 0);
    const double fmax = timing()["fmax_mhz"];
    char below[32], above[32];
    std::snprintf(below, sizeof below, "%.4f", fmax * 0.999);
    std::snprintf(above, sizeof above, "%.4f", fmax * 1.001);
    const Result fits = run(spheres("adm-xrc-ii") + "--quiet --clock-mhz " + below + " --report r.json");
    ASSERT_EQ(fits.status, 0) << fits.err;
    EXPECT_TRUE(timing()["meets_clock"].get<bool>());
    // Printed to the decimals that tell the clock from the estimate.
    expect_refusal(run(spheres("adm-xrc-ii") + "--quiet --clock-mhz " + above),
                   "cdvp run: --clock-mhz: " + distinct_figures(std::stod(above), fmax, 1).first +
                       " MHz is beyond the " + distinct_figures(std::stod(above), fmax, 1).second + " MHz");
}

TEST_F(CliClock, IgnoreTimingRunsItWithAWarningInTheSummaryAndTheReport) {
    const Result r = run(spheres("adm-xrc-ii") + "--clock-mhz 500 --ignore-timing --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.rfind("cdvp run: warning: --clock-mhz: 500.0 MHz is beyond the ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("; running it anyway (--ignore-timing)\n"), std::string::npos) << r.err;
    const json t = timing();
    EXPECT_FALSE(t["meets_clock"].get<bool>());
    EXPECT_EQ(t["clock_mhz"], 500.0);
    EXPECT_LT(t["fmax_mhz"].get<double>(), 500.0);
    // The run itself is the faster board's: its frames take fewer nanoseconds.
    const json report = report_of(dir_ / "r.json");
    EXPECT_EQ(report["config"]["clock_mhz"], 500.0);
    // The same line in the report's summary and, under the fit line, in the console's.
    const std::string line = r.err.substr(std::string("cdvp run: warning: ").size(),
                                          r.err.find('\n') - std::string("cdvp run: warning: ").size());
    EXPECT_EQ(report["summary"]["timing_warning"], line);
    EXPECT_NE(r.out.find("\n  warning: " + line + "\n"), std::string::npos) << r.out.substr(0, 1200);
    // A run whose clock is met has neither.
    const Result met = run(spheres("adm-xrc-ii") + "--report r.json");
    ASSERT_EQ(met.status, 0) << met.err;
    EXPECT_FALSE(report_of(dir_ / "r.json")["summary"].contains("timing_warning"));
    EXPECT_EQ(met.out.find("  warning: "), std::string::npos) << met.out.substr(0, 1200);
}

TEST_F(CliClock, IgnoreTimingPassesThroughASweepIntoEveryRowItConcerns) {
    const Result r = run("sweep --board adm-xrc-ii --scene spheres --objects 200 --frames 1 --quiet --ignore-timing "
                         "--set board.clock_mhz=66,500 --out res");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string csv = slurp(dir_ / "res" / "sweep.csv");
    const std::string header = csv.substr(0, csv.find('\n'));
    ASSERT_NE(header.find("timing_warning"), std::string::npos) << header;
    // The 66 MHz point meets its clock; the 500 MHz point's row carries the warning.
    EXPECT_NE(csv.find("500.0 MHz is beyond the "), std::string::npos) << csv.substr(0, 2000);
    EXPECT_EQ(csv.find("66.0 MHz is beyond the "), std::string::npos);
    // Without --ignore-timing the 500 MHz point is refused, naming the limit.
    const Result refused = run("sweep --board adm-xrc-ii --scene spheres --objects 200 --frames 1 --quiet "
                               "--set board.clock_mhz=66,500 --out res2");
    const std::string refused_csv = slurp(dir_ / "res2" / "sweep.csv");
    EXPECT_NE(refused_csv.find("refused"), std::string::npos) << refused_csv.substr(0, 2000);
    EXPECT_NE(refused_csv.find("--ignore-timing runs it anyway"), std::string::npos) << refused_csv.substr(0, 2000);
}

TEST_F(CliClock, EveryPresetRunsAtItsOwnClock) {
    for (const auto& entry : std::filesystem::directory_iterator(CDVP_SOURCE_DIR "/platform/boards")) {
        const std::string name = entry.path().stem().string();
        const Result r = run(spheres(name) + "--report r.json");
        ASSERT_EQ(r.status, 0) << name << ": " << r.err;
        EXPECT_EQ(r.err, "") << name;
        const json t = timing();
        const json config = report_of(dir_ / "r.json")["config"];
        EXPECT_TRUE(t["meets_clock"].get<bool>()) << name;
        EXPECT_GE(t["fmax_mhz"].get<double>(), config["clock_mhz"].get<double>()) << name;
        // The fit line names the estimate and the piece that sets it.
        EXPECT_NE(r.out.find("; Fmax about " + mhz(t["fmax_mhz"]) + " at speed grade -" +
                             std::to_string(t["speed_grade"].get<int>()) + " (its " +
                             t["limited_by"].get<std::string>() + ", "),
                  std::string::npos)
            << name << ": " << r.out.substr(0, 600);
        // Each piece with its path, every one held to the clock on the seed's
        // board, and the whole board as one design among them.
        for (const auto& [key, piece] : t["pieces"].items()) EXPECT_GT(piece["path_ns"].get<double>(), 0) << name;
        EXPECT_FALSE(t.contains("awaiting_pipelining")) << name;
        EXPECT_TRUE(t["pieces"].contains("whole_board")) << name;
        EXPECT_EQ(t["fmax_from"], "every piece and the whole board as one design") << name;
    }
}

TEST_F(CliClock, TheSpeedGradeComesFromTheDeviceName) {
    ASSERT_EQ(run(spheres("adm-xrc-ii") + "--quiet --report r.json").status, 0);
    const double slow = timing()["fmax_mhz"];
    ASSERT_EQ(run(spheres("adm-xrc-ii") + "--quiet --report r.json -c device.name=XC2V6000-6").status, 0);
    EXPECT_EQ(timing()["speed_grade"], 6);
    EXPECT_EQ(timing()["speed_grade_from"], "device name");
    EXPECT_GT(timing()["fmax_mhz"].get<double>(), slow);
    expect_refusal(run(spheres("adm-xrc-ii") + "--quiet -c device.name=XC2V6000-7"),
                   "cdvp run: -c device.name: speed grade -7 of XC2V6000-7: the xc2v timing has -4, -5 or -6\n");
}

// The grid board's fit line names its slowest piece once as written (its
// pieces are named plainly; the line says how they are written).
TEST_F(CliClock, TheGridBoardsFitLineNamesItsSlowestPieceAsWrittenOnce) {
    const Result r = run(spheres("adm-xrc-ii") + "-c board.algorithm=grid --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("; its binning sequencer as written: "), std::string::npos) << r.out.substr(0, 800);
    EXPECT_EQ(r.out.find("as written as written"), std::string::npos) << r.out.substr(0, 800);
    EXPECT_EQ(timing()["as_written_limited_by"], "binning sequencer");
}

}  // namespace
}  // namespace cdvp::test
