// What the commands that drive `cdvp run` as child processes share (`cdvp
// fidelity`, `cdvp sweep`, `cdvp merge`): a child's output captured in
// memory, children that die with their parent, scratch files removed on every
// way out, a trace from a pipe spooled once, forwarded options found by name,
// directories made for --out, and text files committed whole (temporary
// file, synced, then rename).
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cdvp {

// A child's stdout or stderr kept in an anonymous in-memory file (memfd): no
// name in any directory, so nothing is left behind however the process ends,
// and no $TMPDIR is needed.
class CapturedOutput {
public:
    explicit CapturedOutput(const char* name);
    ~CapturedOutput();
    CapturedOutput(const CapturedOutput&) = delete;
    CapturedOutput& operator=(const CapturedOutput&) = delete;
    int fd() const { return fd_; }
    // What was written, from the start, at most 'max_bytes'.
    std::string text(std::size_t max_bytes = std::size_t{1} << 20) const;
    // Empties it for the next child.
    void clear();

private:
    int fd_ = -1;
};

// A file in $TMPDIR for a child's output, removed on every way out but
// SIGKILL (a cleanup signal included: see TemporaryRegistry). Throws
// InputError naming TMPDIR when it cannot be made there.
class ScratchFile {
public:
    explicit ScratchFile(const std::string& suffix);
    ~ScratchFile();
    ScratchFile(const ScratchFile&) = delete;
    ScratchFile& operator=(const ScratchFile&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int slot_ = -1;
};

// The whole file (empty when it cannot be read).
std::string slurp(const std::string& path);
// The whole file, or nothing when it cannot be opened or read (errno tells why).
std::optional<std::string> read_whole_file(const std::string& path);

// The environment variable through which a parent running J children at once
// tells each that its default memory budget is a J-th of the machine's.
constexpr const char* kMemoryShareVariable = "CDVP_MEMORY_SHARE";

// The running cdvp executable, for its child runs.
std::string self_path();

// Where a child's standard streams go and which descriptors it inherits.
struct ChildStreams {
    int in = -1;   // standard input; -1: /dev/null
    int out = -1;  // standard output; -1: this process's
    int err = -1;  // standard error; -1: this process's
    std::vector<int> inherited;  // descriptors the child keeps open (its /proc/self/fd/N paths)
};

// The first executable named 'name' on PATH (a name with a '/' is taken as
// a path), or nothing when there is none.
std::optional<std::string> find_program(const std::string& name);

// Starts args[0] (an absolute path, or looked up in PATH) with 'streams'; the
// child gets SIGTERM should this process die first (even by SIGKILL), so no
// point outlives its sweep. Returns its pid; throws when it cannot start.
pid_t start_child(const std::vector<std::string>& args, const ChildStreams& streams);
// Waits for that child (restarting after a signal handler ran); its wait status.
int wait_child(pid_t pid);
// start_child, then wait_child.
int run_child(const std::vector<std::string>& args, const ChildStreams& streams);

// Runs gnuplot (found on PATH) on 'script'; nothing when it drew, else
// what it said on stderr.
std::optional<std::string> run_gnuplot(const std::string& script);

// A child's one-line message under the parent's name: "cdvp run: X" becomes
// "PROGRAM: X".
std::string renamed_message(std::string message, const std::string& program);

// Where a forwarded option's value is ("--trace FILE" or "--trace=FILE"):
// the argument that holds it and where in it the value starts.
struct OptionValue {
    std::size_t index;
    std::size_t offset;
};
std::optional<OptionValue> find_option(const std::vector<std::string>& args, const std::string& option);
// The option's value, or "" when it is not given.
std::string option_value(const std::vector<std::string>& args, const std::string& option);

// Child runs each read a trace from its start: one that is not a regular file
// (a pipe, a device) is copied once, under the limits every trace is read
// with (InputSpool: /dev/zero stops at its first line), to an unlinked file,
// and the children read the copy through the descriptor they inherit
// ("/proc/self/fd/N"). Messages that name the copy are given back the user's
// name for it.
class InputSpool;
struct InputLimits;
class TraceSpool {
public:
    // Spools 'path' when it is not a regular file, under 'limits'; throws
    // InputError when it cannot be read or passes a limit, SystemError when
    // the copy cannot be written.
    TraceSpool(const std::string& path, const InputLimits& limits);
    ~TraceSpool();
    TraceSpool(const TraceSpool&) = delete;
    TraceSpool& operator=(const TraceSpool&) = delete;
    // The path the children read.
    const std::string& path() const { return path_; }
    // The descriptor a child must inherit to read path(), or -1 (a regular file).
    int descriptor() const;
    std::string restore_names(std::string message) const;

private:
    std::string original_, path_;
    std::unique_ptr<InputSpool> copy_;
};

// The directories made for --out (as mkdir -p), removed again unless kept
// (they are empty then: the outputs' temporaries have gone first).
class CreatedDirectories {
public:
    // 'label' names the path in messages ("--out").
    void create(const std::string& path, const std::string& label = "--out");
    bool made_any() const { return !made_.empty(); }
    void keep() { made_.clear(); }
    ~CreatedDirectories();

private:
    std::vector<std::string> made_;
};

// Replaces 'path' with 'text' whole: written to a temporary beside it,
// synced, then renamed over it, with the cleanup signals held back meanwhile
// so that an interrupted command leaves the old file or the new one, never a
// part. Throws SystemError (a full disk, an I/O error) or InputError, naming
// 'label' and the path, with the system's own error text.
void commit_text_file(const std::string& path, const std::string& text, const std::string& label);

}  // namespace cdvp
