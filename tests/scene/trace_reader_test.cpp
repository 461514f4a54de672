// The trace reader's bounds: line length, per-frame box limit, reading one
// frame at a time; and the number spellings at the edges of double.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <streambuf>
#include <string>

#include "sw/scene/pairs_csv.h"
#include "sw/scene/trace_csv.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

const std::string kTraceHeader = "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n";

std::vector<Frame> parse_trace(const std::string& text, const TraceLimits& limits = {}) {
    std::istringstream in(text);
    return parse_trace_csv(in, "a.csv", limits);
}

// The InputError message of parsing 'text', or "" if it parses.
std::string error_of(const std::string& text, const TraceLimits& limits = {}) {
    try {
        parse_trace(text, limits);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// An endless input: 'prefix', then 'fill' bytes forever, in 64-byte chunks;
// counts the bytes handed out, so a test can bound what the reader consumed.
class EndlessInput : public std::streambuf {
public:
    EndlessInput(std::string prefix, char fill) : prefix_(std::move(prefix)), chunk_(64, fill) {}
    std::size_t bytes_supplied() const { return supplied_; }

protected:
    int_type underflow() override {
        std::string& next = prefix_.empty() ? chunk_ : prefix_;
        current_ = next;
        prefix_.clear();
        supplied_ += current_.size();
        setg(current_.data(), current_.data(), current_.data() + current_.size());
        return traits_type::to_int_type(current_[0]);
    }

private:
    std::string prefix_;
    std::string chunk_;
    std::string current_;
    std::size_t supplied_ = 0;
};

TEST(TraceReader, EndlessLineFailsAfterTheLimitWithoutReadingOn) {
    for (char fill : {'\0', '7', ' '}) {
        EndlessInput source(fill == ' ' ? kTraceHeader + "0,1," : "", fill);
        std::istream in(&source);
        try {
            parse_trace_csv(in, "endless");
            FAIL() << "no exception";
        } catch (const InputError& e) {
            const std::string line = fill == ' ' ? "2" : "1";
            EXPECT_EQ("endless:" + line + ": line longer than 4096 bytes; expected at most 4096 "
                      "bytes a line, counting its line end",
                      std::string(e.what()));
        }
        EXPECT_LE(source.bytes_supplied(), kTraceHeader.size() + 4 + kMaxLineBytes + 64);
    }
}

TEST(TraceReader, DevZeroFailsAtOnce) {
    const auto start = std::chrono::steady_clock::now();
    try {
        read_trace_csv("/dev/zero");
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(0u, std::string(e.what()).rfind("/dev/zero:1: line longer than 4096 bytes", 0))
            << e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(TraceReader, DirectoryIsNamedAsSuch) {
    test::TempDir dir;
    try {
        read_trace_csv(dir.path().string());
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(dir.path().string() + ": cannot open: Is a directory (EISDIR); expected a file", std::string(e.what()));
    }
}

// A row padded with spaces so that the line, with its line end, is 'bytes'.
std::string row_of_length(std::size_t bytes, const std::string& line_end) {
    std::string row = "0,1,0,0,0,1,1,1";
    return row + std::string(bytes - row.size() - line_end.size(), ' ') + line_end;
}

TEST(TraceReader, LineLimitCountsTheLineEnd) {
    for (std::string line_end : {"\n", "\r\n"}) {
        EXPECT_EQ(1u, parse_trace(kTraceHeader + row_of_length(kMaxLineBytes, line_end)).size());
        EXPECT_EQ(0u, error_of(kTraceHeader + row_of_length(kMaxLineBytes + 1, line_end))
                          .rfind("a.csv:2: line longer than 4096 bytes", 0));
    }
    // The last line may lack its line end; it then holds at most 4096 bytes.
    const std::string last = row_of_length(kMaxLineBytes + 1, "\n").substr(0, kMaxLineBytes);
    EXPECT_EQ(1u, parse_trace(kTraceHeader + last).size());
    EXPECT_NE("", error_of(kTraceHeader + last + " "));
}

TEST(TraceReader, NumbersOfAnyLengthWithinALine) {
    // 0.000...0001 with 200 characters, and 1 followed by 300 zeros and a fraction.
    std::string tiny = "0." + std::string(197, '0') + "1";
    std::string huge = "1" + std::string(300, '0') + ".25";
    ASSERT_EQ(200u, tiny.size());
    std::vector<Frame> frames = parse_trace(kTraceHeader + "0,1," + tiny + ",0,0," + huge + ",1,1\n");
    ASSERT_EQ(1u, frames.size());
    EXPECT_EQ(std::strtod(tiny.c_str(), nullptr), frames[0].boxes[0].min[0]);
    EXPECT_EQ(1e300, frames[0].boxes[0].max[0]);
    EXPECT_GT(frames[0].boxes[0].min[0], 0.0);
}

TEST(TraceReader, EdgesOfDouble) {
    std::vector<Frame> frames = parse_trace(kTraceHeader +
                                      "0,1,4.9406564584124654e-324,-0,1e-400,1e39,+0,1e-300\n"
                                      "0,2,-1e-400,-2.2250738585072014e-308,0,0,0x1p-1022,0\n"
                                      "0,3,-inf,-INFINITY,-Inf,inf,Infinity,0x1.fffffffffffffp+1023\n");
    ASSERT_EQ(1u, frames.size());
    const Box& a = frames[0].boxes[0];
    EXPECT_EQ(std::numeric_limits<double>::denorm_min(), a.min[0]);  // denormal kept
    EXPECT_TRUE(std::signbit(a.min[1]));                             // -0 kept
    EXPECT_EQ(0.0, a.min[2]);                                        // underflow rounds to 0
    EXPECT_FALSE(std::signbit(a.min[2]));
    EXPECT_EQ(1e39, a.max[0]);  // beyond float, within double
    const Box& b = frames[0].boxes[1];
    EXPECT_EQ(0.0, b.min[0]);
    EXPECT_TRUE(std::signbit(b.min[0]));  // negative underflow rounds to -0
    EXPECT_EQ(-std::numeric_limits<double>::min(), b.min[1]);
    EXPECT_EQ(std::numeric_limits<double>::min(), b.max[1]);
    const Box& c = frames[0].boxes[2];
    for (int axis = 0; axis < 3; ++axis) EXPECT_TRUE(std::isinf(c.min[axis]) && c.min[axis] < 0);
    EXPECT_EQ(std::numeric_limits<double>::max(), c.max[2]);
}

TEST(TraceReader, IntegersTakeLeadingZerosAndTheFullRange) {
    std::vector<Frame> frames = parse_trace(kTraceHeader + "007,0018446744073709551615,0,0,0,1,1,1\n");
    ASSERT_EQ(1u, frames.size());
    EXPECT_EQ(7u, frames[0].number);
    EXPECT_EQ(std::numeric_limits<uint64_t>::max(), frames[0].ids[0]);
}

TEST(TraceReader, ByteOrderMarkBeforeTheHeader) {
    EXPECT_EQ(1u, parse_trace("\xEF\xBB\xBF" + kTraceHeader + "0,1,0,0,0,1,1,1\n").size());
    test::TempDir dir;
    test::spit(dir.file("p.csv"), "\xEF\xBB\xBF" "frame,a,b\r\n0,1,2\r\n");
    EXPECT_EQ(1u, read_pairs_csv(dir.file("p.csv")).size());
}

TEST(TraceReader, NulByteIsNotText) {
    std::string text = kTraceHeader + "0,1,0,0,0,1,1,1\n0,2";
    text += '\0';
    text += ",0,0,0,1,1,1\n";
    EXPECT_EQ("a.csv:3: NUL byte at column 4; expected a text file", error_of(text));
}

TEST(TraceReader, FrameBeyondTheLimitFailsOnItsLineBeforeTheRest) {
    const TraceLimits limits{3, "the board's address map"};
    std::string rows = "0,1,0,0,0,1,1,1\n0,2,0,0,0,1,1,1\n0,3,0,0,0,1,1,1\n";
    EXPECT_EQ(1u, parse_trace(kTraceHeader + rows, limits).size());
    // The rest of the file is never read: its bad row would be line 6.
    EXPECT_EQ("a.csv:5: frame 0 has more than 3 boxes; expected at most 3 boxes a frame "
              "(the board's address map)",
              error_of(kTraceHeader + rows + "0,4,0,0,0,1,1,1\nnot a row\n", limits));
    // Later frames count from zero again.
    EXPECT_EQ(2u, parse_trace(kTraceHeader + rows + "9,1,0,0,0,1,1,1\n", limits).size());
    EXPECT_EQ(0u, error_of(kTraceHeader + "5,1,0,0,0,1,1,1\n", {0, "none"}).rfind("a.csv:2: frame 5", 0));
}

TEST(TraceReader, ReportsTheFirstRepeatedIdInFileOrder) {
    std::string text = kTraceHeader + "0,5,0,0,0,1,1,1\n0,7,0,0,0,1,1,1\n0,7,0,0,0,1,1,1\n"
                                 "0,5,0,0,0,1,1,1\n0,7,0,0,0,1,1,1\n";
    EXPECT_EQ("a.csv:4: id 7 appears twice in frame 0 (first on line 3); expected unique ids "
              "within a frame",
              error_of(text));
    // Equal ids in different frames are fine.
    EXPECT_EQ(2u, parse_trace(kTraceHeader + "0,5,0,0,0,1,1,1\n1,5,0,0,0,1,1,1\n").size());
}

// Rows made on demand: 'frames' frames of 'per_frame' boxes each.
class GeneratedTrace : public std::streambuf {
public:
    GeneratedTrace(std::size_t frames, std::size_t per_frame) : frames_(frames), per_frame_(per_frame) {}
    std::size_t rows_supplied() const { return row_; }

protected:
    int_type underflow() override {
        if (row_ == frames_ * per_frame_) return traits_type::eof();
        line_ = row_ == 0 && !header_done_ ? kTraceHeader : "";
        header_done_ = true;
        const std::size_t id = row_ % per_frame_;
        line_ += std::to_string(row_ / per_frame_) + "," + std::to_string(id) + "," + std::to_string(id) +
                 ",0,0," + std::to_string(id + 1) + ",1,1\n";
        ++row_;
        setg(line_.data(), line_.data(), line_.data() + line_.size());
        return traits_type::to_int_type(line_[0]);
    }

private:
    std::size_t frames_;
    std::size_t per_frame_;
    std::size_t row_ = 0;
    bool header_done_ = false;
    std::string line_;
};

TEST(TraceReader, ReadsOneFrameAtATime) {
    GeneratedTrace source(1000, 100);
    std::istream in(&source);
    TraceReader reader(in, "generated");
    std::optional<Frame> first = reader.next_frame();
    ASSERT_TRUE(first);
    EXPECT_EQ(100u, first->boxes.size());
    // Only the first frame and the first row of the next were read.
    EXPECT_EQ(101u, source.rows_supplied());
    std::size_t frames = 1;
    while (std::optional<Frame> frame = reader.next_frame()) {
        EXPECT_EQ(frames, frame->number);
        EXPECT_EQ(100u, frame->ids.size());
        ++frames;
    }
    EXPECT_EQ(1000u, frames);
}

TEST(TraceReader, BadRowIsFoundWhenItsFrameIsRead) {
    std::istringstream in(kTraceHeader + "0,1,0,0,0,1,1,1\n1,1,0,0,0,1,1,1\n1,2,x,0,0,1,1,1\n");
    TraceReader reader(in, "a.csv");
    EXPECT_TRUE(reader.next_frame());
    try {
        reader.next_frame();
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(0u, std::string(e.what()).rfind("a.csv:4: field 'min_x'", 0)) << e.what();
    }
}

}  // namespace
}  // namespace cdvp
