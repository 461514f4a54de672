// `cdvp run --board FILE` with a bad preset: exit 2 and one line naming the
// file and the key (issue 6, defect 8).
#include <gtest/gtest.h>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

struct BadPreset {
    const char* name;
    const char* replace;  // text of adm-xrc-ii.json ...
    const char* with;     // ... replaced by this
    const char* flags;
    const char* message;  // after "cdvp run: board.json"
};

class CliBadPreset : public Cli, public ::testing::WithParamInterface<BadPreset> {};

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadPreset,
    ::testing::Values(
        BadPreset{"NegativeInterrupt", "\"interrupt_ns\": {\"value\": 10000", "\"interrupt_ns\": {\"value\": -5", "",
                  ": bus.interrupt_ns: expected 0 to 1000000 ns, got -5"},
        BadPreset{"HugeInterrupt", "\"interrupt_ns\": {\"value\": 10000", "\"interrupt_ns\": {\"value\": 1e300", "",
                  ": bus.interrupt_ns: expected 0 to 1000000 ns, got 1e+300"},
        BadPreset{"TinyLocalBusClock", "\"local_bus_clock_mhz\": {\"value\": 66", "\"local_bus_clock_mhz\": {\"value\": 1e-300",
                  "", ": bus.local_bus_clock_mhz: expected 1 to 1000 MHz, got 1e-300"},
        BadPreset{"NegativePioOverhead", "\"host_pio_overhead_ns\": {\"value\": 200",
                  "\"host_pio_overhead_ns\": {\"value\": -200", "", ": bus.host_pio_overhead_ns: expected 0 to 1000000 ns"},
        BadPreset{"NegativeBoxCost", "\"ns_per_box\": {\"value\": 25", "\"ns_per_box\": {\"value\": -25", "",
                  ": host.ns_per_box: expected 0 to 1000000 ns, got -25"},
        BadPreset{"FractionalCount", "\"wait_states\": {\"value\": 0", "\"wait_states\": {\"value\": 0.5", "",
                  ": bus.wait_states: expected a whole number of clocks, got 0.5"},
        BadPreset{"UnknownKey", "\"interrupt_ns\"", "\"interupt_ns\"", "",
                  ": bus.interupt_ns: unknown key; did you mean 'interrupt_ns'?"},
        BadPreset{"UnknownSection", "\"host\": {", "\"hots\": {", "", ": hots: unknown key; did you mean 'host'?"},
        BadPreset{"UnknownFieldKey", "{\"value\": 2, \"source\": \"assumption: REQ#",
                  "{\"value\": 2, \"sauce\": \"assumption: REQ#", "",
                  ": bus.arbitration_clocks: expected {\"value\": <number>, \"source\": \"<source or assumption>\"}, found 'sauce'"},
        BadPreset{"RepeatedKey", "\"wait_states\": {\"value\": 0,", "\"wait_states\": {\"value\": 0, \"value\": 1,", "",
                  ": bus.wait_states.value: key given twice"},
        BadPreset{"MissingKey", "\"call_ns\"", "\"call_nanoseconds\"", "",
                  ": host.call_nanoseconds: unknown key; did you mean 'call_ns'?"},
        BadPreset{"BadJson", "\"host\": {", "\"host\" {", "", ":48:10: invalid JSON: syntax error"},
        BadPreset{"FifoTooSmallForM", "\"fifo_depth\": {\"value\": 512", "\"fifo_depth\": {\"value\": 4", "--m 8",
                  ": board.fifo_depth: expected 2m-1 = 15 (one cycle's hits) to 1048576 pairs, got 4 (with --m 8)"},
        BadPreset{"ControlCharacterInName", "\"name\": \"adm-xrc-ii\"", "\"name\": \"adm\\u001b[2J\"", "",
                  ": name: control character \\x1b in a string; expected printable text"},
        BadPreset{"RawControlCharacterInHostName", "\"name\": \"pentium4-1.8\"", "\"name\": \"p4\x07\"", "",
                  ": host.name: control character \\x07 in a string; expected printable text"},
        BadPreset{"ModelRule", "\"width_bits\": {\"value\": 32", "\"width_bits\": {\"value\": 48", "",
                  ": bus.width_bits: expected 32 or 64, got 48"}),
    [](const ::testing::TestParamInfo<BadPreset>& info) { return info.param.name; });

TEST_P(CliBadPreset, ExitsWithOneLineNamingFileAndKey) {
    const BadPreset& c = GetParam();
    std::string text = slurp(preset("adm-xrc-ii"));
    const std::size_t at = text.find(c.replace);
    ASSERT_NE(at, std::string::npos) << c.replace;
    text.replace(at, std::string(c.replace).size(), c.with);
    write("board.json", text);
    const Result r = run("run --trace " + trace("small.csv") + " --board board.json " + c.flags +
                         " --pairs-out p.csv --report r.json --vcd w.vcd");
    EXPECT_EQ(2, r.status) << r.err;
    EXPECT_EQ(0u, r.err.rfind(std::string("cdvp run: board.json") + c.message, 0)) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_EQ(std::vector<std::string>{"board.json"}, files());
}

TEST_F(Cli, FlagStillNamesItselfOverAPreset) {
    const Result r = run("run --trace " + trace("small.csv") + " --board adm-xrc-ii --m 8 --fifo-depth 4");
    EXPECT_EQ(2, r.status);
    EXPECT_EQ(0u, r.err.rfind("cdvp run: --fifo-depth: expected 2m-1 = 15", 0)) << r.err;
}

}  // namespace
}  // namespace cdvp::test
