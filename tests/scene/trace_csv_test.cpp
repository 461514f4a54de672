#include "sw/scene/trace_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "sw/scene/spheres.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
const std::string kHeader = "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n";

std::vector<Frame> parse(const std::string& text) {
    std::istringstream in(text);
    return parse_trace_csv(in, "a.csv");
}

// Bitwise comparison, so -0 vs +0 and exact round-trips are checked.
void expect_same_frames(const std::vector<Frame>& expected, const std::vector<Frame>& actual) {
    ASSERT_EQ(expected.size(), actual.size());
    for (std::size_t f = 0; f < expected.size(); ++f) {
        EXPECT_EQ(expected[f].number, actual[f].number);
        EXPECT_EQ(expected[f].ids, actual[f].ids);
        ASSERT_EQ(expected[f].boxes.size(), actual[f].boxes.size());
        for (std::size_t k = 0; k < expected[f].boxes.size(); ++k) {
            EXPECT_EQ(0, std::memcmp(&expected[f].boxes[k], &actual[f].boxes[k], sizeof(Box)))
                << "frame " << f << " box " << k;
        }
    }
}

TEST(TraceCsv, RoundTripsExactly) {
    std::vector<Frame> frames(3);
    frames[0] = {0, {7, 3}, {{{0.1, -0.0, 1e-310}, {1.0 / 3, 0.0, 2.0}},
                             {{-kInfinity, -1.0, -kInfinity}, {kInfinity, 0.0, kInfinity}}}};
    frames[1] = {5, {18446744073709551615ULL}, {{{1e300, 2, 3}, {1e301, 4, 5}}}};
    frames[2] = {6, {1, 0, 2}, {{{0, 0, 0}, {0, 0, 0}},
                                {{-5e-324, 1, 1}, {5e-324, 1.5, 1.25}},
                                {{123456.789, 2, 3}, {123456.7890000001, 3, 4}}}};
    std::ostringstream out;
    write_trace_csv(out, frames);
    EXPECT_EQ(0u, out.str().rfind(kHeader, 0));
    EXPECT_NE(std::string::npos, out.str().find(",-inf,"));
    expect_same_frames(frames, parse(out.str()));
}

TEST(TraceCsv, HeaderOnlyIsZeroFrames) {
    EXPECT_TRUE(parse(kHeader).empty());
    EXPECT_TRUE(parse(kHeader + "\n\n").empty());
    EXPECT_TRUE(parse("frame,id,min_x,min_y,min_z,max_x,max_y,max_z").empty());
}

TEST(TraceCsv, AcceptsCrlfSpacesInfinitiesAndGaps) {
    std::string text =
        "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\r\n"
        "2, 9 ,-inf,-INF,-Infinity, +inf ,inf,INFINITY\r\n"
        "2,4,1e308,0,0,1.7976931348623157e308,0,0\r\n"
        "7,9,-inf,-0,0,0,0,0x1p-3\r\n"
        "\r\n";
    std::vector<Frame> frames = parse(text);
    ASSERT_EQ(2u, frames.size());
    EXPECT_EQ(2u, frames[0].number);
    EXPECT_EQ(7u, frames[1].number);
    EXPECT_EQ((std::vector<uint64_t>{9, 4}), frames[0].ids);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(-kInfinity, frames[0].boxes[0].min[axis]);
        EXPECT_EQ(kInfinity, frames[0].boxes[0].max[axis]);
    }
    EXPECT_EQ(1e308, frames[0].boxes[1].min[0]);
    EXPECT_EQ(std::numeric_limits<double>::max(), frames[0].boxes[1].max[0]);
    EXPECT_EQ(-kInfinity, frames[1].boxes[0].min[0]);
    EXPECT_TRUE(std::signbit(frames[1].boxes[0].min[1]));
    EXPECT_EQ(0.125, frames[1].boxes[0].max[2]);
}

TEST(TraceCsv, ReadsFileAndReportsMissingFile) {
    test::TempDir dir;
    test::spit(dir.file("t.csv"), kHeader + "0,1,0,0,0,1,1,1\n");
    EXPECT_EQ(1u, read_trace_csv(dir.file("t.csv")).size());
    std::string missing = dir.file("missing.csv");
    try {
        read_trace_csv(missing);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(missing + ": cannot open: No such file or directory (ENOENT)", e.what());
    }
}

TEST(TraceCsv, WriteRejectsMismatchedFrame) {
    std::ostringstream out;
    EXPECT_THROW(write_trace_csv(out, {Frame{0, {1, 2}, {Box{}}}}), std::invalid_argument);
}

struct BadInput {
    const char* name;    // test name suffix
    const char* text;
    const char* prefix;  // "a.csv:LINE: "
    const char* words;   // part of the message
};

class TraceCsvBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(TraceCsvBadInput, ThrowsOneLineErrorWithLocation) {
    const BadInput& bad = GetParam();
    try {
        parse(bad.text);
        FAIL() << "no exception for:\n" << bad.text;
    } catch (const InputError& e) {
        std::string message = e.what();
        EXPECT_EQ(0u, message.rfind(bad.prefix, 0)) << message;
        EXPECT_NE(std::string::npos, message.find(bad.words)) << message;
        EXPECT_EQ(std::string::npos, message.find_first_of("\r\n")) << message;
        EXPECT_LT(message.size(), 160u) << message;
    }
}

#define H "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n"
#define ROW "0,1,0,0,0,1,1,1\n"

// {name, input, location prefix, part of the message}
INSTANTIATE_TEST_SUITE_P(
    Errors, TraceCsvBadInput,
    ::testing::Values(
        BadInput{"EmptyFile", "", "a.csv:1: ",
                 "expected header 'frame,id,min_x,min_y,min_z,max_x,max_y,max_z', "
                 "found end of file"},
        BadInput{"WrongHeader", "frame,id,x\n0,1,2\n", "a.csv:1: ", "found 'frame,id,x'"},
        BadInput{"BlankBeforeHeader", "\n" H ROW, "a.csv:1: ", "found ''"},
        BadInput{"LongHeaderTruncated",
                 "frame,id,min_x,min_y,min_z,max_x,max_y,max_z,extra,columns,to,make,long\n",
                 "a.csv:1: ", "... (71 bytes)'"},
        BadInput{"TooFewFields", H ROW "0,2,0,0,0,1,1\n", "a.csv:3: ",
                 "expected 8 comma-separated fields, found 7"},
        BadInput{"TooManyFields", H "0,2,0,0,0,1,1,1,\n", "a.csv:2: ", "found 9"},
        BadInput{"NotANumber", H "0,1,abc,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'min_x': expected a decimal number, found 'abc'"},
        BadInput{"SpaceInsideNumber", H "0,1,0,0,0,1,1 2,1\n", "a.csv:2: ",
                 "field 'max_y': expected a decimal"},
        BadInput{"EmptyNumber", H "0,1,0,0,,1,1,1\n", "a.csv:2: ",
                 "field 'min_z': expected a decimal"},
        BadInput{"Nan", H "0,1,0,0,0,1,nan,1\n", "a.csv:2: ",
                 "field 'max_y': NaN is not allowed (expected a number or +-inf)"},
        BadInput{"NegativeNanPayload", H "0,1,-NaN(123),0,0,1,1,1\n", "a.csv:2: ",
                 "field 'min_x': NaN"},
        BadInput{"MinAboveMax", H "0,1,3,0,0,2,1,1\n", "a.csv:2: ",
                 "min_x (3) is greater than max_x (2); expected min <= max"},
        BadInput{"InfMinAboveMax", H "0,1,0,0,inf,1,1,1e308\n", "a.csv:2: ",
                 "min_z (inf) is greater"},
        BadInput{"DuplicateId", H ROW "0,4,0,0,0,1,1,1\n0,5,0,0,0,1,1,1\n0,4,0,0,0,1,1,1\n",
                 "a.csv:5: ",
                 "id 4 appears twice in frame 0 (first on line 3); expected unique ids"},
        BadInput{"DescendingFrame", H ROW "2,1,0,0,0,1,1,1\n1,1,0,0,0,1,1,1\n", "a.csv:4: ",
                 "frame 1 after frame 2; expected ascending frame numbers"},
        BadInput{"FrameNotContiguous", H ROW "1,1,0,0,0,1,1,1\n0,2,0,0,0,1,1,1\n",
                 "a.csv:4: ", "frame 0 after frame 1"},
        BadInput{"NegativeFrame", H "-1,1,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'frame': expected a non-negative integer, found '-1'"},
        BadInput{"PlusSignedFrame", H "+1,1,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'frame': expected a non-negative integer"},
        BadInput{"FractionalId", H "0,1.5,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'id': expected a non-negative integer"},
        BadInput{"EmptyId", H "0,,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'id': expected a non-negative integer"},
        BadInput{"IdOverflow", H "0,18446744073709551616,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'id': expected an integer below 2^64"},
        BadInput{"BlankLineInMiddle", H ROW "\n0,2,0,0,0,1,1,1\n", "a.csv:3: ",
                 "blank line"},
        BadInput{"StrayCarriageReturn", H "0,1,0,0,0,1,1,1\r\r\n", "a.csv:2: ",
                 "carriage return not followed by a line feed at column 16; expected LF or "
                 "CRLF line ends"},
        BadInput{"CarriageReturnOnlyLineEnds", "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\r"
                 "0,1,0,0,0,1,1,1\r", "a.csv:1: ", "carriage return not followed by a line feed at column 45"},
        BadInput{"CarriageReturnAtEndOfFile", H "0,1,0,0,0,1,1,1\r", "a.csv:2: ",
                 "carriage return not followed by a line feed"},
        BadInput{"ControlCharacter", H "0,1,0,0,0,1,1,1\x01\n", "a.csv:2: ",
                 "control character 0x01 at column 16; expected printable text"},
        BadInput{"VerticalTab", H "0,1,0,0,0,1,1,\v1\n", "a.csv:2: ", "control character 0x0b"},
        BadInput{"Delete", H "0,1\x7f,0,0,0,1,1,1\n", "a.csv:2: ", "control character 0x7f at column 4"},
        BadInput{"TrailingComma", H "0,1,0,0,0,1,1,1,\n", "a.csv:2: ",
                 "expected 8 comma-separated fields, found 9"},
        BadInput{"SemicolonSeparated", H "0;1;0;0;0;1;1;1\n", "a.csv:2: ",
                 "expected 8 comma-separated fields, found 1"},
        BadInput{"BomBeforeRow", H "\xEF\xBB\xBF" ROW, "a.csv:2: ", "field 'frame'"},
        BadInput{"HexId", H "0,0x10,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'id': expected a non-negative integer, found '0x10'"},
        BadInput{"ExponentFrame", H "1e3,1,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'frame': expected a non-negative integer, found '1e3'"},
        BadInput{"SpaceInsideId", H "0,1 2,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'id': expected a non-negative integer, found '1 2'"},
        BadInput{"FrameOverflow", H "99999999999999999999999,1,0,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'frame': expected an integer below 2^64"},
        BadInput{"OverflowToInfinity", H "0,1,0,0,0,1e999,1,1\n", "a.csv:2: ",
                 "field 'max_x': '1e999' is beyond the double range"},
        BadInput{"NegativeOverflowToInfinity", H "0,1,-1e99999,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'min_x': '-1e99999' is beyond the double range"},
        BadInput{"NanSpelledOut", H "0,1,0,0,0,1,1,NAN\n", "a.csv:2: ", "field 'max_z': NaN"},
        BadInput{"DecimalComma", H "0,1,0,0,0,\"1,5\",1,1\n", "a.csv:2: ", "found 9"},
        BadInput{"HexWithoutDigits", H "0,1,0x,0,0,1,1,1\n", "a.csv:2: ",
                 "field 'min_x': expected a decimal number, found '0x'"},
        BadInput{"MinusZeroAboveNegative", H "0,1,-0,0,0,-1e-300,1,1\n", "a.csv:2: ",
                 "min_x (-0) is greater than max_x (-1e-300)"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });

#undef ROW
#undef H

// A 100,000-row trace round-trips exactly (parse speed is measured in
// board_bench, not asserted here).
TEST(TraceCsv, RoundTripsALargeTrace) {
    SpheresConfig config;
    config.objects = 1000;
    SpheresScene scene(config);
    std::vector<Frame> frames;
    for (int k = 0; k < 100; ++k) frames.push_back(scene.next());
    std::ostringstream out;
    write_trace_csv(out, frames);
    expect_same_frames(frames, parse(out.str()));
}

}  // namespace
}  // namespace cdvp
