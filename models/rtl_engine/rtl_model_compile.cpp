#include "models/rtl_engine/rtl_model_compile.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include "models/common/user_text.h"

extern char** environ;

namespace cdvp {

namespace {

bool is_executable_file(const std::string& path) {
    struct stat info {};
    return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && access(path.c_str(), X_OK) == 0;
}

// `name` on PATH (or itself, when it holds a slash).
std::optional<std::string> on_path(const std::string& name) {
    if (name.find('/') != std::string::npos) return is_executable_file(name) ? std::optional(name) : std::nullopt;
    const char* path = std::getenv("PATH");
    std::istringstream directories(path != nullptr ? path : "");
    for (std::string directory; std::getline(directories, directory, ':');) {
        const std::string candidate = (directory.empty() ? "." : directory) + "/" + name;
        if (is_executable_file(candidate)) return candidate;
    }
    return std::nullopt;
}

// This process's environment less the variables make and the compiler would
// add flags from: the model is made from what its key names, whoever runs it.
std::vector<char*> compile_environment() {
    static const char* const kDropped[] = {"CXXFLAGS=", "CPPFLAGS=", "LDFLAGS=", "LDLIBS=", "MAKEFLAGS=", "MFLAGS="};
    std::vector<char*> kept;
    for (char** variable = environ; *variable != nullptr; ++variable) {
        bool dropped = false;
        for (const char* name : kDropped) dropped |= std::strncmp(*variable, name, std::strlen(name)) == 0;
        if (!dropped) kept.push_back(*variable);
    }
    kept.push_back(nullptr);
    return kept;
}

// Runs args (args[0] an absolute path) with standard input from /dev/null
// and both outputs appended to `log`; its wait status.
int run_logged(const std::vector<std::string>& args, const std::string& log) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) throw_os_error(log + ": cannot write the compile's log", errno);
    std::string line = "$";
    for (const std::string& a : args) line += " " + a;
    line += "\n";
    if (write(fd, line.data(), line.size()) < 0) {
        const int error = errno;
        close(fd);
        throw_os_error(log + ": cannot write the compile's log", error);
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, fd, STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, fd, STDERR_FILENO);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::vector<char*> environment = compile_environment();
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, args[0].c_str(), &actions, nullptr, argv.data(), environment.data());
    posix_spawn_file_actions_destroy(&actions);
    close(fd);
    if (spawned != 0) throw_os_error(args[0] + ": cannot start", spawned);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The kit's entry template with the model's class and the exported name.
std::string entry_source(const RtlKit& kit, const RtlVariant& variant) {
    std::string text = read_text(kit.path(kit.cxx.front()));
    if (text.empty()) throw InputError(kit.path(kit.cxx.front()) + ": cannot read the RTL model's entry template");
    const std::pair<std::string, std::string> fills[] = {{"@prefix@", "Vcdvp_rtl_" + variant.name()},
                                                         {"@entry@", kRtlBoardMakerSymbol},
                                                         {"@probes@", variant.probes()}};
    for (const auto& [key, value] : fills) {
        for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size())) {
            text.replace(at, key.size(), value);
        }
    }
    return text;
}

// What a failed step says: the tool, how it ended, and where its log is.
[[noreturn]] void step_failed(const std::string& step, int status, const std::string& log) {
    if (WIFSIGNALED(status)) {
        throw SystemError(step + " was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                          strsignal(WTERMSIG(status)) + "); its log: " + log);
    }
    const std::string why = step + " exited with status " + std::to_string(WEXITSTATUS(status)) + "; its log: " + log;
    // The system's failure rather than the RTL's: a full disk or quota.
    if (read_text(log).find(std::strerror(ENOSPC)) != std::string::npos) throw SystemError(why);
    throw InputError(why);
}

}  // namespace

const std::vector<std::string>& rtl_model_make_options() {
    // As the built-in variants' code: the model at -O3, its once-run (__Slow)
    // files unoptimised, Verilator's run time at -O2; position-independent, and
    // only the entry point visible outside the shared object.
    static const std::vector<std::string> options{"-CFLAGS", "-fPIC", "-CFLAGS", "-fvisibility=hidden",
                                                  "-CFLAGS", "-std=c++17",
                                                  "-MAKEFLAGS", "OPT_FAST=-O3", "-MAKEFLAGS", "OPT_SLOW=-O0",
                                                  "-MAKEFLAGS", "OPT_GLOBAL=-O2", "-MAKEFLAGS", "VM_PARALLEL_BUILDS=1",
                                                  "-LDFLAGS", "-shared"};
    return options;
}

RtlToolchain find_rtl_toolchain(const RtlBuild& build, const std::string& what) {
    RtlToolchain tools;
    const std::optional<std::string> verilator = on_path("verilator");
    if (!verilator) {
        throw InputError(what + " needs verilator, which is not on PATH (Debian's verilator package; scripts/setup.sh "
                                "installs it)");
    }
    const std::optional<std::string> make = on_path("make");
    if (!make) throw InputError(what + " needs make (Verilator's build runs it), which is not on PATH");
    const std::optional<std::string> compiler = on_path(build.compiler_path);
    if (!compiler) {
        throw InputError(what + " needs the C++ compiler cdvp was built with (" + build.compiler + ", " +
                         build.compiler_path + "), which is missing");
    }
    return {*verilator, *make, *compiler};
}

std::string compile_rtl_model(const RtlVariant& variant, const RtlToolchain& tools, const RtlBuild& build,
                              const RtlKit& kit, const std::string& directory, const std::string& log) {
    const std::string entry = directory + "/entry.cpp";
    {
        std::ofstream out(entry, std::ios::binary);
        out << entry_source(kit, variant);
        out.close();
        if (!out) throw_os_error(entry + ": cannot write", errno);
    }
    const int version_status = run_logged({tools.verilator, "--version"}, log);
    if (!WIFEXITED(version_status) || WEXITSTATUS(version_status) != 0) {
        step_failed("verilator --version", version_status, log);
    }
    const std::string printed = read_text(log);
    const std::size_t line = printed.find("\nVerilator ");
    const std::string version =
        line == std::string::npos ? "unknown" : printed.substr(line + 1, printed.find('\n', line + 1) - line - 1);

    const unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::string> args{tools.verilator, "--cc", "--exe", "--build", "-j", std::to_string(jobs),
                                  "--Mdir", directory + "/verilated", "--prefix", "Vcdvp_rtl_" + variant.name(),
                                  "--top-module", variant.top(), "--trace", "-o", directory + "/model.so",
                                  "-MAKEFLAGS", "CXX=" + tools.compiler, "-MAKEFLAGS", "LINK=" + tools.compiler,
                                  "-CFLAGS", "-I" + kit.root};
    const std::vector<std::string>& options = rtl_model_make_options();
    args.insert(args.end(), options.begin(), options.end());
    args.insert(args.end(), build.verilator_arguments.begin(), build.verilator_arguments.end());
    const std::vector<std::string> parameters = variant.verilator_parameters();
    args.insert(args.end(), parameters.begin(), parameters.end());
    for (const std::string& file : kit.verilog) args.push_back(kit.path(file));
    args.push_back(entry);
    const int status = run_logged(args, log);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) step_failed("verilator --build", status, log);
    return version;
}

}  // namespace cdvp
