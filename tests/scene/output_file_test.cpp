#include "sw/scene/output_file.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <utility>

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
