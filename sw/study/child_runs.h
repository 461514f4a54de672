// What the commands that drive `cdvp run` as child processes share (`cdvp
// fidelity`, `cdvp sweep`, `cdvp merge`), beside the child processes
// themselves (sw/output/child_process.h), whole text files
// (sw/output/text_file.h) and the directories made for --out
// (sw/output/created_directories.h): scratch files removed on every way out,
// a trace from a pipe spooled once, forwarded options found by name, and
// gnuplot.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sw/output/child_process.h"
#include "sw/output/created_directories.h"
#include "sw/output/text_file.h"

namespace cdvp {

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

}  // namespace cdvp
