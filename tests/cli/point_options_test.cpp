// PointOptions gives what parse_run_options gives: a point that differs from
// the last only in setting values reuses its parse with those values in
// place; a refused value, another option or another shape parses in full.
#include "sw/cli/point_options.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cdvp {
namespace {

namespace po = boost::program_options;

struct Argv {
    explicit Argv(std::vector<std::string> args) : words(std::move(args)) {
        words.insert(words.begin(), "run");
        for (std::string& w : words) pointers.push_back(w.data());
    }
    int argc() const { return static_cast<int>(pointers.size()); }
    char** argv() { return pointers.data(); }
    std::vector<std::string> words;
    std::vector<char*> pointers;
};

// What a run reads of its options, as text.
std::string describe(const RunOptions& o, const po::variables_map& vm) {
    std::string text = o.scene + "|" + o.trace + "|" + o.layers.board_name + "|" + o.report + "|" +
                       (o.quiet ? "q" : "") + "|";
    for (const Assignment& a : o.layers.flags) text += a.setting->name + "=" + to_text(a.value) + ";";
    text += "|";
    for (const std::string& c : o.layers.overrides) text += c + ";";
    text += "|";
    for (const auto& [name, value] : vm) text += name + ",";
    return text;
}

std::string full(std::vector<std::string> args) {
    Argv a(std::move(args));
    RunOptions o;
    const po::variables_map vm = parse_run_options(a.argc(), a.argv(), o);
    return describe(o, vm);
}

std::string by_points(PointOptions& points, std::vector<std::string> args) {
    Argv a(std::move(args));
    RunOptions o;
    const po::variables_map vm = points.parse(a.argc(), a.argv(), o);
    return describe(o, vm);
}

std::vector<std::string> point(const std::string& m, const std::string& fifo, const std::string& report = "r.json") {
    return {"--scene=spheres", "--board=adm-xrc-ii", "--m=" + m, "-c", "board.fifo_depth=" + fifo,
            "--report=" + report, "-q"};
}

TEST(PointOptions, OtherSettingValuesReuseTheLastParse) {
    PointOptions points;
    EXPECT_EQ(by_points(points, point("2", "64")), full(point("2", "64")));
    EXPECT_EQ(by_points(points, point("8", "128", "s.json")), full(point("8", "128", "s.json")));
    EXPECT_EQ(by_points(points, point("24", "128", "s.json")), full(point("24", "128", "s.json")));
    EXPECT_EQ(points.reused(), 2u);
    EXPECT_NE(full(point("8", "128")), full(point("2", "128"))) << "the values must show in what is compared";
}

TEST(PointOptions, ARefusedValueIsTheParsersRefusal) {
    PointOptions points;
    by_points(points, point("2", "64"));
    std::string expected;
    try {
        full(point("99", "64"));
    } catch (const po::error& e) {
        expected = e.what();
    }
    ASSERT_FALSE(expected.empty());
    try {
        by_points(points, point("99", "64"));
        ADD_FAILURE() << "--m=99 parsed";
    } catch (const po::error& e) {
        EXPECT_EQ(e.what(), expected);
    }
    EXPECT_EQ(points.reused(), 0u);
    // The last good parse stays the one reused.
    EXPECT_EQ(by_points(points, point("3", "64")), full(point("3", "64")));
    EXPECT_EQ(points.reused(), 1u);
}

TEST(PointOptions, AnyOtherDifferenceParsesInFull) {
    PointOptions points;
    by_points(points, point("2", "64"));
    std::vector<std::string> other_board = point("2", "64");
    other_board[1] = "--board=adm-xrc-ii-64";
    EXPECT_EQ(by_points(points, other_board), full(other_board));
    std::vector<std::string> longer = point("2", "64");
    longer.push_back("--seed=4");
    EXPECT_EQ(by_points(points, longer), full(longer));
    std::vector<std::string> other_key = longer;
    other_key[4] = "board.pair_buffer_depth=64";
    EXPECT_EQ(by_points(points, other_key), full(other_key));
    std::vector<std::string> switched = longer;
    switched[2] = "--objects=2";  // another flag in m's place
    EXPECT_EQ(by_points(points, switched), full(switched));
    EXPECT_EQ(points.reused(), 0u);
}

}  // namespace
}  // namespace cdvp
