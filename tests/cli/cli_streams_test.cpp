// Outputs beyond the files: the report written a frame at a time, standard
// output as one more output of the run, outputs given as descriptors, and a
// FIFO without a reader.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

const std::string kSmall = "run --trace in.csv --m 2";

class CliStreams : public Cli {
protected:
    void SetUp() override {
        Cli::SetUp();
        write("in.csv", slurp(trace("small.csv")));
    }
    // `cdvp ARGS` where ARGS may redirect standard output itself; stderr is captured.
    Result shell(const std::string& args) {
        const fs::path err = dir_ / ".stderr";
        const std::string command = "cd '" + dir_.string() + "' && '" CDVP_BINARY "' " + args + " 2> '" +
                                    err.string() + "' < /dev/null";
        const int raw = std::system(command.c_str());
        Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, "", slurp(err)};
        fs::remove(err);
        return r;
    }
};

TEST_F(CliStreams, TheReportIsWrittenAFrameAtATimeAsOneJsonDocument) {
    const Result r = run("run --scene spheres --objects 40 --frames 12 --m 2 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string text = slurp(dir_ / "r.json");
    const nlohmann::json report = nlohmann::json::parse(text);
    EXPECT_EQ(text, report.dump(2) + "\n") << "the layout of a whole-document dump";
    ASSERT_EQ(report["frames"].size(), 12u);
    EXPECT_EQ(report["summary"]["frames"], 12);
    EXPECT_EQ(report["summary"]["frames_in_means"], 10);
    double sum = 0;
    for (std::size_t k = 2; k < 12; ++k) sum += report["frames"][k]["total_ns"].get<double>();
    EXPECT_DOUBLE_EQ(report["summary"]["mean_total_ns"].get<double>(), sum / 10);
    EXPECT_NE(r.out.find("    ... (2 more frames in the report)\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("total: 12 frames, "), std::string::npos) << r.out;

    ASSERT_EQ(run("run --scene spheres --frames 0 --report none.json -q").status, 0);
    const std::string none = slurp(dir_ / "none.json");
    EXPECT_EQ(none, nlohmann::json::parse(none).dump(2) + "\n");
    EXPECT_EQ(nlohmann::json::parse(none)["frames"], nlohmann::json::array());
}

TEST_F(CliStreams, ASummaryThatCannotBePrintedPublishesNoFile) {
    const Result full = shell(kSmall + " --pairs-out p.csv --report r.json > /dev/full");
    EXPECT_EQ(full.status, 4) << "a full device is the system's failure";
    EXPECT_EQ(full.err, "cdvp run: standard output: cannot write: No space left on device\n");
    EXPECT_EQ(files(), std::vector<std::string>{"in.csv"});
    EXPECT_EQ(shell(kSmall + " --pairs-out p.csv -q > /dev/full").status, 0) << "--quiet prints nothing";
    EXPECT_TRUE(fs::exists(dir_ / "p.csv"));
}

TEST_F(CliStreams, AClosedStandardOutputIsRefusedBeforeAnyWork) {
    const Result closed = shell(kSmall + " --pairs-out p.csv >&-");
    EXPECT_EQ(closed.status, 2);
    EXPECT_EQ(closed.err, "cdvp run: standard output: closed when cdvp started; expected it open (or --quiet)\n");
    EXPECT_EQ(files(), std::vector<std::string>{"in.csv"});
    const Result dash = shell(kSmall + " -q --pairs-out - --report r.json >&-");
    EXPECT_EQ(dash.status, 2);
    EXPECT_EQ(dash.err, "cdvp run: --pairs-out: -: cannot write: descriptor 1 was closed when cdvp started\n");
    EXPECT_EQ(files(), std::vector<std::string>{"in.csv"});
    const Result quiet = shell(kSmall + " -q --pairs-out p.csv >&-");
    EXPECT_EQ(quiet.status, 0) << quiet.err;
    EXPECT_EQ(slurp(dir_ / "p.csv"), slurp(trace("small.expected.csv"))) << "no file took descriptor 1";
    EXPECT_EQ(shell("--help >&-").status, 2);
    EXPECT_EQ(shell("run --help > /dev/full").status, 4);
    const Result version = shell("--version > /dev/full");
    EXPECT_EQ(version.status, 4);
    EXPECT_EQ(version.err, "cdvp: standard output: cannot write: No space left on device\n");
}

TEST_F(CliStreams, ADescriptorOntoAnInputIsRefusedBeforeAnyWork) {
    const std::string before = slurp(dir_ / "in.csv");
    const Result fd = shell(kSmall + " -q --pairs-out /dev/fd/3 3>>in.csv");
    EXPECT_EQ(fd.status, 2);
    EXPECT_EQ(fd.err, "cdvp run: --pairs-out '/dev/fd/3' is the input --trace 'in.csv'; an output never writes into "
                      "an input\n");
    const Result out = shell(kSmall + " >> in.csv");
    EXPECT_EQ(out.status, 2);
    EXPECT_EQ(out.err, "cdvp run: standard output is the input --trace 'in.csv'; an output never writes into an input\n");
    const Result dash = shell(kSmall + " -q --pairs-out - >> in.csv");
    EXPECT_EQ(dash.status, 2);
    EXPECT_EQ(slurp(dir_ / "in.csv"), before) << "the trace is untouched";

    write("board.json", slurp(preset("adm-xrc-ii")));
    const Result board = shell(kSmall + " -q --board board.json --report /dev/stdout >> board.json");
    EXPECT_EQ(board.status, 2);
    EXPECT_NE(board.err.find("is the input --board 'board.json'"), std::string::npos) << board.err;

    const Result twice = shell(kSmall + " -q --report r.json --pairs-out /dev/fd/3 3>>r.json");
    EXPECT_EQ(twice.status, 2);
    EXPECT_EQ(twice.err, "cdvp run: --report 'r.json' is the same file as --pairs-out '/dev/fd/3'; give each output "
                         "its own file\n");
    EXPECT_EQ(files(), (std::vector<std::string>{"board.json", "in.csv", "r.json"})) << "r.json is the shell's, empty";
    EXPECT_EQ(fs::file_size(dir_ / "r.json"), 0u);

    // One descriptor written twice in turn is fine: the pairs, then the summary.
    const Result shared = shell(kSmall + " --pairs-out - > out.txt");
    EXPECT_EQ(shared.status, 0) << shared.err;
    EXPECT_EQ(slurp(dir_ / "out.txt").find(slurp(trace("small.expected.csv"))), 0u);
}

// A file size limit (ulimit -f) kills a write past it with SIGXFSZ: the run
// ends with 128+25 and leaves no temporary, even for the VCD, whose writer
// would not notice a failed write.
TEST_F(CliStreams, AFileSizeLimitEndsTheRunWithNoOutput) {
    const std::string command = "cd '" + dir_.string() + "' && ulimit -c 0 && ulimit -f 16 && '" CDVP_BINARY
                                "' run --scene spheres --objects 100 --frames 200 --m 2 -q --pairs-out p.csv "
                                "--report r.json --vcd w.vcd 2> /dev/null";
    const int raw = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(raw)) << raw;
    EXPECT_EQ(WEXITSTATUS(raw), 128 + SIGXFSZ);
    EXPECT_EQ(files(), std::vector<std::string>{"in.csv"});
}

bool any_temporary(const fs::path& dir) {
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (entry.path().filename().string().find(".part-") != std::string::npos) return true;
    }
    return false;
}

TEST_F(CliStreams, SigintStopsARunWaitingForAFifoReader) {
    ASSERT_EQ(mkfifo((dir_ / "pipe").c_str(), 0600), 0);
    fs::create_directories(dir_ / "tmp");
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        if (chdir(dir_.c_str()) != 0) _exit(127);
        setenv("TMPDIR", (dir_ / "tmp").c_str(), 1);
        const int null = open("/dev/null", O_RDWR);
        dup2(null, 0);
        dup2(null, 1);
        dup2(null, 2);
        execl(CDVP_BINARY, CDVP_BINARY, "run", "--trace", "in.csv", "--m", "2", "-q", "--pairs-out", "pipe",
              "--report", "r.json", static_cast<char*>(nullptr));
        _exit(127);
    }
    // The run takes milliseconds; then it waits in open() for a reader, which
    // the kernel shows as the wait channel "wait_for_partner" (where /proc
    // shows none, two seconds are ample).
    const fs::path wchan = "/proc/" + std::to_string(pid) + "/wchan";
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (slurp(wchan) != "wait_for_partner" && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_EQ(kill(pid, SIGINT), 0);
    int status = 0;
    pid_t done = 0;
    for (int k = 0; k < 500 && done == 0; ++k) {
        done = waitpid(pid, &status, WNOHANG);
        if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (done == 0) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        FAIL() << "SIGINT did not stop a run blocked on a FIFO";
    }
    ASSERT_TRUE(WIFSIGNALED(status)) << status;
    EXPECT_EQ(WTERMSIG(status), SIGINT) << "so a shell reports 130";
    EXPECT_FALSE(any_temporary(dir_)) << "no temporary, here or in TMPDIR";
    EXPECT_FALSE(fs::exists(dir_ / "r.json")) << "nothing published";
}

}  // namespace
}  // namespace cdvp::test
