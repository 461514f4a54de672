#include "sw/study/study_run.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/run/exit_codes.h"
#include "sw/run/run.h"
#include "sw/run/run_arguments.h"

namespace cdvp {

namespace {

bool executable(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error) && access(path.c_str(), X_OK) == 0;
}

// Outputs a request may not name: where the report and pairs go is the study's.
void check_outputs(const RunSpec& spec) {
    if (spec.outputs.report || spec.outputs.pairs_csv || spec.outputs.waves) {
        throw InputError("the report, the pairs and the waveforms of a study's run are the study's own: the report "
                         "comes back as a RunResult");
    }
}

// The run in a child: its exit status, and its stderr's first line.
void run_child_configuration(const RunRequest& request, const RunSpec& spec) {
    CapturedOutput errors("cdvp-run-stderr");
    std::vector<std::string> args{request.cdvp_binary.empty() ? find_cdvp() : request.cdvp_binary, command_of(spec)};
    for (std::string& word : to_arguments(spec)) args.push_back(std::move(word));
    ChildStreams streams;
    streams.err = errors.fd();
    const int wait_status = run_child(args, streams);
    const std::string program = std::string("cdvp ") + command_of(spec);
    if (WIFSIGNALED(wait_status)) {
        throw RunFailed(kExitInternal, program + ": killed by signal " + std::to_string(WTERMSIG(wait_status)));
    }
    if (const int status = WEXITSTATUS(wait_status); status != kExitDone) {
        const std::string text = errors.text(64 * 1024);
        throw RunFailed(status, text.substr(0, text.find('\n')));
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
    check_outputs(request.spec);
    ScratchFile report(".json"), pairs(".csv");
    RunSpec spec = request.spec;
    spec.outputs.report = report.path();
    if (request.pairs) spec.outputs.pairs_csv = pairs.path();
    spec.outputs.summary = false;
    bool ran = false;
    if (request.in_process) {
        RunObserver quiet;
        RunContext context;
        context.kernel_free = true;
        const RunOutcome outcome = run(spec, quiet, context);
        if (outcome.ran && outcome.status != kExitDone) {
            throw RunFailed(outcome.status, std::string("cdvp ") + command_of(spec) + ": " + outcome.message);
        }
        ran = outcome.ran;
    }
    if (!ran) run_child_configuration(request, spec);
    RunResult result;
    result.report = nlohmann::json::parse(slurp(report.path()));
    result.summary = summary_from_json(result.report.at("summary"), "the run's report");
    if (request.pairs) result.pairs_csv = slurp(pairs.path());
    return result;
}

}  // namespace cdvp
