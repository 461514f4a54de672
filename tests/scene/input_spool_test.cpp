// Inputs read under limits, and the bounded copy of a pipe: the limits hold
// while the bytes are copied (an endless input stops at once or at its size
// limit), the copy is whole and nameless, and a child process reads it
// through an inherited descriptor.
#include "sw/scene/input_spool.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <string>
#include <thread>

#include "models/common/user_text.h"
#include "sw/scene/trace_csv.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

InputLimits limits(uint64_t max_bytes) {
    InputLimits l;
    l.max_bytes = max_bytes;
    l.max_bytes_origin = "--max-trace-size 1";
    return l;
}

std::string read_all(std::istream& in) {
    std::string text;
    for (char c; in.get(c);) text += c;
    return text;
}

// What reading the spool's stream to its end throws ("" for nothing).
std::string refusal_of(InputSpool& spool) {
    try {
        read_all(spool.stream());
        spool.finish();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(InputSpool, CopiesAPipeWholeAndNamelessAsItIsRead) {
    test::TempDir dir, spool_dir;
    const std::string fifo = dir.file("fifo");
    ASSERT_EQ(0, mkfifo(fifo.c_str(), 0600));
    std::string text;
    for (int k = 0; k < 20000; ++k) text += std::to_string(k) + ",0,0,0,0,1,1,1\n";  // several chunks
    std::thread writer([&] { test::spit(fifo, text); });
    InputSpool spool(fifo, limits(1 << 20), spool_dir.path().string());
    EXPECT_EQ(read_all(spool.stream()), text);
    spool.finish();
    writer.join();
    EXPECT_EQ(spool.bytes(), text.size());
    EXPECT_EQ(spool_dir.count(), 0u) << "the copy has no name";
    EXPECT_EQ(test::slurp(spool.path()), text) << "read anew from its start";
    EXPECT_EQ(test::slurp(spool.path()), text) << "as often as needed";
}

// /dev/zero has no line ends: refused at its first line, after one chunk.
TEST(InputSpool, AnEndlessLineIsRefusedAtItsFirstLine) {
    test::TempDir spool_dir;
    const auto start = std::chrono::steady_clock::now();
    InputSpool spool("/dev/zero", limits(uint64_t{1} << 40), spool_dir.path().string());
    EXPECT_EQ(refusal_of(spool),
              "/dev/zero:1: line longer than 4096 bytes; expected at most 4096 bytes a line, counting its line end");
    EXPECT_LE(spool.bytes(), kMaxLineBytes) << "nothing past the limit is copied";
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

// Good lines without end: refused at the size limit, with no more copied.
TEST(InputSpool, EndlessGoodLinesAreRefusedAtTheSizeLimit) {
    test::TempDir dir, spool_dir;
    const std::string fifo = dir.file("fifo");
    ASSERT_EQ(0, mkfifo(fifo.c_str(), 0600));
    const pid_t yes = fork();
    if (yes == 0) {
        execlp("sh", "sh", "-c", ("exec yes 0,0,0,0,0,1,1,1 > '" + fifo + "' 2>/dev/null").c_str(), nullptr);
        _exit(127);
    }
    std::string refusal;
    try {
        InputSpool spool(fifo, limits(1 << 20), spool_dir.path().string());
        spool.finish();
    } catch (const InputError& e) {
        refusal = e.what();
    }
    kill(yes, SIGTERM);  // it dies of SIGPIPE anyway once the reader has gone
    waitpid(yes, nullptr, 0);
    EXPECT_EQ(refusal, fifo + ": more than 1048576 bytes; expected at most 1048576 bytes (--max-trace-size 1)");
}

TEST(InputSpool, TheSizeLimitIsTheFirstBytePastIt) {
    test::TempDir dir, spool_dir;
    const std::string path = dir.file("t.csv");
    test::spit(path, std::string(100, 'x') + "\n" + std::string(100, 'y') + "\n");
    for (uint64_t max : {uint64_t{202}, uint64_t{201}, uint64_t{101}}) {
        InputSpool spool(path, limits(max), spool_dir.path().string());
        const std::string refusal = refusal_of(spool);
        if (max == 202) {
            EXPECT_EQ(refusal, "");
        } else {
            EXPECT_EQ(refusal, path + ": more than " + std::to_string(max) + " bytes; expected at most " +
                                   std::to_string(max) + " bytes (--max-trace-size 1)");
            EXPECT_EQ(spool.bytes(), max);
        }
    }
}

// A line of exactly the limit with its line end passes; one byte more does
// not, whether the line end is LF or CRLF, whichever chunk it falls in.
TEST(LimitedFile, LinesAtTheLimitPassAndOneByteMoreDoesNot) {
    test::TempDir dir;
    const std::string path = dir.file("t.csv");
    for (const char* end : {"\n", "\r\n"}) {
        const std::string at_limit = std::string(kMaxLineBytes - std::strlen(end), 'a') + end;
        std::string filler;  // 65,500 bytes: the line at the limit spans the first chunk's end
        for (int k = 0; k < 655; ++k) filler += std::string(99, 'b') + "\n";
        test::spit(path, filler + at_limit + "b\n");
        LimitedFile fine(path, limits(1 << 20));
        EXPECT_EQ(read_all(fine.stream()).size(), filler.size() + kMaxLineBytes + 2);
        test::spit(path, "b\n" + std::string(kMaxLineBytes, 'a') + end);
        LimitedFile past(path, limits(1 << 20));
        try {
            read_all(past.stream());
            ADD_FAILURE() << "a line of " << kMaxLineBytes + std::strlen(end) << " bytes passed";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), path + ":2: " + line_too_long(kMaxLineBytes));
        }
    }
}

TEST(LimitedFile, AFilePastTheSizeLimitIsRefusedBeforeItIsRead) {
    test::TempDir dir;
    const std::string path = dir.file("t.csv");
    test::spit(path, std::string(2000, '\n'));
    try {
        LimitedFile file(path, limits(1000));
        FAIL() << "no refusal";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": 2000 bytes, more than 1000; expected at most 1000 bytes "
                                                "(--max-trace-size 1)");
    }
}

// A child inherits the copy's descriptor and reads the copy by path().
TEST(InputSpool, AChildProcessReadsTheCopy) {
    test::TempDir dir, spool_dir;
    const std::string path = dir.file("fifo");
    ASSERT_EQ(0, mkfifo(path.c_str(), 0600));
    const std::string text = std::string(kTraceCsvHeader) + "\n0,1,0,0,0,1,1,1\n";
    std::thread writer([&] { test::spit(path, text); });
    InputSpool spool(path, limits(1 << 20), spool_dir.path().string());
    spool.finish();
    writer.join();
    spool.keep_across_exec();
    const std::string copy = dir.file("copy");
    const pid_t child = fork();
    if (child == 0) {
        execlp("sh", "sh", "-c", ("cat '" + spool.path() + "' > '" + copy + "'").c_str(), nullptr);
        _exit(127);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_EQ(test::slurp(copy), text);
}

}  // namespace
}  // namespace cdvp
