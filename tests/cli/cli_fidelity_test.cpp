// `cdvp fidelity`: every level run, the CSV and the plot written together,
// bad input refused like `cdvp run` refuses it.
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::vector<std::string> fields;
        std::istringstream cells(line);
        std::string cell;
        while (std::getline(cells, cell, ',')) fields.push_back(cell);
        rows.push_back(fields);
    }
    return rows;
}

TEST_F(Cli, FidelityRunsEveryLevelAndWritesTheTableAndThePlot) {
    // A loaded PCI bus, polling, pair-buffer pauses and a pyramid's bursts of
    // contacts in a 15-pair FIFO: the formula misses the load, the analytic
    // level the stalls of the bursts; the engines are exact.
    const Result r = run("fidelity --scene pyramid --frames 3 --board adm-xrc-ii --m 8 --fifo-depth 15 --pair-buffer 128 "
                         "--wait poll -c bus.load_bytes_per_s=20e6 --out results/fidelity");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const auto rows = csv_rows(slurp(dir_ / "results" / "fidelity" / "fidelity.csv"));
    ASSERT_EQ(rows.size(), 17u) << "a header and sixteen levels";
    const std::vector<std::string>& header = rows[0];
    auto column = [&](const std::string& name) {
        const auto at = static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
        if (at == header.size()) ADD_FAILURE() << "fidelity.csv has no column " << name;
        return std::min(at, header.size() - 1);
    };
    auto error = [&](std::size_t row) { return std::stod(rows[row][column("error_total_percent")]); };
    EXPECT_EQ(rows[1][column("fidelity")], "cycle");
    EXPECT_EQ(rows[1][column("bus_model")], "transaction");
    for (std::size_t k = 1; k < rows.size(); ++k) {
#ifndef CDVP_RTL_BUILT
        if (rows[k][column("fidelity")] == "rtl") {  // a build without Verilator's board models
            EXPECT_EQ(rows[k].back(), "not run") << "level " << k;
            continue;
        }
#endif
        EXPECT_EQ(rows[k][column("frames_in_means")], "1") << "three frames less the default two of warm-up";
        EXPECT_GT(std::stod(rows[k][column("mean_sim_wall_native_ns")]), 0.0);
        EXPECT_GT(std::stod(rows[k][column("mean_total_ns")]), 0.0);
        EXPECT_EQ(rows[k][column("pairs_identical")], "yes") << "level " << k;
        // Every level gives the board's energy a frame, and its parts add up (docs/energy.md).
        const double energy = std::stod(rows[k][column("mean_energy_j")]);
        EXPECT_GT(energy, 0.0) << "level " << k;
        double parts = 0;
        for (const char* part : {"static", "dynamic", "bus", "host"}) {
            parts += std::stod(rows[k][column(std::string("mean_energy_") + part + "_j")]);
        }
        EXPECT_NEAR(parts, energy, energy * 1e-6) << "level " << k;
        const bool formula = rows[k][column("bus_model")] == "formula";
        const bool engine = rows[k][column("fidelity")] != "analytic";
        if (engine && !formula) {
            EXPECT_EQ(error(k), 0.0) << "level " << k << ": the engines are exact at any quantum";
        }
        if (formula) {
            EXPECT_GT(error(k), 1.0) << "level " << k << ": the formula times an idle bus";
        }
    }
    // The RTL (a built variant: m=8, fifo=15, buffer=128) runs next to the clocked engine, exact.
    EXPECT_EQ(rows[3][column("fidelity")], "rtl");
    EXPECT_EQ(rows[3][column("bus_model")], "transaction");
    EXPECT_EQ(rows[15][column("fidelity")], "analytic");
    EXPECT_GT(error(15), 0.1) << "the analytic level's FIFO stalls are estimated";
    EXPECT_LT(error(15), 5.0);
    EXPECT_EQ(std::stod(rows[15][column("error_upload_percent")]), 0.0) << "the upload is exact at the analytic level";
    const std::string png = slurp(dir_ / "results" / "fidelity" / "fidelity.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    EXPECT_NE(r.out.find("cycle transaction q=0ns"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("identical"), std::string::npos) << r.out;
}

// A level's figures are its run's: the simulated means over the frames after
// the warm-up, as `cdvp run --report` summarises the same run.
TEST_F(Cli, FidelityTakesEachLevelsFiguresFromItsRunsSummaryAfterTheWarmup) {
    const std::string scene = "--scene spheres --objects 120 --frames 5 --warmup 2 --board adm-xrc-ii --m 2 --drain-rate 2";
    const Result f = run("fidelity " + scene + " --out fid -q");
    ASSERT_EQ(f.status, 0) << f.err;
    const Result r = run("run " + scene + " --fidelity cycle --report r.json -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json summary = report_of(dir_ / "r.json")["summary"];
    const auto rows = csv_rows(slurp(dir_ / "fid" / "fidelity.csv"));
    ASSERT_EQ(rows.size(), 17u);
    const std::vector<std::string>& header = rows[0];
    // The RTL moves one pair a cycle into the pair buffer: the rtl rows say they did not run.
    for (std::size_t k : {3u, 4u}) {
        EXPECT_EQ(rows[k][1], "rtl");
        EXPECT_EQ(rows[k].back(), "not run") << "row " << k;
    }
    EXPECT_NE(slurp(dir_ / "fid" / "fidelity.csv").find(",0" + std::string(23, ',') + "not run\n"), std::string::npos);
    for (const char* name : {"frames_in_means", "mean_total_ns", "mean_compute_ns", "mean_upload_ns"}) {
        const auto at = static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
        ASSERT_LT(at, header.size()) << name;
        const double expected = summary.at(name).get<double>();
        EXPECT_NEAR(std::stod(rows[1][at]), expected, 1e-9 * std::fabs(expected)) << name;
    }
    EXPECT_EQ(summary.at("frames_in_means").get<int>(), 3) << "five frames less two of warm-up";
}

TEST_F(Cli, FidelityRefusesBadInputWithOneLineAndWritesNothing) {
    struct Case {
        const char* args;
        const char* message;
    } cases[] = {
        {"fidelity --scene spheres --objects 10", "cdvp fidelity: --out DIR is required"},
        {"fidelity --scene spheres --objects 10 --out r --vcd w.vcd", "cdvp fidelity: --vcd: set by cdvp fidelity"},
        {"fidelity --scene spheres --objects 10 --out r/deeper --m 0", "cdvp fidelity: --m"},
        {"fidelity --trace missing.csv --out r", "cdvp fidelity: missing.csv: cannot open"},
    };
    for (const Case& c : cases) {
        expect_refusal(run(c.args), c.message, c.args);
        EXPECT_FALSE(fs::exists(dir_ / "r")) << c.args << ": a failed run leaves no directory either";
    }
}

// A trace from a pipe is read once and given to every level.
TEST_F(Cli, FidelityReadsATraceFromAPipeOnce) {
    ASSERT_EQ(mkfifo((dir_ / "pipe").c_str(), 0600), 0);
    const Result r = run("fidelity --trace pipe --out r -q",
                         "(cat '" + trace("small.csv") + "' > pipe &) ;");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string csv = slurp(dir_ / "r" / "fidelity.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 17) << csv;
    EXPECT_EQ(csv.find(",no\n"), std::string::npos) << "every level saw the same frames: " << csv;
}

TEST_F(Cli, FidelityNeverWritesOverItsInputs) {
    fs::create_directories(dir_ / "d");
    const std::string original = slurp(trace("small.csv"));
    write("d/fidelity.csv", original);
    const Result r = run("fidelity --trace d/fidelity.csv --out d");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("--trace"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(slurp(dir_ / "d" / "fidelity.csv"), original) << "the input is untouched";
    EXPECT_FALSE(fs::exists(dir_ / "d" / "fidelity.png"));
    const Result file = run("fidelity --scene spheres --objects 10 --out d/fidelity.csv");
    EXPECT_EQ(file.status, 2);
    EXPECT_EQ(file.err.rfind("cdvp fidelity: --out: d/fidelity.csv: expected a directory", 0), 0u) << file.err;
}

}  // namespace
}  // namespace cdvp::test
