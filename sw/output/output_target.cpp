#include "sw/output/output_target.h"

#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>

#include "sw/scene/scene.h"

namespace cdvp {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxLinkHops = 40;  // as the kernel's ELOOP limit

bool g_closed_at_start[3] = {false, false, false};

[[noreturn]] void refuse(const std::string& given, const std::string& reason) {
    throw InputError(given + ": cannot write: " + reason);
}

std::string real_path(const std::string& path) {
    char buffer[PATH_MAX];
    return realpath(path.c_str(), buffer) != nullptr ? std::string(buffer) : std::string();
}

std::string parent_of(const std::string& path) {
    const std::string parent = fs::path(path).parent_path().string();
    return parent.empty() ? "." : parent;
}

// /proc/<pid>/fd/N (what /dev/stdout and /dev/fd/N lead to) is a link to an
// open descriptor, which may be a pipe or socket with no name to rename over.
bool is_descriptor_directory(const std::string& real_directory) {
    static const std::regex kFdDirectory("/proc/[^/]+/fd");
    return std::regex_match(real_directory, kFdDirectory);
}

void require_writable_directory(const std::string& given, const std::string& directory) {
    if (access(directory.c_str(), W_OK | X_OK) != 0) {
        refuse(given, "directory '" + directory + "' is not writable (" + std::strerror(errno) + ")");
    }
}

}  // namespace

void reserve_standard_descriptors() {
    for (int fd = 0; fd < 3; ++fd) {
        if (fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        // open() takes the lowest free number: this one.
        if (open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY) == fd) g_closed_at_start[fd] = true;
    }
}

bool standard_descriptor_was_closed(int descriptor) {
    return descriptor >= 0 && descriptor < 3 && g_closed_at_start[descriptor];
}

namespace {

// Nothing at `path`: the file is created in its (existing, writable) directory.
OutputTarget new_file_target(const std::string& given, const std::string& path) {
    const std::string parent = parent_of(path);
    const std::string name = fs::path(path).filename().string();
    struct stat parent_status {};
    if (stat(parent.c_str(), &parent_status) != 0) {
        refuse(given, "directory '" + parent + "'" +
                          (errno == ENOENT ? std::string(" does not exist") : ": " + std::string(std::strerror(errno))));
    }
    if (!S_ISDIR(parent_status.st_mode)) refuse(given, "'" + parent + "' is not a directory");
    if (name == "." || name == "..") refuse(given, "names a directory, expected a file");
    const std::string real_parent = real_path(parent);
    if (real_parent.empty()) refuse(given, std::strerror(errno));
    require_writable_directory(given, real_parent);
    OutputTarget target;
    target.kind = OutputTarget::Kind::kNew;
    target.path = (fs::path(real_parent) / name).string();
    return target;
}

// A link in /proc/self/fd or /dev/fd: the descriptor is written as it is.
OutputTarget descriptor_target(const std::string& given, const std::string& path, const std::string& real_parent) {
    OutputTarget target;
    target.kind = OutputTarget::Kind::kDirect;
    target.path = path;
    if (real_parent == "/proc/" + std::to_string(getpid()) + "/fd") {
        target.descriptor = std::atoi(fs::path(path).filename().c_str());
        if (standard_descriptor_was_closed(target.descriptor)) {
            refuse(given, "descriptor " + std::to_string(target.descriptor) + " was closed when cdvp started");
        }
    }
    if (stat(path.c_str(), &target.status) != 0) refuse(given, std::strerror(errno));
    if (access(path.c_str(), W_OK) != 0) refuse(given, std::strerror(errno));
    return target;
}

// Something that is no link: a regular file is replaced, a device or FIFO written.
OutputTarget existing_target(const std::string& given, const std::string& path, const struct stat& status) {
    const mode_t type = status.st_mode & S_IFMT;
    if (type == S_IFDIR) refuse(given, "is a directory");
    if (type != S_IFREG && type != S_IFCHR && type != S_IFIFO) refuse(given, "not a regular file, character device or FIFO");
    OutputTarget target;
    target.status = status;
    target.path = real_path(path);
    if (target.path.empty()) refuse(given, std::strerror(errno));
    if (access(target.path.c_str(), W_OK) != 0) refuse(given, std::strerror(errno));
    if (type == S_IFREG) {
        target.kind = OutputTarget::Kind::kRegular;
        require_writable_directory(given, parent_of(target.path));
    } else {
        target.kind = OutputTarget::Kind::kDirect;
    }
    return target;
}

}  // namespace

OutputTarget resolve_output_target(const std::string& given) {
    if (given.empty()) refuse(given, "empty path");
    if (given == "-") {  // the usual spelling of standard output
        try {
            return resolve_output_target("/dev/stdout");
        } catch (const InputError& e) {
            throw InputError("-" + std::string(e.what()).substr(std::strlen("/dev/stdout")));
        }
    }
    if (given.back() == '/') refuse(given, "names a directory, expected a file");
    std::string path = given;
    for (int hops = 0;; ++hops) {
        if (hops > kMaxLinkHops) refuse(given, std::strerror(ELOOP));
        struct stat status {};
        if (lstat(path.c_str(), &status) != 0) {
            if (errno != ENOENT && errno != ENOTDIR) refuse(given, std::strerror(errno));
            return new_file_target(given, path);
        }
        if (!S_ISLNK(status.st_mode)) return existing_target(given, path, status);
        const std::string real_parent = real_path(parent_of(path));
        if (is_descriptor_directory(real_parent)) return descriptor_target(given, path, real_parent);
        char link[PATH_MAX];
        const ssize_t length = readlink(path.c_str(), link, sizeof link - 1);
        if (length < 0) refuse(given, std::strerror(errno));
        link[length] = '\0';
        path = link[0] == '/' ? std::string(link) : (fs::path(parent_of(path)) / link).string();
    }
}

FileIdentity identity_of(const OutputTarget& target) {
    FileIdentity id;
    id.path = target.path;
    id.exists = target.kind != OutputTarget::Kind::kNew;
    id.device = target.status.st_dev;
    id.inode = target.status.st_ino;
    return id;
}

FileIdentity identity_of_input(const std::string& path) {
    FileIdentity id;
    struct stat status {};
    id.exists = stat(path.c_str(), &status) == 0;
    id.device = status.st_dev;
    id.inode = status.st_ino;
    id.path = real_path(path);
    std::error_code error;
    if (id.path.empty()) id.path = fs::absolute(path, error).lexically_normal().string();
    return id;
}

}  // namespace cdvp
