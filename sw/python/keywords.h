// Python's keyword arguments as the run layer's typed values: a RunSpec for
// cdvp.run and a SweepSpec for cdvp.sweep, built directly (no command-line
// words). A value of the wrong Python type raises TypeError naming its
// keyword; a value its setting refuses throws InputError naming it, in the
// module's words (python_names.h).
#pragma once

#include <string>

#include <pybind11/pybind11.h>

#include "sw/run/run_spec.h"
#include "sw/study/sweep.h"

namespace cdvp {

// keywords: cdvp.run's (board, scene, trace, config, baseline, inject,
// software_timings and every setting's keyword: m, objects, quantum_ns,
// ...); None leaves one out. settings: None or a dict of dotted setting
// name -> value. function: the caller's name for an unknown keyword's TypeError.
RunSpec run_spec_of(const pybind11::dict& keywords, const pybind11::handle& settings, const std::string& function);

// axes: name -> a list of values or the command line's list text ("50:800:x2");
// own: the sweep's own keywords (out, jobs, shard, record, software_timings,
// plots, quiet, rerun_invalid); keywords and settings: each point's, as for
// run_spec_of, where board, scene, trace and fidelity are axes of one value
// or of a list's.
SweepSpec sweep_spec_of(const pybind11::dict& axes, const pybind11::dict& own, const pybind11::dict& keywords,
                        const pybind11::handle& settings);

}  // namespace cdvp
