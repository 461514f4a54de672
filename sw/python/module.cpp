// _cdvp: the C++ half of the Python module cdvp (docs/python.md). It hands
// the settings table, the presets, one run and one sweep to Python as JSON
// text and plain values; the package (cdvp/__init__.py) makes them Python
// objects. Every simulation is a `cdvp run` child (the study library), so no
// SystemC kernel ever elaborates in the Python process.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <boost/program_options/errors.hpp>

#include <exception>
#include <functional>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "platform/settings/board_preset.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/run_command.h"
#include "sw/run/run_budgets.h"
#include "sw/cli/settings_command.h"
#include "sw/cli/sweep_options.h"
#include "sw/run/exit_codes.h"
#include "sw/study/study_run.h"
#include "sw/study/sweep.h"

namespace py = pybind11;

namespace cdvp {

namespace {

// A call that ended as the command would have ended: its exit status and its
// one line. The translator below raises it as cdvp's exception of that status.
struct Refusal {
    int status;
    std::string message;
};

// Runs body and turns whatever C++ throws into a Refusal worded as
// exit_status_of and run_command_line word it, so that no C++ exception
// reaches the interpreter (where it would abort). A Python exception raised
// inside (a progress callback's) passes through as it is.
template <typename Body>
auto as_command(const std::string& program, Body&& body) -> decltype(body()) {
    try {
        return body();
    } catch (const py::error_already_set&) {
        throw;
    } catch (const RunFailed& e) {
        throw Refusal{e.status(), e.what()};
    } catch (const boost::program_options::error& e) {
        throw Refusal{kExitBadInput, program + ": " + printable(e.what()) + " (see " + program + " --help)"};
    } catch (const std::exception&) {
        const CommandFailure failure = failure_of_current_exception(program);
        throw Refusal{failure.status, failure.line};
    }
}

std::string presets_json() {
    return as_command("cdvp presets", [] {
        nlohmann::json all = nlohmann::json::array();
        for (const std::string& name : board_preset_names()) {
            const BoardPreset preset = load_board_preset(name);
            nlohmann::json values = nlohmann::json::object();
            for (const Assignment& assignment : preset.values) values[assignment.setting->name] = to_json(assignment.value);
            all.push_back({{"name", name}, {"description", preset.description}, {"path", preset.path}, {"values", values}});
        }
        return all.dump();
    });
}

// One run: (the report as JSON text, its summary as JSON text, the pairs CSV or "").
py::tuple run(const std::vector<std::string>& options, bool pairs, const std::string& cdvp_binary) {
    RunResult result = as_command("cdvp run", [&] {
        std::vector<std::string> words{"run"};
        words.insert(words.end(), options.begin(), options.end());
        std::vector<char*> argv;
        for (std::string& word : words) argv.push_back(word.data());
        argv.push_back(nullptr);
        RunOptions parsed;
        const auto vm = parse_run_options(static_cast<int>(words.size()), argv.data(), parsed);
        RunRequest request{run_spec_of(parsed, vm), pairs, cdvp_binary, false};
        py::gil_scoped_release unlocked;
        return run_configuration(request);
    });
    return py::make_tuple(result.report.dump(), to_json(result.summary).dump(), py::bytes(result.pairs_csv));
}

// Calls a Python progress callable as (done, total) with the GIL held. The
// first exception it raises is kept for after the sweep (a sweep cannot be
// left halfway through its points) and silences it.
class ProgressCallback : public SweepObserver {
public:
    explicit ProgressCallback(py::object callback) : callback_(std::move(callback)) {}
    void started(std::size_t total, std::size_t done) override {
        total_ = total;
        done_ = done;
        report();
    }
    void point_done() override {
        ++done_;
        report();
    }
    void rethrow_any() {
        if (failure_) std::rethrow_exception(failure_);
    }

private:
    void report() {
        if (callback_.is_none() || failure_) return;
        py::gil_scoped_acquire locked;
        try {
            callback_(done_, total_);
        } catch (py::error_already_set&) {
            failure_ = std::current_exception();
        }
    }

    py::object callback_;
    std::size_t total_ = 0, done_ = 0;
    std::exception_ptr failure_;
};

// argv: cdvp sweep's arguments after "sweep". Returns the outcome as a dict.
py::dict sweep(const std::vector<std::string>& arguments, const std::string& cdvp_binary, py::object progress) {
    ProgressCallback observer(std::move(progress));
    const SweepOutcome outcome = as_command("cdvp sweep", [&] {
        std::vector<std::string> words{"sweep"};
        words.insert(words.end(), arguments.begin(), arguments.end());
        std::vector<char*> argv;
        for (std::string& word : words) argv.push_back(word.data());
        argv.push_back(nullptr);
        std::optional<SweepSpec> spec = parse_sweep_options(static_cast<int>(words.size()), argv.data());
        if (!spec) throw InputError("--help is the command's: see help(cdvp.sweep)");
        spec->trace_limits = spooled_trace_limits();
        spec->cdvp_binary = cdvp_binary;
        py::gil_scoped_release unlocked;
        return run_sweep(*spec, &observer);
    });
    observer.rethrow_any();
    py::dict result;
    result["status"] = outcome.status;
    result["points"] = outcome.points;
    result["ok"] = outcome.ok;
    result["refused"] = outcome.refused;
    result["faulted"] = outcome.faulted;
    result["run_now"] = outcome.run_now;
    result["stop_signal"] = sweep_stop_signal();
    return result;
}

}  // namespace

}  // namespace cdvp

PYBIND11_MODULE(_cdvp, module) {
    module.doc() = "The C++ half of cdvp: the settings table, presets, runs and sweeps (docs/python.md).";
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const cdvp::Refusal& refusal) {
            const py::object error_class = py::module_::import("cdvp._errors").attr("error_class")(refusal.status);
            PyErr_SetObject(error_class.ptr(), py::make_tuple(refusal.message, refusal.status).ptr());
        }
    });
    module.def("settings_json", [] { return cdvp::as_command("cdvp settings", [] { return cdvp::settings_json().dump(); }); },
               "The settings table as cdvp settings --json gives it.");
    module.def("presets_json", &cdvp::presets_json, "Every board preset: name, description, path, values.");
    module.def("boards_directory", &cdvp::boards_directory, "Where the presets are read.");
    module.def("run", &cdvp::run, py::arg("options"), py::arg("pairs"), py::arg("cdvp_binary"),
               "One cdvp run in a child: (report JSON, summary JSON, pairs CSV bytes).");
    module.def("sweep", &cdvp::sweep, py::arg("arguments"), py::arg("cdvp_binary"), py::arg("progress"),
               "One cdvp sweep in this process, its points children: the outcome as a dict.");
}
