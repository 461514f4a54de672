// --inject through the binary: a recovered fault gives exactly the pairs of a
// clean run; a fatal one exits 3 naming the frame and leaves no output.
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

const std::string kScene = "run --board adm-xrc-ii --scene spheres --objects 300 --frames 4 --m 8 --quiet";

class CliFaults : public Cli {
protected:
    std::string clean_pairs() {
        const Result r = run(kScene + " --pairs-out clean.csv");
        EXPECT_EQ(r.status, 0) << r.err;
        return slurp(dir_ / "clean.csv");
    }
};

TEST_F(CliFaults, RecoveredFaultsGiveEveryPairOfACleanRun) {
    const std::string clean = clean_pairs();
    ASSERT_NE(clean.find('\n'), clean.rfind('\n')) << "the scene has pairs";
    for (const char* spec : {"retry@frame=2,n=3", "disconnect@frame=1,n=2", "lost-irq@frame=0", "lost-irq@frame=3,n=2"}) {
        SCOPED_TRACE(spec);
        const Result r = run(kScene + " --inject " + spec + " --pairs-out faulted.csv --report r.json");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(slurp(dir_ / "faulted.csv"), clean);
        const auto report = report_of(dir_ / "r.json");
        EXPECT_EQ(report["config"]["inject"], nlohmann::json::array({spec}));
    }
}

TEST_F(CliFaults, ALostInterruptCostsATimeoutInItsFrameOnly) {
    ASSERT_EQ(run(kScene + " --report clean.json").status, 0);
    ASSERT_EQ(run(kScene + " --inject lost-irq@frame=2 --report lost.json").status, 0);
    const auto clean = report_of(dir_ / "clean.json")["frames"];
    const auto lost = report_of(dir_ / "lost.json")["frames"];
    for (std::size_t k = 0; k < 4; ++k) {
        SCOPED_TRACE(k);
        EXPECT_EQ(lost[k]["timeouts_recovered"], k == 2 ? 1 : 0);
        if (k == 2) {
            EXPECT_GT(lost[k]["total_ns"].get<double>(), clean[k]["total_ns"].get<double>() + 50000.0);
        } else {
            EXPECT_DOUBLE_EQ(lost[k]["total_ns"].get<double>(), clean[k]["total_ns"].get<double>());
        }
    }
}

TEST_F(CliFaults, FatalFaultsExitThreeNamingTheFrameAndLeaveNoOutput) {
    struct Case {
        const char* spec;
        const char* message;
    };
    const Case cases[] = {
        {"target-abort@frame=1", "cdvp run: frame 1: DMA fault: target abort"},
        {"master-abort@frame=2", "cdvp run: frame 2: DMA fault: descriptor fetch failed (master abort)"},
        {"dma-hang@frame=3", "cdvp run: frame 3: DMA timed out: no completion within "},
        {"board-error@frame=0", "cdvp run: frame 0: board error status: the board reported an error"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.spec);
        const Result r = run(kScene + " --inject " + c.spec + " --pairs-out p.csv --report r.json --vcd w.vcd");
        EXPECT_EQ(r.status, 3);
        EXPECT_EQ(r.err.rfind(c.message, 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(files(), std::vector<std::string>{}) << "no output, no temporary";
    }
}

TEST_F(CliFaults, AFaultInAFrameThatNeverRunsIsRefusedBeforeAnyWork) {
    const Result r = run(kScene + " --inject dma-hang@frame=4 --pairs-out p.csv --report r.json");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "cdvp run: --inject: 'dma-hang@frame=4': frame 4 is past the run's last frame 3 (--frames 4)\n");
    EXPECT_EQ(files(), std::vector<std::string>{});
    const Result none = run("run --scene spheres --frames 0 --inject retry@frame=0 --quiet");
    EXPECT_EQ(none.status, 2);
    EXPECT_EQ(none.err, "cdvp run: --inject: 'retry@frame=0': frame 0 never runs: the run has no frames (--frames 0)\n");
}

TEST_F(CliFaults, ATraceFrameNumberTheTraceDoesNotHoldIsRefused) {
    write("t.csv", "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n"
                   "5,1,0,0,0,1,1,1\n5,2,0,0,0,1,1,1\n9,1,0,0,0,1,1,1\n9,2,0,0,0,1,1,1\n");
    EXPECT_EQ(run("run --trace t.csv --quiet --inject retry@frame=9").status, 0) << "the trace's own numbers";
    const Result past = run("run --trace t.csv --quiet --inject retry@frame=10 --pairs-out p.csv");
    EXPECT_EQ(past.status, 2);
    EXPECT_EQ(past.err, "cdvp run: --inject: 'retry@frame=10': frame 10 is past the run's last frame 9 (trace t.csv)\n");
    const Result gap = run("run --trace t.csv --quiet --inject retry@frame=7 --pairs-out p.csv");
    EXPECT_EQ(gap.status, 2);
    EXPECT_EQ(gap.err, "cdvp run: --inject: 'retry@frame=7': frame 7 is not one of the run's frames (trace t.csv)\n");
    EXPECT_EQ(files(), std::vector<std::string>{"t.csv"});
}

TEST_F(CliFaults, SpecsTheDriverCannotMeetAreBadInput) {
    struct Case {
        const char* args;
        const char* message;
    };
    const Case cases[] = {
        {"--transfer pio --inject dma-hang@frame=1", "cdvp run: --inject: 'dma-hang@frame=1' faults a DMA; it needs --transfer dma\n"},
        {"--wait poll --inject lost-irq@frame=1", "cdvp run: --inject: 'lost-irq@frame=1' loses an interrupt; it needs --wait irq\n"},
        {"--inject boom@frame=1", "cdvp run: --inject: 'boom@frame=1': unknown fault kind 'boom'; expected one of: "
                                  "target-abort, master-abort, retry, disconnect, lost-irq, dma-hang, board-error\n"},
        {"--inject retry@frame=-1", "cdvp run: --inject: 'retry@frame=-1': frame: expected an integer from 0 to "
                                    "18446744073709551615, found '-1'\n"},
        {"--inject ''", "cdvp run: --inject: expected KIND@frame=N[,n=K]; kinds: target-abort, master-abort, retry, "
                        "disconnect, lost-irq, dma-hang, board-error\n"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        const Result r = run(kScene + " " + c.args + " --pairs-out p.csv");
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.err, c.message);
        EXPECT_EQ(files(), std::vector<std::string>{});
    }
}

TEST_F(CliFaults, SeveralSpecsInOneFlagOrRepeated) {
    const std::string clean = clean_pairs();
    ASSERT_EQ(run(kScene + " --inject 'retry@frame=0; lost-irq@frame=1' --inject disconnect@frame=2 --pairs-out p.csv "
                           "--report r.json").status, 0);
    EXPECT_EQ(slurp(dir_ / "p.csv"), clean);
    EXPECT_EQ(report_of(dir_ / "r.json")["config"]["inject"],
              nlohmann::json::array({"retry@frame=0", "lost-irq@frame=1", "disconnect@frame=2"}));
}

}  // namespace
}  // namespace cdvp::test
