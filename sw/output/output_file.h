// An output file that appears at its final path only once complete: data go
// to a temporary file beside the file the path leads to (through symbolic
// links), renamed over it by commit(). Temporaries are removed when the
// object is destroyed uncommitted and when the process is killed by a
// catchable signal (see output_cleanup.h).
#pragma once

#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

#include "sw/output/output_target.h"

namespace cdvp {

// A stream buffer over a file descriptor that keeps the first error of any
// write, so that a failure is reported with the system's own text (No space
// left on device) however many writes later it is noticed.
class DescriptorBuffer : public std::streambuf {
public:
    explicit DescriptorBuffer(int fd);  // takes the descriptor
    ~DescriptorBuffer() override;
    DescriptorBuffer(const DescriptorBuffer&) = delete;
    DescriptorBuffer& operator=(const DescriptorBuffer&) = delete;
    // Writes what is buffered and closes the descriptor: 0, or the errno of
    // the first write, flush or close that failed.
    int close();

protected:
    int_type overflow(int_type c) override;
    int sync() override;

private:
    bool drain();

    int fd_;
    int error_ = 0;
    char buffer_[1 << 16];
};

class OutputFile {
public:
    // Resolves final_path (resolve_output_target), then creates
    // "<target>.part-XXXXXX<suffix>" beside the target (unique, via
    // mkstemps; for a device, FIFO or /dev/stdout, in $TMPDIR) with the
    // replaced file's mode, or the umask's for a new file, and, if
    // open_stream, opens stream() on it. With open_stream false the caller
    // has some library write temp_path() itself; 'suffix' is for libraries
    // that append an extension to a base name (for a VCD, pass ".vcd" and
    // give the library temp_path() minus ".vcd").
    // Throws InputError "FINAL_PATH: cannot write: <reason>".
    explicit OutputFile(std::string final_path, std::string suffix = "", bool open_stream = true);
    ~OutputFile();

    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&& other) noexcept;

    // The stream on the temporary file; std::logic_error without one.
    std::ostream& stream();
    const std::string& temp_path() const { return temp_path_; }
    const std::string& final_path() const { return final_path_; }
    const OutputTarget& target() const { return target_; }

    // Flushes and closes the stream and checks for write errors (SystemError
    // for a full disk or an I/O error, else InputError, "FINAL_PATH: cannot
    // write: <the system's reason>"). Nothing is published yet.
    void finish();
    // A regular target: renames the finished temporary over it. The old
    // file, if any, stays reachable under the returned backup path (a hard
    // link, empty where the file system has none) until the caller removes
    // it or puts it back. A kDirect target: copies the temporary into it.
    std::string publish();
    // finish() and publish() for a single file, removing the backup.
    void commit();

    // finish() and publish() without exceptions: 0 or the errno, which
    // error_message() turns into the text the throwing versions give. After
    // a SystemC run, an exception on the main stack can trip AddressSanitizer
    // (its stack bounds are stale after the kernel's coroutine switches), so
    // a run's final commit reports failure by value.
    int try_finish() noexcept;
    int try_publish(std::string& backup) noexcept;
    std::string error_message(int err) const;

private:
    void discard() noexcept;
    void forget_temporary() noexcept;
    [[noreturn]] void fail(int err) const;

    std::string final_path_;
    OutputTarget target_;
    std::string temp_path_;  // empty once published, discarded or moved from
    int cleanup_slot_ = -1;
    std::unique_ptr<DescriptorBuffer> buffer_;
    std::unique_ptr<std::ostream> stream_;
};

}  // namespace cdvp
