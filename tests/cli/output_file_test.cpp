#include "sw/output/output_file.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <thread>

#include <filesystem>
#include <utility>

#include "sw/output/output_cleanup.h"
#include "sw/scene/scene.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

namespace fs = std::filesystem;

TEST(OutputFile, CommitRenamesAndLeavesNoTemp) {
    test::TempDir dir;
    std::string final_path = dir.file("out.csv");
    OutputFile file(final_path);
    std::string temp = file.temp_path();
    EXPECT_EQ(0u, temp.rfind(final_path + ".part-", 0)) << temp;
    EXPECT_TRUE(fs::exists(temp));
    EXPECT_FALSE(fs::exists(final_path));
    file.stream() << "hello\n";
    file.commit();
    EXPECT_EQ("hello\n", test::slurp(final_path));
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_EQ(1u, dir.count());
    EXPECT_THROW(file.commit(), std::logic_error);
}

TEST(OutputFile, CommitReplacesExistingFileAndUsesUmaskMode) {
    test::TempDir dir;
    std::string final_path = dir.file("out.csv");
    test::spit(final_path, "old contents\n");
    {
        OutputFile file(final_path);
        file.stream() << "new\n";
        file.commit();
    }
    EXPECT_EQ("new\n", test::slurp(final_path));
    mode_t mask = umask(0);
    umask(mask);
    struct stat st{};
    ASSERT_EQ(0, stat(final_path.c_str(), &st));
    EXPECT_EQ(0666 & ~mask, st.st_mode & 0777);
}

TEST(OutputFile, DestructionWithoutCommitLeavesNothing) {
    test::TempDir dir;
    std::string final_path = dir.file("out.csv");
    std::string temp;
    {
        OutputFile file(final_path);
        temp = file.temp_path();
        file.stream() << "partial";
        EXPECT_EQ(1u, dir.count());
    }
    EXPECT_FALSE(fs::exists(temp));
    EXPECT_FALSE(fs::exists(final_path));
    EXPECT_EQ(0u, dir.count());
}

TEST(OutputFile, MissingDirectoryThrows) {
    test::TempDir dir;
    std::string final_path = dir.file("no/such/dir/out.csv");
    try {
        OutputFile file(final_path);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(final_path + ": cannot write: directory '" + dir.file("no/such/dir") + "' does not exist",
                  std::string(e.what()));
    }
}

TEST(OutputFile, PathOnlyModeWithSuffix) {
    test::TempDir dir;
    std::string final_path = dir.file("wave.vcd");
    OutputFile file(final_path, ".vcd", false);
    const std::string& temp = file.temp_path();
    ASSERT_GT(temp.size(), 4u);
    EXPECT_EQ(".vcd", temp.substr(temp.size() - 4));
    EXPECT_THROW(file.stream(), std::logic_error);
    test::spit(temp, "$end\n");  // a library writing the file itself
    file.commit();
    EXPECT_EQ("$end\n", test::slurp(final_path));
    EXPECT_EQ(1u, dir.count());
}

TEST(OutputFile, MoveTransfersOwnership) {
    test::TempDir dir;
    std::string final_path = dir.file("out.csv");
    OutputFile a(final_path);
    std::string temp = a.temp_path();
    OutputFile b(std::move(a));
    EXPECT_EQ(temp, b.temp_path());
    EXPECT_TRUE(a.temp_path().empty());
    OutputFile c(dir.file("other.csv"));
    std::string other_temp = c.temp_path();
    c = std::move(b);  // discards c's own temporary file
    EXPECT_FALSE(fs::exists(other_temp));
    c.stream() << "moved\n";
    c.commit();
    EXPECT_EQ("moved\n", test::slurp(final_path));
    EXPECT_EQ(1u, dir.count());
}

TEST(OutputFile, TwoOutputsForOnePathDoNotCollide) {
    test::TempDir dir;
    OutputFile a(dir.file("out.csv"));
    OutputFile b(dir.file("out.csv"));
    EXPECT_NE(a.temp_path(), b.temp_path());
}

}  // namespace
}  // namespace cdvp

namespace cdvp {
namespace {

namespace fs = std::filesystem;

std::string written_through(const test::TempDir& dir, const std::string& link_name) {
    OutputFile file(dir.file(link_name));
    file.stream() << "through\n";
    file.commit();
    return test::slurp(dir.file(link_name));
}

TEST(OutputFile, SymbolicLinkIsWrittenThroughAndStaysALink) {
    test::TempDir dir;
    test::spit(dir.file("real.csv"), "old\n");
    fs::create_symlink("real.csv", dir.file("link.csv"));
    EXPECT_EQ("through\n", written_through(dir, "link.csv"));
    EXPECT_TRUE(fs::is_symlink(dir.file("link.csv")));
    EXPECT_EQ("through\n", test::slurp(dir.file("real.csv")));
    EXPECT_EQ(2u, dir.count()) << "no temporary or backup left";
}

TEST(OutputFile, LinkChainAcrossDirectoriesReplacesTheFileAtItsEnd) {
    test::TempDir dir;
    fs::create_directories(dir.path() / "a");
    fs::create_directories(dir.path() / "b");
    // first -> a/second -> ../b/end (relative links resolve from their own directory); end does not exist yet.
    fs::create_symlink("../b/end.csv", dir.path() / "a" / "second");
    fs::create_symlink("a/second", dir.path() / "first");
    EXPECT_EQ("through\n", written_through(dir, "first"));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "first"));
    EXPECT_TRUE(fs::is_symlink(dir.path() / "a" / "second"));
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir.path() / "b" / "end.csv")));
    EXPECT_EQ(1u, static_cast<std::size_t>(std::distance(fs::directory_iterator(dir.path() / "b"), {})));
}

TEST(OutputFile, LinkLoopIsRefused) {
    test::TempDir dir;
    fs::create_symlink("y", dir.file("x"));
    fs::create_symlink("x", dir.file("y"));
    EXPECT_THROW(OutputFile(dir.file("x")), InputError);
    EXPECT_EQ(2u, dir.count());
}

TEST(OutputFile, ReplacedFileKeepsItsMode) {
    test::TempDir dir;
    test::spit(dir.file("out.csv"), "old\n");
    fs::permissions(dir.file("out.csv"), fs::perms(0640));
    OutputFile file(dir.file("out.csv"));
    file.stream() << "new\n";
    file.commit();
    struct stat st {};
    ASSERT_EQ(0, stat(dir.file("out.csv").c_str(), &st));
    EXPECT_EQ(0640u, st.st_mode & 0777);
}

TEST(OutputFile, DirectoryAndUnwritableTargetsAreRefusedUpFront) {
    test::TempDir dir;
    fs::create_directories(dir.path() / "sub");
    const auto message = [](const std::string& path) {
        try {
            OutputFile file(path);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(dir.file("sub") + ": cannot write: is a directory", message(dir.file("sub")));
    EXPECT_EQ(dir.file("sub/") + ": cannot write: names a directory, expected a file", message(dir.file("sub/")));
    EXPECT_EQ(": cannot write: empty path", message(""));
    EXPECT_NE(std::string::npos, message("/proc/cdvp-out.csv").find("/proc/cdvp-out.csv: cannot write: "))
        << "even root cannot create files in /proc";
    test::spit(dir.file("plain"), "");
    EXPECT_EQ(dir.file("plain/x.csv") + ": cannot write: '" + dir.file("plain") + "' is not a directory",
              message(dir.file("plain/x.csv")));
    if (geteuid() != 0) {  // root writes anywhere
        fs::permissions(dir.path() / "sub", fs::perms(0555));
        EXPECT_NE(std::string::npos, message(dir.file("sub/x.csv")).find("is not writable"));
        fs::permissions(dir.path() / "sub", fs::perms(0755));
    }
    EXPECT_EQ(2u, dir.count());
}

TEST(OutputFile, LongNameStillGetsATemporary) {
    test::TempDir dir;
    const std::string name(250, 'n');
    OutputFile file(dir.file(name));
    EXPECT_LT(fs::path(file.temp_path()).filename().string().size(), 256u);
    file.stream() << "long\n";
    file.commit();
    EXPECT_EQ("long\n", test::slurp(dir.file(name)));
}

TEST(OutputFile, DeviceIsWrittenNeverReplaced) {
    OutputFile file("/dev/null");
    EXPECT_EQ(OutputTarget::Kind::kDirect, file.target().kind);
    EXPECT_NE(0u, file.temp_path().rfind("/dev/", 0)) << "the temporary is not made in /dev";
    file.stream() << "discarded\n";
    file.commit();
    struct stat st {};
    ASSERT_EQ(0, stat("/dev/null", &st));
    EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(OutputFile, FifoGetsTheDataAtCommit) {
    test::TempDir dir;
    ASSERT_EQ(0, mkfifo(dir.file("pipe").c_str(), 0600));
    OutputFile file(dir.file("pipe"));
    file.stream() << "through a pipe\n";
    std::string received;
    std::thread reader([&] { received = test::slurp(dir.file("pipe")); });
    file.commit();
    reader.join();
    EXPECT_EQ("through a pipe\n", received);
    struct stat st {};
    ASSERT_EQ(0, lstat(dir.file("pipe").c_str(), &st));
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

// In a child process: create an output, then be killed by 'signal_number'.
// Returns the child's wait status.
int status_of_child_killed_with_output(const std::string& path, int signal_number, bool ignore_first) {
    const pid_t child = fork();
    if (child == 0) {
        if (ignore_first) signal(signal_number, SIG_IGN);  // as nohup does
        const struct rlimit no_core {0, 0};
        setrlimit(RLIMIT_CORE, &no_core);  // SIGQUIT, SIGXCPU and SIGXFSZ dump core
        {
            OutputFile file(path);
            file.stream() << "partial" << std::flush;
            raise(signal_number);
        }
        _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return status;
}

TEST(OutputFile, KillingSignalsRemoveTheTemporaryAndKeepTheirStatus) {
    for (int signal_number : TemporaryRegistry::kSignals) {
        test::TempDir dir;
        const int status = status_of_child_killed_with_output(dir.file("out.csv"), signal_number, false);
        ASSERT_TRUE(WIFSIGNALED(status)) << signal_number;
        EXPECT_EQ(signal_number, WTERMSIG(status));
        EXPECT_EQ(0u, dir.count()) << "signal " << signal_number << " left a temporary";
    }
}

TEST(OutputFile, IgnoredSignalStaysIgnored) {
    test::TempDir dir;
    const int status = status_of_child_killed_with_output(dir.file("out.csv"), SIGHUP, true);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(0, WEXITSTATUS(status));
    EXPECT_EQ(0u, dir.count()) << "the child went on and discarded its temporary";
}

}  // namespace
}  // namespace cdvp
