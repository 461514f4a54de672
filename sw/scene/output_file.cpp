#include "sw/scene/output_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sw/scene/scene.h"

namespace cdvp {

namespace {

// mkstemps creates the file with mode 0600; a finished output should get the
// mode an ordinary open() would give. umask can only be read by setting it,
// so this briefly sets it to 0 (harmless in the single-threaded CLI).
mode_t default_file_mode() {
    mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

}  // namespace

OutputFile::OutputFile(std::string final_path, std::string suffix, bool open_stream)
    : final_path_(std::move(final_path)) {
    std::string name = final_path_ + ".part-XXXXXX" + suffix;
    std::vector<char> buf(name.begin(), name.end());
    buf.push_back('\0');
    int fd = mkstemps(buf.data(), static_cast<int>(suffix.size()));
    if (fd < 0) {
        fail(errno);
    }
    temp_path_.assign(buf.data());
    int err = fchmod(fd, default_file_mode()) == 0 ? 0 : errno;
    close(fd);
    if (err != 0) {
        discard();
        fail(err);
    }
    if (open_stream) {
        stream_ = std::make_unique<std::ofstream>(
            temp_path_, std::ios::binary | std::ios::trunc);
        if (!*stream_) {
            err = errno != 0 ? errno : EIO;
            discard();
            fail(err);
        }
    }
}

OutputFile::~OutputFile() {
    discard();
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : final_path_(std::move(other.final_path_)),
      temp_path_(std::exchange(other.temp_path_, std::string())),
      stream_(std::move(other.stream_)) {}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
    if (this != &other) {
        discard();
        final_path_ = std::move(other.final_path_);
        temp_path_ = std::exchange(other.temp_path_, std::string());
        stream_ = std::move(other.stream_);
    }
    return *this;
}

std::ostream& OutputFile::stream() {
    if (!stream_) {
        throw std::logic_error("OutputFile::stream: no stream open for " + final_path_);
    }
    return *stream_;
}

void OutputFile::commit() {
    if (temp_path_.empty()) {
        throw std::logic_error("OutputFile::commit: nothing to commit for " + final_path_);
    }
    if (stream_) {
        errno = 0;
        stream_->close();  // flushes
        if (stream_->fail()) {
            fail(errno != 0 ? errno : EIO);
        }
        stream_.reset();
    }
    if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0) {
        fail(errno);
    }
    temp_path_.clear();
}

void OutputFile::discard() noexcept {
    stream_.reset();
    if (!temp_path_.empty()) {
        std::remove(temp_path_.c_str());
        temp_path_.clear();
    }
}

void OutputFile::fail(int err) const {
    throw InputError(final_path_ + ": cannot write: " + std::strerror(err));
}

}  // namespace cdvp
