#include "models/common/input_path.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "models/common/user_text.h"

namespace cdvp {

std::string path_text(const std::string& path) {
    constexpr std::size_t kMaxPathBytes = 4096;
    if (path.size() <= kMaxPathBytes) return printable(path);
    const auto inside = [&path](std::size_t k) { return (static_cast<unsigned char>(path[k]) & 0xC0) == 0x80; };
    std::size_t head = kExcerptBytes, tail = path.size() - kExcerptBytes;
    while (head > 0 && inside(head)) --head;  // never splitting a UTF-8 sequence
    while (tail < path.size() && inside(tail)) ++tail;
    return printable(path.substr(0, head)) + "... (" + std::to_string(path.size()) + " bytes) ..." +
           printable(path.substr(tail));
}

std::string errno_reason(int error) {
    if (error == 0) return "not a regular file";
    const char* name = strerrorname_np(error);
    return std::string(std::strerror(error)) + (name != nullptr ? " (" + std::string(name) + ")" : "");
}

InputPresence input_presence(const std::string& path) {
    struct stat status {};
    if (stat(path.c_str(), &status) == 0) return {InputPresence::Kind::kPresent, {}};
    if (errno == ENOENT) return {InputPresence::Kind::kAbsent, {}};
    return {InputPresence::Kind::kUnreadable, errno_reason(errno)};
}

void refuse_input(const std::string& shown, int error, const std::string& expected) {
    throw InputError(shown + ": cannot open: " + errno_reason(error) + (expected.empty() ? "" : "; " + expected));
}

void require_regular_file(const std::string& path, const std::string& shown) {
    const std::string named = shown.empty() ? path : shown;
    struct stat status {};
    if (stat(path.c_str(), &status) != 0) refuse_input(named, errno);
    if (S_ISDIR(status.st_mode)) refuse_input(named, EISDIR);
    if (!S_ISREG(status.st_mode)) refuse_input(named, 0);
}

namespace {

[[noreturn]] void refuse_size(const InputFile& file) {
    throw InputError(path_text(file.path) + ": larger than " + std::to_string(file.max_bytes) + " bytes; not " + file.what);
}

}  // namespace

bool read_input_blocks(const InputFile& file, const std::function<void(const char*, std::size_t)>& take) {
    const std::string shown = path_text(file.path);
    const int fd = open(file.path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0 && errno == ENOENT && file.absent_ok) return false;
    if (fd < 0) refuse_input(shown, errno);
    struct Closer {
        int fd;
        ~Closer() { close(fd); }
    } closer{fd};
    struct stat status {};
    if (fstat(fd, &status) != 0) refuse_input(shown, errno);
    if (S_ISDIR(status.st_mode)) refuse_input(shown, EISDIR);
    if (!S_ISREG(status.st_mode)) refuse_input(shown, 0, "expected " + file.what);
    if (static_cast<uint64_t>(status.st_size) > file.max_bytes) refuse_size(file);
    char block[1 << 16];
    for (std::size_t got = 0;;) {  // to the end, which may come before or after the size seen (a file being written)
        const ssize_t n = read(fd, block, sizeof block);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw InputError(shown + ": cannot read: " + errno_reason(errno));
        if (n == 0) return true;
        got += static_cast<std::size_t>(n);
        if (got > file.max_bytes) refuse_size(file);
        take(block, static_cast<std::size_t>(n));
    }
}

std::optional<std::string> read_input_file(const InputFile& file) {
    std::string text;
    if (!read_input_blocks(file, [&text](const char* data, std::size_t size) { text.append(data, size); })) {
        return std::nullopt;
    }
    return text;
}

}  // namespace cdvp
