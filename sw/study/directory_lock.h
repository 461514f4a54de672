// One writer per sweep directory: `cdvp sweep` and `cdvp merge` hold an
// exclusive flock on DIR/sweep.lock while they run, so a second one into the
// same directory is refused, naming the holder, instead of both writing one
// table. The lock ends with the process however it ends (the kernel drops
// it), so a killed sweep never leaves its directory locked; one that ends
// removes the file too. A lock taken on a file already removed is let go and
// taken again on the new one, so that removing it never lets two writers in.
#pragma once

#include <string>

namespace cdvp {

class DirectoryLock {
public:
    static constexpr const char* kFileName = "sweep.lock";
    // Locks DIR (which must exist). Throws InputError naming 'label', the
    // directory and the holder's pid when another process holds it.
    DirectoryLock(const std::string& dir, const std::string& label);
    // Removes the lock file, then lets the lock go.
    ~DirectoryLock();
    DirectoryLock(const DirectoryLock&) = delete;
    DirectoryLock& operator=(const DirectoryLock&) = delete;

private:
    std::string path_;
    int fd_ = -1;
};

}  // namespace cdvp
