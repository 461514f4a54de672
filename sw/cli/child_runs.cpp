#include "sw/cli/child_runs.h"

#include <spawn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "models/common/user_text.h"
#include "sw/scene/output_cleanup.h"

extern char** environ;

namespace cdvp {

ScratchFile::ScratchFile(const std::string& suffix) {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") + "/cdvp-XXXXXX" + suffix;
    const int fd = mkstemps(pattern.data(), static_cast<int>(suffix.size()));
    if (fd < 0) throw std::runtime_error("cannot create a temporary file in $TMPDIR: " + std::string(std::strerror(errno)));
    close(fd);
    path_ = pattern;
    slot_ = TemporaryRegistry::hold(path_);
}

ScratchFile::~ScratchFile() {
    unlink(path_.c_str());
    TemporaryRegistry::release(slot_);
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string self_path() {
    std::string path(4096, '\0');
    const ssize_t n = readlink("/proc/self/exe", path.data(), path.size() - 1);
    if (n <= 0) throw std::runtime_error("cannot find the cdvp executable (/proc/self/exe)");
    path.resize(static_cast<std::size_t>(n));
    return path;
}

pid_t start_child(const std::vector<std::string>& args, const std::string& err_path, const char* out_path) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path.c_str(), O_WRONLY | O_TRUNC, 0600);
    if (out_path != nullptr) {
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path, O_WRONLY | O_TRUNC, 0600);
    }
    pid_t pid = 0;
    const int error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw std::runtime_error(args[0] + ": cannot start: " + std::strerror(error));
    return pid;
}

int wait_child(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

int run_child(const std::vector<std::string>& args, const std::string& err_path, const char* out_path) {
    return wait_child(start_child(args, err_path, out_path));
}

std::optional<std::string> run_gnuplot(const std::string& script) {
    ScratchFile script_file(".gp"), errors(".err");
    std::ofstream(script_file.path()) << script;
    const int status = run_child({"gnuplot", script_file.path()}, errors.path());
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return std::nullopt;
    return slurp(errors.path());
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

TraceSpool::TraceSpool(const std::string& path) : original_(path) {
    struct stat status {};
    if (path.empty() || stat(path.c_str(), &status) != 0 || S_ISREG(status.st_mode)) return;
    copy_.emplace(".csv");
    std::ifstream in(path, std::ios::binary);
    std::ofstream out(copy_->path(), std::ios::binary);
    if (!in) throw InputError("--trace: " + excerpt(path) + ": cannot open");
    if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();  // an empty one stays empty
    if (!out.flush()) throw std::runtime_error("cannot copy the trace to $TMPDIR");
}

std::string TraceSpool::restore_names(std::string message) const {
    if (!copy_) return message;
    for (std::size_t at; (at = message.find(copy_->path())) != std::string::npos;) {
        message.replace(at, copy_->path().size(), original_);
    }
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
    FILE* file = std::fopen(temp.c_str(), "wb");
    if (file == nullptr) throw InputError(label + ": " + excerpt(temp) + ": cannot write: " + std::strerror(errno));
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    const int write_error = errno;
    if (std::fclose(file) != 0 || !written || std::rename(temp.c_str(), path.c_str()) != 0) {
        const int error = written ? errno : write_error;
        unlink(temp.c_str());
        throw InputError(label + ": " + excerpt(path) + ": cannot write: " + std::strerror(error));
    }
}

}  // namespace cdvp
