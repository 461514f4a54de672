// The files of a sweep directory, shared by `cdvp sweep` and `cdvp merge`:
// sweep.json (what the sweep is), sweep.csv (its rows), points/ (each
// point's report) and the figures.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/cli/sweep_grid.h"
#include "sw/cli/sweep_table.h"

namespace cdvp {

// DIR/sweep.json, DIR/sweep.csv, DIR/points and a point's report there.
std::string manifest_path(const std::string& dir);
std::string table_path(const std::string& dir);
std::string points_dir(const std::string& dir);
std::string report_path(const std::string& dir, const Point& point);

// The directory's sweep.json, or nothing when it has none; throws
// InputError when it cannot be read as one.
std::optional<nlohmann::json> read_manifest(const std::string& dir);
// Two manifests of the same grid and options (their shards aside).
bool same_sweep(const nlohmann::json& a, const nlohmann::json& b);
// The grid and the options passed on to every point, as a manifest holds them.
Grid manifest_grid(const nlohmann::json& manifest);
std::vector<std::string> manifest_run_options(const nlohmann::json& manifest);

// Reads DIR/sweep.csv into 'table' (nothing when there is none).
void read_table(const std::string& dir, SweepTable& table);

// Draws the figures the table supports into 'dir' (one gnuplot run, all
// committed together) and prints why any were skipped on stderr unless
// 'quiet'. Returns the exit status: 0, or 1 when gnuplot fails.
int write_figures(const std::string& dir, const Grid& grid, const SweepTable& table, const std::string& program,
                  bool quiet);

}  // namespace cdvp
