// The CLI's trace source: checked up front, then read again frame by frame
// (a pipe through an unlinked copy), with the board's per-frame limit.
#include "sw/run/frame_source.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <sstream>
#include <thread>

#include "models/control_registers/control_registers.h"
#include "sw/scene/spheres.h"
#include "sw/scene/trace_csv.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

std::string trace_text(std::size_t frames, std::size_t objects) {
    SpheresConfig config;
    config.objects = objects;
    SpheresScene scene(config);
    std::vector<Frame> all;
    for (std::size_t k = 0; k < frames; ++k) all.push_back(scene.next());
    std::ostringstream out;
    write_trace_csv(out, all);
    return out.str();
}

// Drains the source, checking each frame bitwise against 'expected'.
void expect_frames(FrameSource& source, const std::vector<Frame>& expected) {
    EXPECT_EQ(expected.size(), source.frame_count());
    for (const Frame& want : expected) {
        std::optional<Frame> got = source.next();
        ASSERT_TRUE(got);
        EXPECT_EQ(want.number, got->number);
        EXPECT_EQ(want.ids, got->ids);
        ASSERT_EQ(want.boxes.size(), got->boxes.size());
        EXPECT_EQ(0, std::memcmp(want.boxes.data(), got->boxes.data(), want.boxes.size() * sizeof(Box)));
    }
    EXPECT_FALSE(source.next());
}

TEST(TraceSource, RegularFileIsReadFrameByFrame) {
    test::TempDir dir;
    const std::string path = dir.file("t.csv");
    test::spit(path, trace_text(4, 60));
    std::unique_ptr<FrameSource> source = trace_source(path);
    EXPECT_EQ(60u, source->max_objects());
    EXPECT_EQ("trace " + path, source->describe());
    expect_frames(*source, read_trace_csv(path));
}

// A pipe is copied to an unlinked file in $TMPDIR and read twice from it, so
// memory holds a frame, not the pipe's frames, and nothing is left behind.
TEST(TraceSource, PipeIsSpooledToAnUnlinkedFileAndReadTwice) {
    test::TempDir dir;
    test::TempDir spool;
    const char* previous = std::getenv("TMPDIR");
    const std::string saved = previous != nullptr ? previous : "";
    setenv("TMPDIR", spool.file("").c_str(), 1);
    const std::string path = dir.file("fifo");
    ASSERT_EQ(0, mkfifo(path.c_str(), 0600));
    const std::string text = trace_text(3, 40);
    std::thread writer([&] { test::spit(path, text); });
    std::unique_ptr<FrameSource> source = trace_source(path);
    writer.join();
    EXPECT_EQ(0u, spool.count()) << "the copy has no name";
    std::istringstream in(text);
    expect_frames(*source, parse_trace_csv(in, "text"));
    if (previous != nullptr) {
        setenv("TMPDIR", saved.c_str(), 1);
    } else {
        unsetenv("TMPDIR");
    }
}

// Each change is at the end of a file larger than a stream buffer, so the
// second reading sees it (what it had buffered before is still the original).
TEST(TraceSource, FileChangedBetweenReadingsIsBadInput) {
    test::TempDir dir;
    const std::string path = dir.file("t.csv");
    const std::string original = trace_text(3, 300);
    ASSERT_GT(original.size(), 64u * 1024);
    std::string one_bound_changed = original;
    one_bound_changed[one_bound_changed.rfind(',') + 1] ^= 1;  // a digit of the last row
    struct Change {
        std::string text;
        const char* how;
    };
    for (const Change& change :
         {Change{trace_text(2, 300), "fewer frames than on the first reading"},
          Change{original + "3,1,0,0,0,1,1,1\n", "more frames than on the first reading"},
          Change{original + "2,1000,0,0,0,1,1,1\n", "more than 300 boxes"},
          Change{one_bound_changed, "frame 2 differs from the first reading"}}) {
        test::spit(path, original);
        std::unique_ptr<FrameSource> source = trace_source(path);
        test::spit(path, change.text);  // the same file, rewritten in place
        try {
            while (source->next()) {
            }
            ADD_FAILURE() << "no exception for " << change.how;
        } catch (const InputError& e) {
            EXPECT_NE(std::string::npos, std::string(e.what()).find(change.how)) << e.what();
            EXPECT_NE(std::string::npos, std::string(e.what()).find("changed while being read")) << e.what();
        }
    }
}

TEST(TraceSource, FrameLimitIsTheBoardsAddressMap) {
    EXPECT_EQ(address_map::kMaxObjects, board_trace_limits().max_boxes_per_frame);
    test::TempDir dir;
    const std::string path = dir.file("t.csv");
    test::spit(path, trace_text(2, 3) + "not read\n");
    try {
        trace_source(path, TraceLimits{2, "the board's address map"});
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(path + ":4: frame 0 has more than 2 boxes; expected at most 2 boxes a frame (the board's "
                         "address map)",
                  std::string(e.what()));
    }
}

TEST(TraceSource, FramesPastTheLimitAreRefusedAtTheFirstRowBeyond) {
    test::TempDir dir;
    const std::string path = dir.file("t.csv");
    test::spit(path, trace_text(3, 2));
    TraceLimits limits = board_trace_limits();
    limits.max_frames = 2;
    limits.frames_reason = "the memory budget";
    try {
        trace_source(path, limits);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(path + ":6: frame 2 is one more than 2 frames; expected at most 2 frames (the memory budget)",
                  std::string(e.what()));
    }
}

// A trace of any kind is held to the size limit while it is first read.
TEST(TraceSource, FilesAndPipesPastTheSizeLimitAreRefused) {
    test::TempDir dir;
    const std::string text = trace_text(3, 40);
    InputLimits input;
    input.max_bytes = text.size() - 1;
    input.max_bytes_origin = "the test's";
    const std::string file = dir.file("t.csv");
    test::spit(file, text);
    EXPECT_THROW(trace_source(file, board_trace_limits(), input), InputError);
    const std::string fifo = dir.file("fifo");
    ASSERT_EQ(0, mkfifo(fifo.c_str(), 0600));
    std::thread writer([&] { test::spit(fifo, text); });
    try {
        trace_source(fifo, board_trace_limits(), input);
        ADD_FAILURE() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(fifo + ": more than " + std::to_string(input.max_bytes) + " bytes; expected at most " +
                      std::to_string(input.max_bytes) + " bytes (the test's)",
                  std::string(e.what()));
    }
    writer.join();
    input.max_bytes = text.size();
    std::thread again([&] { test::spit(fifo, text); });
    EXPECT_EQ(trace_source(fifo, board_trace_limits(), input)->frame_count(), 3u) << "at the limit it is read";
    again.join();
}

}  // namespace
}  // namespace cdvp
