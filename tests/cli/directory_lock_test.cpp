// One writer per sweep directory, as plain C++: a second writer is refused
// naming the holder's pid and its lock file, also when both start at the same
// instant; the file goes with the first.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "models/common/user_text.h"
#include "sw/study/directory_lock.h"
#include "tests/scene/temp_dir.h"

namespace cdvp {
namespace {

namespace fs = std::filesystem;

TEST(DirectoryLockTest, ASecondWriterIsRefusedNamingTheHolderAndTheFileGoesWithTheFirst) {
    test::TempDir temp;
    {
        const DirectoryLock first(temp.path().string(), "--out");
        try {
            const DirectoryLock second(temp.path().string(), "--out");
            ADD_FAILURE() << "two writers";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), "--out: " + temp.path().string() +
                                                 " is in use by another cdvp sweep or merge (pid " +
                                                 std::to_string(getpid()) + ", holding " +
                                                 (temp.path() / DirectoryLock::kFileName).string() +
                                                 "); wait for it to end, or give another directory");
        }
    }
    EXPECT_FALSE(fs::exists(temp.path() / DirectoryLock::kFileName));
    EXPECT_NO_THROW(DirectoryLock(temp.path().string(), "--out"));
}

// Two sweeps started at the same instant: the second finds the lock taken
// before its holder has written its pid. It waits for the pid rather than
// saying nothing of the holder; a holder that never writes one is still
// named by its lock file.
class HeldLockFile {
public:
    explicit HeldLockFile(const fs::path& dir) : path_((dir / DirectoryLock::kFileName).string()) {
        fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        EXPECT_EQ(flock(fd_, LOCK_EX | LOCK_NB), 0);  // a descriptor of its own: a holder apart from DirectoryLock
    }
    ~HeldLockFile() { close(fd_); }
    void write_pid(pid_t pid) const {
        const std::string text = std::to_string(pid) + "\n";
        EXPECT_EQ(pwrite(fd_, text.data(), text.size(), 0), static_cast<ssize_t>(text.size()));
    }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int fd_ = -1;
};

std::string lock_refusal(const fs::path& dir) {
    try {
        const DirectoryLock second(dir.string(), "--out");
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "two writers";
    return {};
}

TEST(DirectoryLockTest, ASecondWriterStartedWithTheFirstWaitsForItsPid) {
    test::TempDir temp;
    const HeldLockFile holder(temp.path());
    std::thread late([&holder] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // locked, its pid not yet written
        holder.write_pid(getpid());
    });
    const std::string refusal = lock_refusal(temp.path());
    late.join();
    EXPECT_EQ(refusal, "--out: " + temp.path().string() + " is in use by another cdvp sweep or merge (pid " +
                           std::to_string(getpid()) + ", holding " + holder.path() +
                           "); wait for it to end, or give another directory");
}

TEST(DirectoryLockTest, AHolderThatNeverWritesItsPidIsNamedByItsLock) {
    test::TempDir temp;
    const HeldLockFile holder(temp.path());
    holder.write_pid(999999999);  // a killed holder's, no process now: not the holder
    EXPECT_EQ(lock_refusal(temp.path()), "--out: " + temp.path().string() +
                                             " is in use by another cdvp sweep or merge (holding " + holder.path() +
                                             ", its pid not yet written); wait for it to end, or give another directory");
}

}  // namespace
}  // namespace cdvp
