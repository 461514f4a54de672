// Board presets: every key declared, every number range-checked against its
// unit, and every error naming the file and the key.
#include "platform/settings/board_preset.h"

#include <gtest/gtest.h>

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/common/nesting_limit.h"
#include "platform/settings/preset_json.h"
#include "sw/scene/scene.h"
#include "tests/platform/nested_text.h"

namespace cdvp {
namespace {

using nlohmann::json;

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class PresetFile : public ::testing::Test {
protected:
    void SetUp() override {
        char pattern[] = "/tmp/cdvp-preset-XXXXXX";
        ASSERT_NE(nullptr, mkdtemp(pattern));
        dir_ = pattern;
        path_ = dir_ + "/board.json";
    }
    void TearDown() override {
        std::remove(path_.c_str());
        rmdir(dir_.c_str());
    }
    // Writes 'text' as the preset and returns load_board_preset's error.
    std::string error_for(const std::string& text) {
        std::ofstream(path_, std::ios::binary) << text;
        try {
            load_board_preset(path_);
        } catch (const InputError& e) {
            return e.what();
        }
        return "accepted";
    }
    static json preset(const std::string& name) { return json::parse(read(boards_directory() + "/" + name + ".json")); }
    // visit(preset name, its JSON, section, key) for every {"value": ...} field of every shipped preset; how many.
    static int for_each_field(const std::function<void(const std::string&, const json&, const char*, const std::string&)>& visit) {
        int fields = 0;
        for (const std::string& name : board_preset_names()) {
            const json original = preset(name);
            for (const char* section : {"board", "device", "bus", "host"}) {
                for (const auto& [key, field] : original[section].items()) {
                    if (!field.is_object()) continue;
                    ++fields;
                    visit(name, original, section, key);
                }
            }
        }
        return fields;
    }

    std::string dir_, path_;
};

// Every {"value": ...} field of every shipped preset, set far outside any
// plausible range either way, is refused by a range naming its key and unit.
TEST_F(PresetFile, EveryNumberOfEveryPresetIsRangeChecked) {
    const int fields = for_each_field([&](const std::string& name, const json& original, const char* section,
                                          const std::string& key) {
        for (const double bad : {1e300, -1e300, -1.0}) {
            json changed = original;
            changed[section][key]["value"] = bad;
            const std::string error = error_for(changed.dump());
            const std::string expected = path_ + ": " + section + "." + key + ": expected ";
            EXPECT_EQ(0u, error.rfind(expected, 0)) << name << ": " << error;
            EXPECT_NE(std::string::npos, error.find(" to ")) << "a range: " << error;
        }
    });
    EXPECT_EQ(47 + 47 + 41 + 41, fields)
        << "board 5, device 12 (6 of them power), host 12 (package power at load and idle, cores, five reference "
           "times), PCI bus 18, PCIe bus 12 fields";
}

// Every number of every shipped preset, the power figures among them, names
// its source: one without, or with an empty one, is refused naming its key.
TEST_F(PresetFile, EveryNumberOfEveryPresetNamesItsSource) {
    const int fields = for_each_field([&](const std::string& name, const json& original, const char* section,
                                          const std::string& key) {
        EXPECT_FALSE(original[section][key].at("source").get<std::string>().empty()) << name << ": " << key;
        json unsourced = original;
        unsourced[section][key].erase("source");
        json empty = original;
        empty[section][key]["source"] = "";
        for (const json& bad : {unsourced, empty}) {
            const std::string error = error_for(bad.dump());
            EXPECT_EQ(0u, error.rfind(path_ + ": " + section + "." + key + ": expected {\"value\"", 0))
                << name << ": " << error;
        }
    });
    EXPECT_GT(fields, 100);
    // The energy model's figures are every preset's to give.
    for (const std::string& name : board_preset_names()) {
        const json original = preset(name);
        for (const char* power : {"static_w", "clb_uw_per_mhz", "block_ram_uw_per_mhz", "io_pj_per_toggle"}) {
            EXPECT_GT(original["device"][power]["value"].get<double>(), 0) << name << ": device." << power;
        }
        EXPECT_GT(original["bus"]["active_w"]["value"].get<double>(), 0) << name;
        EXPECT_GT(original["host"]["package_w"]["value"].get<double>(), 0) << name;
    }
}

TEST_F(PresetFile, CountsMustBeWholeNumbers) {
    json changed = preset("adm-xrc-ii");
    changed["board"]["fifo_depth"]["value"] = 511.5;
    EXPECT_EQ(path_ + ": board.fifo_depth: expected a whole number of pairs, got 511.5", error_for(changed.dump()));
}

TEST_F(PresetFile, UnknownKeysSuggestTheNearestValidOne) {
    json changed = preset("pcie-gen3-x8");
    changed["bus"]["lane"] = changed["bus"]["lanes"];
    changed["bus"].erase("lanes");
    EXPECT_EQ(path_ + ": bus.lane: unknown key; did you mean 'lanes'?", error_for(changed.dump()));
    changed = preset("adm-xrc-ii");
    changed["descripton"] = "typo";
    EXPECT_EQ(path_ + ": descripton: unknown key; did you mean 'description'?", error_for(changed.dump()));
    changed = preset("adm-xrc-ii");
    changed["bus"]["lanes"] = changed["bus"]["wait_states"];  // a PCIe key on a PCI bus
    EXPECT_EQ(path_ + ": bus.lanes: a key of a pcie bus; this preset's bus is pci", error_for(changed.dump()));
}

TEST_F(PresetFile, MissingAndMalformedFieldsNameTheKey) {
    json changed = preset("adm-xrc-ii");
    changed["host"].erase("call_ns");
    EXPECT_EQ(path_ + ": host.call_ns: missing; expected {\"value\": <number>, \"source\": \"<source or assumption>\"}",
              error_for(changed.dump()));
    changed = preset("adm-xrc-ii");
    changed["host"]["call_ns"] = 2000;
    EXPECT_EQ(0u, error_for(changed.dump()).rfind(path_ + ": host.call_ns: expected {\"value\"", 0));
    changed = preset("adm-xrc-ii");
    changed["host"]["call_ns"]["value"] = "2000";
    EXPECT_EQ(0u, error_for(changed.dump()).rfind(path_ + ": host.call_ns: expected {\"value\"", 0));
    changed = preset("adm-xrc-ii");
    changed["name"] = "";
    EXPECT_EQ(path_ + ": name: expected a non-empty string", error_for(changed.dump()));
    changed = preset("adm-xrc-ii");
    changed["bus"] = 5;
    EXPECT_EQ(path_ + ": bus: expected an object of fields", error_for(changed.dump()));
}

TEST_F(PresetFile, SyntaxErrorsGiveLineAndColumn) {
    EXPECT_EQ(0u, error_for("{\n  \"name\": \"x\",\n  \"board\" {}\n}\n").rfind(path_ + ":3:11: invalid JSON: ", 0));
    EXPECT_EQ(0u, error_for("").rfind(path_ + ":1:1: invalid JSON: ", 0));
    // A number beyond double's range is the library's out_of_range, not a parse_error.
    EXPECT_EQ(error_for("{\"name\": 1e3000}"), path_ + ": invalid JSON: number overflow parsing '1e3000'");
    EXPECT_EQ(path_ + ": expected a JSON object", error_for("[1, 2]"));
    // nlohmann takes a NUL byte for the end of the input: what follows one is refused, not ignored.
    const std::string preset_then_nul = read(boards_directory() + "/adm-xrc-ii.json") + '\0' + "{\"name\": \"x\"}";
    const std::string line = std::to_string(std::count(preset_then_nul.begin(), preset_then_nul.end(), '\n') + 1);
    EXPECT_EQ(path_ + ":" + line + ":1: invalid JSON: syntax error while parsing value - unexpected NUL byte; expected "
                                   "end of input",
              error_for(preset_then_nul));
}

TEST_F(PresetFile, KeysGivenTwiceAreRefused) {
    EXPECT_EQ(path_ + ": board.clock_mhz: key given twice",
              error_for("{\"board\": {\"clock_mhz\": {}, \"clock_mhz\": {}}}"));
    EXPECT_EQ(path_ + ": name: key given twice", error_for("{\"name\": \"a\", \"name\": \"b\"}"));
    // A key holding an escaped line end is quoted on one line (found by config_fuzzer).
    EXPECT_EQ(path_ + ": b\\nm: key given twice", error_for("{\"b\\nm\": 50, \"b\\nm\": 500}"));
}

TEST_F(PresetFile, OnlyASmallRegularFileIsAPreset) {
    try {
        load_board_preset(dir_ + "/");
        ADD_FAILURE() << "a directory was read as a preset";
    } catch (const InputError& e) {
        EXPECT_EQ(dir_ + "/: cannot open: Is a directory (EISDIR)", std::string(e.what()));
    }
    EXPECT_EQ(path_ + ": larger than 1048576 bytes; not a board preset", error_for(std::string(2 << 20, ' ')));
    // A named pipe is refused at once, not waited on for a writer.
    const std::string fifo = dir_ + "/pipe.json";
    ASSERT_EQ(0, mkfifo(fifo.c_str(), 0600));
    try {
        load_board_preset(fifo);
        ADD_FAILURE() << "a named pipe was read as a preset";
    } catch (const InputError& e) {
        EXPECT_EQ(fifo + ": cannot open: not a regular file; expected a board preset", std::string(e.what()));
    }
    std::remove(fifo.c_str());
}

// While pins live, a pinned preset is the text pinned, whatever the file now
// holds (a sweep's points read what its manifest digested); after, the file.
TEST_F(PresetFile, APinnedPresetIsReadAsPinned) {
    const std::string adm = read(boards_directory() + "/adm-xrc-ii.json");
    const std::string pcie = read(boards_directory() + "/pcie-gen3-x8.json");
    std::ofstream(path_, std::ios::binary) << pcie;
    {
        PinnedFiles pins;
        pins.pin(path_, adm);
        EXPECT_THROW(PinnedFiles(), std::logic_error);
        EXPECT_EQ(load_board_preset(path_).name, load_board_preset(boards_directory() + "/adm-xrc-ii.json").name);
        EXPECT_EQ(read_small_file(path_, "a preset"), adm);
        EXPECT_EQ(PinnedFiles::find(dir_ + "/other.json"), nullptr);
    }
    EXPECT_EQ(PinnedFiles::find(path_), nullptr);
    EXPECT_EQ(read_small_file(path_, "a preset"), pcie);
    EXPECT_NE(load_board_preset(path_).name, load_board_preset(boards_directory() + "/adm-xrc-ii.json").name);
}

TEST_F(PresetFile, ErrorsStayOnOneLineWhateverTheFileHolds) {
    json changed = preset("adm-xrc-ii");
    changed["bus"]["type"] = "pc\x01i";
    EXPECT_EQ(path_ + ": bus.type: control character \\x01 in a string; expected printable text",
              error_for(changed.dump()));
    changed = preset("adm-xrc-ii");
    changed["host"]["tab\tkey"] = 1;
    EXPECT_EQ(path_ + ": host.tab\\tkey: control character \\t in a key; expected printable text",
              error_for(changed.dump()));
}

// Escaped (\u0007) or raw, C0, DEL or C1: a control character in any string
// of a preset is refused naming the key, and the message never holds the raw
// byte. Whitespace between tokens is ordinary.
TEST_F(PresetFile, ControlCharactersInStringsAreRefusedNamingTheKey) {
    const std::string text = read(boards_directory() + "/adm-xrc-ii.json");
    const std::string name = "\"name\": \"adm-xrc-ii\"";
    ASSERT_NE(text.find(name), std::string::npos);
    struct Case {
        std::string name_value, shown;
    };
    const Case cases[] = {
        {"\"adm\\u001b[31m\"", "\\x1b"},   // escaped ESC
        {"\"adm\x1b[31m\"", "\\x1b"},        // raw ESC
        {"\"two\nlines\"", "\\n"},           // raw newline inside the string
        {"\"tab\\there\"", "\\t"},          // escaped tab
        {"\"del\x7f\"", "\\x7f"},            // DEL
        {"\"c1\\u0085\"", "\\u0085"},         // NEL, a C1 control
    };
    for (const Case& c : cases) {
        std::string changed = text;
        changed.replace(changed.find(name), name.size(), "\"name\": " + c.name_value);
        const std::string error = error_for(changed);
        EXPECT_EQ(path_ + ": name: control character " + c.shown + " in a string; expected printable text", error);
        for (const char byte : error) EXPECT_FALSE(static_cast<unsigned char>(byte) < 0x20 || byte == 0x7f) << error;
        EXPECT_EQ(std::string::npos, error.find("\xc2\x85")) << error;
    }
    std::string spaced = text;
    spaced.replace(spaced.find(name), name.size(), "\"name\"\t:\r\n \"adm-xrc-ii\"");
    EXPECT_EQ("accepted", error_for(spaced)) << "tabs and line ends between tokens are whitespace";
    std::string stray = text;
    stray.replace(stray.find(name), name.size(), "\"name\": \x01\"adm\"");
    EXPECT_NE(std::string::npos, error_for(stray).find(": invalid JSON: ")) << "outside a string: a syntax error";
}

// Objects, arrays or both nested past kMaxNesting are refused from the text,
// at the bracket of the level too many, before any walk of the tree (the
// control-character check recursed once a level, and 20,000 levels overflowed
// the stack). At the limit the preset is read on and refused for what it
// holds, an unknown key.
TEST_F(PresetFile, NestingPastTheLimitIsRefusedAtItsBracket) {
    using test::nested;
    struct Case {
        const char* what;
        std::function<std::string(int levels)> text;
        const char* position;  // of level 65
    };
    const Case cases[] = {
        {"objects", [](int n) { return nested("{\"a\": ", "}", n, "1"); }, ":1:385"},
        {"arrays in an object", [](int n) { return "{\"a\": " + nested("[", "]", n - 1) + "}"; }, ":1:70"},
        {"objects in arrays", [](int n) { return nested("{\"a\": [", "]}", n / 2, n % 2 ? "{}" : ""); }, ":1:225"},
        {"one a line", [](int n) { return nested("{\n  \"a\": ", "}", n, "1"); }, ":65:8"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        const std::string at_limit = error_for(c.text(kMaxNesting));
        EXPECT_EQ(path_ + ": a: unknown key", at_limit) << "'a' is no typo of any key";
        EXPECT_EQ(path_ + c.position + ": nesting deeper than 64 levels; a board preset nests objects and arrays at most "
                                       "64 deep",
                  error_for(c.text(kMaxNesting + 1)));
    }
    EXPECT_EQ(path_ + ":1:577: nesting deeper than 64 levels; a board preset nests objects and arrays at most 64 deep",
              error_for(nested("{\"board\":", "}", 20000, "1")))
        << "the file of the crash: 40 KB, 20,000 levels";
}

// Brackets inside strings are text, whatever quotes are escaped before them.
TEST_F(PresetFile, BracketsInStringsDoNotNest) {
    json changed = preset("adm-xrc-ii");
    changed["description"] = "\"" + test::repeated("[{", kMaxNesting) + "\\\" ]";
    EXPECT_EQ("accepted", error_for(changed.dump()));
}

TEST_F(PresetFile, RangesReadInFull) {
    json changed = preset("adm-xrc-ii");
    changed["board"]["fifo_depth"]["value"] = 4294967296.0;
    EXPECT_EQ(path_ + ": board.fifo_depth: expected 1 to 1048576 pairs, got 4294967296.0", error_for(changed.dump()));
}

TEST_F(PresetFile, ModelRulesNameThePresetKey) {
    json changed = preset("adm-xrc-ii");
    changed["bus"]["width_bits"]["value"] = 48;
    EXPECT_EQ(path_ + ": bus.width_bits: expected 32 or 64, got 48", error_for(changed.dump()));
}

}  // namespace
}  // namespace cdvp
