#include "sw/output/text_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "models/common/user_text.h"
#include "sw/output/digest.h"
#include "sw/output/output_cleanup.h"

namespace cdvp {

std::optional<std::string> read_whole_file(const std::string& path) {
    std::string text;
    if (!read_file_blocks(path, [&](const char* data, std::size_t size) { text.append(data, size); })) {
        return std::nullopt;
    }
    return text;
}

std::string slurp(const std::string& path) { return read_whole_file(path).value_or(std::string()); }

void commit_text_file(const std::string& path, const std::string& text, const std::string& label) {
    const CleanupSignalsBlocked held;
    const std::string temp = path + ".part-" + std::to_string(getpid());
    const int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw_os_error(label + ": " + excerpt(temp) + ": cannot write", errno);
    int error = 0;
    for (std::size_t done = 0; done < text.size() && error == 0;) {
        const ssize_t put = write(fd, text.data() + done, text.size() - done);
        if (put < 0 && errno == EINTR) continue;
        if (put < 0) error = errno;
        if (put > 0) done += static_cast<std::size_t>(put);
    }
    // Synced before the rename: a crash leaves the old file or the whole new one.
    if (error == 0 && fdatasync(fd) != 0) error = errno;
    if (close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && std::rename(temp.c_str(), path.c_str()) != 0) error = errno;
    if (error != 0) {
        unlink(temp.c_str());
        throw_os_error(label + ": " + excerpt(path) + ": cannot write", error);
    }
}

}  // namespace cdvp
