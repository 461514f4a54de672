// All output files of a run as one transaction: declared with the run's
// inputs, checked together before any work, committed together or not at
// all.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/output/output_file.h"
#include "sw/output/output_target.h"

namespace cdvp {

// Why a commit failed: one line ("LABEL: PATH: cannot write: REASON") and
// the system's error number behind it.
struct OutputFailure {
    std::string message;
    int error = 0;
    // The system failed (a full disk, an I/O error) rather than the path.
    bool system() const { return is_system_failure(error); }
    // Throws it: SystemError when system(), else InputError.
    [[noreturn]] void raise() const;
};

class OutputSet {
public:
    // 'label' names the path in messages: the flag that gave it ("--trace").
    void add_input(std::string label, std::string path);
    // Declares an output (see OutputFile for suffix and open_stream); its
    // index is for file(). Nothing is touched before open().
    std::size_t add_output(std::string label, std::string path, std::string suffix = "",
                           bool open_stream = true);

    // Resolves every output, refuses one that names an input or another
    // output (same resolved path, or same file through any link), then
    // creates every temporary. Throws InputError naming the labels and paths;
    // nothing is left behind then. A character device, FIFO or /dev/stdout
    // is exempt from the sameness check: it is written, never replaced.
    void open();
    OutputFile& file(std::size_t index) { return files_.at(index); }

    // Standard output as one more output of the run (the summary): checked
    // by open() like the others (open when cdvp started; a regular file
    // behind it is no input and no other output, unless written through the
    // same descriptor), and written by commit() after the devices and before
    // any rename, so a summary that cannot be printed publishes no file. When
    // another output is written to standard output itself ("-",
    // /dev/stdout), open() drops the summary: the stream carries only that
    // output's data (JSON, CSV), for the program reading it.
    void add_standard_output(std::string label);
    void set_standard_output(std::string text);

    // Finishes every file, then publishes them all: devices, FIFOs and
    // descriptors are written first, then standard output, then each regular
    // file renamed into place. If any step fails, the renames already done
    // are undone (the old files restored from their hard-link backups, new
    // ones removed) before the InputError propagates. Signals are held back
    // during the renames only, so a run stuck on a FIFO without a reader can
    // still be interrupted; one arriving during the renames is delivered
    // after them, with every output in place.
    void commit();
    // The same without exceptions (see OutputFile::try_finish): what failed,
    // or nothing on success.
    std::optional<OutputFailure> try_commit() noexcept;

private:
    std::vector<OutputTarget> resolve_targets() const;

    struct Declared {
        std::string label, path, suffix;
        bool open_stream;
    };
    std::vector<Declared> inputs_, outputs_;
    std::deque<OutputFile> files_;  // deque: file() references stay valid
    std::optional<std::string> stdout_label_;
    std::string stdout_text_;
};

}  // namespace cdvp
