// Hostile command lines, presets and traces: every refusal is one short line
// on stderr naming where the bad value came from, exit status 2, no output.
#include <gtest/gtest.h>

#include "tests/cli/cli_support.h"
#include "tests/platform/nested_text.h"

namespace cdvp::test {
namespace {

// A shell word expanding to 100,000 'x's.
const std::string kHuge = "\"$(head -c 100000 /dev/zero | tr '\\0' x)\"";

void expect_refused(const Result& r, const std::string& start) {
    expect_refusal(r, "cdvp run: " + start);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line, at the end";
}

TEST_F(Cli, ArgumentsAfterDoubleDashArePositionalSoHelpThereIsStray) {
    const Result r = run("run --scene spheres -- --help");
    expect_refused(r, "unexpected argument '--help'");
    EXPECT_EQ(run("run --help --").status, 0) << "before '--' it is still help";
}

TEST_F(Cli, HugeValuesAreQuotedShortInEveryMessage) {
    const std::string small = "--trace " + trace("small.csv") + " --pairs-out p.csv ";
    struct Case {
        std::string args, start;
    };
    const Case cases[] = {
        {small + "--m " + kHuge, "--m: expected an integer from 1 to 32, got 'xxxx"},
        {small + "--clock-mhz " + kHuge, "--clock-mhz: expected a number from 1 to 1000, got 'xxxx"},
        {"--scene " + kHuge,
         "--scene: expected spheres, pile, heavy, planar, brownian or one of Bullet's scenes (pyramid, boxes, mixed, stack, bullet-spheres), got 'xxxx"},
        {small + "--transfer " + kHuge, "--transfer: expected dma or pio, got 'xxxx"},
        {small + "--wait " + kHuge, "--wait: expected irq or poll, got 'xxxx"},
        {small + "--baseline " + kHuge, "--baseline: unknown baseline 'xxxx"},
        {small + "--inject " + kHuge, "--inject: 'xxxx"},
        {small + "--inject retry@frame=" + kHuge, "--inject: 'retry@frame=xxxx"},
        {small + "--board " + kHuge, "--board: expected a path of at most 4095 bytes, got 'xxxx"},
        {small + kHuge, "unexpected argument 'xxxx"},
        {small + "--" + kHuge, "unrecognised option '--xxxx"},
        {"--trace " + kHuge, "--trace: expected a path of at most 4095 bytes, got 'xxxx"},
        {small + "--report " + kHuge, "--report: expected a path of at most 4095 bytes, got 'xxxx"},
        {small + "--vcd " + kHuge + "/w.vcd", "--vcd: expected a path of at most 4095 bytes, got 'xxxx"},
        {small + "--board " + kHuge + ".json", "--board: expected a path of at most 4095 bytes, got 'xxxx"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.start);
        const Result r = run("run " + c.args);
        expect_refused(r, c.start);
        EXPECT_NE(r.err.find(std::string(50, 'x') + "... (1000"), std::string::npos) << r.err.substr(0, 300);
        EXPECT_LT(r.err.size(), 300u);
        EXPECT_EQ(files(), std::vector<std::string>{});
    }
}

TEST_F(Cli, HugeTraceFieldAndPresetStringAreQuotedShort) {
    // A trace line holds at most 4096 bytes.
    write("t.csv", "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n0,1," + std::string(4000, '7') + "x,0,0,1,1,1\n");
    const Result field = run("run --trace t.csv --quiet");
    expect_refused(field, "t.csv:2: field 'min_x': expected a decimal number, found '7777");
    EXPECT_NE(field.err.find(std::string(60, '7') + "... (4001 bytes)'"), std::string::npos) << field.err.substr(0, 300);
    EXPECT_LT(field.err.size(), 300u);

    std::string text = slurp(preset("adm-xrc-ii"));
    text.replace(text.find("\"pci\""), 5, "\"" + std::string(100000, 'p') + "\"");
    write("board.json", text);
    const Result type = run("run --trace " + trace("small.csv") + " --board board.json --quiet");
    expect_refused(type, "board.json: bus.type: expected \"pci\" or \"pcie\", got \"pppp");
    EXPECT_NE(type.err.find(std::string(60, 'p') + "... (100000 bytes)\""), std::string::npos);
    EXPECT_LT(type.err.size(), 300u);
}

TEST_F(Cli, TooFewBlockRamsBlameThePresetKeyAndNameWhereMAndNCameFrom) {
    const Result flag_m = run("run --scene spheres --objects 500 --board adm-xrc-ii --m 30 --quiet");
    expect_refused(flag_m, preset("adm-xrc-ii") + ": device.block_rams: 144 block RAMs are too few for --m 30 at 500 "
                           "objects (--objects): they need 6 x m x ceil(N/512) = 180 (largest m that fits: 24; "
                           "--ignore-capacity runs it anyway)\n");

    std::string text = slurp(preset("adm-xrc-ii"));
    text.replace(text.find("\"value\": 144"), 12, "\"value\": 40");
    write("board.json", text);
    const Result default_m = run("run --trace " + trace("small.csv") + " --board board.json --quiet");
    expect_refused(default_m, "board.json: device.block_rams: 40 block RAMs are too few for m=8 (the default of --m) "
                              "at ");
    EXPECT_NE(default_m.err.find(" objects (the largest frame of --trace "), std::string::npos) << default_m.err;
    EXPECT_NE(default_m.err.find("(largest m that fits: 6; --ignore-capacity runs it anyway)"), std::string::npos)
        << default_m.err;
}

TEST_F(Cli, FifoDepthCheckNamesWhereMCameFrom) {
    std::string text = slurp(preset("adm-xrc-ii"));
    text.replace(text.find("\"fifo_depth\": {\"value\": 512"), 27, "\"fifo_depth\": {\"value\": 4");
    write("board.json", text);
    const Result r = run("run --trace " + trace("small.csv") + " --board board.json --quiet");
    expect_refused(r, "board.json: board.fifo_depth: expected 2m-1 = 15 (one cycle's hits) to 1048576 pairs, got 4 "
                      "(with m=8 (the default of --m))\n");
}

// Files 40 KB and 20,000 levels deep, far under the 1 MiB cap, overflowed
// the stack (SIGSEGV). Past 64 levels they are refused at the level too many,
// for --board and --config alike; at 64 they are read on, and refused for
// what they hold.
TEST_F(Cli, DeeplyNestedPresetsAndConfigFilesAreRefusedNotACrash) {
    write("deep.json", repeated("{\"board\":", 20000) + "1" + repeated("}", 20000) + "\n");
    write("deep_arrays.json", "{\"board\": " + repeated("[", 20000) + repeated("]", 20000) + "}\n");
    write("headers.toml", "[" + repeated("a.", 19999) + "a]\nx=1\n");
    write("dotted.toml", repeated("a.", 20000) + "b={c=1}\n");
    const std::string run_with = "run --scene spheres --objects 10 --quiet ";
    const std::string refused = " nesting deeper than 64 levels; ";
    const std::string preset = refused + "a board preset nests objects and arrays at most 64 deep\n";
    expect_refused(run(run_with + "--board deep.json"), "deep.json:1:577:" + preset);
    expect_refused(run(run_with + "--board deep_arrays.json"), "deep_arrays.json:1:74:" + preset);
    const std::string json = refused + "a config file nests objects and arrays at most 64 deep\n";
    const std::string toml = refused + "a config file nests tables and arrays at most 64 deep\n";
    expect_refused(run(run_with + "--config deep.json"), "deep.json:1:577:" + json);
    expect_refused(run(run_with + "--config headers.toml"), "headers.toml:1:128:" + toml);
    expect_refused(run(run_with + "--config dotted.toml"), "dotted.toml:1:127:" + toml);

    write("limit.json", repeated("{\"board\":", 64) + "1" + repeated("}", 64) + "\n");
    write("limit.toml", "[" + repeated("board.", 62) + "m]\nx = 1\n");
    expect_refused(run(run_with + "--board limit.json"), "limit.json: name: expected a non-empty string\n");
    const Result config_at_limit = run(run_with + "--config limit.toml");
    expect_refused(config_at_limit, "limit.toml:2: board.board.board.");
    EXPECT_NE(config_at_limit.err.find(": unknown setting"), std::string::npos) << config_at_limit.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"deep.json", "deep_arrays.json", "dotted.toml", "headers.toml",
                                                 "limit.json", "limit.toml"}));
}


// A multi-threaded baseline the system will not start all the threads of (2
// GiB of address space: 8 MiB of stack a thread) is refused in one line naming
// --threads, exit 4, neither hanging (the timeout) nor aborting; as many
// threads as the system has run.
TEST_F(Cli, ThreadsTheSystemWillNotStartAreRefusedNamingThreads) {
#ifdef CDVP_ADDRESS_SANITIZER
    GTEST_SKIP() << "AddressSanitizer cannot start under ulimit -v (its shadow memory); the Release build runs this";
#endif
    const std::string limited = "ulimit -v 2097152 && timeout 120";
    const std::string args = "run --board adm-xrc-ii --scene spheres --objects 50 --frames 2 -q --baseline ";
    for (const char* baseline : {"sap_mt", "prune_mt", "hgrid_mt"}) {
        const Result r = run(args + baseline + " --threads 1024", limited);
        EXPECT_EQ(r.status, 4) << baseline << ": " << r.err;
        EXPECT_EQ(r.err.rfind("cdvp run: --threads: 1024 threads asked; the system started ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("expected fewer\n"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    const Result fewer = run(args + "sap_mt --threads 4", limited);
    EXPECT_EQ(fewer.status, 0) << fewer.err;
    // The case found from outside: the default board and 2,000 spheres.
    const Result spheres = run("run --scene spheres --objects 2000 -q --baseline sap_mt --threads 1024", limited);
    EXPECT_EQ(spheres.status, 4) << spheres.err;
    EXPECT_EQ(spheres.err.rfind("cdvp run: --threads: 1024 threads asked; the system started ", 0), 0u) << spheres.err;
}

}  // namespace
}  // namespace cdvp::test
