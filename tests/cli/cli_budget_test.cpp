// Budgets before work: every class of refusal cdvp run makes for memory,
// pairs, simulated time and input size exits 2 with one line naming each
// value and its origin, leaves no output, and costs little: the refusals made
// before any work are measured here (wall time and peak RSS of the process).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

const char* const kHeader = "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n";

// AddressSanitizer's shadow memory, redzones and quarantine multiply what a
// process holds: peak RSS is held to figures in ordinary builds only. (A
// sanitized build compiles the tests themselves without it: CMakeLists.txt.)
#if defined(__SANITIZE_ADDRESS__) || defined(CDVP_CODE_UNDER_ASAN)
constexpr bool kRssIsTheProgramsOwn = false;
#else
constexpr bool kRssIsTheProgramsOwn = true;
#endif

struct Measured {
    Result result;
    double seconds = 0;
    long peak_kb = 0;
};

class CliBudget : public Cli {
protected:
    // n boxes in one frame, all alike: n(n-1)/2 pairs.
    fs::path identical_boxes(const std::string& name, int n) {
        std::string text = kHeader;
        for (int i = 0; i < n; ++i) text += "0," + std::to_string(i) + ",0,0,0,1,1,1\n";
        return write(name, text);
    }
    // `cdvp ARGS` (words), stderr kept, with its wall time and peak RSS; the
    // trace may come from `producer`, a shell command writing into the FIFO
    // "in" of the test's directory.
    Measured measure(const std::vector<std::string>& args, const std::string& producer = "") {
        pid_t writer = -1;
        if (!producer.empty()) {
            const fs::path fifo = dir_ / "in";
            if (mkfifo(fifo.c_str(), 0600) != 0) ADD_FAILURE() << "mkfifo";
            writer = fork();
            if (writer == 0) {
                setpgid(0, 0);  // a group of its own, ended as one below
                execlp("sh", "sh", "-c", ("exec 2>/dev/null; { " + producer + "; } > '" + fifo.string() + "'").c_str(),
                       nullptr);
                _exit(127);
            }
            setpgid(writer, writer);
        }
        const fs::path err = dir_ / ".stderr";
        const auto start = std::chrono::steady_clock::now();
        const pid_t child = fork();
        if (child == 0) {
            if (chdir(dir_.c_str()) != 0) _exit(127);
            const int null = open("/dev/null", O_RDWR);
            const int error = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
            dup2(null, 0);
            dup2(null, 1);
            dup2(error, 2);
            std::vector<char*> argv{const_cast<char*>(CDVP_BINARY)};
            for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            execv(CDVP_BINARY, argv.data());
            _exit(127);
        }
        int status = 0;
        rusage usage{};
        wait4(child, &status, 0, &usage);
        Measured m;
        m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        m.peak_kb = usage.ru_maxrss;
        if (writer > 0) {
            kill(-writer, SIGTERM);
            waitpid(writer, nullptr, 0);
            fs::remove(dir_ / "in");
        }
        m.result = Result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, "", slurp(err)};
        fs::remove(err);
        return m;
    }
    // A refusal made before any work: one line, nothing written, quick and small.
    void expect_cheap_refusal(const Measured& m, const std::string& start, const std::vector<std::string>& left) {
        expect_refusal(m.result, start);
        EXPECT_EQ(files(), left);
        // A hang guard, not a speed claim (machines are shared; sanitizers slow
        // every run): an input read past its limit would never end.
        EXPECT_LT(m.seconds, 60.0) << m.result.err;
        if (kRssIsTheProgramsOwn) {
            EXPECT_LT(m.peak_kb, 64 * 1024) << m.result.err;
        }
    }
};

std::vector<std::string> with_outputs(std::vector<std::string> args) {
    for (const char* a : {"--pairs-out", "p.csv", "--report", "r.json"}) args.push_back(a);
    return args;
}

TEST_F(CliBudget, AMillionsOfObjectsSceneIsRefusedBeforeItIsGenerated) {
    // The frame's sweep and the driver's timeout for it, against one limit in one unit.
    const Measured m = measure(with_outputs({"run", "--scene", "spheres", "--objects", "4194304"}));
    expect_cheap_refusal(m,
                         "cdvp run: a run of 12 frames (the default of --frames) of up to 4194304 objects (--objects) "
                         "at m=8 (the default of --m) and 66 MHz (the default of --clock-mhz) would reach ",
                         {});
    EXPECT_NE(m.result.err.find("of simulated time (up to 8884.970 s a frame before any pair"), std::string::npos)
        << m.result.err;
    EXPECT_NE(m.result.err.find(", past the limit of 9223.372 s (2^63 fs, half SystemC's 64-bit femtosecond clock)"),
              std::string::npos)
        << m.result.err;
    EXPECT_EQ(m.result.err.find("2^64"), std::string::npos) << "one limit: " << m.result.err;
}

TEST_F(CliBudget, ASceneBeyondTheMemoryBudgetIsRefusedBeforeItIsGenerated) {
    const Measured m =
        measure(with_outputs({"run", "--scene", "spheres", "--objects", "200000", "--max-memory", "40"}));
    expect_cheap_refusal(m,
                         "cdvp run: --max-memory: the memory budget of 40 MiB (--max-memory 40) is too little for "
                         "200000 objects (--objects) in 12 frames (the default of --frames): they need an estimated ",
                         {});
    // The clocked board's block RAM words count too, named with m's origin.
    const Measured words = measure(with_outputs({"run", "--scene", "spheres", "--objects", "100000", "--m", "32",
                                                 "--fidelity", "cycle", "--max-memory", "100"}));
    expect_cheap_refusal(words, "cdvp run: --max-memory: the memory budget of 100 MiB (--max-memory 100)", {});
    EXPECT_NE(words.result.err.find("the board model's block RAM words at --m 32 "), std::string::npos)
        << words.result.err;
}

TEST_F(CliBudget, ABudgetBeyondThisMachineAndPairsBeyondTheBudgetAreRefused) {
    expect_cheap_refusal(measure(with_outputs({"run", "--scene", "spheres", "--max-memory", "1073741824"})),
                         "cdvp run: --max-memory: a memory budget of 1073741824 MiB is more than ", {});
    expect_cheap_refusal(measure(with_outputs({"run", "--trace", trace("small.csv"), "--max-memory", "10"})),
                         "cdvp run: --max-memory: the memory budget of 10 MiB (--max-memory 10) is too little for the "
                         "program itself: it needs an estimated ",
                         {});
    const Measured m =
        measure(with_outputs({"run", "--scene", "spheres", "--max-memory", "100", "--max-pairs", "1000000000"}));
    expect_cheap_refusal(m, "cdvp run: --max-pairs: 1000000000 pairs a frame at ", {});
    EXPECT_NE(m.result.err.find("more than the memory budget of 100 MiB (--max-memory 100); give a smaller --max-pairs"),
              std::string::npos)
        << m.result.err;
}

// The tester's frame of alike boxes, in every way it was run: the pairs are
// refused where they are found (the fast engine's search, the clocked
// board's read-back), never reaching the baselines, the reference or the CSV.
TEST_F(CliBudget, AFrameWhosePairsOutgrowTheBudgetIsRefusedWhereverItRuns) {
    identical_boxes("same.csv", 400);  // 79,800 pairs
    for (const std::vector<std::string>& extra :
         {std::vector<std::string>{}, {"--baseline", "sap,dbvt,brute,soa"}, {"--format", "fixed16"},
          {"--fidelity", "cycle"}, {"--fidelity", "cycle", "--pair-buffer", "1000"}}) {
        std::vector<std::string> args = with_outputs({"run", "--trace", "same.csv", "--max-pairs", "5000"});
        args.insert(args.end(), extra.begin(), extra.end());
        const Measured m = measure(args);
        const std::string context = extra.empty() ? "plain" : extra[0] + " " + extra[1];
        expect_refusal(m.result, "cdvp run: frame 0: ", context);
        EXPECT_NE(m.result.err.find(" pairs found, more than the pair budget of 5000 (--max-pairs 5000); expected at "
                                    "most that many pairs a frame"),
                  std::string::npos)
            << context << ": " << m.result.err;
        EXPECT_EQ(files(), std::vector<std::string>{"same.csv"}) << context;
    }
    // The budget the memory leaves, by default: refused long before the memory is spent.
    identical_boxes("same20k.csv", 20000);  // 2e8 pairs
    const Measured m = measure(with_outputs({"run", "--trace", "same20k.csv", "--max-memory", "1024"}));
    expect_refusal(m.result, "cdvp run: frame 0: ");
    EXPECT_NE(m.result.err.find("(the default of --max-pairs: what the memory budget of 1024 MiB leaves, at "),
              std::string::npos)
        << m.result.err;
    if (kRssIsTheProgramsOwn) {
        EXPECT_LT(m.peak_kb, 1024 * 1024) << "within the memory budget";
    }
}

TEST_F(CliBudget, AFrameOrAFrameCountBeyondTheMemoryBudgetIsRefusedAsTheTraceIsRead) {
    identical_boxes("wide.csv", 20000);
    const Measured wide = measure(with_outputs({"run", "--trace", "wide.csv", "--max-memory", "36"}));
    expect_refusal(wide.result, "cdvp run: wide.csv:");
    EXPECT_NE(wide.result.err.find(" boxes a frame (what the memory budget of 36 MiB (--max-memory 36) holds at "),
              std::string::npos)
        << wide.result.err;
    std::string text = kHeader;
    for (int f = 0; f < 100000; ++f) text += std::to_string(f) + ",0,0,0,0,1,1,1\n";
    write("long.csv", text);
    const Measured many = measure(with_outputs({"run", "--trace", "long.csv", "--max-memory", "35"}));
    expect_refusal(many.result, "cdvp run: long.csv:");
    EXPECT_NE(many.result.err.find(" frames (what the memory budget of 35 MiB (--max-memory 35) holds at "),
              std::string::npos)
        << many.result.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"long.csv", "wide.csv"}));
}

// Endless and oversized inputs stop at their first line or byte past the
// limits, a file or a pipe, and leave no copy behind.
TEST_F(CliBudget, EveryTraceIsReadUnderTheSameLimits) {
    const fs::path spool = dir_ / "spool";
    fs::create_directory(spool);
    setenv("TMPDIR", spool.c_str(), 1);
    expect_cheap_refusal(measure(with_outputs({"run", "--trace", "/dev/zero"})),
                         "cdvp run: /dev/zero:1: line longer than 4096 bytes; expected at most 4096 bytes a line, "
                         "counting its line end\n",
                         {"spool"});
    expect_cheap_refusal(measure(with_outputs({"run", "--trace", "/dev/urandom"})), "cdvp run: /dev/urandom:1: ",
                         {"spool"});
    expect_cheap_refusal(measure(with_outputs({"run", "--trace", "in"}), "yes 0,0,0,0,0,1,1,1"),
                         "cdvp run: in:1: expected header 'frame,id,min_x,min_y,min_z,max_x,max_y,max_z', found "
                         "'0,0,0,0,0,1,1,1'\n",
                         {"spool"});
    // Good lines without end: the size limit.
    const std::string endless = "printf '" + std::string(kHeader).substr(0, std::string(kHeader).size() - 1) +
                                "\\n'; seq 0 999999999 | sed 's/$/,0,0,0,0,1,1,1/'";  // a box a frame
    expect_cheap_refusal(measure(with_outputs({"run", "--trace", "in", "--max-trace-size", "1"}), endless),
                         "cdvp run: in: more than 1048576 bytes; expected at most 1048576 bytes "
                         "(--max-trace-size 1)\n",
                         {"spool"});
    std::string big = kHeader;
    while (big.size() <= (1u << 20)) big += "0,1,0,0,0,1,1,1\n";
    write("big.csv", big);
    expect_cheap_refusal(measure(with_outputs({"run", "--trace", "big.csv", "-c", "run.max_trace_size=1"})),
                         "cdvp run: big.csv: " + std::to_string(big.size()) +
                             " bytes, more than 1048576; expected at most 1048576 bytes (-c run.max_trace_size=1)\n",
                         {"big.csv", "spool"});
    unsetenv("TMPDIR");
    EXPECT_TRUE(fs::is_empty(spool)) << "no copy is left";
}

// Within its budgets a run records them in its report, and its estimate
// lies above what it held.
TEST_F(CliBudget, TheReportRecordsTheBudgetsAndTheEstimateCoversThePeak) {
    identical_boxes("same.csv", 1500);  // 1.1 million pairs
    const Measured m = measure({"run", "--trace", "same.csv", "--baseline", "sap,soa", "--pairs-out", "p.csv",
                                "--report", "r.json", "-q"});
    ASSERT_EQ(m.result.status, 0) << m.result.err;
    const nlohmann::json budgets = report_of(dir_ / "r.json")["config"]["budgets"];
    const uint64_t pairs = 1500 * 1499 / 2;
    const uint64_t estimate = budgets["estimate_before_pairs_bytes"].get<uint64_t>() +
                              pairs * budgets["estimate_bytes_per_pair"].get<uint64_t>();
    if (kRssIsTheProgramsOwn) {
        EXPECT_GT(estimate, static_cast<uint64_t>(m.peak_kb) * 1024);
    }
    EXPECT_GE(budgets["pairs_per_frame"].get<uint64_t>(), pairs);
    EXPECT_DOUBLE_EQ(budgets["simulated_time_limit_s"].get<double>(), 9223.372036854775808);
}

// A Bullet run's estimate counts its two worlds' bodies and contacts: a pile
// of mixed shapes at rest, thousands of touching pairs a frame.
TEST_F(CliBudget, ABulletRunsEstimateCoversItsWorlds) {
    const Measured m = measure({"bullet", "--scene", "mixed", "--objects", "1500", "--frames", "80", "--report",
                                "r.json", "-q"});
    ASSERT_EQ(m.result.status, 0) << m.result.err;
    const nlohmann::json report = report_of(dir_ / "r.json");
    uint64_t pairs = 0;
    for (const auto& frame : report["frames"]) pairs = std::max(pairs, frame["pairs"].get<uint64_t>());
    EXPECT_GT(pairs, 5000u) << "the pile has landed";
    const nlohmann::json& budgets = report["config"]["budgets"];
    const uint64_t estimate = budgets["estimate_before_pairs_bytes"].get<uint64_t>() +
                              pairs * budgets["estimate_bytes_per_pair"].get<uint64_t>();
    if (kRssIsTheProgramsOwn) {
        EXPECT_GT(estimate, static_cast<uint64_t>(m.peak_kb) * 1024);
    }
}

}  // namespace
}  // namespace cdvp::test
