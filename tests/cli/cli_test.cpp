// The cdvp command line, run as users run it.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

#include "models/address_generator/address_generator.h"
#include "sw/scene/pairs_csv.h"

using cdvp::test::Result;
using cdvp::test::slurp;
using cdvp::test::report_of;
using Cli = cdvp::test::Cli;
namespace fs = std::filesystem;

namespace {

TEST_F(Cli, HardCasesGiveTheHandDerivedPairs) {
    for (int m : {1, 2, 5}) {
        const Result r = run("run --trace " + trace("hard_cases.csv") + " --m " + std::to_string(m) +
                             " --pairs-out pairs.csv --quiet");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.out, "") << "--quiet prints nothing";
        EXPECT_EQ(cdvp::read_pairs_csv((dir_ / "pairs.csv").string()),
                  cdvp::read_pairs_csv(trace("hard_cases.expected.csv")))
            << "m=" << m;
    }
}

TEST_F(Cli, SmallTracePairsAndReport) {
    const Result r = run("run --trace " + trace("small.csv") + " --m 2 --pairs-out p.csv --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "p.csv"), slurp(trace("small.expected.csv")));
    const nlohmann::json report = report_of(dir_ / "r.json");
    EXPECT_EQ(report["config"]["m"], 2);
    EXPECT_EQ(report["config"]["pipeline_latency_cycles"], 4);
    ASSERT_EQ(report["frames"].size(), 3u);
    const std::vector<int> pairs = {3, 3, 3};
    for (std::size_t k = 0; k < 3; ++k) {
        const auto& f = report["frames"][k];
        EXPECT_EQ(f["frame"], k);
        EXPECT_EQ(f["objects"], 12);
        EXPECT_EQ(f["pairs"], pairs[k]);
        EXPECT_EQ(f["compute_cycles"].get<uint64_t>(),
                  cdvp::AddressGenerator::sweep_cycles(12, 2) + 4 + f["stall_cycles"].get<uint64_t>());
    }
    EXPECT_NE(r.out.find("total: 3 frames, 9 pairs"), std::string::npos) << r.out;
}

TEST_F(Cli, SpheresAreDeterministicBySeed) {
    const std::string scene = "run --scene spheres --objects 300 --frames 4 --m 4 --quiet";
    ASSERT_EQ(run(scene + " --seed 5 --pairs-out a.csv").status, 0);
    ASSERT_EQ(run(scene + " --seed 5 --pairs-out b.csv").status, 0);
    ASSERT_EQ(run(scene + " --seed 6 --pairs-out c.csv").status, 0);
    EXPECT_EQ(slurp(dir_ / "a.csv"), slurp(dir_ / "b.csv"));
    EXPECT_NE(slurp(dir_ / "a.csv"), slurp(dir_ / "c.csv"));
    EXPECT_GT(cdvp::read_pairs_csv((dir_ / "a.csv").string()).size(), 100u) << "a scene with something to find";
}

TEST_F(Cli, HelpListsEveryOption) {
    const Result top = run("--help");
    EXPECT_EQ(top.status, 0);
    EXPECT_NE(top.out.find("run "), std::string::npos);
    const Result help = run("run --help");
    EXPECT_EQ(help.status, 0);
    for (const char* flag : {"--trace", "--scene", "--objects", "--frames", "--seed", "--m ", "--clock-mhz", "--board",
                             "--transfer", "--wait", "--baseline", "--host-factor",
                             "--compare-latency", "--fifo-depth", "--drain-rate", "--pair-buffer", "--pairs-out",
                             "--report", "--vcd", "--quiet"}) {
        EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
    }
    EXPECT_NE(help.out.find("no abbreviations"), std::string::npos) << "the prefix rule is documented";
}

// The command-line reference (docs/cli.md) is what the binary prints: every
// command's --help appears there verbatim, so neither can drift
// (scripts/cli-help.py writes them there).
TEST_F(Cli, DocsCarryEveryCommandsHelpVerbatim) {
    std::ifstream in(CDVP_SOURCE_DIR "/docs/cli.md");
    std::stringstream page;
    page << in.rdbuf();
    ASSERT_FALSE(page.str().empty());
    for (const char* command : {"", "run", "fidelity", "settings", "sweep", "merge", "bullet", "record", "calibrate", "rtl-variants"}) {
        const Result help = run(std::string(command) + " --help");
        ASSERT_EQ(help.status, 0) << command;
        EXPECT_NE(page.str().find("```\n" + help.out + "```\n"), std::string::npos)
            << "docs/cli.md lacks the current 'cdvp " << command << " --help': run scripts/cli-help.py";
    }
}

// The presets --board lists are the ones it finds: none is left out of the help.
TEST_F(Cli, RunHelpListsEveryPreset) {
    const Result help = run("run --help");
    ASSERT_EQ(help.status, 0);
    std::string flat;  // the help with its wrapping undone
    for (const char c : help.out) {
        if (c == '\n' || c == ' ') {
            if (!flat.empty() && flat.back() != ' ') flat += ' ';
        } else {
            flat += c;
        }
    }
    int presets = 0;
    for (const auto& entry : std::filesystem::directory_iterator(CDVP_SOURCE_DIR "/platform/boards")) {
        if (entry.path().extension() != ".json") continue;
        ++presets;
        const std::string name = entry.path().stem().string();
        EXPECT_TRUE(flat.find(name + ",") != std::string::npos || flat.find(name + ")") != std::string::npos)
            << name << " not in: " << flat.substr(0, 2000);
    }
    EXPECT_GE(presets, 4);
}

// Progress where stderr is captured: none by default (auto shows it on a
// terminal only), a line a second and the last frame's with --progress
// lines, none with -q whatever --progress says.
TEST_F(Cli, ProgressLinesForWhateverCapturesStderr) {
    const std::string run_small = "run --scene spheres --objects 40 --frames 12 --fidelity analytic ";
    const Result quiet_default = run(run_small);
    ASSERT_EQ(quiet_default.status, 0) << quiet_default.err;
    EXPECT_EQ(quiet_default.err.find("frame "), std::string::npos) << quiet_default.err;
    const Result lines = run(run_small + "--progress lines");
    ASSERT_EQ(lines.status, 0) << lines.err;
    EXPECT_EQ(lines.err.find('\r'), std::string::npos) << "lines, not a line kept in place";
    EXPECT_NE(lines.err.find("cdvp run: frame 12/12 (100%), "), std::string::npos) << lines.err;
    EXPECT_EQ(run(run_small + "--progress lines -q").err, "");
    EXPECT_EQ(run(run_small + "--progress none").err.find("frame "), std::string::npos);
    expect_refusal(run(run_small + "--progress sometimes"),
                   "cdvp run: --progress: expected auto, lines or none, got 'sometimes'\n");
}

// Every help fits a terminal of 80 columns and no line ends in spaces.
TEST_F(Cli, EveryHelpFitsEightyColumnsWithoutTrailingSpaces) {
    for (const char* command : {"", "run", "fidelity", "settings", "sweep", "merge", "bullet", "record", "calibrate", "rtl-variants"}) {
        const Result help = run(std::string(command) + " --help");
        ASSERT_EQ(help.status, 0) << command;
        std::istringstream lines(help.out);
        std::string line;
        int number = 0;
        while (std::getline(lines, line)) {
            ++number;
            EXPECT_LE(line.size(), 80u) << "cdvp " << command << " --help, line " << number << ": " << line;
            EXPECT_TRUE(line.empty() || line.back() != ' ') << "cdvp " << command << " --help, line " << number;
        }
        EXPECT_GT(number, 5) << command;
    }
}

TEST_F(Cli, TopLevelCommandLine) {
    const Result none = run("");
    EXPECT_EQ(none.status, 2);
    EXPECT_EQ(none.out, "");
    EXPECT_EQ(none.err.rfind("Usage: cdvp <command>", 0), 0u) << "usage goes to stderr on error";
    const Result version = run("--version");
    EXPECT_EQ(version.status, 0);
    EXPECT_EQ(version.out, "cdvp 0.1.0\n");
    for (const char* bad : {"frobnicate", "--frobnicate", "-x", "ru"}) {
        const Result r = run(bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_EQ(r.err, std::string("cdvp: unknown command '") + bad +
                             "'; expected one of: run, fidelity, settings, sweep, merge, bullet, record, calibrate, rtl-variants, help (see cdvp --help)\n");
    }
    EXPECT_EQ(run("run").err, "cdvp run: give exactly one of --trace FILE or --scene NAME (spheres, pile, heavy, planar, "
                              "brownian, or one of Bullet's)\n");
    // cdvp help [COMMAND]: the same text as --help.
    EXPECT_EQ(run("help").out, run("--help").out);
    for (const char* command : {"run", "sweep", "merge", "settings", "bullet"}) {
        const Result help = run(std::string("help ") + command);
        EXPECT_EQ(help.status, 0) << command;
        EXPECT_EQ(help.out, run(std::string(command) + " --help").out) << command;
    }
    EXPECT_EQ(run("help frobnicate").status, 2);
    EXPECT_EQ(run("help run extra").err, "cdvp help: unexpected argument 'extra' (see cdvp --help)\n");
}

TEST_F(Cli, AnEmptyPresetDirectoryIsSaidSoNotListedAsNothing) {
    fs::create_directories(dir_ / "none");
    const Result r = run("run --scene spheres --board adm-xrc-ii", "CDVP_BOARDS=none");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "cdvp run: --board: unknown board 'adm-xrc-ii': $CDVP_BOARDS (none) holds no preset (NAME.json); "
                     "give a .json path, or unset CDVP_BOARDS\n");
    EXPECT_EQ(run("run --scene spheres --objects 5 --board adm-xrc-ii -q", "CDVP_BOARDS=").status, 0)
        << "an empty CDVP_BOARDS is unset";
}

TEST_F(Cli, ControlCharactersInArgumentsKeepErrorsOnOneLine) {
    const Result r = run("run --scene \"$(printf 'two\\nlines\\033[31m')\"");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "cdvp run: --scene: expected spheres, pile, heavy, planar, brownian or one of Bullet's scenes (pyramid, boxes, mixed, stack, "
                     "bullet-spheres), got 'two\\nlines\\x1b[31m'\n");
}

TEST_F(Cli, BoardRunTimesBaselinesAndReportsConsistentPhases) {
    const Result r = run("run --board adm-xrc-ii --scene spheres --objects 150 --frames 4 --m 8 "
                         "--baseline sap,dbvt,brute,soa --host-factor 2.5 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json report = report_of(dir_ / "r.json");
    EXPECT_EQ(report["config"]["board"], "adm-xrc-ii");
    EXPECT_EQ(report["config"]["host_factor"], 2.5);
    EXPECT_EQ(report["config"]["transfer"], "dma");
    ASSERT_EQ(report["frames"].size(), 4u);
    for (const auto& f : report["frames"]) {
        double sum = 0;
        for (const char* phase : {"upload_ns", "start_ns", "compute_ns", "irq_ns", "readback_ns", "driver_ns"}) {
            ASSERT_TRUE(f.contains(phase)) << phase;
            EXPECT_GE(f[phase].get<double>(), 0.0) << phase;
            sum += f[phase].get<double>();
        }
        EXPECT_NEAR(sum, f["total_ns"].get<double>(), 1e-6 * f["total_ns"].get<double>());
        EXPECT_NEAR(f["compute_ns"].get<double>(), f["compute_cycles"].get<double>() * 1e3 / 66.0, 1e-3);
        for (const char* b : {"sap", "dbvt", "brute", "soa"}) {
            ASSERT_TRUE(f["baselines"].contains(b)) << b;
            EXPECT_GT(f["baselines"][b]["native_ns"].get<double>(), 0.0);
            EXPECT_DOUBLE_EQ(f["baselines"][b]["host_ns"].get<double>(), 2.5 * f["baselines"][b]["native_ns"].get<double>());
        }
    }
    const auto& summary = report["summary"];
    EXPECT_EQ(summary["frames_in_means"], 2) << "the two warm-up frames are left out of the statistics";
    const auto& sap = summary["baselines"]["sap"];
    EXPECT_DOUBLE_EQ(sap["mean_host_ns"].get<double>(), 2.5 * sap["mean_native_ns"].get<double>());
    EXPECT_NEAR(sap["speedup"].get<double>(),
                sap["mean_host_ns"].get<double>() / summary["mean_total_ns"].get<double>(), 1e-9)
        << "a ratio of means";
    EXPECT_NE(r.out.find("speedup"), std::string::npos) << r.out;
}

TEST_F(Cli, TraceOnThePaperBoardByPioAndPolling) {
    const Result r = run("run --trace " + trace("hard_cases.csv") + " --board adm-xrc-ii --m 4 --transfer pio "
                         "--wait poll --baseline sap,dbvt,brute,soa --pairs-out p.csv --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(cdvp::read_pairs_csv((dir_ / "p.csv").string()), cdvp::read_pairs_csv(trace("hard_cases.expected.csv")))
        << "infinite slabs, denormals and touching boxes through PCI and every baseline";
    const nlohmann::json report = report_of(dir_ / "r.json");
    EXPECT_EQ(report["config"]["transfer"], "pio");
    EXPECT_EQ(report["config"]["wait"], "poll");
    const auto& f = report["frames"][0];
    EXPECT_LT(f["irq_ns"].get<double>(), 1000.0) << "polling notices within one status read, not 10 us";
    EXPECT_GT(f["upload_ns"].get<double>(), 0.0);
}

// Bad input: exit status 2, one line naming the file and line (or the flag)
// and what was expected, and no output file left behind.
struct BadInput {
    const char* name;
    const char* trace;  // written to bad.csv; nullptr: use small.csv
    const char* flags;
    const char* message;
};

class CliBadInput : public Cli, public ::testing::WithParamInterface<BadInput> {};

#define HEADER "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n"
#define BOX "0,1,0,0,0,1,1,1\n"
INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"NaN", HEADER BOX "0,2,0,nan,0,1,1,1\n", "", "bad.csv:3: field 'min_y': NaN"},
        BadInput{"MinAboveMax", HEADER BOX "0,2,0,0,5,1,1,1\n", "", "bad.csv:3: min_z (5) is greater than max_z"},
        BadInput{"FieldCount", HEADER BOX "0,2,0,0,0,1,1\n", "", "bad.csv:3: expected 8 comma-separated fields"},
        BadInput{"NotANumber", HEADER "0,1,0,0,0,1,x1,1\n", "", "bad.csv:2: field 'max_y': expected a decimal"},
        BadInput{"WrongHeader", "frame,id,x,y,z\n" BOX, "", "bad.csv:1: expected header"},
        BadInput{"DuplicateId", HEADER BOX "0,1,2,2,2,3,3,3\n", "", "bad.csv:3: id 1 appears twice in frame 0"},
        BadInput{"FramesOutOfOrder", HEADER "1,1,0,0,0,1,1,1\n" BOX, "", "bad.csv:3: frame 0 after frame 1"},
        BadInput{"NegativeId", HEADER "0,-1,0,0,0,1,1,1\n", "", "bad.csv:2: field 'id': expected a non-negative"},
        BadInput{"MissingTrace", nullptr, "--trace nowhere.csv", "nowhere.csv: cannot open"},
        BadInput{"ZeroM", nullptr, "--m 0", "--m: expected an integer from 1 to 32, got"},
        BadInput{"AbsurdM", nullptr, "--m 100000", "--m: expected an integer from 1 to 32, got"},
        BadInput{"NonNumericM", nullptr, "--m eight", "--m: expected an integer from 1 to 32, got 'eight'"},
        BadInput{"SmallFifo", nullptr, "--m 8 --fifo-depth 4", "--fifo-depth: expected 2m-1 = 15"},
        BadInput{"UnknownBoard", nullptr, "--board nope", "--board: unknown board 'nope'; expected one of: adm-xrc-ii"},
        BadInput{"UnknownBaseline", nullptr, "--baseline sap,fast", "--baseline: unknown baseline 'fast'"},
        BadInput{"RepeatedBaseline", nullptr, "--baseline sap,dbvt,sap", "--baseline: 'sap' given twice"},
        BadInput{"BadTransfer", nullptr, "--transfer usb", "--transfer: expected dma or pio"},
        BadInput{"BadWait", nullptr, "--wait sleep", "--wait: expected irq or poll"},
        BadInput{"TooManyBlockRams", nullptr, "--board adm-xrc-ii --m 30", "(largest m that fits: 24; --ignore-capacity"},
        BadInput{"UnwritableOutput", nullptr, "--report no/such/dir/r.json",
                 "--report: no/such/dir/r.json: cannot write: directory 'no/such/dir' does not exist"},
        // Numbers: one checked parser for every option; what the user typed is quoted.
        BadInput{"MWrapsAround", nullptr, "--m -4294967295", "--m: expected an integer from 1 to 32, got '-4294967295'"},
        BadInput{"NegativeM", nullptr, "--m -1", "--m: expected an integer from 1 to 32, got '-1'"},
        BadInput{"PairBufferWrapsAround", nullptr, "--pair-buffer -4294967295",
                 "--pair-buffer: expected an integer from 1 to 2097152, got '-4294967295'"},
        BadInput{"FifoWrapsAround", nullptr, "--fifo-depth -4294966784",
                 "--fifo-depth: expected an integer from 1 to 1048576, got '-4294966784'"},
        BadInput{"NegativeSeed", nullptr, "--scene spheres --seed -1",
                 "--seed: expected an integer from 0 to 18446744073709551615, got '-1'"},
        BadInput{"SeedTooLarge", nullptr, "--scene spheres --seed 18446744073709551616", "got '18446744073709551616'"},
        BadInput{"FractionalObjects", nullptr, "--scene spheres --objects 2.5", "--objects: expected an integer"},
        BadInput{"ExponentM", nullptr, "--m 1e1", "--m: expected an integer from 1 to 32, got '1e1'"},
        BadInput{"HexM", nullptr, "--m 0x8", "got '0x8'"},
        BadInput{"SignedM", nullptr, "--m +8", "got '+8'"},
        BadInput{"BlankM", nullptr, "--m ' 8'", "got ' 8'"},
        BadInput{"EmptyM", nullptr, "--m ''", "--m: expected an integer from 1 to 32, got ''"},
        BadInput{"HugeObjects", nullptr, "--scene spheres --objects 99999999999999999999999",
                 "--objects: expected an integer from 0 to 4194304, got '99999999999999999999999'"},
        BadInput{"NegativeFrames", nullptr, "--scene spheres --frames -1", "--frames: expected an integer"},
        BadInput{"NanClock", nullptr, "--clock-mhz nan", "--clock-mhz: expected a number from 1 to 1000, got 'nan'"},
        BadInput{"InfClock", nullptr, "--clock-mhz inf", "got 'inf'"},
        BadInput{"HexClock", nullptr, "--clock-mhz 0x42", "got '0x42'"},
        BadInput{"ClockTooHigh", nullptr, "--clock-mhz 1e6", "got '1e6'"},
        BadInput{"ClockWithUnit", nullptr, "--clock-mhz 66MHz", "got '66MHz'"},
        BadInput{"CompareTooDeep", nullptr, "--compare-latency 65", "--compare-latency: expected an integer from 0 to 64"},
        BadInput{"NoDrain", nullptr, "--drain-rate 0", "--drain-rate: expected an integer from 1 to 64, got '0'"},
        BadInput{"ZeroHostFactor", nullptr, "--host-factor 0", "--host-factor: expected a number from 0.001 to 1000"},
        BadInput{"NegativeHostFactor", nullptr, "--host-factor -1", "got '-1'"},
        BadInput{"RunTooLongForSystemC", nullptr, "--scene spheres --objects 4000000 --m 1",
                 "a run of 12 frames (the default of --frames) of up to 4000000 objects (--objects) at --m 1 and "
                 "66 MHz (the default of --clock-mhz) would reach "},
        BadInput{"ModelTooLargeForTheMemoryBudget", nullptr, "--scene spheres --objects 4194304 --m 32 --max-memory 2048",
                 "--max-memory: the memory budget of 2048 MiB (--max-memory 2048) is too little for 4194304 objects "
                 "(--objects) in 12 frames (the default of --frames): they need an estimated "},
        // Words: no stray arguments, no abbreviations, no empty paths or names.
        BadInput{"StrayArgument", nullptr, "extra", "unexpected argument 'extra'"},
        BadInput{"AbbreviatedOption", nullptr, "--rep r.json", "unrecognised option '--rep'"},
        BadInput{"RepeatedOption", nullptr, "--m 2 --m 3", "'--m' cannot be specified more than once"},
        BadInput{"EmptyTracePath", nullptr, "--trace ''", "--trace: expected a file path, got ''"},
        BadInput{"EmptyBoard", nullptr, "--board ''", "--board: expected a preset name or a .json path, got ''"},
        BadInput{"EmptyReportPath", nullptr, "--report ''", "--report: expected a file path, got ''"},
        BadInput{"EmptyScene", nullptr, "--scene ''", "--scene: expected spheres, pile, heavy, planar, brownian or one of Bullet's scenes"},
        BadInput{"BoardIsADirectory", nullptr, "--board ./", "./: cannot open: Is a directory (EISDIR)"},
        BadInput{"OutputIsADirectory", nullptr, "--report .", "--report: .: cannot write: is a directory"},
        BadInput{"OutputInAFile", nullptr, "--report " CDVP_SOURCE_DIR "/README.md/r.json", "is not a directory"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });
#undef BOX
#undef HEADER

TEST_P(CliBadInput, ExitsWithOneLineAndWritesNothing) {
    const BadInput& c = GetParam();
    std::string args = "run ";
    if (c.trace != nullptr) {
        write("bad.csv", c.trace);
        args += "--trace bad.csv ";
    } else if (std::string(c.flags).find("--trace") == std::string::npos &&
               std::string(c.flags).find("--scene") == std::string::npos) {
        args += "--trace " + trace("small.csv") + " ";
    }
    args += std::string(c.flags) + " --pairs-out pairs.csv --vcd waves.vcd" +
            (std::string(c.flags).find("--report") == std::string::npos ? " --report report.json" : "");
    const Result r = run(args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "exactly one line: " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    const std::vector<std::string> left = files();
    EXPECT_EQ(left, c.trace ? std::vector<std::string>{"bad.csv"} : std::vector<std::string>{});
}

}  // namespace
