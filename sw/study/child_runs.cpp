#include "sw/study/child_runs.h"

#include <sys/mman.h>
#include <sys/prctl.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "models/common/user_text.h"
#include "sw/study/digest.h"
#include "sw/scene/input_spool.h"
#include "sw/study/output/output_cleanup.h"

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

ScratchFile::ScratchFile(const std::string& suffix) {
    const char* dir = std::getenv("TMPDIR");
    const std::string directory = dir != nullptr && *dir != '\0' ? dir : "/tmp";
    std::string pattern = directory + "/cdvp-XXXXXX" + suffix;
    const int fd = mkstemps(pattern.data(), static_cast<int>(suffix.size()));
    if (fd < 0) {
        const int error = errno;
        throw_os_error((dir != nullptr && *dir != '\0' ? "TMPDIR: " : "the temporary directory ") + excerpt(directory) +
                           ": cannot create a temporary file (set TMPDIR to a writable directory)",
                       error);
    }
    close(fd);
    path_ = pattern;
    slot_ = TemporaryRegistry::hold(path_);
}

ScratchFile::~ScratchFile() {
    unlink(path_.c_str());
    TemporaryRegistry::release(slot_);
}

std::optional<std::string> read_whole_file(const std::string& path) {
    std::string text;
    if (!read_file_blocks(path, [&](const char* data, std::size_t size) { text.append(data, size); })) {
        return std::nullopt;
    }
    return text;
}

std::string slurp(const std::string& path) { return read_whole_file(path).value_or(std::string()); }

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

std::optional<std::string> run_gnuplot(const std::string& script) {
    // The script in memory too, read by gnuplot through its descriptor.
    CapturedOutput script_file("cdvp-figures.gp"), errors("cdvp-gnuplot-errors");
    for (std::size_t done = 0; done < script.size();) {
        const ssize_t put = write(script_file.fd(), script.data() + done, script.size() - done);
        if (put < 0 && errno == EINTR) continue;
        if (put <= 0) throw_os_error("cannot hand gnuplot its script", errno);
        done += static_cast<std::size_t>(put);
    }
    const std::string script_path = "/proc/self/fd/" + std::to_string(script_file.fd());
    ChildStreams streams;
    streams.err = errors.fd();
    streams.inherited = {script_file.fd()};
    const int status = run_child({"gnuplot", script_path}, streams);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return std::nullopt;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) return std::string("gnuplot: not found on PATH");
    return errors.text(64 * 1024);
}

std::string renamed_message(std::string message, const std::string& program) {
    if (message.rfind("cdvp run: ", 0) == 0) message = program + ": " + message.substr(10);
    return message;
}

std::optional<OptionValue> find_option(const std::vector<std::string>& args, const std::string& option) {
    for (std::size_t k = 0; k < args.size(); ++k) {
        if (args[k] == option && k + 1 < args.size()) return OptionValue{k + 1, 0};
        if (args[k].rfind(option + "=", 0) == 0) return OptionValue{k, option.size() + 1};
    }
    return std::nullopt;
}

std::string option_value(const std::vector<std::string>& args, const std::string& option) {
    const std::optional<OptionValue> at = find_option(args, option);
    return at ? args[at->index].substr(at->offset) : std::string();
}

TraceSpool::TraceSpool(const std::string& path, const InputLimits& limits) : original_(path), path_(path) {
    struct stat status {};
    if (path.empty() || stat(path.c_str(), &status) != 0 || S_ISREG(status.st_mode)) return;
    copy_ = std::make_unique<InputSpool>(path, limits);
    copy_->finish();
    path_ = copy_->path();
}

TraceSpool::~TraceSpool() = default;

int TraceSpool::descriptor() const { return copy_ ? copy_->descriptor() : -1; }

std::string TraceSpool::restore_names(std::string message) const {
    if (!copy_) return message;
    for (std::size_t at; (at = message.find(path_)) != std::string::npos;) message.replace(at, path_.size(), original_);
    return message;
}

void CreatedDirectories::create(const std::string& path, const std::string& label) {
    namespace fs = std::filesystem;
    std::vector<fs::path> missing;
    for (fs::path p = fs::absolute(path); !p.empty() && !fs::exists(p); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        std::error_code error;
        if (!fs::create_directory(*it, error) && error) {
            throw InputError(label + ": " + excerpt(path) + ": cannot create: " + error.message());
        }
        made_.push_back(it->string());
    }
}

CreatedDirectories::~CreatedDirectories() {
    std::error_code ignored;
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) std::filesystem::remove(*it, ignored);
}

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
