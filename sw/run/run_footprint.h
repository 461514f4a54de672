// What a run of cdvp run holds in memory at its peak, estimated before any
// work from what the run is: its largest frame's boxes, its frames, and the
// bytes each pair of a frame costs on its way through the run. The figures
// are the sizes of the structures that hold them (sizeof where the code
// decides them, measured where a library does), so the estimate follows the
// code; tests/cli/cli_budget_test.cpp holds it above the peak RSS of runs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "models/board_spec/board_config.h"

namespace cdvp {

// What decides a run's memory besides its boxes, frames and pairs.
struct BudgetShape {
    bool trace = false;         // frames from a trace (else the spheres application or a Bullet scene)
    uint32_t bullet_worlds = 0; // Bullet worlds stepped beside the board (a Bullet scene's)
    bool clocked = false;       // the clocked engine (its block RAM words are kept)
    bool pairs_out = false;     // --pairs-out: the pairs by id, sorted
    std::vector<std::string> baselines;
    uint32_t repeat = 1;        // baseline runs
    BoardConfig board;          // as planned for the scene: format, m, tiles, pair buffer
};

// Bytes, by part.
struct Footprint {
    uint64_t program = 0;   // the program, SystemC and libraries, and what a pair buffer sizes
    uint64_t boxes = 0;     // what the largest frame's boxes size: scene, board, engine, baselines
    uint64_t model = 0;     // the clocked board's block RAM words and SSRAM, a tiled board's schedule
    uint64_t frames = 0;    // what each frame leaves: timing samples, a trace's digests
    uint64_t per_pair = 0;  // what one pair of a frame costs, everywhere it is held

    uint64_t before_pairs() const { return program + boxes + model + frames; }
    // With `pairs` pairs in a frame (saturating: no wrap for huge budgets).
    uint64_t with_pairs(uint64_t pairs) const;
};

Footprint estimate_footprint(const BudgetShape& shape, uint64_t objects, uint64_t frames);

// The parts of the estimate that grow with a frame's boxes and with the
// number of frames: before a trace is read, they bound how many of each the
// reader may take (the board model aside, which the full estimate adds).
uint64_t bytes_per_box(const BudgetShape& shape);
uint64_t bytes_per_frame(const BudgetShape& shape);
uint64_t program_bytes(const BudgetShape& shape);

}  // namespace cdvp
