#include "sw/output/child_process.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <stdexcept>

#include "models/common/user_text.h"

namespace cdvp {

CapturedOutput::CapturedOutput(const char* name) : fd_(memfd_create(name, MFD_CLOEXEC)) {
    if (fd_ < 0) throw_os_error(std::string("cannot keep a child's output (memfd_create ") + name + ")", errno);
}

CapturedOutput::~CapturedOutput() { close(fd_); }

std::string CapturedOutput::text(std::size_t max_bytes) const {
    std::string text(max_bytes, '\0');
    std::size_t done = 0;
    while (done < max_bytes) {
        const ssize_t got = pread(fd_, text.data() + done, max_bytes - done, static_cast<off_t>(done));
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        done += static_cast<std::size_t>(got);
    }
    text.resize(done);
    return text;
}

void CapturedOutput::clear() {
    if (ftruncate(fd_, 0) != 0) throw_os_error("cannot reuse a child's output", errno);
    lseek(fd_, 0, SEEK_SET);
}

std::string self_path() {
    std::string path(4096, '\0');
    const ssize_t n = readlink("/proc/self/exe", path.data(), path.size() - 1);
    if (n <= 0) throw std::runtime_error("cannot find the cdvp executable (/proc/self/exe)");
    path.resize(static_cast<std::size_t>(n));
    return path;
}

std::optional<std::string> find_program(const std::string& name) {
    if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? std::optional(name) : std::nullopt;
    const char* path = std::getenv("PATH");
    std::string dirs = path != nullptr ? path : "/usr/bin:/bin";
    for (std::size_t start = 0; start <= dirs.size();) {
        const std::size_t colon = std::min(dirs.find(':', start), dirs.size());
        const std::string dir = dirs.substr(start, colon - start);
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
        start = colon + 1;
    }
    return std::nullopt;
}

namespace {

// args[0] as a path to exec: itself when it names a directory, else the
// first executable of that name on PATH (looked up before fork, as exec in
// the child may not allocate); a name not found fails in exec (status 127).
std::string executable(const std::string& name) {
    if (name.find('/') != std::string::npos) return name;
    return find_program(name).value_or(name);
}

}  // namespace

pid_t start_child(const std::vector<std::string>& args, const ChildStreams& streams) {
    const std::string program = executable(args[0]);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int null_in = streams.in < 0 ? open("/dev/null", O_RDONLY | O_CLOEXEC) : -1;
    const pid_t parent = getpid();
    // vfork: the child borrows this process's memory until it execs, so
    // starting a point costs the same however large the sweep's table has
    // grown (fork would copy its page tables).
    const pid_t pid = vfork();
    if (pid < 0) {
        const int error = errno;
        if (null_in >= 0) close(null_in);
        throw_os_error(args[0] + ": cannot start", error);
    }
    if (pid == 0) {
        // Only system calls on values computed before vfork from here to exec.
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (getppid() != parent) _exit(127);  // the parent died before the line above
        const int in = streams.in >= 0 ? streams.in : null_in;
        if (in >= 0) dup2(in, STDIN_FILENO);
        if (streams.out >= 0) dup2(streams.out, STDOUT_FILENO);
        if (streams.err >= 0) dup2(streams.err, STDERR_FILENO);
        for (const int fd : streams.inherited) fcntl(fd, F_SETFD, 0);
        execv(program.c_str(), argv.data());
        _exit(127);
    }
    if (null_in >= 0) close(null_in);
    return pid;
}

int wait_child(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

int run_child(const std::vector<std::string>& args, const ChildStreams& streams) {
    return wait_child(start_child(args, streams));
}

}  // namespace cdvp
