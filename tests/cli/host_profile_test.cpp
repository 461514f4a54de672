// Host profiles and host factors without processes: the profile written and
// read back, damaged and foreign profiles refused naming file and field, and
// the factor derived from a preset's reference times and a profile's.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "sw/run/host_factor.h"
#include "sw/timing/spread.h"
#include "sw/run/host_profile.h"
#include "sw/run/reference_workload.h"

namespace cdvp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A profile of this machine in which every baseline's reference time is 'ns'
// at each size, except as 'edit' changes it.
HostProfile profile_of(double ns, const std::function<void(HostProfile&)>& edit = {}) {
    HostProfile p;
    p.created = "2025-01-01T00:00:00Z";
    p.machine.cpu_model = "Test CPU";
    p.machine.cpu_mhz = 2600;
    p.build = {"0.1.0", "abc", "GNU 12.2.0", "Release", "-O3"};
    p.repeat = 3;
    p.runs = 4;
    p.spread = 0.01;
    p.target_spread = 0.03;
    p.load_average_start = {0.5, 0.25, 0.125};
    for (const std::string& name : reference_workload::baselines()) {
        BaselineReference& b = p.reference[name];
        for (const uint64_t objects : reference_workload::objects()) {
            // Four runs, one disturbed (x 1.5): the three kept lie within 1%.
            b.sizes.push_back({objects, {ns, ns * 1.5, ns * 1.01, ns}, {ns, ns, ns * 1.01}, ns});
        }
        b.reference_native_ns = ns;
    }
    if (edit) edit(p);
    return p;
}

HostConfig paper_host(double reference_ns) {
    HostConfig host;
    host.name = "pentium4-1.8";
    host.speed_factor = 4;
    host.reference_sap_host_ns = host.reference_dbvt_host_ns = host.reference_brute_host_ns =
        host.reference_soa_host_ns = reference_ns;
    return host;
}

class HostProfileFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("cdvp-profile-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        path_ = (dir_ / "profile.json").string();
    }
    void TearDown() override { fs::remove_all(dir_); }
    void write(const std::string& text) { std::ofstream(path_, std::ios::binary) << text; }
    json written(const HostProfile& p) { return json::parse(host_profile_json(p)); }
    // The one-line refusal of a profile with 'change' applied to its JSON.
    std::string refusal(const std::function<void(json&)>& change) {
        json j = written(profile_of(1000));
        change(j);
        write(j.dump(2));
        try {
            read_host_profile(path_);
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
            return what;
        }
        ADD_FAILURE() << "accepted: " << j.dump();
        return {};
    }
    fs::path dir_;
    std::string path_;
};

TEST_F(HostProfileFile, WhatIsWrittenReadsBack) {
    write(host_profile_json(profile_of(1234.5)));
    const HostProfile read = read_host_profile(path_);
    EXPECT_EQ(read.machine.cpu_model, "Test CPU");
    EXPECT_EQ(read.created, "2025-01-01T00:00:00Z");
    EXPECT_EQ(read.repeat, 3u);
    EXPECT_EQ(read.build.flags, "-O3");
    ASSERT_EQ(read.reference.size(), reference_workload::baselines().size());
    EXPECT_EQ(read.reference.count("sap_mt"), 1u) << "calibrated like the others";
    EXPECT_DOUBLE_EQ(read.reference.at("dbvt").reference_native_ns, 1234.5);
    EXPECT_EQ(read.sha256.size(), 64u);
    const json j = written(profile_of(1000));
    EXPECT_EQ(j["workload"]["objects"], json(reference_workload::objects()));
    EXPECT_NEAR(j["reference"]["sap"]["sizes"][0]["spread"].get<double>(), 0.01, 1e-12) << "max/min - 1 of the kept runs";
    EXPECT_EQ(j["calibration"]["clock"], "thread CPU time");
    EXPECT_EQ(j["calibration"]["quality"], "good");
    EXPECT_EQ(read.runs, 4u);
    EXPECT_DOUBLE_EQ(read.spread, 0.01);
    EXPECT_DOUBLE_EQ(read.target_spread, 0.03);
    EXPECT_DOUBLE_EQ(read.load_average_start[1], 0.25);
    ASSERT_EQ(read.reference.at("sap").sizes.size(), reference_workload::objects().size());
    EXPECT_NEAR(read.reference.at("sap").sizes[0].spread(), 0.01, 1e-12) << "the kept runs are read back";
}

TEST_F(HostProfileFile, APoorProfileIsWrittenSoAndARunOnItSaysSo) {
    const HostProfile poor = profile_of(1000, [](HostProfile& p) { p.spread = 0.076; });
    EXPECT_TRUE(poor.poor());
    EXPECT_FALSE(profile_of(1000).poor());
    EXPECT_EQ(written(poor)["calibration"]["quality"], "poor");
    write(host_profile_json(poor));
    HostConfig host = paper_host(4000);
    host.profile = path_;
    const HostTiming timing = resolve_host_timing(host, false);
    EXPECT_TRUE(timing.profile_poor());
    EXPECT_EQ(uncalibrated_note(timing), "host factors rest on a poor profile, " + path_ +
                                             ": its runs stayed 7.6% apart, over the 3.0% it was asked for, at load "
                                             "0.50 (cdvp calibrate on a quieter machine; docs/timing.md)");
}

TEST_F(HostProfileFile, ACalibrationSectionOutOfRangeIsRefused) {
    EXPECT_EQ(refusal([](json& j) { j["calibration"].erase("spread"); }), path_ + ": calibration.spread: missing");
    EXPECT_EQ(refusal([](json& j) { j["calibration"]["runs"] = 1; }).rfind(path_ + ": calibration.runs: expected a number from 3", 0), 0u)
        << "fewer runs than it kept";
    EXPECT_EQ(refusal([](json& j) { j["load_average"]["start"] = {1, 2}; }),
              path_ + ": load_average.start: expected the 1, 5 and 15 minute load averages");
    EXPECT_EQ(refusal([](json& j) { j["reference"]["dbvt"]["sizes"][1].erase("kept_means_native_ns"); }),
              path_ + ": reference.dbvt.sizes.1.kept_means_native_ns: expected a list of times");
}

TEST_F(HostProfileFile, ADamagedProfileIsRefusedNamingFileAndField) {
    EXPECT_EQ(refusal([](json& j) { j["reference"]["sap"].erase("reference_native_ns"); }),
              path_ + ": reference.sap.reference_native_ns: missing");
    EXPECT_EQ(refusal([](json& j) { j["reference"]["soa"]["reference_native_ns"] = -3; }).rfind(
                  path_ + ": reference.soa.reference_native_ns: expected a number from 0 to", 0),
              0u);
    EXPECT_EQ(refusal([](json& j) { j["reference"]["brute"]["reference_native_ns"] = 0; }),
              path_ + ": reference.brute.reference_native_ns: expected a positive time, got 0");
    EXPECT_EQ(refusal([](json& j) { j["machine"]["cpu_model"] = 7; }), path_ + ": machine.cpu_model: expected a string");
    EXPECT_EQ(refusal([](json& j) { j.erase("created"); }), path_ + ": created: missing");
    write("{\"format\": ");
    EXPECT_THROW(read_host_profile(path_), InputError);
    write("");
    try {
        read_host_profile(path_);
        ADD_FAILURE() << "an empty file accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path_ + ":", 0), 0u) << e.what();
    }
}

TEST_F(HostProfileFile, AForeignProfileIsRefused) {
    EXPECT_EQ(refusal([](json& j) { j["format"] = "something else"; }),
              path_ + ": format: expected \"cdvp host profile\"");
    EXPECT_EQ(refusal([](json& j) { j["format_version"] = 1; }),
              path_ + ": format_version: expected 2 (a profile of another cdvp version: run cdvp calibrate again)")
        << "a profile timed in wall time, before CPU time";
    EXPECT_EQ(refusal([](json& j) { j["workload"]["objects"] = {100, 500}; })
                  .rfind(path_ + ": workload.objects: a profile of another reference workload ([100,500], this cdvp "
                                 "times [100,500,2000]): run cdvp calibrate again",
                         0),
              0u);
    EXPECT_EQ(refusal([](json& j) { j["workload"]["seed"] = 2; }).rfind(path_ + ": workload.seed: ", 0), 0u);
    EXPECT_EQ(refusal([](json& j) { j = json::array(); }), path_ + ": expected a JSON object");
}

// A profile of the first workload, before sap_mt joined it, still
// calibrates the baselines it timed; sap_mt takes its overall factor. A
// version this cdvp does not know is another workload's.
TEST_F(HostProfileFile, AProfileOfTheFirstWorkloadCalibratesAllButSapMt) {
    json j = written(profile_of(1000, [](HostProfile& p) { p.reference["sap"].reference_native_ns = 500; }));
    j["workload"]["version"] = reference_workload::kFirstVersion;
    j["workload"]["baselines"] = reference_workload::first_version_baselines();
    j["reference"].erase("sap_mt");
    write(j.dump(2));
    const HostProfile first = read_host_profile(path_);
    EXPECT_EQ(first.reference.count("sap_mt"), 0u);
    HostConfig host = paper_host(4000);
    host.reference_sap_mt_host_ns = 4000;
    const std::map<std::string, double> factors = derive_factors(host, first);
    EXPECT_DOUBLE_EQ(factors.at("sap"), 8);
    EXPECT_EQ(factors.count("sap_mt"), 0u) << "not timed: the overall factor stands in";
    HostTiming timing;
    timing.factors = factors;
    timing.overall = factors.at("overall");
    EXPECT_DOUBLE_EQ(timing.factor("sap_mt"), factors.at("overall"));
    EXPECT_EQ(refusal([](json& w) { w["workload"]["version"] = reference_workload::kVersion + 1; })
                  .rfind(path_ + ": workload.version: a profile of another reference workload", 0),
              0u);
    EXPECT_EQ(refusal([](json& w) { w["workload"]["version"] = reference_workload::kFirstVersion; })
                  .rfind(path_ + ": workload.baselines: a profile of another reference workload", 0),
              0u)
        << "the first workload did not time sap_mt";
}

// With sap_mt on one thread in the workload and in the preset, its factor
// is its own, like the other baselines'.
TEST(HostFactor, SapMtIsCalibratedLikeTheOthers) {
    const HostProfile profile = profile_of(1000, [](HostProfile& p) { p.reference["sap_mt"].reference_native_ns = 2000; });
    HostConfig host = paper_host(4000);
    host.reference_sap_mt_host_ns = 4000;
    const std::map<std::string, double> factors = derive_factors(host, profile);
    EXPECT_DOUBLE_EQ(factors.at("sap_mt"), 2);
    EXPECT_DOUBLE_EQ(factors.at("sap"), 4);
    EXPECT_NEAR(factors.at("overall"), std::pow(4.0 * 4 * 4 * 4 * 2, 0.2), 1e-12);
}

TEST(HostFactor, IsTheHostsReferenceTimeOverThisMachinesPerBaseline) {
    const HostProfile profile = profile_of(1000, [](HostProfile& p) { p.reference["sap"].reference_native_ns = 500; });
    const std::map<std::string, double> factors = derive_factors(paper_host(4000), profile);
    EXPECT_DOUBLE_EQ(factors.at("dbvt"), 4);
    EXPECT_DOUBLE_EQ(factors.at("sap"), 8) << "this machine runs sap twice as fast: twice the factor";
    // The overall factor is the geometric mean of the four: (8 * 4 * 4 * 4)^(1/4).
    EXPECT_NEAR(factors.at("overall"), std::pow(8.0 * 4 * 4 * 4, 0.25), 1e-12);
}

TEST(HostFactor, TheReferenceMachinesProfileGivesThePresetsFactorBack) {
    // The shipped presets state 4 x the reference machine's times: its own
    // profile must give 4 for every baseline.
    const HostProfile reference = profile_of(0, [](HostProfile& p) {
        double ns = 100;
        for (auto& [name, b] : p.reference) b.reference_native_ns = ns *= 3;
    });
    HostConfig host = paper_host(0);
    host.reference_sap_host_ns = 4 * reference.reference.at("sap").reference_native_ns;
    host.reference_dbvt_host_ns = 4 * reference.reference.at("dbvt").reference_native_ns;
    host.reference_brute_host_ns = 4 * reference.reference.at("brute").reference_native_ns;
    host.reference_soa_host_ns = 4 * reference.reference.at("soa").reference_native_ns;
    for (const auto& [name, factor] : derive_factors(host, reference)) EXPECT_DOUBLE_EQ(factor, 4) << name;
}

TEST(HostFactor, ABaselineTheHostStatesNoTimeForTakesTheOverallFactor) {
    HostConfig host = paper_host(2000);
    host.reference_soa_host_ns = 0;
    const std::map<std::string, double> factors = derive_factors(host, profile_of(1000));
    EXPECT_EQ(factors.count("soa"), 0u);
    EXPECT_DOUBLE_EQ(factors.at("overall"), 2);
}

TEST_F(HostProfileFile, ARunIsCalibratedByTheProfileItFindsAndOverriddenByAGivenFactor) {
    ::setenv("XDG_CONFIG_HOME", (dir_ / "config").c_str(), 1);
    HostConfig host = paper_host(4000);
    HostTiming timing = resolve_host_timing(host, false);
    EXPECT_EQ(timing.basis, HostTiming::Basis::kUncalibrated) << "no profile at the default location";
    EXPECT_DOUBLE_EQ(timing.factor("sap"), 4);
    EXPECT_EQ(timing.profile_path, (dir_ / "config" / "cdvp" / "host-profile.json").string());
    EXPECT_NE(uncalibrated_note(timing).find("uncalibrated estimate: no host profile at " + timing.profile_path),
              std::string::npos);

    fs::create_directories(dir_ / "config" / "cdvp");
    std::ofstream(timing.profile_path) << host_profile_json(profile_of(500));
    timing = resolve_host_timing(host, false);
    EXPECT_EQ(timing.basis, HostTiming::Basis::kCalibrated) << "the default location";
    EXPECT_DOUBLE_EQ(timing.factor("sap"), 8);
    EXPECT_DOUBLE_EQ(timing.overall, 8);
    EXPECT_EQ(timing.profile_sha256.size(), 64u);
    EXPECT_EQ(uncalibrated_note(timing), "");

    host.profile = path_;
    write(host_profile_json(profile_of(2000)));
    EXPECT_DOUBLE_EQ(resolve_host_timing(host, false).factor("brute"), 2) << "--host-profile over the default";

    host.speed_factor = 3;
    timing = resolve_host_timing(host, true);
    EXPECT_EQ(timing.basis, HostTiming::Basis::kOverridden);
    EXPECT_DOUBLE_EQ(timing.factor("sap"), 3) << "--host-factor overrides every profile";

    host.profile = (dir_ / "missing.json").string();
    EXPECT_THROW(resolve_host_timing(host, false), InputError) << "a profile named must be there";
    ::unsetenv("XDG_CONFIG_HOME");
}

TEST_F(HostProfileFile, AHostWithoutReferenceTimesKeepsItsSpeedFactorButANamedProfileIsStillChecked) {
    HostConfig host;  // no preset: this machine, x 1
    const HostTiming timing = resolve_host_timing(host, false);
    EXPECT_EQ(timing.basis, HostTiming::Basis::kUnstated);
    EXPECT_DOUBLE_EQ(timing.factor("sap"), 1);
    write("{}");
    host.profile = path_;
    EXPECT_THROW(resolve_host_timing(host, false), InputError);
    write(host_profile_json(profile_of(500)));
    EXPECT_EQ(resolve_host_timing(host, false).basis, HostTiming::Basis::kUnstated);
}

// A reference time that gives a factor outside host.speed_factor's range
// (0.001 to 1000) describes no machine: tiny, denormal, huge; 0, negative,
// inf and nan are refused as numbers. Refused on one line naming the file,
// the field and the times expected; no factor is ever inf.
TEST_F(HostProfileFile, AReferenceTimeGivingAnAbsurdFactorIsRefusedNamingFieldAndRange) {
    HostConfig host = paper_host(360470);
    host.profile = path_;
    for (const double ns : {1e-300, 4.9e-324, 1e-3, 360.0, 3.7e8, 1e12}) {
        write(host_profile_json(profile_of(1000, [ns](HostProfile& p) { p.reference["sap"].reference_native_ns = ns; })));
        try {
            resolve_host_timing(host, false);
            ADD_FAILURE() << ns << " ns accepted";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path_ + ": reference.sap.reference_native_ns: ", 0), 0u) << what;
            EXPECT_NE(what.find("expected a time from 360.47 to 360470000 ns, a factor of 0.001 to 1000"),
                      std::string::npos) << what;
            EXPECT_EQ(what.find("inf"), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
    for (const double ns : {361.0, 3.6e8}) {
        write(host_profile_json(profile_of(1000, [ns](HostProfile& p) { p.reference["sap"].reference_native_ns = ns; })));
        EXPECT_TRUE(std::isfinite(resolve_host_timing(host, false).factor("sap"))) << ns << " ns: in range";
    }
    for (const char* bad : {"0", "-5", "1e13", "\"nan\""}) {
        const std::string what = refusal([bad](json& j) { j["reference"]["sap"]["reference_native_ns"] = json::parse(bad); });
        EXPECT_NE(what.find("reference.sap.reference_native_ns: expected a"), std::string::npos) << bad << ": " << what;
    }
}

// No ratio a summary or report shows is inf or nan, whatever its parts.
TEST(FiniteRatio, IsZeroWhereTheRatioIsUndefined) {
    EXPECT_DOUBLE_EQ(finite_ratio(6, 3), 2);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto& [n, d] : std::vector<std::pair<double, double>>{{1, 0}, {0, 0}, {1, -2}, {inf, 1}, {nan, 1},
                                                                      {1, nan}, {1e300, 1e-300}, {1, inf}}) {
        EXPECT_EQ(finite_ratio(n, d), 0.0) << n << " / " << d;
    }
    EXPECT_EQ(speedup(Spread{1e308, 0, 0, 0, 1}, Spread{1e-308, 0, 0, 0, 1}), 0.0);
}

}  // namespace
}  // namespace cdvp
