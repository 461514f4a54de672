// One writer per sweep directory: `cdvp sweep` and `cdvp merge` hold an
// exclusive flock on DIR/sweep.lock while they run, so a second one into the
// same directory is refused, naming the holder, instead of both writing one
// table. The lock ends with the process however it ends (the kernel drops
// it), so a killed sweep never leaves its directory locked; one that ends
// removes the file too. A lock taken on a file already removed is let go and
// taken again on the new one, so that removing it never lets two writers in.
#pragma once

#include <string>

#include "sw/study/child_runs.h"

namespace cdvp {

class DirectoryLock {
public:
    static constexpr const char* kFileName = "sweep.lock";
    // Locks DIR (which must exist). Throws InputError naming 'label', the
    // directory, the lock file and the holder's pid when another process
    // holds it; a holder that has the lock but has not yet written its pid
    // (two started at the same instant) is waited for up to a second, then
    // said to be one ("its pid not yet written").
    DirectoryLock(const std::string& dir, const std::string& label);
    // Removes the lock file, then lets the lock go.
    ~DirectoryLock();
    DirectoryLock(const DirectoryLock&) = delete;
    DirectoryLock& operator=(const DirectoryLock&) = delete;

private:
    std::string path_;
    int fd_ = -1;
};

// The --out directory a sweep or a merge writes: refused when it names a
// file, made as mkdir -p (the directories it made removed again unless
// made().keep() is called) and locked for as long as this lives.
class LockedOutDirectory {
public:
    explicit LockedOutDirectory(const std::string& dir);
    CreatedDirectories& made() { return made_; }

private:
    CreatedDirectories made_;  // declared first: the lock goes before the directories do
    DirectoryLock lock_;
};

}  // namespace cdvp
