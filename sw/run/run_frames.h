// Inside run(): a run's output files and what it simulates on, and the loop
// over its frames, shared by every kind of frame source (a trace, a
// generated scene, Bullet's worlds).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "sw/output/output_set.h"
#include "sw/run/baseline_timing.h"
#include "sw/run/frame_source.h"
#include "sw/run/run.h"
#include "sw/run/run_budgets.h"
#include "sw/run/run_setup.h"
#include "sw/run/shared_baselines.h"
#include "sw/run/wave_outputs.h"

namespace cdvp {

// The run's output files: one transaction (see OutputSet).
struct RunFiles {
    OutputSet files;
    OutputFile* pairs = nullptr;
    OutputFile* report = nullptr;
    WaveOutputs waves;  // the dump, its GTKWave save file and state names
};

// Declares the inputs (the trace, the preset, the config file) and the
// outputs and checks them together before any work; `level` (the setup's)
// says what the waveforms hold.
void open_run_files(const RunSpec& spec, ModelLevel level, RunFiles& out);

// What a run simulates on: the board, its bus and host from the settings,
// the software baselines to time beside it and the traced frames' window.
struct RunSetup : BoardSetup {
    BaselineTimer baselines;
    std::pair<uint64_t, uint64_t> trace_window{0, UINT64_MAX};
};

// A shape of the run for its budgets (its board is planned for each scene).
BudgetShape budget_shape(const RunSpec& spec, const RunSetup& setup);

struct FrameRun {
    const RunSpec& spec;
    FrameSource& source;
    RunSetup& setup;
    RunFiles& files;
    const RunBudgets& budgets;
    RunObserver& observer;
    const RunContext& context;
    SharedBaselines* shared = nullptr;  // a sweep's timing of this workload, if any
};

// Simulates every frame, checks its pairs against the float32 reference,
// times the baselines, writes the outputs and commits them: the outcome.
RunOutcome run_frames(FrameRun& run);

}  // namespace cdvp
