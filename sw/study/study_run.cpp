#include "sw/study/study_run.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/exit_codes.h"

namespace cdvp {

namespace {

bool executable(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error) && access(path.c_str(), X_OK) == 0;
}

// Options a request may not give: where the report and pairs go is the study's.
void check_options(const std::vector<std::string>& options) {
    for (const std::string& option : options) {
        // A command-line word ends at its first NUL: the rest would be lost, not refused.
        if (option.find('\0') != std::string::npos) {
            throw InputError("option " + excerpt(option.substr(0, option.find('\0'))) + "...: holds a NUL character");
        }
        for (const char* own : {"--report", "--pairs-out"}) {
            if (option == own || option.rfind(std::string(own) + "=", 0) == 0) {
                throw InputError(std::string(own) + " is the study's own: the report comes back as a RunResult");
            }
        }
    }
}

}  // namespace

std::string find_cdvp() {
    if (const char* env = std::getenv("CDVP_BINARY"); env != nullptr && env[0] != '\0') {
        if (!executable(env)) throw InputError("$CDVP_BINARY (" + excerpt(env) + ") is not an executable file");
        return env;
    }
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error && executable(self.parent_path() / "cdvp")) return (self.parent_path() / "cdvp").string();
    if (const std::optional<std::string> found = find_program("cdvp")) return *found;
    throw InputError("no cdvp to run: set $CDVP_BINARY, or put the installed PREFIX/bin on PATH");
}

RunResult run_configuration(const RunRequest& request) {
    check_options(request.options);
    ScratchFile report(".json"), pairs(".csv");
    CapturedOutput errors("cdvp-run-stderr");
    std::vector<std::string> args{request.cdvp_binary.empty() ? find_cdvp() : request.cdvp_binary, "run"};
    args.insert(args.end(), request.options.begin(), request.options.end());
    args.insert(args.end(), {"--report", report.path(), "-q"});
    if (request.pairs) args.insert(args.end(), {"--pairs-out", pairs.path()});
    ChildStreams streams;
    streams.err = errors.fd();
    const int wait_status = run_child(args, streams);
    if (WIFSIGNALED(wait_status)) {
        throw RunFailed(kExitInternal, "cdvp run: killed by signal " + std::to_string(WTERMSIG(wait_status)));
    }
    if (const int status = WEXITSTATUS(wait_status); status != kExitDone) {
        const std::string text = errors.text(64 * 1024);
        throw RunFailed(status, text.substr(0, text.find('\n')));
    }
    RunResult result;
    result.report = nlohmann::json::parse(slurp(report.path()));
    result.summary = summary_from_json(result.report.at("summary"), "the run's report");
    if (request.pairs) result.pairs_csv = slurp(pairs.path());
    return result;
}

}  // namespace cdvp
