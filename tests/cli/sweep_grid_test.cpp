// The sweep's grid as plain C++: lists expanded (ranges, repeated values),
// points numbered and named, shards, and the size of a grid refused before
// any work a value or a point costs.
#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "models/common/user_text.h"
#include "sw/study/sweep_grid.h"

namespace cdvp {
namespace {

using Values = std::vector<std::string>;

TEST(SweepList, CommaListsKeepTheirValuesAsWritten) {
    EXPECT_EQ(expand_list("a,b,c", "--board"), (Values{"a", "b", "c"}));
    EXPECT_EQ(expand_list("24", "--set m"), (Values{"24"}));
    EXPECT_EQ(expand_list("0.50,1e3", "--set x"), (Values{"0.50", "1e3"}));
}

TEST(SweepList, GeometricRangesMultiplyUpToTheEndInclusive) {
    EXPECT_EQ(expand_list("50:2000:x2", "--set objects"), (Values{"50", "100", "200", "400", "800", "1600"}));
    EXPECT_EQ(expand_list("1:16:x2", "--set m"), (Values{"1", "2", "4", "8", "16"}));
    EXPECT_EQ(expand_list("0.5:4:x2", "--set x"), (Values{"0.5", "1", "2", "4"}));
    EXPECT_EQ(expand_list("1:1:x10", "--set x"), (Values{"1"}));
    EXPECT_EQ(expand_list("0.1:1:x10", "--set x"), (Values{"0.1", "1"})) << "B is reached up to rounding";
}

TEST(SweepList, ArithmeticRangesStepUpToTheEndInclusive) {
    EXPECT_EQ(expand_list("1:24:+8", "--set m"), (Values{"1", "9", "17"}));
    EXPECT_EQ(expand_list("0:1:+0.25", "--set q"), (Values{"0", "0.25", "0.5", "0.75", "1"}));
    EXPECT_EQ(expand_list("5:5:+1", "--set q"), (Values{"5"}));
}

TEST(SweepList, WholeRangesStepExactlyInIntegersWhateverTheirSize) {
    // B's size once widened the end by a billionth of B: 1,003 points here.
    EXPECT_EQ(expand_list("999999999999:1000000000001:+1", "--set seed"),
              (Values{"999999999999", "1000000000000", "1000000000001"}));
    EXPECT_EQ(expand_list("999999999998:1000000000000:+1", "--set seed").back(), "1000000000000");
    EXPECT_EQ(expand_list("999999999999:1000000000000:+1", "--set seed").size(), 2u);
    // Past 2^53 a double cannot step by one; integers do.
    EXPECT_EQ(expand_list("9007199254740993:9007199254740995:+1", "--set seed"),
              (Values{"9007199254740993", "9007199254740994", "9007199254740995"}));
    EXPECT_EQ(expand_list("18446744073709551:18446744073709560:+4", "--set seed"),
              (Values{"18446744073709551", "18446744073709555", "18446744073709559"}));
    const Values tens = expand_list("1:1e17:x10", "--set scene.seed");
    ASSERT_EQ(tens.size(), 18u);
    EXPECT_EQ(tens[16], "10000000000000000") << "an integer setting takes it; 1e+16 it refuses";
    EXPECT_EQ(tens.back(), "100000000000000000");
    EXPECT_EQ(expand_list("1:1e30:x1000", "--set x").back(), "1000000000000000000") << "no overflow past INT64_MAX";
    EXPECT_EQ(expand_list("-3:3:+3", "--set x"), (Values{"-3", "0", "3"}));
    EXPECT_EQ(expand_list("1:10.5:+3", "--set x"), (Values{"1", "4", "7", "10"}));
}

TEST(SweepList, RealRangesReachTheEndUpToAFractionOfTheStepNotOfTheEnd) {
    EXPECT_EQ(expand_list("0:0.3:+0.1", "--set q"), (Values{"0", "0.1", "0.2", "0.3"})) << "0.1 x 3 rounds above 0.3";
    EXPECT_EQ(expand_list("0.5:1e12:x10", "--set q").back(), "500000000000");
    EXPECT_EQ(expand_list("0.001:1000:x10", "--set q"), (Values{"0.001", "0.01", "0.1", "1", "10", "100", "1000"}));
    EXPECT_EQ(expand_list("0.25:1:+0.375", "--set q"), (Values{"0.25", "0.625", "1"}));
}

TEST(SweepList, LongRangesAreRefusedWithTheirCountBeforeAnyValueIsMade) {
    const auto message = [](const std::string& list) {
        try {
            expand_list(list, "--set seed");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("1:100001:+1"), "--set seed: '1:100001:+1': 100001 values, more than 100000");
    EXPECT_EQ(expand_list("1:100000:+1", "--set seed").size(), 100000u);
    EXPECT_EQ(message("0:9e18:+1"), "--set seed: '0:9e18:+1': 9000000000000000001 values, more than 100000");
    EXPECT_EQ(message("0:1e300:+1e-300"), "--set seed: '0:1e300:+1e-300': 1e+600 values, more than 100000")
        << "counted as a double: inf";
    EXPECT_EQ(message("0:1:+0.000001"), "--set seed: '0:1:+0.000001': 1000001 values, more than 100000");
}

TEST(SweepList, ARepeatedValueInALongListIsFoundAndNamed) {
    std::string list;
    for (int k = 0; k < 100000; ++k) list += std::to_string(k) + ",";
    list += "99999";
    try {
        expand_list(list, "--set seed");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("more than 100000 values"), std::string::npos) << e.what();
    }
    list.resize(list.rfind(','));
    list.resize(list.rfind(',') + 1);
    list += "5";  // 99,999 distinct values, then 5 again
    try {
        expand_list(list, "--set seed");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'5' is given twice"), std::string::npos) << e.what();
    }
}

TEST(SweepList, ColonsAreKeptInPlainListsWithoutRanges) {
    EXPECT_EQ(expand_list("a:b:c", "--trace", false), (Values{"a:b:c"}));
}

TEST(SweepList, BadListsAreRefusedWithOneLineNamingTheList) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"", "an empty value"},          {"a,,b", "an empty value"},     {"a,", "an empty value"},
        {"1,2,1", "'1' is given twice"}, {"1:8", "expected a,b,c or"},   {"1:8:2", "expected the step"},
        {"1:8:x", "expected the step"},  {"a:8:x2", "expected numbers"}, {"8:1:x2", "A is above B"},
        {"1:8:x1", "a factor above 1"},  {"0:8:x2", "a factor above 1"}, {"1:8:+0", "an increment above 0"},
        {"1:8:+-1", "an increment above 0"}, {"1:8:x2:3", "expected a,b,c or"}, {"0x10:20:+1", "expected numbers"},
        {"1:inf:+1", "expected numbers"}, {"1:1e9:+1", "1000000000 values, more than 100000"}};
    for (const auto& [list, why] : cases) {
        try {
            expand_list(list, "--set m");
            ADD_FAILURE() << list << ": accepted";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind("--set m: '" + list + "': ", 0), 0u) << message;
            EXPECT_NE(message.find(why), std::string::npos) << list << ": " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos);
        }
    }
}

TEST(SweepSet, NamesAFlagOrADottedSetting) {
    const Axis m = parse_set("m=1,2");
    EXPECT_EQ(m.name, "m");
    EXPECT_EQ(m.values, (Values{"1", "2"}));
    EXPECT_EQ(parse_set("bus.interrupt_ns=5000:10000:x2").values, (Values{"5000", "10000"}));
    for (const char* bad : {"m", "=1,2", "M=1", "1m=2", "m x=1", "--m=1"}) {
        EXPECT_THROW(parse_set(bad), InputError) << bad;
    }
}

TEST(SweepShard, TakesEveryNthPointFromK) {
    const Shard shard = parse_shard("2/3");
    std::vector<std::size_t> runs;
    for (std::size_t k = 0; k < 8; ++k) {
        if (shard.runs(k)) runs.push_back(k);
    }
    EXPECT_EQ(runs, (std::vector<std::size_t>{1, 4, 7}));
    EXPECT_TRUE(parse_shard("1/1").whole());
    for (const char* bad : {"0/2", "3/2", "1", "1/", "/2", "a/b", "1/2/3", "-1/2", "1/0"}) {
        EXPECT_THROW(parse_shard(bad), InputError) << bad;
    }
}

TEST(SweepGrid, PointsRunRowMajorWithReadableUniqueIds) {
    const Grid grid(std::vector<Axis>{{"board", {"adm-xrc-ii", "pcie-gen3-x8"}}, {"m", {"1", "8", "24"}}, {"objects", {"50", "100"}}});
    ASSERT_EQ(grid.size(), 12u);
    const Point p = grid.point(9);  // 9 = 1*6 + 1*2 + 1: board 1, m 8, objects 100
    EXPECT_EQ(p.values, (Values{"pcie-gen3-x8", "8", "100"}));
    EXPECT_EQ(p.id, "board-pcie-gen3-x8_m-8_objects-100");
    EXPECT_EQ(grid.run_arguments(p), (Values{"--board=pcie-gen3-x8", "--m=8", "--objects=100"}))
        << "each value one word, so that none is taken for an option";
    std::set<std::string> ids;
    for (std::size_t k = 0; k < grid.size(); ++k) ids.insert(grid.point(k).id);
    EXPECT_EQ(ids.size(), grid.size());
}

TEST(SweepGrid, SettingsGoThroughDashCAndFilesAreNamedByTheirStems) {
    const Grid grid(std::vector<Axis>{{"trace", {"a/x.csv", "c/y z.csv", "d/u_v.csv"}}, {"bus.interrupt_ns", {"5000"}}});
    EXPECT_EQ(grid.point(0).id, "trace-x_bus.interrupt_ns-5000");
    EXPECT_EQ(grid.point(1).id, "trace-y-z_bus.interrupt_ns-5000");
    EXPECT_EQ(grid.point(2).id, "trace-u-v_bus.interrupt_ns-5000") << "a value's '_' would blur the axes apart";
    EXPECT_EQ(grid.run_arguments(grid.point(1)), (Values{"--trace=c/y z.csv", "-c", "bus.interrupt_ns=5000"}));
}

TEST(SweepGrid, ValuesThatWouldShareAnIdGetADigestOfTheirText) {
    // Two traces of one name in two folders, and a third whose name is what
    // a place in the list used to give.
    const Grid grid(std::vector<Axis>{{"trace", {"a/t.csv", "b/t.csv", "t.1.csv", "t.csv"}}});
    std::set<std::string> ids;
    for (std::size_t k = 0; k < grid.size(); ++k) ids.insert(grid.point(k).id);
    EXPECT_EQ(ids.size(), grid.size());
    EXPECT_EQ(grid.point(2).id, "trace-t.1");
    EXPECT_EQ(grid.point(0).id.rfind("trace-t~", 0), 0u) << grid.point(0).id;
    EXPECT_EQ(grid.point(0).id.size(), std::string("trace-t~").size() + 8);
    EXPECT_NE(grid.point(0).id, grid.point(1).id);
    EXPECT_NE(grid.point(0).id, grid.point(3).id);
    EXPECT_EQ(grid.fragments(0)[2], "t.1");
}

TEST(SweepGrid, IdsStayUniqueAndShortEnoughForAFileNameHoweverLongTheValues) {
    std::vector<Axis> axes;
    for (int a = 0; a < 6; ++a) {
        Values values;
        for (int v = 0; v < 3; ++v) values.push_back(std::string(300, static_cast<char>('a' + v)) + std::to_string(a));
        axes.push_back({"section.a_long_setting_name_" + std::to_string(a), values});
    }
    axes.push_back({"objects", {"1", "2"}});
    const Grid grid(axes);
    std::set<std::string> ids;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const std::string id = grid.point(k).id;
        EXPECT_LE(id.size(), kMaxIdBytes) << id;
        EXPECT_EQ(id.find('/'), std::string::npos);
        ids.insert(id);
    }
    EXPECT_EQ(ids.size(), grid.size());
    EXPECT_NE(grid.point(7).id.find("~p7"), std::string::npos) << grid.point(7).id;
    for (const std::string& fragment : grid.fragments(0)) EXPECT_LE(fragment.size(), kMaxFragmentBytes);
}

TEST(SweepGrid, AnAxisKeyedByItsSettingIsOneAxisWhateverItsName) {
    EXPECT_THROW(Grid(std::vector<Axis>{{"m", {"1"}, "board.m", "m"}, {"board.m", {"2"}, "board.m", ""}}), InputError);
    try {
        Grid(std::vector<Axis>{{"m", {"1"}, "board.m", "m"}, {"board.m", {"2"}, "board.m", ""}});
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "--set board.m: the same setting as the axis m; give it once");
    }
    const Grid grid(std::vector<Axis>{{"board.m", {"2"}, "board.m", "m"}});
    EXPECT_EQ(grid.run_arguments(grid.point(0)), (Values{"--m=2"})) << "a setting with a flag is given by its flag";
    EXPECT_EQ(grid.find("board.m"), &grid.axes()[0]);
}

TEST(SweepGrid, RefusesRepeatedAxesAndNoAxes) {
    EXPECT_THROW(Grid(std::vector<Axis>{{"m", {"1"}}, {"m", {"2"}}}), InputError);
    EXPECT_THROW(Grid(std::vector<Axis>{}), InputError);
}

TEST(SweepGrid, AGridPastAMillionPointsIsRefusedWithItsCount) {
    const auto axis = [](const char* name, const std::string& list) { return Axis{name, expand_list(list, name)}; };
    try {
        Grid(std::vector<Axis>{axis("seed", "1:100000:+1"), axis("m", "1:11:+1")});
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "the grid has 1100000 points, more than 1000000");
    }
    try {
        Grid(std::vector<Axis>{axis("seed", "1:100000:+1"), axis("objects", "1:100000:+1"), axis("m", "1:100000:+1")});
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "the grid has 1000000000000000 points, more than 1000000") << "no overflow";
    }
    EXPECT_EQ(Grid(std::vector<Axis>{axis("seed", "1:100000:+1"), axis("m", "1:10:+1")}).size(), 1000000u);
}

// The size is known from the axes' lengths alone, so a sweep refuses a grid
// too big before it reads any value by its setting (sw/cli/sweep_options.cpp).
TEST(SweepGrid, ItsSizeIsCheckedFromTheAxesLengthsAlone) {
    std::vector<Axis> axes{{"seed", Values(100000, "x")}, {"m", Values(32, "y")}};
    try {
        check_grid_size(axes);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "the grid has 3200000 points, more than 1000000");
    }
    axes[1].values.resize(10);
    EXPECT_NO_THROW(check_grid_size(axes)) << "a million points exactly";
}

// Every repeated-value check of an axis goes through first_repeat: a million
// values in one pass (a pairwise check would compare 5e11 pairs, hours; the
// suite's timeout for this executable is minutes).
TEST(SweepList, ARepeatIsFoundInOnePassOverAMillionValues) {
    constexpr std::size_t kValues = 1000000;
    Values keys;
    keys.reserve(kValues + 1);
    for (std::size_t k = 0; k < kValues; ++k) keys.push_back(std::to_string(k * 7919));
    EXPECT_EQ(first_repeat(keys), std::nullopt);
    keys.push_back(keys[123456]);
    const auto repeat = first_repeat(keys);
    ASSERT_TRUE(repeat.has_value());
    EXPECT_EQ(repeat->first, kValues) << "the later of the two";
    EXPECT_EQ(repeat->second, 123456u) << "the earlier one it repeats";
    EXPECT_EQ(first_repeat(Values{"a", "b", "a", "b"}), std::make_optional(std::make_pair(std::size_t{2}, std::size_t{0})));
}

}  // namespace
}  // namespace cdvp
