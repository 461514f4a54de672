#include "sw/study/directory_lock.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <optional>
#include <string>
#include <thread>

#include "models/common/input_path.h"
#include "models/common/user_text.h"

namespace cdvp {

namespace {

// Whether the path still names the file open on 'fd' (not removed and made anew).
bool still_named(int fd, const std::string& path) {
    struct stat open_file {}, named {};
    return fstat(fd, &open_file) == 0 && stat(path.c_str(), &named) == 0 && open_file.st_ino == named.st_ino &&
           open_file.st_dev == named.st_dev;
}

// The pid the lock file open on 'fd' names, when it names a living process:
// nothing while its holder has locked it but not yet written (or it still
// holds a killed holder's pid, which the next holder writes over).
std::optional<pid_t> holder_of(int fd) {
    char text[32] = {};
    const ssize_t got = pread(fd, text, sizeof text - 1, 0);
    if (got <= 0) return std::nullopt;
    const std::string line(text, static_cast<std::size_t>(got));
    const std::size_t digits = line.find_first_not_of("0123456789");
    if (digits == 0 || digits == std::string::npos || digits > 9 || line[digits] != '\n') return std::nullopt;
    const auto pid = static_cast<pid_t>(std::stol(line.substr(0, digits)));
    if (pid <= 0 || (kill(pid, 0) != 0 && errno != EPERM)) return std::nullopt;
    return pid;
}

// How long a second writer waits for the holder's pid to appear: the holder
// writes it right after it takes the lock, so only two started at the same
// instant ever wait, and then for microseconds.
constexpr auto kHolderWait = std::chrono::seconds(1);

}  // namespace

DirectoryLock::DirectoryLock(const std::string& dir, const std::string& label) : path_(dir + "/" + kFileName) {
    const auto deadline = std::chrono::steady_clock::now() + kHolderWait;
    for (;;) {
        fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd_ < 0) throw_os_error(label + ": " + path_text(path_) + ": cannot create the lock", errno);
        if (flock(fd_, LOCK_EX | LOCK_NB) == 0) {
            if (still_named(fd_, path_)) break;
            close(fd_);  // its holder removed it as we took it: take the new one
            continue;
        }
        const int error = errno;
        const std::optional<pid_t> holder = holder_of(fd_);
        close(fd_);
        fd_ = -1;
        if (error != EWOULDBLOCK) throw_os_error(label + ": " + path_text(path_) + ": cannot lock", error);
        if (!holder && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));  // its pid is on its way, or it ends
            continue;
        }
        throw InputError(label + ": " + path_text(dir) + " is in use by another cdvp sweep or merge (" +
                         (holder ? "pid " + std::to_string(*holder) + ", holding " + path_text(path_)
                                 : "holding " + path_text(path_) + ", its pid not yet written") +
                         "); wait for it to end, or give another directory");
    }
    // The holder's pid, for the refusal of the next one: written over what a
    // killed holder left, then cut to its length, so that the file never
    // reads empty once written.
    const std::string pid = std::to_string(getpid()) + "\n";
    if (pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size()) ||
        ftruncate(fd_, static_cast<off_t>(pid.size())) != 0) {
        const int error = errno;
        unlink(path_.c_str());
        close(fd_);
        fd_ = -1;
        throw_os_error(label + ": " + path_text(path_) + ": cannot write", error);
    }
}

DirectoryLock::~DirectoryLock() {
    if (fd_ < 0) return;
    // Before the lock goes (see still_named), and only while the name is
    // this lock's: a merge swaps its directory away under it.
    if (still_named(fd_, path_)) unlink(path_.c_str());
    close(fd_);
}

namespace {

// Makes the directory (as mkdir -p; a file is refused): the path to lock.
const std::string& made_directory(CreatedDirectories& made, const std::string& dir) {
    made.create(dir);
    return dir;
}

}  // namespace

LockedOutDirectory::LockedOutDirectory(const std::string& dir) : lock_(made_directory(made_, dir), "--out") {}

}  // namespace cdvp
