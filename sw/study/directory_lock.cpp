#include "sw/study/directory_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

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

}  // namespace

DirectoryLock::DirectoryLock(const std::string& dir, const std::string& label) : path_(dir + "/" + kFileName) {
    for (;;) {
        fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd_ < 0) throw_os_error(label + ": " + path_text(path_) + ": cannot create the lock", errno);
        if (flock(fd_, LOCK_EX | LOCK_NB) == 0) {
            if (still_named(fd_, path_)) break;
            close(fd_);  // its holder removed it as we took it: take the new one
            continue;
        }
        const int error = errno;
        char holder[32] = {};
        const ssize_t got = pread(fd_, holder, sizeof holder - 1, 0);
        close(fd_);
        fd_ = -1;
        if (error != EWOULDBLOCK) throw_os_error(label + ": " + path_text(path_) + ": cannot lock", error);
        std::string pid = got > 0 ? std::string(holder, static_cast<std::size_t>(got)) : std::string();
        pid = pid.substr(0, pid.find_first_not_of("0123456789"));
        throw InputError(label + ": " + path_text(dir) + " is in use by another cdvp sweep or merge" +
                         (pid.empty() ? std::string() : " (pid " + pid + ")") +
                         "; wait for it to end, or give another directory");
    }
    // The holder's pid, for the refusal of the next one.
    const std::string pid = std::to_string(getpid()) + "\n";
    if (ftruncate(fd_, 0) != 0 || pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
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

// Refuses a file, then makes the directory (as mkdir -p): the path to lock.
const std::string& made_directory(CreatedDirectories& made, const std::string& dir) {
    struct stat status {};
    if (stat(dir.c_str(), &status) == 0 && !S_ISDIR(status.st_mode)) {
        throw InputError("--out: " + path_text(dir) + ": expected a directory");
    }
    made.create(dir);
    return dir;
}

}  // namespace

LockedOutDirectory::LockedOutDirectory(const std::string& dir) : lock_(made_directory(made_, dir), "--out") {}

}  // namespace cdvp
