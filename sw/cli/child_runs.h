// What the commands that drive `cdvp run` as child processes share (`cdvp
// fidelity`, `cdvp sweep`, `cdvp merge`): scratch files removed on every way
// out, starting and reaping children, a trace from a pipe spooled once,
// forwarded options found by name, directories made for --out, and text
// files committed whole (temporary file, then rename).
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cdvp {

// A file in $TMPDIR for a child's output, removed on every way out (a
// cleanup signal included: see TemporaryRegistry).
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

// The running cdvp executable, for its child runs.
std::string self_path();

// Starts args[0] (looked up in PATH) with stderr into err_path and, when
// given, stdout into out_path; returns its pid. Throws when it cannot start.
pid_t start_child(const std::vector<std::string>& args, const std::string& err_path,
                  const char* out_path = nullptr);
// Waits for that child (restarting after a signal handler ran); its wait status.
int wait_child(pid_t pid);
// start_child, then wait_child.
int run_child(const std::vector<std::string>& args, const std::string& err_path, const char* out_path = nullptr);

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
// (a pipe, a device) is copied once and the children read the copy. Messages
// that name the copy are given back the user's name for it.
class TraceSpool {
public:
    // Spools 'path' when it is not a regular file; throws InputError when it
    // cannot be read.
    explicit TraceSpool(const std::string& path);
    // The path the children read.
    const std::string& path() const { return copy_ ? copy_->path() : original_; }
    std::string restore_names(std::string message) const;

private:
    std::string original_;
    std::optional<ScratchFile> copy_;
};

// The directories made for --out (as mkdir -p), removed again unless kept
// (they are empty then: the outputs' temporaries have gone first).
class CreatedDirectories {
public:
    // 'label' names the path in messages ("--out").
    void create(const std::string& path, const std::string& label = "--out");
    void keep() { made_.clear(); }
    ~CreatedDirectories();

private:
    std::vector<std::string> made_;
};

// Replaces 'path' with 'text' whole: written to a temporary beside it, then
// renamed over it, with the cleanup signals held back meanwhile so that an
// interrupted command leaves the old file or the new one, never a part.
// Throws InputError naming 'label' and the path when it cannot.
void commit_text_file(const std::string& path, const std::string& text, const std::string& label);

}  // namespace cdvp
