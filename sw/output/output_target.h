// Where an output path really leads: symbolic links followed to the file
// they name, so that the file is replaced and the link stays a link.
#pragma once

#include <sys/stat.h>

#include <string>

namespace cdvp {

struct OutputTarget {
    enum class Kind {
        kNew,      // nothing there yet: created by rename
        kRegular,  // an existing regular file: replaced by rename, keeping its mode
        kDirect,   // a character device, FIFO or inherited descriptor (/dev/null,
                   // /dev/stdout): opened and written at commit, never replaced
    };
    Kind kind = Kind::kNew;
    // The path that is written: absolute, through every symbolic link and
    // '..'. For kDirect, the path to open (a /proc/self/fd link is kept).
    std::string path;
    struct stat status {};  // of 'path' when it exists (kRegular, kDirect)
    // For /dev/stdout, /dev/fd/N and /proc/self/fd/N: this process's
    // descriptor N, written through a duplicate so that it shares the
    // descriptor's file offset with everything else the process writes there
    // (reopening the path would start a second offset at 0). -1 otherwise.
    int descriptor = -1;
};

// Standard input, output and error closed when the process started (as by
// `>&-`) are opened on /dev/null, so that no file the process opens takes
// their numbers and receives what is meant for them; an output that names
// one of them (/dev/stdout, "-") is then refused. Call first thing in main().
void reserve_standard_descriptors();
bool standard_descriptor_was_closed(int descriptor);

// Resolves 'given' ("-" is standard output) and checks it can be written: not a directory, in an
// existing writable directory, no symbolic-link loop. Throws InputError
// "GIVEN: cannot write: REASON".
OutputTarget resolve_output_target(const std::string& given);

// Identity of a file for "is this the same file?": device and inode where it
// exists (so hard links match), else the resolved path.
struct FileIdentity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::string path;
    bool operator==(const FileIdentity& other) const {
        return exists && other.exists ? device == other.device && inode == other.inode : path == other.path;
    }
};

FileIdentity identity_of(const OutputTarget& target);
// An input that cannot be resolved (missing) gets exists = false and the
// path as given made absolute; its reader reports the problem later.
FileIdentity identity_of_input(const std::string& path);

}  // namespace cdvp
