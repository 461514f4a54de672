// `cdvp calibrate` and the host profile a run then uses; runs without one say
// they are uncalibrated; and one vocabulary for times: every *_ns field of a
// report and every *_ns column of sweep.csv says whether it is native,
// modelled-host or simulated time.
#include <set>

#include <nlohmann/json.hpp>

#include "sw/study/sweep_csv.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

// The simulated-time fields (docs/timing.md, "One vocabulary"): the
// platform's phases (cdvp bullet's board too), what extra pairs cost, the
// settings of the model given in ns, and the board's estimated path delays.
const std::set<std::string> kSimulatedTimeFields = {
    "upload_ns", "start_ns", "compute_ns", "irq_ns", "readback_ns", "driver_ns", "total_ns", "overlap_ns", "latency_ns",
    "extra_readback_ns", "extra_driver_ns", "quantum_ns", "interrupt_ns", "host_pio_overhead_ns",
    "read_round_trip_ns", "posted_write_ns", "ns_per_box", "ns_per_pair", "call_ns", "poll_gap_ns", "poll_gap_max_ns",
    "timeout_floor_ns", "path_ns"};

// A key of a time: "mean_upload_ns" -> "upload_ns", "host.call_ns" -> "call_ns".
std::string time_field(std::string key) {
    if (const std::size_t dot = key.rfind('.'); dot != std::string::npos) key = key.substr(dot + 1);
    for (const char* figure : {"mean_", "p50_", "p99_", "max_", "median_", "run_means_"}) {
        if (key.rfind(figure, 0) == 0) return key.substr(std::string(figure).size());
    }
    return key;
}

bool names_its_clock(const std::string& key) {
    const auto ends = [&](const std::string& end) {
        return key.size() >= end.size() && key.compare(key.size() - end.size(), end.size(), end) == 0;
    };
    // A frame's baselines.NAME holds native_ns and host_ns themselves.
    return key == "native_ns" || key == "host_ns" || ends("_native_ns") || ends("_host_ns") ||
           kSimulatedTimeFields.count(time_field(key)) != 0;
}

// Every key of 'value' that mentions ns, and whether it names its clock.
void check_time_keys(const json& value, const std::string& where, std::size_t& checked) {
    if (value.is_array()) {
        for (const json& item : value) check_time_keys(item, where, checked);
        return;
    }
    if (!value.is_object()) return;
    for (const auto& [key, item] : value.items()) {
        if (key.find("ns") != std::string::npos && (key.size() > 3 && key.compare(key.size() - 3, 3, "_ns") == 0)) {
            EXPECT_TRUE(names_its_clock(key)) << where << ": " << key << " says neither native, host nor simulated";
            ++checked;
        }
        check_time_keys(item, where, checked);
    }
}

class CliCalibrate : public Cli {
protected:
    Result calibrate(const std::string& args = "--out p.json") { return run("calibrate --repeat 1 -q " + args); }
    json report(const std::string& name) { return report_of(dir_ / name); }
    const std::string kRun = "run --board adm-xrc-ii --scene spheres --objects 60 --frames 4 --m 4 --baseline sap,soa ";
};

TEST_F(CliCalibrate, WritesAProfileThatARunThenReportsUsing) {
    const Result c = calibrate();
    ASSERT_EQ(c.status, 0) << c.err;
    const json profile = report("p.json");
    EXPECT_EQ(profile["format"], "cdvp host profile");
    EXPECT_FALSE(profile["machine"]["cpu_model"].get<std::string>().empty());
    EXPECT_FALSE(profile["build"]["compiler"].get<std::string>().empty());
    EXPECT_EQ(profile["reference"]["sap"]["sizes"].size(), 3u);
    EXPECT_GT(profile["reference"]["brute"]["reference_native_ns"].get<double>(), 0);
    EXPECT_GT(profile["factors"]["adm-xrc-ii"]["sap"].get<double>(), 0) << "the factor to each preset's host";

    const Result r = run(kRun + "--host-profile p.json --report r.json -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "") << "a calibrated run has nothing to say";
    const json j = report("r.json");
    const json& calibration = j["config"]["host_calibration"];
    EXPECT_EQ(calibration["basis"], "calibrated");
    EXPECT_EQ(j["config"]["provenance"]["host_profile"]["path"], "p.json");
    EXPECT_EQ(j["config"]["provenance"]["host_profile"]["sha256"].get<std::string>().size(), 64u);
    // The factor is the preset's reference time over the profile's.
    const json paper = json::parse(slurp(preset("adm-xrc-ii")));
    const double expected = paper["host"]["reference_sap_host_ns"]["value"].get<double>() /
                            profile["reference"]["sap"]["reference_native_ns"].get<double>();
    EXPECT_DOUBLE_EQ(calibration["factors"]["sap"].get<double>(), expected);
    const json& sap = j["summary"]["baselines"]["sap"];
    EXPECT_DOUBLE_EQ(sap["host_factor"].get<double>(), expected);
    EXPECT_DOUBLE_EQ(sap["mean_host_ns"].get<double>(), expected * sap["mean_native_ns"].get<double>());
}

TEST_F(CliCalibrate, WithoutAProfileARunSaysOnceThatItIsUncalibrated) {
    const Result r = run(kRun + "--report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("cdvp run: host factor 4 for pentium4-1.8 is the preset's uncalibrated estimate: no host "
                          "profile at " + (dir_ / ".config" / "cdvp" / "host-profile.json").string(), 0),
              0u)
        << r.err;
    EXPECT_NE(r.out.find("native x 4 (the preset's uncalibrated estimate)"), std::string::npos) << r.out;
    const json j = report("r.json");
    EXPECT_EQ(j["config"]["host_calibration"]["basis"], "uncalibrated");
    EXPECT_EQ(j["config"]["provenance"]["host_profile"], "uncalibrated");
    EXPECT_DOUBLE_EQ(j["summary"]["baselines"]["sap"]["host_factor"].get<double>(), 4);
}

TEST_F(CliCalibrate, TheDefaultLocationIsFoundAndHostFactorOverridesIt) {
    const Result c = run("calibrate --repeat 1 -q");
    ASSERT_EQ(c.status, 0) << c.err;
    ASSERT_TRUE(fs::exists(dir_ / ".config" / "cdvp" / "host-profile.json"));
    ASSERT_EQ(run(kRun + "--report r.json -q").status, 0);
    EXPECT_EQ(report("r.json")["config"]["host_calibration"]["basis"], "calibrated");
    const Result given = run(kRun + "--host-factor 2.5 --report g.json");
    ASSERT_EQ(given.status, 0) << given.err;
    EXPECT_EQ(given.err, "");
    const json g = report("g.json");
    EXPECT_EQ(g["config"]["host_calibration"]["basis"], "overridden");
    EXPECT_DOUBLE_EQ(g["summary"]["baselines"]["soa"]["host_factor"].get<double>(), 2.5);
}

TEST_F(CliCalibrate, ADamagedOrMissingProfileIsRefusedOnOneLine) {
    ASSERT_EQ(calibrate().status, 0);
    json damaged = report("p.json");
    damaged["reference"]["dbvt"]["reference_native_ns"] = "fast";
    write("bad.json", damaged.dump());
    expect_refusal(run(kRun + "--host-profile bad.json"), "cdvp run: bad.json: reference.dbvt.reference_native_ns: expected a number");
    expect_refusal(run(kRun + "--host-profile missing.json"), "cdvp run: --host-profile: missing.json: no such file");
    write("foreign.json", "{\"name\": \"adm-xrc-ii\"}");
    expect_refusal(run("bullet --scene stack --objects 10 --board adm-xrc-ii --host-profile foreign.json"),
                   "cdvp bullet: foreign.json: format: missing");
    expect_refusal(run("calibrate --repeat 0"), "cdvp calibrate: --repeat: expected");
}

TEST_F(CliCalibrate, EveryTimeFieldOfAReportAndASweepSaysItsClock) {
    std::size_t checked = 0;
    ASSERT_EQ(run(kRun + "--format fixed16 --repeat 2 --report r.json -q").status, 0);
    check_time_keys(report("r.json"), "cdvp run's report", checked);
    ASSERT_EQ(run("bullet --scene stack --objects 10 --frames 3 --board adm-xrc-ii -q --report b.json").status, 0);
    check_time_keys(report("b.json"), "cdvp bullet's report", checked);
    ASSERT_EQ(run("sweep --board adm-xrc-ii --set objects=20,40 --m 2 --frames 3 --baseline sap --no-plots -q --out s")
                  .status,
              0);
    const auto rows = parse_csv(slurp(dir_ / "s" / "sweep.csv"), "sweep.csv");
    json columns = json::object();
    for (const std::string& column : rows[0]) columns[column] = 0;
    check_time_keys(columns, "sweep.csv", checked);
    EXPECT_GT(checked, 60u) << "the reports and the sweep have many time fields";
    for (const char* column : {"sap_mean_host_ns", "sap_p50_host_ns", "sap_p99_host_ns", "sap_max_host_ns",
                               "sap_speedup", "sap_host_factor", "mean_total_ns", "config.provenance.cpu_model",
                               "config.provenance.git_commit", "config.host_calibration.basis", "load_average_end"}) {
        EXPECT_TRUE(columns.contains(column)) << column;
    }
    EXPECT_FALSE(columns.contains("sap_median_ns")) << "the old, ambiguous name";
}

}  // namespace
}  // namespace cdvp::test
