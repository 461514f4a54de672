// _cdvp: the C++ half of the Python module cdvp (docs/python.md). Keyword
// arguments become the run layer's typed RunSpec and SweepSpec
// (keywords.h), never command-line words; the presets, one run and one
// sweep come back to Python as JSON text and plain values, which the package
// (cdvp/__init__.py) makes Python objects. A run at the analytic level runs
// in this process; any other level in a `cdvp run` child (SystemC
// elaborates a design once a process), as do a sweep's points but its
// analytic ones.
//
// A good citizen of the interpreter: cdvp's signal handlers are in place
// only while a call works (HandlersInstalled), Python's own Ctrl-C handler
// is never replaced but by a sweep's stop handler for the sweep's length,
// and a Ctrl-C during a call is raised as KeyboardInterrupt: between the
// frames of a run in this process, else when the call returns.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <csignal>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "platform/settings/board_preset.h"
#include "sw/output/output_cleanup.h"
#include "sw/python/keywords.h"
#include "sw/run/exit_codes.h"
#include "sw/run/run.h"
#include "sw/run/run_budgets.h"
#include "sw/study/child_runs.h"
#include "sw/study/study_run.h"
#include "sw/study/sweep.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_manifest.h"
#include "sw/study/sweep_merge.h"
#include "sw/study/sweep_state.h"
#include "sw/study/sweep_table.h"

namespace py = pybind11;

namespace cdvp {

namespace {

// A call that ended as the command would have ended: its exit status and its
// one line. The translator below raises it as cdvp's exception of that status.
struct Refusal {
    int status;
    std::string message;
};

// A Ctrl-C (or another signal Python handles) that arrived while cdvp
// worked: raised now, before anything else the call would return or raise.
void raise_pending_signals() {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

// Runs body with cdvp's signal handlers in place and turns whatever C++
// throws into a Refusal under `program`'s name, so that no C++ exception
// reaches the interpreter. A Python exception (a TypeError of a keyword, a
// progress callback's) passes through as it is.
template <typename Body>
auto as_call(const std::string& program, Body&& body) -> decltype(body()) {
    try {
        const HandlersInstalled handlers;
        auto result = body();
        raise_pending_signals();
        return result;
    } catch (const py::error_already_set&) {
        throw;
    } catch (const py::builtin_exception&) {
        throw;
    } catch (const RunFailed& e) {
        raise_pending_signals();
        throw Refusal{e.status(), renamed_message(e.what(), program)};
    } catch (const std::exception&) {
        raise_pending_signals();
        const Failure failure = failure_of_current_exception();
        throw Refusal{failure.status, program + ": " + failure.message};
    }
}

std::string presets_json() {
    return as_call("cdvp.presets", [] {
        nlohmann::json all = nlohmann::json::array();
        for (const std::string& name : board_preset_names()) {
            const BoardPreset preset = load_board_preset(name);
            nlohmann::json values = nlohmann::json::object();
            for (const Assignment& assignment : preset.values) values[assignment.setting->name] = to_json(assignment.value);
            all.push_back({{"name", name}, {"description", preset.description}, {"path", preset.path}, {"values", values}});
        }
        return all.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    });
}

// Between the frames of a run in this process, Python's signal handlers
// run (the GIL taken for it): a Ctrl-C's KeyboardInterrupt, or whatever a
// handler of the user's raises, stops the run there and is raised by run().
class SignalsBetweenFrames : public RunObserver {
public:
    struct Stopped : std::runtime_error {
        Stopped() : std::runtime_error("stopped by a Python exception raised by a signal handler") {}
    };
    void frame_done(std::size_t, std::size_t) override {
        if (raised_) return;
        py::gil_scoped_acquire locked;
        if (PyErr_CheckSignals() == 0) return;
        raised_ = std::make_unique<py::error_already_set>();
        throw Stopped();
    }
    void rethrow_any() {
        if (raised_) throw *raised_;
    }

private:
    std::unique_ptr<py::error_already_set> raised_;
};

// One run: (the report as JSON text, its summary as JSON text, the pairs CSV or "").
py::tuple run_keywords(const py::dict& keywords, const py::object& settings, bool pairs, const std::string& cdvp_binary) {
    SignalsBetweenFrames signals;
    RunResult result = as_call("cdvp.run", [&] {
        RunRequest request{run_spec_of(keywords, settings, "cdvp.run"), pairs, cdvp_binary, true, true, &signals};
        try {
            py::gil_scoped_release unlocked;
            return run_configuration(request);
        } catch (const RunFailed&) {
            signals.rethrow_any();
            throw;
        }
    });
    const auto text = [](const nlohmann::json& json) { return json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); };
    return py::make_tuple(text(result.report), text(to_json(result.summary)), py::bytes(result.pairs_csv));
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

// One sweep at a time a process: the sweep waits for any child and keeps its
// points in process-wide state, so one started from another's progress
// callback (or another thread) is refused.
std::atomic<bool> g_sweeping{false};

class OneSweep {
public:
    OneSweep() {
        if (g_sweeping.exchange(true)) {
            throw InputError("another sweep is running in this process (this one was started from its progress "
                             "callback or another thread); start it after that one returns");
        }
    }
    ~OneSweep() { g_sweeping = false; }
    OneSweep(const OneSweep&) = delete;
    OneSweep& operator=(const OneSweep&) = delete;
};

// The sweep's outcome as a dict.
py::dict sweep_keywords(const py::dict& axes, const py::dict& own, const py::dict& keywords, const py::object& settings,
               const std::string& cdvp_binary, py::object progress) {
    ProgressCallback observer(std::move(progress));
    const SweepOutcome outcome = as_call("cdvp.sweep", [&] {
        const OneSweep only;
        SweepSpec spec = sweep_spec_of(axes, own, keywords, settings);
        spec.trace_limits = spooled_trace_limits();
        spec.cdvp_binary = cdvp_binary;
        py::gil_scoped_release unlocked;
        return run_sweep(spec, &observer);
    });
    observer.rethrow_any();
    py::dict result;
    result["status"] = outcome.status;
    result["points"] = outcome.points;
    result["ok"] = outcome.ok;
    result["refused"] = outcome.refused;
    result["faulted"] = outcome.faulted;
    result["failed"] = outcome.failed;
    result["run_now"] = outcome.run_now;
    result["stop_signal"] = sweep_stop_signal();
    return result;
}

// A sweep's OUT made ready for its points to be spread over an executor's
// tasks (cdvp/_spread.py), checked as a resume checks it: {"points": the
// grid's, "held": the indices OUT holds, "began_now": OUT held no sweep}.
py::dict prepare_keywords(const py::dict& axes, const py::dict& own, const py::dict& keywords, const py::object& settings) {
    const PreparedSweep prepared = as_call("cdvp.sweep", [&] {
        const SweepSpec spec = sweep_spec_of(axes, own, keywords, settings);
        py::gil_scoped_release unlocked;
        return prepare_sweep(spec);
    });
    py::dict result;
    result["points"] = prepared.grid_points;
    result["held"] = prepared.held;
    result["began_now"] = prepared.began_now;
    return result;
}

// The tasks' directories gathered into OUT, as `cdvp merge` gathers shards
// (one transaction): 0, or 1 when gnuplot failed and OUT was left as it was.
int merge_tasks(const std::string& out, const std::vector<std::string>& tasks, bool plots, bool quiet) {
    return as_call("cdvp.sweep", [&] {
        MergeSpec spec;
        spec.out = out;
        spec.shards = tasks;
        spec.plots = plots;
        spec.quiet = quiet;
        spec.program = "cdvp.sweep";
        py::gil_scoped_release unlocked;
        return merge_sweeps(spec).status;
    });
}

// The point indices a task's directory holds (none: no sweep there), every
// row checked against its grid, shard and report as a merge checks it: what
// the client counts a task by, whatever the task returned.
std::vector<std::size_t> task_rows(const std::string& dir) {
    return as_call("cdvp.sweep", [&] {
        std::vector<std::size_t> indices;
        const std::optional<Manifest> manifest = read_manifest(manifest_path(dir));
        if (!manifest) return indices;
        const Grid grid(manifest->axes);
        SweepTable table(grid);
        read_table(dir, grid, manifest->shard, table, false, manifest->record);
        table.for_each([&](std::size_t index, const RowView&) { indices.push_back(index); });
        return indices;
    });
}

}  // namespace

}  // namespace cdvp

PYBIND11_MODULE(_cdvp, module) {
    module.doc() = "The C++ half of cdvp: presets, runs and sweeps from typed keywords (docs/python.md).";
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const cdvp::Refusal& refusal) {
            const py::object error_class = py::module_::import("cdvp._errors").attr("error_class")(refusal.status);
            // A name of no UTF-8 in the message (a file's, a value's) by its escapes (\xe9), never a UnicodeDecodeError.
            const std::string& text = refusal.message;
            PyObject* message = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "backslashreplace");
            if (message == nullptr) return;  // no memory: that error stays raised
            const py::tuple arguments = py::make_tuple(py::reinterpret_steal<py::str>(message), refusal.status);
            PyErr_SetObject(error_class.ptr(), arguments.ptr());
        }
    });
    module.def("presets_json", &cdvp::presets_json, "Every board preset: name, description, path, values.");
    module.def("boards_directory", &cdvp::boards_directory, "Where the presets are read.");
    module.def("run", &cdvp::run_keywords, py::arg("keywords"), py::arg("settings"), py::arg("pairs"), py::arg("cdvp_binary"),
               "One run, in this process at the analytic level, else in a child: (report JSON, summary JSON, pairs CSV bytes).");
    module.def("sweep", &cdvp::sweep_keywords, py::arg("axes"), py::arg("own"), py::arg("keywords"), py::arg("settings"),
               py::arg("cdvp_binary"), py::arg("progress"),
               "One sweep in this process, its points children but the analytic ones: the outcome as a dict.");
    module.def("sweep_prepare", &cdvp::prepare_keywords, py::arg("axes"), py::arg("own"), py::arg("keywords"),
               py::arg("settings"), "A sweep's out made ready for tasks, checked as a resume: points, held, began_now.");
    module.def("merge", &cdvp::merge_tasks, py::arg("out"), py::arg("tasks"), py::arg("plots"), py::arg("quiet"),
               "The tasks' directories merged into out in one transaction: 0, or 1 when gnuplot failed.");
    module.def("task_rows", &cdvp::task_rows, py::arg("directory"),
               "The point indices a task's directory holds, every row checked as a merge checks it.");
}
