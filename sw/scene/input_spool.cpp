#include "sw/scene/input_spool.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "models/common/input_path.h"
#include "models/common/user_text.h"

namespace cdvp {

namespace {

constexpr std::size_t kChunkBytes = 1 << 16;

[[noreturn]] void system_error(const std::string& what, int error) {
    throw SystemError(what + ": " + std::strerror(error));
}

// Opens `path` for reading, as open_input refuses what is no file.
int open_for_reading(const std::string& path) {
    struct stat status {};
    if (stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode)) {
        refuse_input(path, EISDIR, "expected a file");
    }
    int fd;
    do {
        fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    } while (fd < 0 && errno == EINTR);  // a FIFO waits for its writer here
    if (fd < 0) refuse_input(path, errno);
    return fd;
}

void write_all(int fd, const char* data, std::size_t count, const std::string& what) {
    while (count > 0) {
        const ssize_t put = write(fd, data, count);
        if (put < 0 && errno == EINTR) continue;
        if (put < 0) system_error(what, errno);
        data += put;
        count -= static_cast<std::size_t>(put);
    }
}

}  // namespace

LimitedInput::LimitedInput(int fd, std::string name, InputLimits limits, int copy, std::string copy_name)
    : fd_(fd),
      name_(std::move(name)),
      limits_(std::move(limits)),
      copy_(copy),
      copy_name_(std::move(copy_name)),
      chunk_(kChunkBytes) {}

std::size_t LimitedInput::within_limits(std::size_t count) {
    const char* data = chunk_.data();
    const uint64_t room = limits_.max_bytes - handed_out_;
    const std::size_t allowed = count > room ? static_cast<std::size_t>(room) : count;
    for (std::size_t at = 0; at < allowed;) {
        const void* line_end = std::memchr(data + at, '\n', allowed - at);
        const std::size_t end = line_end != nullptr ? static_cast<std::size_t>(static_cast<const char*>(line_end) - data) + 1
                                                    : allowed;
        if (line_bytes_ + (end - at) > limits_.max_line_bytes) {
            refusal_ = name_ + ":" + std::to_string(line_) + ": " + line_too_long(limits_.max_line_bytes);
            return at + (limits_.max_line_bytes - line_bytes_);
        }
        line_bytes_ = line_end != nullptr ? 0 : line_bytes_ + (end - at);
        line_ += line_end != nullptr ? 1 : 0;
        at = end;
    }
    if (allowed < count) {
        refusal_ = name_ + ": more than " + std::to_string(limits_.max_bytes) + " bytes; expected at most " +
                   std::to_string(limits_.max_bytes) + " bytes (" + limits_.max_bytes_origin + ")";
    }
    return allowed;
}

void LimitedInput::refuse() const { throw InputError(refusal_); }

// A chunk is read, cut at the first byte past a limit, copied, then handed
// out; the refusal comes when the reader asks for the byte past the limit.
LimitedInput::int_type LimitedInput::underflow() {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (!refusal_.empty()) refuse();
    if (at_end_) return traits_type::eof();
    ssize_t got;
    do {
        got = read(fd_, chunk_.data(), chunk_.size());
    } while (got < 0 && errno == EINTR);
    if (got < 0) system_error(name_ + ": cannot read", errno);
    if (got == 0) {
        at_end_ = true;
        return traits_type::eof();
    }
    const std::size_t kept = within_limits(static_cast<std::size_t>(got));
    if (kept == 0) refuse();
    if (copy_ >= 0) write_all(copy_, chunk_.data(), kept, name_ + ": cannot copy to a temporary file in " + copy_name_);
    handed_out_ += kept;
    setg(chunk_.data(), chunk_.data(), chunk_.data() + kept);
    return traits_type::to_int_type(*gptr());
}

void LimitedInput::drain() {
    while (underflow() != traits_type::eof()) setg(egptr(), egptr(), egptr());
}

std::string InputSpool::temp_directory() {
    const char* tmp = std::getenv("TMPDIR");
    return tmp != nullptr && tmp[0] != '\0' ? tmp : "/tmp";
}

InputSpool::InputSpool(const std::string& path, InputLimits limits, const std::string& directory) {
    copy_ = open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (copy_ < 0) {  // a file system without O_TMPFILE: unlinked at once instead
        std::string name = directory + "/cdvp-input.XXXXXX";
        copy_ = mkostemp(name.data(), O_CLOEXEC);
        if (copy_ >= 0) unlink(name.c_str());
    }
    if (copy_ < 0) {
        // A full or failing file system is the system's; a directory that is
        // missing or not writable is the user's TMPDIR.
        const int error = errno;
        const char* tmp = std::getenv("TMPDIR");
        const std::string where = tmp != nullptr && tmp[0] != '\0' && directory == tmp ? "TMPDIR " + excerpt(directory)
                                                                                        : excerpt(directory);
        throw_os_error(excerpt(path) + ": cannot copy it to a temporary file in " + where +
                           (is_system_failure(error) ? std::string() : " (set TMPDIR to a writable directory)"),
                       error);
    }
    try {
        source_ = open_for_reading(path);
    } catch (...) {
        close(copy_);
        throw;
    }
    input_ = std::make_unique<LimitedInput>(source_, path, std::move(limits), copy_, directory);
    stream_.rdbuf(input_.get());
    stream_.exceptions(std::ios::badbit);  // a refusal reaches readers of the stream as itself
}

InputSpool::~InputSpool() {
    if (source_ >= 0) close(source_);
    if (copy_ >= 0) close(copy_);
}

void InputSpool::finish() { input_->drain(); }

std::string InputSpool::path() const { return "/proc/self/fd/" + std::to_string(copy_); }

void InputSpool::keep_across_exec() {
    const int flags = fcntl(copy_, F_GETFD);
    if (flags < 0 || fcntl(copy_, F_SETFD, flags & ~FD_CLOEXEC) < 0) system_error("cannot share a temporary file", errno);
}

LimitedFile::LimitedFile(const std::string& path, InputLimits limits) {
    fd_ = open_for_reading(path);
    struct stat status {};
    if (fstat(fd_, &status) == 0 && static_cast<uint64_t>(status.st_size) > limits.max_bytes) {
        close(fd_);
        throw InputError(path + ": " + std::to_string(status.st_size) + " bytes, more than " +
                         std::to_string(limits.max_bytes) + "; expected at most " + std::to_string(limits.max_bytes) +
                         " bytes (" + limits.max_bytes_origin + ")");
    }
    input_ = std::make_unique<LimitedInput>(fd_, path, std::move(limits));
    stream_.rdbuf(input_.get());
    stream_.exceptions(std::ios::badbit);  // a refusal reaches readers of the stream as itself
}

LimitedFile::~LimitedFile() {
    if (fd_ >= 0) close(fd_);
}

}  // namespace cdvp
