// Reading an input under limits, and a bounded copy of one that cannot be
// read twice (a pipe, a FIFO, a character device: /dev/stdin, <(...),
// /dev/zero).
//
// Every input is read with the same limits, a regular file or not: a line
// holds at most max_line_bytes counting its line end, the whole at most
// max_bytes. The first byte past either is refused (InputError naming the
// input and the line, or the limit and where it came from), never read into
// memory or copied: /dev/zero stops at its first line, an endless stream of
// good lines at the size limit.
//
// InputSpool copies such an input to an unlinked temporary file as it is
// read. Two ways to fill it:
//   - read stream() as the input itself: each byte it hands out has been
//     copied first, so a reader that checks as it reads (TraceReader) refuses
//     bad input at its first bad line and nothing after it is copied; then
//     finish() copies the rest, if any;
//   - or finish() at once, for a caller that only hands the copy on (cdvp
//     sweep spooling a piped trace once for its child runs).
// Then read the copy from its start as often as needed: path() opens it anew
// in this process and, after keep_across_exec(), in child processes, which
// inherit its descriptor. Nothing is left on disk, whatever ends the process.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <memory>
#include <streambuf>
#include <string>
#include <vector>

#include "sw/scene/csv_reader.h"

namespace cdvp {

struct InputLimits {
    uint64_t max_bytes = std::numeric_limits<uint64_t>::max();
    std::size_t max_line_bytes = kMaxLineBytes;
    // What sets max_bytes, for the refusal: "16384 MiB (the default of --max-trace-size)".
    std::string max_bytes_origin = "the limit";
};

// A descriptor read a chunk at a time as a stream buffer, under the limits;
// each chunk is written to `copy` (when it is a descriptor, not -1) before any
// of it is handed out. `name` names the input in messages. Throws InputError
// at the first byte past a limit, SystemError when reading or copying fails.
class LimitedInput : public std::streambuf {
public:
    LimitedInput(int fd, std::string name, InputLimits limits, int copy = -1, std::string copy_name = "");
    uint64_t bytes() const { return handed_out_; }
    // Reads to the input's end (copying it), under the same limits.
    void drain();

protected:
    int_type underflow() override;

private:
    // The first bytes of a chunk of `count` that keep within the limits;
    // records the refusal for the byte after them, if any.
    std::size_t within_limits(std::size_t count);
    [[noreturn]] void refuse() const;

    int fd_;
    std::string name_;
    InputLimits limits_;
    int copy_;
    std::string copy_name_;
    std::vector<char> chunk_;
    uint64_t handed_out_ = 0;                     // bytes handed out in all
    uint64_t line_ = 1;                           // the line of the next byte
    std::size_t line_bytes_ = 0;                  // of that line so far
    std::string refusal_;                         // the limit the next byte would pass
    bool at_end_ = false;
};

class InputSpool {
public:
    // Opens `path` for reading and an unlinked temporary file in `directory`
    // (default: $TMPDIR, else /tmp). Nothing is copied yet. Throws InputError
    // when the input cannot be opened, SystemError when no temporary file can
    // be made.
    InputSpool(const std::string& path, InputLimits limits, const std::string& directory = temp_directory());
    ~InputSpool();
    InputSpool(const InputSpool&) = delete;
    InputSpool& operator=(const InputSpool&) = delete;

    // The input, copied as it is read (see above).
    std::istream& stream() { return stream_; }
    // Copies the rest of the input; the copy is then complete.
    void finish();
    uint64_t bytes() const { return input_->bytes(); }

    // "/proc/self/fd/N": opens the copy anew at its start, in this process
    // and in a child that inherited descriptor N.
    std::string path() const;
    int descriptor() const { return copy_; }
    // Lets child processes inherit the copy's descriptor (it is close-on-exec
    // until then), so that they open it by path().
    void keep_across_exec();

    static std::string temp_directory();

private:
    int source_ = -1, copy_ = -1;
    std::unique_ptr<LimitedInput> input_;
    std::istream stream_{nullptr};
};

// The input `path` under limits without a copy (a regular file): its size is
// checked first, then every byte as it is read. Throws InputError.
class LimitedFile {
public:
    LimitedFile(const std::string& path, InputLimits limits);
    ~LimitedFile();
    LimitedFile(const LimitedFile&) = delete;
    LimitedFile& operator=(const LimitedFile&) = delete;
    std::istream& stream() { return stream_; }

private:
    int fd_ = -1;
    std::unique_ptr<LimitedInput> input_;
    std::istream stream_{nullptr};
};

}  // namespace cdvp
