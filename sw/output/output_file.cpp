#include "sw/output/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sw/output/output_cleanup.h"
#include "sw/scene/scene.h"

namespace cdvp {

namespace {

namespace fs = std::filesystem;

// Room for ".part-XXXXXX" and a suffix within NAME_MAX (255).
constexpr std::size_t kMaxStemBytes = 200;

// mkstemps creates the file with mode 0600; a new output should get the
// mode an ordinary open() would give. umask can only be read by setting it,
// so this briefly sets it to 0 (harmless in the single-threaded CLI).
mode_t default_file_mode() {
    mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

// "<directory>/<name>.part-XXXXXX", the name cut so the result stays a legal
// file name whatever the target's name length.
std::string temporary_pattern(const fs::path& directory, std::string name) {
    if (name.size() > kMaxStemBytes) name.resize(kMaxStemBytes);
    return (directory / name).string() + ".part-XXXXXX";
}

// Creates a unique file from pattern + suffix; returns its descriptor and
// sets 'pattern' to the file's path. -1 with errno on failure.
int make_unique_file(std::string& pattern, const std::string& suffix) {
    std::string name = pattern + suffix;
    std::vector<char> buffer(name.begin(), name.end());
    buffer.push_back('\0');
    const int fd = mkstemps(buffer.data(), static_cast<int>(suffix.size()));
    if (fd >= 0) pattern.assign(buffer.data());
    return fd;
}

// A second name for 'target' in its directory, so the old file survives a
// rename over it. Empty where the file system has no hard links.
std::string link_backup(const std::string& target) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        std::string name = temporary_pattern(fs::path(target).parent_path(), fs::path(target).filename().string());
        const int fd = make_unique_file(name, ".old");
        if (fd < 0) return {};
        close(fd);
        unlink(name.c_str());
        if (link(target.c_str(), name.c_str()) == 0) return name;
        if (errno != EEXIST) return {};
    }
    return {};
}

// Appends the file at 'from' to the open descriptor 'to'. 0 or errno.
int copy_into(const std::string& from, int to) {
    const int in = open(from.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return errno;
    char buffer[1 << 16];
    int err = 0;
    for (;;) {
        const ssize_t got = read(in, buffer, sizeof buffer);
        if (got == 0) break;
        if (got < 0) {
            if (errno == EINTR) continue;
            err = errno;
            break;
        }
        for (ssize_t done = 0; done < got && err == 0;) {
            const ssize_t put = write(to, buffer + done, static_cast<std::size_t>(got - done));
            if (put < 0 && errno != EINTR) err = errno;
            if (put > 0) done += put;
        }
        if (err != 0) break;
    }
    close(in);
    return err;
}

}  // namespace

DescriptorBuffer::DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }

DescriptorBuffer::~DescriptorBuffer() {
    if (fd_ >= 0) ::close(fd_);
}

bool DescriptorBuffer::drain() {
    for (char* at = pbase(); at < pptr() && error_ == 0;) {
        const ssize_t put = ::write(fd_, at, static_cast<std::size_t>(pptr() - at));
        if (put < 0 && errno == EINTR) continue;
        if (put < 0) error_ = errno;
        if (put > 0) at += put;
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return error_ == 0;
}

DescriptorBuffer::int_type DescriptorBuffer::overflow(int_type c) {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
        *pptr() = traits_type::to_char_type(c);
        pbump(1);
    }
    return traits_type::not_eof(c);
}

int DescriptorBuffer::sync() { return drain() ? 0 : -1; }

int DescriptorBuffer::close() {
    if (fd_ < 0) return error_;
    drain();
    if (::close(fd_) != 0 && error_ == 0) error_ = errno;
    fd_ = -1;
    return error_;
}

OutputFile::OutputFile(std::string final_path, std::string suffix, bool open_stream)
    : final_path_(std::move(final_path)), target_(resolve_output_target(final_path_)) {
    const fs::path target(target_.path);
    std::string pattern;
    if (target_.kind == OutputTarget::Kind::kDirect) {
        const char* tmp = std::getenv("TMPDIR");
        pattern = temporary_pattern(tmp != nullptr && tmp[0] != '\0' ? tmp : "/tmp",
                                    "cdvp-" + fs::path(final_path_).filename().string());
    } else {
        pattern = temporary_pattern(target.parent_path(), target.filename().string());
    }
    int fd;
    {
        // No signal between creating the temporary and registering it.
        CleanupSignalsBlocked blocked;
        fd = make_unique_file(pattern, suffix);
        if (fd < 0 && target_.kind == OutputTarget::Kind::kDirect && !is_system_failure(errno)) {
            // A device or descriptor is written from a temporary in $TMPDIR.
            const int error = errno;
            throw_os_error(final_path_ + ": cannot make its temporary file in " +
                               fs::path(pattern).parent_path().string() + " (set TMPDIR to a writable directory)",
                           error);
        }
        if (fd < 0) fail(errno);
        temp_path_ = pattern;
        cleanup_slot_ = TemporaryRegistry::hold(temp_path_);
    }
    const mode_t mode = target_.kind == OutputTarget::Kind::kRegular ? target_.status.st_mode & 07777
                                                                     : default_file_mode();
    const int err = fchmod(fd, mode) == 0 ? 0 : errno;
    if (err != 0 || !open_stream) close(fd);
    if (err != 0) {
        discard();
        fail(err);
    }
    if (open_stream) {
        buffer_ = std::make_unique<DescriptorBuffer>(fd);
        stream_ = std::make_unique<std::ostream>(buffer_.get());
    }
}

OutputFile::~OutputFile() { discard(); }

OutputFile::OutputFile(OutputFile&& other) noexcept
    : final_path_(std::move(other.final_path_)),
      target_(std::move(other.target_)),
      temp_path_(std::exchange(other.temp_path_, std::string())),
      cleanup_slot_(std::exchange(other.cleanup_slot_, -1)),
      buffer_(std::move(other.buffer_)),
      stream_(std::move(other.stream_)) {}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
    if (this != &other) {
        discard();
        final_path_ = std::move(other.final_path_);
        target_ = std::move(other.target_);
        temp_path_ = std::exchange(other.temp_path_, std::string());
        cleanup_slot_ = std::exchange(other.cleanup_slot_, -1);
        buffer_ = std::move(other.buffer_);
        stream_ = std::move(other.stream_);
    }
    return *this;
}

std::ostream& OutputFile::stream() {
    if (!stream_) throw std::logic_error("OutputFile::stream: no stream open for " + final_path_);
    return *stream_;
}

void OutputFile::finish() {
    if (temp_path_.empty()) throw std::logic_error("OutputFile::finish: nothing to finish for " + final_path_);
    if (const int err = try_finish()) fail(err);
}

int OutputFile::try_finish() noexcept {
    if (temp_path_.empty()) return EINVAL;  // nothing to finish: committed, discarded or moved from
    if (stream_) {
        const int err = buffer_->close();  // flushes
        stream_.reset();
        buffer_.reset();
        if (err != 0) return err;
    }
    return 0;
}

std::string OutputFile::publish() {
    if (temp_path_.empty() || stream_) {
        throw std::logic_error("OutputFile::publish: " + final_path_ + " is not finished");
    }
    std::string backup;
    if (const int err = try_publish(backup)) fail(err);
    return backup;
}

int OutputFile::try_publish(std::string& backup) noexcept {
    backup.clear();
    if (temp_path_.empty() || stream_) return EINVAL;  // not finished
    if (target_.kind == OutputTarget::Kind::kDirect) {
        const int out = target_.descriptor >= 0 ? fcntl(target_.descriptor, F_DUPFD_CLOEXEC, 0)
                                                : open(target_.path.c_str(), O_WRONLY | O_APPEND | O_NOCTTY | O_CLOEXEC);
        if (out < 0) return errno;
        int err = copy_into(temp_path_, out);
        if (close(out) != 0 && err == 0) err = errno;
        if (err != 0) return err;
        discard();
        return 0;
    }
    struct stat existing {};
    if (lstat(target_.path.c_str(), &existing) == 0) backup = link_backup(target_.path);
    if (std::rename(temp_path_.c_str(), target_.path.c_str()) != 0) {
        const int err = errno;
        if (!backup.empty()) unlink(backup.c_str());
        backup.clear();
        return err;
    }
    forget_temporary();
    return 0;
}

std::string OutputFile::error_message(int err) const {
    return final_path_ + ": cannot write: " + std::strerror(err);
}

void OutputFile::commit() {
    finish();
    CleanupSignalsBlocked blocked;
    const std::string backup = publish();
    if (!backup.empty()) unlink(backup.c_str());
}

void OutputFile::forget_temporary() noexcept {
    TemporaryRegistry::release(std::exchange(cleanup_slot_, -1));
    temp_path_.clear();
}

void OutputFile::discard() noexcept {
    stream_.reset();
    buffer_.reset();
    if (!temp_path_.empty()) {
        std::remove(temp_path_.c_str());
        forget_temporary();
    }
}

void OutputFile::fail(int err) const {
    if (is_system_failure(err)) throw SystemError(error_message(err));
    throw InputError(error_message(err));
}

}  // namespace cdvp
