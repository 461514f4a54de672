// Settings from the command line: the layers of `cdvp run` (defaults <
// preset < --config < -c < flags) with their origins in the report, the
// refusals of unknown names and values out of range, `cdvp settings --json`,
// docs/settings.md, and `cdvp fidelity` passing --config and -c on.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "platform/settings/settings.h"
#include "sw/timing/frame_samples.h"
#include "sw/timing/timing_quality.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliSettings : public Cli {
protected:
    std::string small() const { return "run --trace " + trace("small.csv") + " --quiet "; }
public:
    json report() const { return report_of(dir_ / "r.json")["config"]; }
    // A small run with one more setting, reported to r.json.
    Result run_choice(const std::string& setting) { return run(small() + setting + " --report r.json"); }
};

TEST_F(CliSettings, LayersApplyInOrderAndTheReportNamesEachOrigin) {
    write("c.json", R"({"board": {"m": 4, "drain_per_cycle": 2}, "bus": {"interrupt_ns": 7000}, "run.wait": "poll"})");
    const Result r = run(small() + "--board adm-xrc-ii --config c.json -c board.m=5 -c bus.interrupt_ns=5000 "
                                   "--m 6 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json config = report();
    const json& s = config["settings"];
    const auto expect = [&](const char* name, const json& value, const std::string& origin) {
        EXPECT_EQ(s[name]["value"], value) << name;
        EXPECT_EQ(s[name]["origin"], origin) << name;
    };
    expect("board.m", 6, "flag --m");
    expect("bus.interrupt_ns", 5000.0, "-c");
    expect("board.drain_per_cycle", 2, "config c.json");
    expect("run.wait", "poll", "config c.json");
    expect("board.clock_mhz", 66.0, "preset " + preset("adm-xrc-ii"));
    expect("run.transfer", "dma", "default");
    EXPECT_FALSE(s.contains("bus.lanes")) << "only the settings of the bus in effect";
    // The fields other readers use follow the settings.
    EXPECT_EQ(config["m"], 6);
    EXPECT_EQ(config["drain_per_cycle"], 2);
    EXPECT_EQ(config["wait"], "poll");
    EXPECT_EQ(config["version"], "0.1.0");
    EXPECT_EQ(config["seed"], 1);
    EXPECT_EQ(config["command_line"][0], "cdvp");
    EXPECT_EQ(config["command_line"][1], "run");
    EXPECT_EQ(config["command_line"].back(), "r.json");
}

// Every choice a run is given, the report and the summary name as the
// choice's names table does (platform/settings/setting_choices.h): in the settings
// section, and in the config's own keys for the transfer, wait and engine.
template <class T>
void expect_named_as_chosen(CliSettings& cli, const char* setting, const char* config_key = nullptr) {
    for (const ChoiceName<T>& c : Choices<T>::names) {
        const Result r = cli.run_choice(std::string("-c ") + setting + "=" + c.name);
        ASSERT_EQ(r.status, 0) << setting << "=" << c.name << ": " << r.err;
        const json config = cli.report();
        EXPECT_EQ(config["settings"][setting]["value"], c.name) << setting;
        if (config_key != nullptr) {
            EXPECT_EQ(config[config_key], c.name) << setting;
        }
    }
}

TEST_F(CliSettings, TheReportNamesEveryChoiceAsItsNamesTableDoes) {
    expect_named_as_chosen<Transfer>(*this, "run.transfer", "transfer");
    expect_named_as_chosen<WaitMode>(*this, "run.wait", "wait");
    expect_named_as_chosen<ModelLevel>(*this, "run.fidelity", "fidelity");
    expect_named_as_chosen<bool>(*this, "run.ignore_capacity");
    expect_named_as_chosen<BoxMemory>(*this, "board.memory");
    expect_named_as_chosen<DeviceFamily>(*this, "device.family");
    // The bus: a preset's, or none.
    const std::pair<const char*, BusType> buses[] = {
        {"", BusType::kIdeal}, {"--board adm-xrc-ii ", BusType::kPci}, {"--board pcie-gen3-x8 ", BusType::kPcie}};
    for (const auto& [board, type] : buses) {
        const Result r = run(small() + board + "--report r.json");
        ASSERT_EQ(r.status, 0) << board << r.err;
        EXPECT_EQ(report()["settings"]["bus.type"]["value"], name_of(type)) << board;
    }
    // The summary names the engine, or the analytic level, as the report does.
    for (const ChoiceName<ModelLevel>& c : Choices<ModelLevel>::names) {
        const Result r = run("run --trace " + trace("small.csv") + " --fidelity " + c.name);
        ASSERT_EQ(r.status, 0) << r.err;
        const char* what = c.value == ModelLevel::kAnalytic ? " level\n" : " engine\n";
        EXPECT_NE(r.out.find(std::string(", ") + c.name + what), std::string::npos) << r.out;
    }
}

TEST_F(CliSettings, TheBriefsExampleRunsAndChangesTheInterrupt) {
    const std::string scene = "run --scene spheres --objects 50 --board adm-xrc-ii --quiet ";
    ASSERT_EQ(run(scene + "--report base.json").status, 0);
    const Result r = run(scene + "-c bus.interrupt_ns=5000 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const double base = report_of(dir_ / "base.json")["frames"][0]["irq_ns"];
    const double faster = report_of(dir_ / "r.json")["frames"][0]["irq_ns"];
    EXPECT_NEAR(base - faster, 5000.0, 1.0) << "one interrupt a frame, 5 us sooner";
}

TEST_F(CliSettings, TomlAndJsonConfigFilesGiveTheSameRun) {
    write("c.toml", "[board]\nm = 4\n\n[bus]\ninterrupt_ns = 7000\n\n[run]\nwait = \"poll\"\n");
    write("c.json", R"({"board": {"m": 4}, "bus": {"interrupt_ns": 7000}, "run": {"wait": "poll"}})");
    ASSERT_EQ(run(small() + "--board adm-xrc-ii --config c.toml --report t.json").status, 0);
    ASSERT_EQ(run(small() + "--board adm-xrc-ii --config c.json --report j.json").status, 0);
    const json toml = report_of(dir_ / "t.json"), from_json = report_of(dir_ / "j.json");
    EXPECT_EQ(toml["config"]["settings"]["bus.interrupt_ns"]["origin"], "config c.toml:5");
    EXPECT_EQ(from_json["config"]["settings"]["bus.interrupt_ns"]["origin"], "config c.json");
    for (const auto& [name, setting] : toml["config"]["settings"].items()) {
        EXPECT_EQ(setting["value"], from_json["config"]["settings"][name]["value"]) << name;
    }
    EXPECT_EQ(toml["frames"][0]["total_ns"], from_json["frames"][0]["total_ns"]);
}

TEST_F(CliSettings, UnknownNamesAreRefusedWithTheNearest) {
    expect_refusal(run(small() + "-c bus.interupt_ns=5"),
                   "cdvp run: -c bus.interupt_ns: unknown setting; did you mean 'bus.interrupt_ns'?\n");
    write("c.toml", "[board]\nclock_mzh = 50\n");
    expect_refusal(run(small() + "--config c.toml"),
                   "cdvp run: c.toml:2: board.clock_mzh: unknown setting; did you mean 'board.clock_mhz'?\n");
    write("c.json", R"({"scene": {"seeds": 3}})");
    expect_refusal(run(small() + "--config c.json"),
                   "cdvp run: c.json: scene.seeds: unknown setting; did you mean 'scene.seed'?\n");
    expect_refusal(run(small() + "-c board.m"), "cdvp run: -c: expected NAME=VALUE");
}

TEST_F(CliSettings, ValuesOutOfRangeAreRefusedNamingWhereTheyCameFrom) {
    expect_refusal(run(small() + "-c board.m=40"), "cdvp run: -c board.m: expected an integer from 1 to 32, got '40'\n");
    expect_refusal(run(small() + "--board adm-xrc-ii -c bus.interrupt_ns=-5"),
                   "cdvp run: -c bus.interrupt_ns: expected a number from 0 to 1000000, got '-5'\n");
    write("c.toml", "[board]\nm = 40\n");
    expect_refusal(run(small() + "--config c.toml"), "cdvp run: c.toml:2: board.m: expected 1 to 32, got 40\n");
    expect_refusal(run(small() + "-c board.fifo_depth=4"),
                   "cdvp run: -c board.fifo_depth: expected 2m-1 = 15 (one cycle's hits) to 1048576 pairs, got 4 "
                   "(with m=8 (the default of --m))\n");
    expect_refusal(run(small() + "--board adm-xrc-ii -c bus.width_bits=48"),
                   "cdvp run: -c bus.width_bits: expected 32 or 64, got 48\n");
    expect_refusal(run(small() + "-c scene.objects=5"), "cdvp run: -c scene.objects goes with --scene, not --trace\n");
    expect_refusal(run(small() + "-c run.fidelity=fast --vcd w.vcd"), "cdvp run: --vcd: waveforms need the clocked");
    EXPECT_EQ(files(), std::vector<std::string>{"c.toml"});
}

TEST_F(CliSettings, ABusKeyOfTheOtherBusTypeIsRefusedNamingTheBus) {
    expect_refusal(run(small() + "--board adm-xrc-ii -c bus.lanes=4"),
                   "cdvp run: -c bus.lanes: a setting of a pcie bus; the bus is pci (preset " + preset("adm-xrc-ii") +
                       ")\n");
    expect_refusal(run(small() + "-c bus.interrupt_ns=5000"),
                   "cdvp run: -c bus.interrupt_ns: a setting of a pci or pcie bus; the bus is ideal (the default)");
    // Changing the bus type first makes its keys valid.
    EXPECT_EQ(run(small() + "-c bus.type=pcie -c bus.lanes=4").status, 0);
}

// The grid's settings change nothing on the all-pairs board: given there
// (a flag, -c, a config file, a sweep axis, settings), they are refused.
TEST_F(CliSettings, AGridSettingOnTheAllPairsBoardIsRefusedNamingTheAlgorithm) {
    const std::string refused = ": a setting of the grid board; the board is all_pairs (the default): give --algorithm grid\n";
    expect_refusal(run(small() + "-c board.grid.dims=8"), "cdvp run: -c board.grid.dims" + refused);
    expect_refusal(run("settings -c board.grid.cell_capacity=64"), "cdvp settings: -c board.grid.cell_capacity" + refused);
    write("c.toml", "[board.grid]\nmax_span = 4\n");
    expect_refusal(run(small() + "--config c.toml"), "cdvp run: c.toml:2: board.grid.max_span" + refused);
    expect_refusal(run(small() + "--algorithm all_pairs -c board.grid.dims=8"),
                   "cdvp run: -c board.grid.dims: a setting of the grid board; the board is all_pairs (--algorithm)");
    const Result sweep = run("sweep --scene spheres --set board.grid.dims=4,8 --set objects=60 --frames 2 "
                             "--fidelity analytic --out s -q");
    EXPECT_EQ(sweep.status, 2) << sweep.err;
    EXPECT_NE(sweep.err.find("-c board.grid.dims: a setting of the grid board"), std::string::npos) << sweep.err;
    EXPECT_EQ(files(), std::vector<std::string>{"c.toml"}) << "the refused sweep leaves no OUT";
    EXPECT_EQ(run(small() + "--algorithm grid -c board.grid.dims=8").status, 0);
}

TEST_F(CliSettings, SettingsJsonListsEverySettingAndEveryPresetKey) {
    const Result r = run("settings --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json all = json::parse(r.out);
    ASSERT_TRUE(all.is_array());
    std::set<std::string> names, flags;
    for (const json& s : all) {
        for (const char* key : {"name", "type", "unit", "default", "min", "max", "choices", "flag", "help", "source"}) {
            EXPECT_TRUE(s.contains(key)) << s.dump() << ": " << key;
        }
        EXPECT_TRUE(names.insert(s["name"].get<std::string>()).second) << "listed once: " << s["name"];
        if (!s["flag"].is_null()) flags.insert(s["flag"].get<std::string>());
    }
    for (const char* name : {"adm-xrc-ii", "adm-xrc-ii-64", "pcie-gen3-x8", "alveo-u250"}) {
        const json root = json::parse(slurp(preset(name)));
        for (const char* section : {"board", "bus", "host"}) {
            for (const auto& [key, value] : root[section].items()) {
                EXPECT_EQ(names.count(std::string(section) + "." + key), 1u) << name << ": " << section << "." << key;
            }
        }
    }
    for (const char* flag : {"--m", "--clock-mhz", "--compare-latency", "--fifo-depth", "--drain-rate", "--pair-buffer",
                             "--host-factor", "--quantum-ns", "--objects", "--frames", "--seed", "--transfer", "--wait",
                             "--fidelity", "--warmup", "--repeat"}) {
        EXPECT_EQ(flags.count(flag), 1u) << flag;
    }
    EXPECT_EQ(run("settings").status, 0);
    expect_refusal(run("settings --yaml"), "cdvp settings: unknown option '--yaml'");
}

TEST(Settings, TheWarmupDefaultIsTheTimingLibrarys) { EXPECT_EQ(Settings{}.run.warmup, kDefaultWarmupFrames); }
// A run left at its defaults measures enough frames that its figures carry no
// "rest on too few frames" note.
TEST(Settings, TheFramesDefaultIsTheWarmupAndTheFewestMeasuredFrames) {
    EXPECT_EQ(Settings{}.scene.frames, kDefaultWarmupFrames + kMinMeasuredFrames);
}
TEST(Settings, TheRetimeTriesDefaultIsTheTimingLibrarys) { EXPECT_EQ(Settings{}.run.retime_tries, kDefaultRetimeTries); }

TEST_F(CliSettings, TheDocListsTheTableAsCdvpSettingsPrintsIt) {
    const Result r = run("settings --markdown");
    ASSERT_EQ(r.status, 0);
    const std::string doc = slurp(CDVP_SOURCE_DIR "/docs/settings.md");
    EXPECT_NE(doc.find(r.out), std::string::npos)
        << "docs/settings.md is out of date: regenerate its table with ./build/sw/cli/cdvp settings --markdown";
}

TEST_F(CliSettings, FidelityPassesConfigAndOverridesToEveryLevel) {
    write("c.json", R"({"board": {"m": 4}})");
    const Result r = run("fidelity --trace " + trace("small.csv") + " --board adm-xrc-ii --config c.json "
                         "-c bus.interrupt_ns=5000 --out out -q");
    ASSERT_EQ(r.status, 0) << r.err;
    // A bad -c reaches the levels and comes back as their refusal.
    expect_refusal(run("fidelity --trace " + trace("small.csv") + " -c board.mm=4 --out out2 -q"),
                   "cdvp fidelity: -c board.mm: unknown setting; did you mean 'board.m'?\n");
    expect_refusal(run("fidelity --trace " + trace("small.csv") + " -c run.quantum_ns=5 --out out2 -q"),
                   "cdvp fidelity: -c run.quantum_ns: set by cdvp fidelity for each level");
}

TEST_F(Cli, SettingsShowWhatAPresetConfigAndOverridesResolveTo) {
    write("c.toml", "[board]\nfifo_depth = 1024\n");
    const Result r = run("settings --board adm-xrc-ii --config c.toml -c board.m=4");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("board.m = 4  (-c board.m)\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("board.fifo_depth = 1024  (config c.toml:2: board.fifo_depth)\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("board.clock_mhz = 66  (preset "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("board.format = float32  (default)\n"), std::string::npos) << r.out;
    const auto json = nlohmann::json::parse(run("settings --board adm-xrc-ii --json").out);
    bool bus = false;
    for (const auto& s : json) bus |= s["name"] == "bus.type" && s["value"] == "pci";
    EXPECT_TRUE(bus) << "the preset's bus";
    expect_refusal(run("settings --board adm-xrc-ii -c board.fifo_depth=1"), "cdvp settings: -c board.fifo_depth");
    expect_refusal(run("settings -c board.mm=3"), "cdvp settings: -c board.mm: unknown setting; did you mean 'board.m'?");
}

// "Did you mean" only for a typo's distance: a name far from every setting
// gets none, wherever a name is looked up (-c, a config file, a preset, a
// sweep axis, an option).
TEST_F(Cli, ANameFarFromEverySettingGetsNoSuggestion) {
    expect_refusal(run("settings -c device.speed_grade=5"), "cdvp settings: -c device.speed_grade: unknown setting\n");
    expect_refusal(run("run --scene spheres -c device.speed_grade=5"),
                   "cdvp run: -c device.speed_grade: unknown setting\n");
    write("c.toml", "[board]\nwhatever_you_like = 3\n");
    expect_refusal(run("run --scene spheres --config c.toml"), "cdvp run: c.toml:2: board.whatever_you_like: unknown setting\n");
    expect_refusal(run("sweep --out o --set speed_grade=1,2 --scene spheres"),
                   "cdvp sweep: --set speed_grade: no flag of cdvp run or setting has this name (see cdvp run --help, "
                   "cdvp settings)");
    expect_refusal(run("run --scene spheres --speed-grade 5"),
                   "cdvp run: unrecognised option '--speed-grade' (see cdvp run --help)");
    // A typo still gets its suggestion.
    expect_refusal(run("settings -c device.block_ram=5"),
                   "cdvp settings: -c device.block_ram: unknown setting; did you mean 'device.block_rams'?\n");
}

// cdvp settings makes every check cdvp run makes of the settings alone: the
// clock against the device's estimate too, refused in the same words.
TEST_F(Cli, SettingsRefuseAClockTheDeviceCannotReachAsRunDoes) {
    for (const std::string board : {"adm-xrc-ii", "alveo-u250"}) {
        for (const std::string algorithm : {"all_pairs", "grid"}) {
            SCOPED_TRACE(board + " " + algorithm);
            const std::string layers = "--board " + board + " -c board.algorithm=" + algorithm + " -c board.clock_mhz=900";
            const Result ran = run("run --scene spheres --frames 1 " + layers);
            const Result listed = run("settings " + layers);
            ASSERT_NE(ran.status, 0) << ran.err;
            EXPECT_EQ(listed.status, ran.status) << listed.err;
            EXPECT_EQ(listed.out, "");
            ASSERT_EQ(ran.err.rfind("cdvp run: ", 0), 0u) << ran.err;
            EXPECT_EQ(listed.err, "cdvp settings: " + ran.err.substr(10));
            EXPECT_NE(listed.err.find("-c board.clock_mhz: 900.0 MHz is beyond the "), std::string::npos) << listed.err;
        }
    }
    const Result warned = run("settings --board adm-xrc-ii -c board.clock_mhz=500 -c run.ignore_timing=yes");
    EXPECT_EQ(warned.status, 0) << warned.err;
    EXPECT_EQ(warned.err.rfind("cdvp settings: warning: -c board.clock_mhz: 500.0 MHz is beyond the ", 0), 0u)
        << warned.err;
}

}  // namespace
}  // namespace cdvp::test
