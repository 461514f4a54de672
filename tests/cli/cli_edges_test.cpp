// The command line at its edges, by class: settings that cdvp run refuses
// are refused by cdvp settings in the same words; inputs that cannot be
// opened say why (a link loop, a directory) with the path; an empty path is
// refused as empty; a host profile or a bus load beyond what a machine could
// be is refused naming the field and the range; --fidelity auto says which
// level ran; a killed sweep of several jobs, resumed, ends in point order.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/run/host_profile.h"
#include "sw/run/reference_workload.h"
#include "sw/study/sweep_csv.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

const std::string kRun = "run --scene spheres --objects 10 --frames 1 ";

using Edges = Cli;

// Each of these cdvp run refuses from its settings alone; cdvp settings,
// which promises to check them as run does, and cdvp bullet must refuse each
// in the same words.
TEST_F(Edges, SettingsRefusesWhatRunRefusesOfItsSettingsInTheSameWords) {
    write("c.toml", "[run]\nlockstep = \"yes\"\n");
    const std::vector<std::string> refused{
        "-c run.lockstep=yes",
        "--config c.toml",
        "-c run.lockstep=yes -c run.fidelity=cycle",
        "-c run.max_error_percent=5",
        "-c run.fidelity=analytic -c run.quantum_ns=100",
        "-c run.fidelity=auto -c run.quantum_ns=100",
        "-c host.profile=missing.json",
        "--board adm-xrc-ii -c bus.model=transaction -c bus.load_bytes_per_s=1e12",
        "--board adm-xrc-ii -c bus.load_bytes_per_s=1e6",
        "--board adm-xrc-ii -c board.fifo_depth=1",
        "-c board.m=0",
        "-c run.lockstep=maybe",
    };
    for (const std::string& layers : refused) {
        const Result by_run = run(kRun + layers);
        const Result by_settings = run("settings " + layers);
        expect_refusal(by_run, "cdvp run: ", layers);
        expect_refusal(by_settings, "cdvp settings: ", layers);
        EXPECT_EQ(by_settings.err.substr(by_settings.err.find(": ")), by_run.err.substr(by_run.err.find(": "))) << layers;
        // A run of Bullet's worlds comes through the same checks.
        const Result by_bullet = run("bullet --scene stack --objects 5 --frames 1 " + layers);
        expect_refusal(by_bullet, "cdvp bullet: ", layers);
        EXPECT_EQ(by_bullet.err.substr(by_bullet.err.find(": ")), by_run.err.substr(by_run.err.find(": "))) << layers;
    }
    // And what run takes, settings takes.
    for (const char* layers : {"-c run.fidelity=analytic", "-c run.fidelity=auto -c run.max_error_percent=5",
                               "--board adm-xrc-ii -c bus.model=transaction -c bus.load_bytes_per_s=1e8"}) {
        EXPECT_EQ(run(kRun + layers).status, 0) << layers;
        EXPECT_EQ(run(std::string("settings ") + layers).status, 0) << layers;
    }
}

// An input that is a symbolic-link loop or a directory says exactly that,
// with its path, wherever cdvp opens it: a preset by name or by path, a host
// profile, a config file, a trace.
TEST_F(Edges, AnInputThatCannotBeOpenedSaysWhyWithItsPath) {
    fs::create_symlink("loop.json", dir_ / "loop.json");
    fs::create_directories(dir_ / "boards");
    fs::copy_file(preset("adm-xrc-ii"), dir_ / "boards" / "adm-xrc-ii.json");
    fs::create_symlink("loop.json", dir_ / "boards" / "loop.json");
    fs::create_directories(dir_ / "folder.json");
    const std::string loop = "cannot open: Too many levels of symbolic links (ELOOP)";
    const std::string folder = "cannot open: Is a directory (EISDIR)";
    const std::vector<std::pair<std::string, std::string>> cases{
        {kRun + "--board loop", "cdvp run: boards/loop.json: " + loop},
        {kRun + "--board ./loop.json", "cdvp run: ./loop.json: " + loop},
        {kRun + "--board folder.json", "cdvp run: folder.json: " + folder},
        {kRun + "--board adm-xrc-ii --host-profile loop.json", "cdvp run: --host-profile: loop.json: " + loop},
        {kRun + "--board adm-xrc-ii --host-profile folder.json", "cdvp run: folder.json: " + folder},
        {kRun + "--config loop.json", "cdvp run: loop.json: " + loop},
        {kRun + "--config folder.json", "cdvp run: folder.json: " + folder},
        {"run --trace loop.json", "cdvp run: loop.json: " + loop},
        {"run --trace folder.json", "cdvp run: folder.json: " + folder},
        {"settings --board loop", "cdvp settings: boards/loop.json: " + loop},
    };
    for (const auto& [args, message] : cases) {
        const Result r = run(args, "CDVP_BOARDS=boards");
        expect_refusal(r, message, args);
        EXPECT_EQ(r.err.find("unknown"), std::string::npos) << args << ": " << r.err;
        EXPECT_EQ(r.err.find("no such file"), std::string::npos) << args << ": " << r.err;
    }
    // The default profile's place in a loop is refused too, not passed over.
    fs::create_directories(dir_ / ".config" / "cdvp");
    fs::create_symlink("host-profile.json", dir_ / ".config" / "cdvp" / "host-profile.json");
    expect_refusal(run(kRun + "--board adm-xrc-ii"), "cdvp run: the default host profile: ");
    EXPECT_NE(run(kRun + "--board adm-xrc-ii").err.find(loop), std::string::npos);
}

// A file it may not read says EACCES, wherever it is named. Root reads
// anything: as root the commands run as nobody (setpriv), so that the
// permission is checked as a user's would be.
TEST_F(Edges, AnInputItMayNotReadSaysPermissionDenied) {
    const std::string as_user = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups" : "";
    fs::copy_file(preset("adm-xrc-ii"), dir_ / "board.json");
    write("c.toml", "[board]\nm = 4\n");
    fs::copy_file(trace("small.csv"), dir_ / "t.csv");
    for (const char* name : {"board.json", "c.toml", "t.csv"}) fs::permissions(dir_ / name, fs::perms::none);
    const std::string denied = "cannot open: Permission denied (EACCES)";
    const std::vector<std::pair<std::string, std::string>> cases{
        {kRun + "--board board.json", "cdvp run: board.json: " + denied},
        {kRun + "--config c.toml", "cdvp run: c.toml: " + denied},
        {"run --trace t.csv", "cdvp run: t.csv: " + denied},
        {"settings --config c.toml", "cdvp settings: c.toml: " + denied},
    };
    for (const auto& [args, message] : cases) expect_refusal(run(args, as_user), message, args);
}

TEST_F(Edges, AnEmptyPathIsRefusedAsEmpty) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"calibrate --out ''", "cdvp calibrate: --out: expected a file path, got ''"},
        {"fidelity --scene spheres --out ''", "cdvp fidelity: --out: expected a directory, got ''"},
        {"sweep --set m=1 --out ''", "cdvp sweep: --out: expected a directory, got ''"},
        {kRun + "--config ''", "cdvp run: --config: expected a file path, got ''"},
        {kRun + "--report ''", "cdvp run: --report: expected a file path, got ''"},
        {kRun + "--host-profile ''", "cdvp run: --host-profile: expected a non-empty string"},
        {"run --trace ''", "cdvp run: --trace: expected a file path, got ''"},
        {"settings --board ''", "cdvp settings: --board: expected a preset name or a .json path, got ''"},
    };
    for (const auto& [args, message] : cases) {
        const Result r = run(args);
        expect_refusal(r, message, args);
        EXPECT_EQ(r.err.find("HOME"), std::string::npos) << args << ": " << r.err;
    }
    EXPECT_EQ(files(), std::vector<std::string>{}) << "nothing written";
}

// A profile whose reference time gives a host factor outside --host-factor's
// range is refused naming the file, the field and the times expected; no
// speedup is ever printed as inf.
TEST_F(Edges, AHostProfileGivingAnAbsurdFactorIsRefusedAndNoSpeedupIsInf) {
    for (const double ns : {1e-300, 4.9e-324, 1e-3}) {
        HostProfile p;
        p.created = "2025-01-01T00:00:00Z";
        p.machine.cpu_model = "Test CPU";
        p.repeat = 3;
        p.runs = 3;
        p.target_spread = 0.03;
        for (const std::string& name : reference_workload::baselines()) {
            BaselineReference& b = p.reference[name];
            for (const uint64_t objects : reference_workload::objects()) b.sizes.push_back({objects, {}, {1e5, 1e5, 1e5}, 1e5});
            b.reference_native_ns = name == "sap" ? ns : 1e5;
        }
        write("p.json", host_profile_json(p));
        const Result r = run(kRun + "--board adm-xrc-ii --baseline sap --host-profile p.json");
        expect_refusal(r, "cdvp run: p.json: reference.sap.reference_native_ns: ", std::to_string(ns));
        EXPECT_NE(r.err.find("expected a time from 360.47 to 360470000 ns"), std::string::npos) << r.err;
        EXPECT_EQ(r.out.find("inf"), std::string::npos) << r.out;
        EXPECT_EQ(r.err.find("inf"), std::string::npos) << r.err;
    }
}

// Background traffic beyond the bus's peak is no load the bus could carry
// (and would be simulated burst by burst): refused with the peak; at the
// peak it runs.
TEST_F(Edges, ABusLoadBeyondTheBusPeakIsRefusedWithThePeak) {
    const std::string bus = kRun + "--board adm-xrc-ii --bus-model transaction ";
    expect_refusal(run(bus + "-c bus.load_bytes_per_s=1e12"),
                   "cdvp run: -c bus.load_bytes_per_s: expected at most the bus's peak of 133332000 B/s (32 bits at "
                   "33.333 MHz), got 1000000000000, 7.5e+03 x it");
    expect_refusal(run(kRun + "--board pcie-gen3-x8 --bus-model transaction -c bus.load_bytes_per_s=8e9"),
                   "cdvp run: -c bus.load_bytes_per_s: expected at most the bus's peak of 7876923076 B/s (8 lanes at 8 "
                   "GT/s after the line code)");
    EXPECT_EQ(run(bus + "-c bus.load_bytes_per_s=133332000").status, 0);
}

// cdvp bullet --fidelity auto says, as cdvp run does, which level timed the
// frames and why, in its summary and in its report.
TEST_F(Edges, BulletUnderAutoNamesTheLevelChosenAndWhy) {
    for (const std::string command : {"bullet --scene stack --objects 20", "run --scene spheres --objects 10"}) {
        const Result r = run(command + " --frames 3 --fidelity auto --report r.json");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_NE(r.out.find("auto engine"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("\nauto: analytic level on 3 of 3 frames (3 exact by bound)\n"), std::string::npos) << r.out;
        const auto report = report_of(dir_ / "r.json");
        EXPECT_EQ(report.at("fidelity_choice").at("analytic_frames"), 3) << command;
        EXPECT_EQ(report.at("config").at("fidelity"), "auto") << command;
    }
}

// A sweep of two jobs whose point 0 ends after point 1 and is killed while
// point 2 runs leaves rows 1, 0; resumed, it runs point 2 and ends in point
// order.
TEST_F(Edges, AKilledSweepOfTwoJobsResumedEndsInPointOrder) {
    const std::string sweep = "sweep --set objects=3000,20,10000 --frames 2 --fidelity cycle --jobs 2 --out s -q";
    const pid_t pid = fork();
    if (pid == 0) {
        const std::string command = "cd '" + dir_.string() + "' && exec '" CDVP_BINARY "' " + sweep;
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    const auto rows = [this] {
        return fs::exists(dir_ / "s" / "sweep.csv") ? parse_csv(slurp(dir_ / "s" / "sweep.csv"), "sweep.csv")
                                                     : std::vector<std::vector<std::string>>{};
    };
    for (int k = 0; k < 3000 && rows().size() < 3; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(kill(pid, SIGKILL), 0);
    waitpid(pid, nullptr, 0);
    const auto killed = rows();
    ASSERT_EQ(killed.size(), 3u) << "two points done, the third running at the kill";
    EXPECT_EQ(killed[1][1], "1") << "the small point first";
    EXPECT_EQ(killed[2][1], "0");
    const Result resumed = run(sweep);
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    const auto table = rows();
    ASSERT_EQ(table.size(), 4u);
    for (std::size_t k = 1; k < table.size(); ++k) EXPECT_EQ(table[k][1], std::to_string(k - 1)) << "row " << k;
}

}  // namespace
}  // namespace cdvp::test
