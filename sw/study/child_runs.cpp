#include "sw/study/child_runs.h"

#include "sw/output/child_process.h"

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
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "models/common/user_text.h"
#include "sw/output/digest.h"
#include "sw/scene/input_spool.h"
#include "sw/output/output_cleanup.h"

namespace cdvp {


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

}  // namespace cdvp
