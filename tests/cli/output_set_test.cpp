// The outputs of a run as one transaction: no output names an input or
// another output, and either all are committed or none.
#include "sw/output/output_set.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sw/scene/scene.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

namespace fs = std::filesystem;

// The InputError open() throws, or "opened".
std::string open_error(OutputSet& set) {
    try {
        set.open();
    } catch (const InputError& e) {
        return e.what();
    }
    return "opened";
}

class OutputSetTest : public ::testing::Test {
protected:
    void SetUp() override {
        test::spit(dir_.file("in.csv"), "input\n");
        previous_ = fs::current_path();
        fs::current_path(dir_.path());  // so "./x" and "x" are the same file
    }
    void TearDown() override { fs::current_path(previous_); }

    // An input, then an output at 'output': the error open() gives.
    std::string output_over_input(const std::string& input, const std::string& output) {
        OutputSet set;
        set.add_input("--trace", input);
        set.add_output("--pairs-out", output);
        return open_error(set);
    }

    test::TempDir dir_;
    fs::path previous_;
};

TEST_F(OutputSetTest, OutputNamingAnInputIsRefusedHoweverSpelt) {
    fs::create_directories("sub");
    fs::create_symlink("in.csv", "link.csv");
    fs::create_symlink("link.csv", "link2.csv");
    fs::create_hard_link("in.csv", "hard.csv");
    const std::string refusal = "--pairs-out '%' is the input --trace 'in.csv'; an output never replaces an input";
    for (const std::string& output : std::vector<std::string>{"in.csv", "./in.csv", "sub/../in.csv", "link.csv", "link2.csv", "hard.csv",
                                     dir_.file("in.csv")}) {
        std::string expected = refusal;
        expected.replace(expected.find('%'), 1, output);
        EXPECT_EQ(expected, output_over_input("in.csv", output)) << output;
    }
    EXPECT_EQ("input\n", test::slurp("in.csv"));
    EXPECT_EQ(5u, dir_.count()) << "no temporary left";
}

TEST_F(OutputSetTest, InputThroughALinkIsRecognisedToo) {
    fs::create_symlink("in.csv", "link.csv");
    EXPECT_NE("opened", output_over_input("link.csv", "in.csv"));
}

TEST_F(OutputSetTest, SameOutputTwiceIsRefused) {
    fs::create_symlink("out.csv", "alias.csv");  // dangling: out.csv does not exist yet
    for (const std::string second : {"out.csv", "./out.csv", "alias.csv"}) {
        OutputSet set;
        set.add_output("--pairs-out", "out.csv");
        set.add_output("--report", second);
        EXPECT_EQ("--report '" + second + "' is the same file as --pairs-out 'out.csv'; give each output its own file",
                  open_error(set));
    }
    EXPECT_EQ(2u, dir_.count());
}

TEST_F(OutputSetTest, AFailingOutputLeavesNoTemporaryOfTheOthers) {
    OutputSet set;
    set.add_output("--pairs-out", "p.csv");
    set.add_output("--report", "no/such/dir/r.json");
    EXPECT_EQ("--report: no/such/dir/r.json: cannot write: directory 'no/such/dir' does not exist", open_error(set));
    EXPECT_EQ(1u, dir_.count());
}

TEST_F(OutputSetTest, DevicesMayBeNamedTwice) {
    OutputSet set;
    set.add_output("--pairs-out", "/dev/null");
    set.add_output("--report", "/dev/null");
    EXPECT_EQ("opened", open_error(set));
    set.file(0).stream() << "a";
    set.file(1).stream() << "b";
    set.commit();
    EXPECT_EQ(1u, dir_.count());
}

TEST_F(OutputSetTest, CommitWritesEveryOutput) {
    test::spit("old.csv", "old\n");
    OutputSet set;
    set.add_input("--trace", "in.csv");
    set.add_output("--pairs-out", "old.csv");
    set.add_output("--report", "new.json");
    ASSERT_EQ("opened", open_error(set));
    set.file(0).stream() << "pairs\n";
    set.file(1).stream() << "report\n";
    set.commit();
    EXPECT_EQ("pairs\n", test::slurp("old.csv"));
    EXPECT_EQ("report\n", test::slurp("new.json"));
    EXPECT_EQ(3u, dir_.count()) << "no temporary or backup left";
}

TEST_F(OutputSetTest, ALateFailureRollsBackEveryRename) {
    test::spit("first.csv", "first, old\n");
    OutputSet set;
    set.add_output("--pairs-out", "first.csv");
    set.add_output("--report", "second.json");
    set.add_output("--vcd", "third.vcd");
    ASSERT_EQ("opened", open_error(set));
    for (std::size_t k = 0; k < 3; ++k) set.file(k).stream() << "new " << k << "\n";
    // Something takes the third path after the checks: its rename fails.
    fs::create_directories("third.vcd/occupied");
    try {
        set.commit();
        FAIL() << "commit over a directory succeeded";
    } catch (const InputError& e) {
        EXPECT_EQ(0u, std::string(e.what()).rfind("--vcd: third.vcd: cannot write: ", 0)) << e.what();
    }
    EXPECT_EQ("first, old\n", test::slurp("first.csv")) << "the replaced file is restored";
    EXPECT_FALSE(fs::exists("second.json")) << "the new file is removed";
    EXPECT_EQ(4u, dir_.count()) << "in.csv, first.csv, third.vcd and nothing else";
}

}  // namespace
}  // namespace cdvp
