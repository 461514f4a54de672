// The settings table: every preset key maps to exactly one setting, layers
// apply in order with their origins, and config files and -c overrides are
// checked against the table with messages naming file, line and setting.
#include "platform/settings/settings.h"

#include <gtest/gtest.h>

#include <stdlib.h>
#include <unistd.h>

#include <fstream>
#include <functional>
#include <optional>
#include <utility>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "platform/settings/board_preset.h"
#include "platform/settings/config_file.h"
#include "platform/platform_settings.h"
#include "models/pci/pci_transaction_bus.h"
#include "models/common/nesting_limit.h"
#include "tests/platform/nested_text.h"

namespace cdvp {
namespace {

using nlohmann::json;

int entries_named(const std::string& name) {
    int count = 0;
    for (const Setting& s : settings_table()) count += s.name == name ? 1 : 0;
    return count;
}

TEST(SettingsTable, EveryPresetKeyMapsToExactlyOneSettingOfItsBus) {
    int keys = 0;
    for (const std::string& preset : board_preset_names()) {
        std::ifstream in(boards_directory() + "/" + preset + ".json");
        const json root = json::parse(in);
        const std::optional<BusType> bus = parse_choice<BusType>(root["bus"]["type"].get<std::string>());
        ASSERT_TRUE(bus.has_value()) << preset;
        for (const char* section : {"board", "device", "bus", "host"}) {
            for (const auto& [key, value] : root[section].items()) {
                const std::string name = std::string(section) + "." + key;
                EXPECT_EQ(1, entries_named(name)) << preset << ": " << name;
                const Setting* s = find_setting(name);
                ASSERT_NE(s, nullptr) << name;
                EXPECT_TRUE(s->in_preset) << name;
                EXPECT_TRUE(s->applies_to_bus(*bus)) << preset << ": " << name;
                ++keys;
            }
        }
    }
    EXPECT_EQ(4 * (5 + 14 + 13) + 19 + 19 + 13 + 13, keys)
        << "board, device (power figures among them), host and bus keys of the four presets";
}

TEST(SettingsTable, EveryDedicatedFlagBindsExactlyOneSetting) {
    const char* flags[] = {"m",      "clock-mhz", "compare-latency", "fifo-depth", "drain-rate",
                           "pair-buffer", "host-factor", "quantum-ns", "objects", "frames",
                           "seed",   "transfer",  "wait",            "fidelity", "warmup", "repeat"};
    for (const char* flag : flags) {
        int count = 0;
        for (const Setting& s : settings_table()) count += s.flag == flag ? 1 : 0;
        EXPECT_EQ(1, count) << "--" << flag;
    }
    for (const Setting& s : settings_table()) {
        EXPECT_EQ(1, entries_named(s.name)) << s.name;
        EXPECT_FALSE(s.help.empty()) << s.name;
        EXPECT_FALSE(s.source.empty()) << s.name;
    }
}

TEST(SettingsTable, BusModelPicksTheLevelAndTheDefaultIsTheFormula) {
    Settings s;
    s.bus_type = BusType::kPci;
    EXPECT_NE(dynamic_cast<const PciTiming*>(s.make_bus().get()), nullptr);
    s.bus_model = BusModel::kTransaction;
    EXPECT_NE(dynamic_cast<const PciTransactionTiming*>(s.make_bus().get()), nullptr);
    s.bus_type = BusType::kPcie;
    EXPECT_NE(dynamic_cast<const PcieTlpTiming*>(s.make_bus().get()), nullptr);
    s.bus_model = BusModel::kFormula;
    EXPECT_NE(dynamic_cast<const PcieTiming*>(s.make_bus().get()), nullptr);
    s.bus_load.bytes_per_s = 1e6;
    EXPECT_THROW(s.make_bus(), std::invalid_argument) << "the formula cannot honour a load";
    for (const char* name : {"bus.model", "bus.load_bytes_per_s", "bus.read_completion_boundary_bytes"}) {
        ASSERT_NE(find_setting(name), nullptr) << name;
        EXPECT_FALSE(find_setting(name)->in_preset) << name << " is the user's, not a board's";
    }
    EXPECT_EQ(to_text(find_setting("bus.model")->default_value()), "formula");
    EXPECT_EQ(to_text(find_setting("bus.load_bytes_per_s")->default_value()), "0");
}

TEST(SettingsTable, ValuesBindTheirMembers) {
    Settings s;
    find_setting("board.fifo_depth")->set(s, SettingValue(uint64_t{77}));
    EXPECT_EQ(77u, s.board.collector.fifo_depth);
    s.bus_type = BusType::kPcie;
    find_setting("bus.interrupt_ns")->set(s, SettingValue(1234.0));
    EXPECT_EQ(1234.0, s.pcie.interrupt_ns);
    EXPECT_EQ(PciConfig{}.interrupt_ns, s.pci.interrupt_ns) << "a key of both buses sets the bus in effect";
    EXPECT_EQ(SettingValue(1234.0), find_setting("bus.interrupt_ns")->get(s));
    EXPECT_EQ(SettingValue(std::string("dma")), find_setting("run.transfer")->default_value());
}

// Each choice setting's names are its type's names, in the table's order,
// and each parses to the value whose name it is and prints back the same.
template <class T>
void expect_choice_round_trip(const char* name) {
    const Setting& setting = *find_setting(name);
    EXPECT_EQ(SettingType::kChoice, setting.type) << name;
    EXPECT_EQ(choice_names<T>(), setting.choices) << name;
    for (const ChoiceName<T>& c : Choices<T>::names) {
        ASSERT_EQ(std::optional<T>(c.value), parse_choice<T>(c.name)) << name << ' ' << c.name;
        EXPECT_STREQ(c.name, name_of(c.value)) << name;
        Settings s;
        setting.set(s, setting.from_string(c.name));
        EXPECT_EQ(SettingValue(std::string(c.name)), setting.get(s)) << name;
        EXPECT_EQ(SettingValue(std::string(c.name)), setting.parse_text(c.name)) << name;
    }
    EXPECT_EQ(std::nullopt, parse_choice<T>("")) << name;
    EXPECT_EQ(std::nullopt, parse_choice<T>(std::string(choice_names<T>().front()) + " ")) << name;
}

TEST(SettingsTable, ChoicesRoundTripThroughTheirNames) {
    expect_choice_round_trip<BoxMemory>("board.memory");
    expect_choice_round_trip<BoardAlgorithm>("board.algorithm");
    expect_choice_round_trip<DeviceFamily>("device.family");
    expect_choice_round_trip<BusType>("bus.type");
    expect_choice_round_trip<Transfer>("run.transfer");
    expect_choice_round_trip<WaitMode>("run.wait");
    expect_choice_round_trip<ModelLevel>("run.fidelity");
    expect_choice_round_trip<bool>("run.ignore_capacity");
    expect_choice_round_trip<bool>("run.ignore_timing");
    expect_choice_round_trip<bool>("run.lockstep");
    expect_choice_round_trip<BusModel>("bus.model");
    expect_choice_round_trip<Direction>("bus.load_direction");
    expect_choice_round_trip<LoadArrivals>("bus.load_arrivals");
    expect_choice_round_trip<UploadMode>("driver.upload");
    expect_choice_round_trip<PairFormat>("driver.pair_format");
    expect_choice_round_trip<InterruptPolicy>("driver.interrupts");
    int choices = 0;
    for (const Setting& s : settings_table()) choices += s.type == SettingType::kChoice ? 1 : 0;
    EXPECT_EQ(16, choices) << "a new choice setting: add it above";
    // The engines' own names are the setting's, and each level but the analytic one runs the engine of its name.
    for (const ChoiceName<Fidelity>& c : Choices<Fidelity>::names) EXPECT_STREQ(c.name, to_string(c.value));
    for (const ChoiceName<ModelLevel>& c : Choices<ModelLevel>::names) {
        if (c.value == ModelLevel::kCycle || c.value == ModelLevel::kFast || c.value == ModelLevel::kRtl) {
            EXPECT_STREQ(c.name, to_string(engine_of(c.value)));
        }
    }
    EXPECT_EQ(Fidelity::kLockstep, engine_of(ModelLevel::kRtl, true)) << "--lockstep: the RTL with the clocked engine beside it";
    for (ModelLevel level : {ModelLevel::kCycle, ModelLevel::kFast}) {
        EXPECT_EQ(engine_of(level), engine_of(level, true)) << "lockstep is the rtl level's alone (refused elsewhere)";
    }
}

TEST(SettingsTable, ChoiceDefaultsAreTheTypedDefaults) {
    const Settings defaults;
    EXPECT_EQ(BoxMemory::kAuto, defaults.memory.memory);
    EXPECT_EQ(DeviceFamily::kNone, defaults.device.family);
    EXPECT_EQ(BusType::kIdeal, defaults.bus_type);
    EXPECT_EQ(Transfer::kDma, defaults.driver.transfer);
    EXPECT_EQ(WaitMode::kIrq, defaults.driver.wait);
    EXPECT_EQ(ModelLevel::kFast, defaults.run.fidelity);
    EXPECT_FALSE(defaults.run.ignore_capacity);
    EXPECT_EQ(BusModel::kFormula, defaults.bus_model);
    EXPECT_EQ(Direction::kToHost, defaults.bus_load.direction);
    EXPECT_EQ(LoadArrivals::kPeriodic, defaults.bus_load.arrivals);
    EXPECT_EQ(SettingValue(std::string("auto")), find_setting("board.memory")->default_value());
    EXPECT_EQ(SettingValue(std::string("no")), find_setting("run.ignore_capacity")->default_value());
    EXPECT_EQ(SettingValue(std::string("fast")), find_setting("run.fidelity")->default_value());
}

TEST(SettingsTable, UnknownChoicesAreRefusedNamingEveryChoice) {
    const std::pair<const char*, const char*> refusals[] = {
        {"board.memory", "expected auto, block_ram or ssram, got 'sram'"},
        {"device.family", "expected none, xc2v or xcup, got 'sram'"},
        {"bus.type", "expected ideal, pci or pcie, got 'sram'"},
        {"run.transfer", "expected dma or pio, got 'sram'"},
        {"run.wait", "expected irq or poll, got 'sram'"},
        {"run.fidelity", "expected rtl, cycle, fast, analytic or auto, got 'sram'"},
        {"run.ignore_capacity", "expected no or yes, got 'sram'"},
    };
    for (const auto& [name, message] : refusals) {
        try {
            find_setting(name)->parse_text("sram");
            ADD_FAILURE() << name;
        } catch (const std::invalid_argument& e) {
            EXPECT_STREQ(message, e.what());
        }
        Settings s;
        EXPECT_THROW(find_setting(name)->set(s, SettingValue(std::string("sram"))), std::logic_error) << name;
    }
}

TEST(SettingsTable, ValuesOutsideTypeOrRangeAreRefused) {
    const Setting& m = *find_setting("board.m");
    EXPECT_THROW(m.parse_text("33"), std::invalid_argument);
    EXPECT_EQ(SettingValue(uint64_t{4}), m.parse_text("4"));
    try {
        find_setting("bus.wait_states")->from_number(0.5, "0.5");
        ADD_FAILURE();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ("expected a whole number of clocks, got 0.5", e.what());
    }
    try {
        find_setting("run.wait")->from_string("sleep");
        ADD_FAILURE();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ("expected irq or poll, got 'sleep'", e.what());
    }
}

TEST(PlatformConfig, FoldsEverySettingThePlatformTakes) {
    SettingValues values;
    values.apply(load_board_preset("adm-xrc-ii").values);
    const PlatformConfig paper = platform_config(values);
    EXPECT_EQ("PCI 32-bit/33.3 MHz", paper.bus->describe());
    EXPECT_TRUE(paper.driver.transfer == Transfer::kDma);
    EXPECT_TRUE(paper.driver.wait == WaitMode::kIrq);
    EXPECT_EQ(Fidelity::kFast, paper.fidelity);
    EXPECT_EQ(values.settings().driver.ns_per_box, paper.driver.ns_per_box);
    EXPECT_EQ(values.settings().board.clock_mhz, paper.board.clock_mhz);
    values.apply({parse_override("run.transfer=pio"), parse_override("run.wait=poll"),
                  parse_override("run.fidelity=cycle"), parse_override("run.quantum_ns=250"),
                  parse_override("board.m=4")});
    const PlatformConfig folded = platform_config(values);
    EXPECT_FALSE(folded.driver.transfer == Transfer::kDma);
    EXPECT_FALSE(folded.driver.wait == WaitMode::kIrq);
    // One field each: the table binds run.transfer and run.wait to the driver's own.
    EXPECT_TRUE(values.settings().driver.transfer == Transfer::kPio);
    EXPECT_TRUE(values.settings().driver.wait == WaitMode::kPoll);
    EXPECT_EQ(Fidelity::kCycle, folded.fidelity);
    EXPECT_EQ(250.0, folded.quantum_ns);
    EXPECT_EQ(4u, folded.board.m);
    EXPECT_EQ(nullptr, platform_config(SettingValues()).bus) << "the ideal bus";
    values.apply({parse_override("board.fifo_depth=2")});
    EXPECT_THROW(platform_config(values), InputError) << "the FIFO holds one cycle's hits, 2m-1";
}

TEST(SettingValues, LayersApplyInOrderAndKeepTheirOrigins) {
    SettingValues values;
    values.apply(load_board_preset("adm-xrc-ii").values);
    values.apply({parse_override("bus.interrupt_ns=5000"), parse_override("board.m=4")});
    const Setting& interrupt = *find_setting("bus.interrupt_ns");
    EXPECT_EQ(5000.0, values.settings().pci.interrupt_ns);
    EXPECT_EQ("override", values.origin_words(interrupt)) << "below the faces, an override is named as one";
    const Setting& clock = *find_setting("board.clock_mhz");
    EXPECT_EQ("preset " + boards_directory() + "/adm-xrc-ii.json", values.origin_words(clock));
    EXPECT_EQ("board.m=4", values.value_and_origin(*find_setting("board.m")));
    EXPECT_EQ(5000.0, values.bus()->interrupt_ns());
}

TEST(SettingValues, ABusKeyOfAnotherBusIsRefusedNamingTheBus) {
    SettingValues values;
    try {
        values.apply({parse_override("bus.lanes=4")});
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(0u, std::string(e.what()).rfind("bus.lanes: a setting of a pcie bus; the bus is ideal", 0))
            << e.what();
    }
    // bus.type goes first within a layer, whatever the order given.
    values.apply({parse_override("bus.lanes=4"), parse_override("bus.type=pcie")});
    EXPECT_EQ(4u, values.settings().pcie.lanes);
}

TEST(SettingValues, UnknownOverridesSuggestTheNearestSetting) {
    try {
        parse_override("bus.interupt_ns=5");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_STREQ("override bus.interupt_ns: unknown setting; did you mean 'bus.interrupt_ns'?", e.what());
    }
}

class ConfigFile : public ::testing::Test {
protected:
    void SetUp() override {
        char pattern[] = "/tmp/cdvp-config-XXXXXX";
        ASSERT_NE(nullptr, mkdtemp(pattern));
        dir_ = pattern;
    }
    void TearDown() override {
        for (const std::string& name : written_) std::remove(name.c_str());
        rmdir(dir_.c_str());
    }
    std::string write(const std::string& name, const std::string& text) {
        const std::string path = dir_ + "/" + name;
        std::ofstream(path) << text;
        written_.push_back(path);
        return path;
    }
    std::string error_for(const std::string& name, const std::string& text) {
        const std::string path = write(name, text);
        try {
            read_config_file(path);
        } catch (const InputError& e) {
            return std::string(e.what()).substr(path.size());
        }
        return "accepted";
    }
    std::string dir_;
    std::vector<std::string> written_;
};

TEST_F(ConfigFile, TomlAndJsonGiveTheSameSettings) {
    const auto json_values = read_config_file(write(
        "c.json", R"({"board": {"m": 4}, "bus.type": "pcie", "bus": {"lanes": {"value": 4, "source": "x"}}, "run": {"wait": "poll"}})"));
    const auto toml_values = read_config_file(write("c.toml", "[board]\nm = 4\n[bus]\ntype = \"pcie\"\nlanes = 4\n[run]\nwait = \"poll\"\n"));
    SettingValues from_json, from_toml;
    from_json.apply(json_values);
    from_toml.apply(toml_values);
    for (const Setting& s : settings_table()) {
        EXPECT_EQ(s.get(from_json.settings()), s.get(from_toml.settings())) << s.name;
    }
    EXPECT_EQ(4u, from_toml.settings().pcie.lanes);
    EXPECT_EQ(WaitMode::kPoll, from_toml.settings().driver.wait);
    const Setting& m = *find_setting("board.m");
    EXPECT_EQ("config " + dir_ + "/c.toml:2", from_toml.origin_words(m));
}

TEST_F(ConfigFile, RefusalsNameFileLineAndSetting) {
    EXPECT_EQ(":2: board.m: expected 1 to 32, got 40", error_for("m.toml", "[board]\nm = 40\n"));
    EXPECT_EQ(":3: bus.interupt_ns: unknown setting; did you mean 'bus.interrupt_ns'?",
              error_for("u.toml", "[bus]\ntype = \"pci\"\ninterupt_ns = 5\n"));
    EXPECT_EQ(": board.mm: unknown setting; did you mean 'board.m'?", error_for("u.json", R"({"board": {"mm": 4}})"));
    EXPECT_EQ(": board.m: expected 1 to 32, got 40", error_for("m.json", R"({"board": {"m": 40}})"));
    EXPECT_EQ(": run.wait: expected irq or poll, got 'sleep'", error_for("w.json", R"({"run.wait": "sleep"})"));
    EXPECT_EQ(0u, error_for("s.toml", "[board\n").rfind(":1:", 0));
    EXPECT_EQ(": board.m: given twice", error_for("twice.json", R"({"board.m": 4, "board": {"m": 5}})"));
}

// toml++ quotes what it saw as it is, a newline included; the refusal stays
// one line. nlohmann takes a NUL byte for the end of the input: what follows
// one is refused, not ignored (both found by tests/fuzz/config_fuzzer).
TEST_F(ConfigFile, RefusalsStayOnOneLineAndReadTheWholeFile) {
    using namespace std::string_literals;
    EXPECT_EQ(":1:6: invalid TOML: Error while parsing boolean: expected 'true', saw 't\\n'",
              error_for("bool.toml", "x = t\n"));
    EXPECT_EQ(":1:20: invalid JSON: syntax error while parsing value - unexpected NUL byte; expected end of input",
              error_for("nul.json", "{\"board\": {\"m\": 4}}\0{\"board\": {\"m\": 5}}"s));
    EXPECT_EQ(": host.name: control character \\x00 in a string; expected printable text",
              error_for("nul_in_string.json", "{\"host\": {\"name\": \"a\0b\"}}"s));
}

// A TOML float beyond int64_t's range is shown as %g, as written (found by
// tests/fuzz/config_fuzzer: the check for a whole number converted it first).
TEST_F(ConfigFile, HugeNumbersAreShownInRefusals) {
    EXPECT_EQ(":2: board.clock_mhz: expected 1 to 1000 MHz, got 1.11111e+34",
              error_for("huge.toml", "[board]\nclock_mhz = 11111111000000000000000000000001111.0\n"));
    EXPECT_EQ(":2: board.clock_mhz: expected 1 to 1000 MHz, got -1e+300",
              error_for("low.toml", "[board]\nclock_mhz = -1e300\n"));
    EXPECT_EQ(":2: board.clock_mhz: expected 1 to 1000 MHz, got 100000000000000",
              error_for("whole.toml", "[board]\nclock_mhz = 1e14\n"));
}

// Every way a config file nests, at the limit and one level past it: at the
// limit the file is read on (and refused for an unknown name or a value that
// is no number), past it refused from the text, before toml::parse or any
// walk of the tree, at the key part or bracket of the level too many.
TEST_F(ConfigFile, NestingPastTheLimitIsRefusedAtTheLevelTooMany) {
    using test::dotted;
    using test::nested;
    using test::repeated;
    struct Case {
        const char* name;
        std::function<std::string(int levels)> text;
        const char* position;  // of level 65
    };
    const Case cases[] = {
        {"objects.json", [](int n) { return nested("{\"a\": ", "}", n, "1"); }, ":1:385"},
        {"arrays.json", [](int n) { return "{\"board\": {\"m\": " + nested("[", "]", n - 2) + "}}"; }, ":1:79"},
        {"mixed.json", [](int n) { return nested("{\"a\": [", "]}", n / 2, n % 2 ? "{}" : ""); }, ":1:225"},
        {"headers.toml", [](int n) { return "[" + dotted(n - 1) + "]\nx = 1\n"; }, ":1:128"},
        {"dotted.toml", [](int n) { return dotted(n) + " = 1\n"; }, ":1:127"},
        {"dotted_in_table.toml", [](int n) { return "[board]\n" + dotted(n - 1) + " = 1\n"; }, ":2:125"},
        {"quoted_parts.toml", [](int n) { return "[" + dotted(n - 1, "\"a.b\"") + "]\nx = 1\n"; }, ":1:380"},
        {"inline_tables.toml", [](int n) { return "x = " + nested("{a = ", "}", n - 1, "1") + "\n"; }, ":1:320"},
        {"inline_dotted.toml", [](int n) { return "x = {" + dotted(n - 1) + " = 1}\n"; }, ":1:130"},
        {"arrays.toml", [](int n) { return "[board]\nm = " + nested("[", "]", n - 2) + "\n"; }, ":2:67"},
        {"arrays_of_tables.toml",  // each [[a.a]] level is the array and its element
         [](int n) {
             std::string text;
             for (int k = 1; k <= (n - 1) / 2; ++k) text += "[[" + dotted(k) + "]]\n";
             return text + (n % 2 ? "x = 1\n" : "b.x = 1\n");
         },
         ":32:65"},
        {"mixed.toml",
         [](int n) { return "[" + dotted(30) + "]\n" + dotted(10) + " = " + nested("[{a = ", "}]", 12, n > 64 ? "[]" : "1"); },
         ":2:95"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string at_limit = error_for(c.name, c.text(kMaxNesting));
        EXPECT_EQ(std::string::npos, at_limit.find("nesting")) << at_limit;
        EXPECT_TRUE(at_limit.find(": unknown setting") != std::string::npos ||
                    at_limit.find(": expected a number") != std::string::npos)
            << at_limit;
        const std::string containers = std::string(c.name).find(".toml") != std::string::npos ? "tables" : "objects";
        EXPECT_EQ(std::string(c.position) + ": nesting deeper than 64 levels; a config file nests " + containers +
                      " and arrays at most 64 deep",
                  error_for(c.name, c.text(kMaxNesting + 1)));
    }
}

// The files of the crash, 40 KB and 20,000 levels deep.
TEST_F(ConfigFile, TwentyThousandLevelsAreRefusedNotACrash) {
    using test::nested;
    using test::repeated;
    const std::string refused = " nesting deeper than 64 levels; a config file nests ";
    EXPECT_EQ(":1:577:" + refused + "objects and arrays at most 64 deep",
              error_for("deep.json", nested("{\"board\":", "}", 20000, "1")));
    EXPECT_EQ(":1:128:" + refused + "tables and arrays at most 64 deep",
              error_for("headers.toml", "[" + test::dotted(20000) + "]\nx=1\n"));
    EXPECT_EQ(":1:127:" + refused + "tables and arrays at most 64 deep",
              error_for("dotted.toml", repeated("a.", 20000) + "b={c=1}\n"));
}

// Brackets and dots inside strings and comments are text: here each holds
// what would nest past the limit if it were read as TOML.
TEST_F(ConfigFile, BracketsInStringsAndCommentsDoNotNest) {
    const std::string brackets = test::repeated("[{", kMaxNesting);
    EXPECT_EQ(": run.wait: expected irq or poll, got '\"" + brackets.substr(0, 59) + "... (130 bytes)'",
              error_for("s.json", "{\"run\": {\"wait\": \"\\\"" + brackets + "\\\\\"}}"));
    const std::string header = "[" + test::dotted(kMaxNesting) + "]";
    const std::string arrays = test::repeated("[", kMaxNesting);
    const std::string toml = "# " + header + "\n[run] # " + header + "\nwait = \"\\\"" + header + "\"\n" +
                             "[host]\nname = \"\"\"\n" + header + "\n\"\"\"\nspeed_factor = 2 # '" + header + "\n" +
                             "[board]\nm = [\"1, " + arrays + "\", # " + arrays + "\n  '" + arrays + "', '''\n" +
                             header + "''']\n";
    EXPECT_EQ(":10: board.m: expected a number", error_for("s.toml", toml));
}

}  // namespace
}  // namespace cdvp
