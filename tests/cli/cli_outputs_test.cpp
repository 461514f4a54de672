// `cdvp run` output files: nothing lost, nothing clobbered, nothing left
// behind (issue 6, defects 1-5).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

class CliOutputs : public Cli {
protected:
    void SetUp() override {
        Cli::SetUp();
        write("in.csv", slurp(trace("small.csv")));
    }
    // Runs on in.csv; the run must be refused with 'message' and change nothing.
    void expect_refused(const std::string& flags, const std::string& message, int status = 2) {
        const std::vector<std::string> before = files();
        const Result r = run("run --trace in.csv --m 2 -q " + flags);
        EXPECT_EQ(status, r.status) << flags;
        EXPECT_EQ(r.err, "cdvp run: " + message + "\n") << flags;
        EXPECT_EQ(before, files()) << flags << ": nothing written, nothing left";
        EXPECT_EQ(slurp(trace("small.csv")), slurp(dir_ / "in.csv")) << flags;
    }
};

TEST_F(CliOutputs, AnOutputNeverReplacesTheTrace) {  // defect 1
    expect_refused("--pairs-out in.csv", "--pairs-out 'in.csv' is the input --trace 'in.csv'; an output never replaces an input");
    fs::create_symlink("in.csv", dir_ / "link.csv");
    fs::create_hard_link(dir_ / "in.csv", dir_ / "hard.csv");
    expect_refused("--report ./link.csv", "--report './link.csv' is the input --trace 'in.csv'; an output never replaces an input");
    expect_refused("--vcd hard.csv", "--vcd 'hard.csv' is the input --trace 'in.csv'; an output never replaces an input");
}

TEST_F(CliOutputs, TwoOutputsNeverShareAFile) {  // defect 2
    expect_refused("--pairs-out x --report x", "--report 'x' is the same file as --pairs-out 'x'; give each output its own file");
    expect_refused("--pairs-out x --vcd ./x", "--vcd './x' is the same file as --pairs-out 'x'; give each output its own file");
}

TEST_F(CliOutputs, AnOutputNeverReplacesThePreset) {
    write("board.json", slurp(preset("adm-xrc-ii")));
    expect_refused("--board board.json --report board.json",
                   "--report 'board.json' is the input --board 'board.json'; an output never replaces an input");
    // A preset found by name in the boards directory is an input too.
    write("mine.json", slurp(preset("adm-xrc-ii")));
    const Result named =
        run("run --trace in.csv --board mine -q --pairs-out mine.json", "CDVP_BOARDS='" + dir_.string() + "'");
    EXPECT_EQ(2, named.status);
    EXPECT_EQ("cdvp run: --pairs-out 'mine.json' is the input --board '" + (dir_ / "mine.json").string() +
                  "'; an output never replaces an input\n",
              named.err);
    EXPECT_EQ(slurp(preset("adm-xrc-ii")), slurp(dir_ / "mine.json"));
}

TEST_F(CliOutputs, ALateBadOutputLeavesNoOtherOutput) {  // defect 3
    fs::create_directories(dir_ / "d");
    write("p.csv", "old pairs\n");
    for (const char* late : {"--report d", "--vcd d"}) {
        expect_refused(std::string("--pairs-out p.csv ") + late,
                       std::string(late).substr(0, std::string(late).find(' ')) + ": d: cannot write: is a directory");
        EXPECT_EQ("old pairs\n", slurp(dir_ / "p.csv"));
    }
}

TEST_F(CliOutputs, ALinkIsWrittenThrough) {  // defect 4
    fs::create_directories(dir_ / "results");
    write("results/pairs.csv", "old\n");
    fs::create_symlink("results/pairs.csv", dir_ / "latest.csv");
    const Result r = run("run --trace in.csv --m 2 -q --pairs-out latest.csv");
    ASSERT_EQ(0, r.status) << r.err;
    EXPECT_TRUE(fs::is_symlink(dir_ / "latest.csv"));
    EXPECT_EQ(slurp(trace("small.expected.csv")), slurp(dir_ / "results" / "pairs.csv"));
    EXPECT_EQ(std::vector<std::string>{"pairs.csv"}, [&] {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_ / "results")) names.push_back(e.path().filename().string());
        return names;
    }());
}

TEST_F(CliOutputs, DevicesAreWrittenNotReplaced) {
    const Result r = run("run --trace in.csv --m 2 -q --pairs-out /dev/stdout --report /dev/null --vcd /dev/null");
    ASSERT_EQ(0, r.status) << r.err;
    EXPECT_EQ(slurp(trace("small.expected.csv")), r.out) << "pairs through /dev/stdout";
    struct stat st {};
    ASSERT_EQ(0, stat("/dev/null", &st));
    EXPECT_TRUE(S_ISCHR(st.st_mode));
    EXPECT_EQ(std::vector<std::string>{"in.csv"}, files());
    const Result dash = run("run --trace in.csv --m 2 -q --pairs-out -");
    ASSERT_EQ(0, dash.status) << dash.err;
    EXPECT_EQ(slurp(trace("small.expected.csv")), dash.out) << "'-' is standard output";
    EXPECT_EQ(std::vector<std::string>{"in.csv"}, files());
    // Data on standard output are the stream: no summary is mixed in, -q or not.
    const Result both = run("run --trace in.csv --m 2 --pairs-out /dev/stdout");
    ASSERT_EQ(0, both.status) << both.err;
    EXPECT_EQ(slurp(trace("small.expected.csv")), both.out);
    const Result report = run("run --trace in.csv --m 2 --report -");
    ASSERT_EQ(0, report.status) << report.err;
    EXPECT_EQ(nlohmann::json::parse(report.out)["frames"].size(), 3u) << "only the JSON";
    EXPECT_EQ(run("run --trace in.csv --m 2 --report r.json").out.find("total: 3 frames, 9 pairs") != std::string::npos,
              true)
        << "the summary, when no output takes standard output";
}

TEST_F(CliOutputs, AWriteErrorAtCommitLeavesNoOtherOutput) {
    // /dev/full fails every write (ENOSPC), as a full disk would: the
    // system's failure (status 4), with its own words.
    expect_refused("--pairs-out p.csv --report /dev/full", "--report: /dev/full: cannot write: No space left on device", 4);
}

TEST_F(CliOutputs, ReplacedOutputKeepsItsMode) {
    write("p.csv", "old\n");
    fs::permissions(dir_ / "p.csv", fs::perms(0640));
    ASSERT_EQ(0, run("run --trace in.csv --m 2 -q --pairs-out p.csv").status);
    EXPECT_EQ(fs::perms(0640), fs::status(dir_ / "p.csv").permissions() & fs::perms::all);
}


bool has_temporary(const fs::path& dir) {
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().filename().string().find(".part-") != std::string::npos) return true;
    }
    return false;
}

TEST_F(CliOutputs, KillingARunRemovesItsTemporaries) {  // defect 5
    for (int signal_number : {SIGTERM, SIGINT, SIGHUP}) {
        const pid_t pid = spawn(dir_, {"run", "--scene", "spheres", "--objects", "1000", "--frames", "100000", "--m",
                                       "2", "--vcd", "waves.vcd", "--pairs-out", "pairs.csv", "--report", "r.json"});
        ASSERT_GT(pid, 0);
        // Wait until the run is writing its temporaries, then a little more.
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (!has_temporary(dir_) && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        ASSERT_TRUE(has_temporary(dir_)) << "the run never started";
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        kill(pid, signal_number);
        int status = 0;
        ASSERT_EQ(pid, waitpid(pid, &status, 0));
        ASSERT_TRUE(WIFSIGNALED(status)) << "signal " << signal_number << ": status " << status;
        EXPECT_EQ(signal_number, WTERMSIG(status)) << "so a shell reports 128+" << signal_number;
        EXPECT_EQ(std::vector<std::string>{"in.csv"}, files()) << "signal " << signal_number;
    }
}

}  // namespace
}  // namespace cdvp::test
