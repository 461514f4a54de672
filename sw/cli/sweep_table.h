// The table of `cdvp sweep`: one row per point, built from the point's
// report (or its refusal), written as sweep.csv and read back for resuming
// and merging. Plain C++, no processes.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/cli/sweep_grid.h"

namespace cdvp {

using Row = std::map<std::string, std::string>;  // column -> value

// Outcome of a point, as its child ended: ok (0), refused (2), fault (3).
enum class PointStatus { kOk, kRefused, kFault };
const char* to_string(PointStatus status);

// A row, and the order in which its report gave its columns.
struct PointRow {
    std::vector<std::string> columns;
    Row values;
};

// The row of a point that ran: the axes, every effective setting of the
// report's "config" flattened ("config.NAME", nested keys joined by '.',
// arrays by '+'; its command_line left out), report_frames and
// frames_in_medians, then the median over the frames after the warm-up
// (summary.warmup_frames, else the first; at least one frame stays) of
// every number a report frame holds ("median_NAME"), each baseline's median
// time on the modelled host ("NAME_median_ns", with NAME_p10_ns and
// NAME_p90_ns) and its speedup over the board (from the report's summary
// when it has them, else medians of the frames and their ratio), and the
// child's wall time (point_wall_s).
PointRow report_row(const Grid& grid, const Point& point, const nlohmann::json& report, double wall_seconds);
// The row of a point refused or faulted: the axes, the child's reason and
// its wall time.
PointRow failed_row(const Grid& grid, const Point& point, PointStatus status, const std::string& reason,
                    double wall_seconds);

// Columns whose values are measured, so differ from run to run: wall times,
// baseline times and speedups.
bool is_timing_column(const std::string& column);

// Rows by point index, and the columns in a stable order: point, index,
// status, reason, the axes in grid order, then the report's columns in the
// order first seen (settings, counts and phases, baselines, wall times).
class SweepTable {
public:
    explicit SweepTable(const Grid& grid);

    void add(std::size_t index, const PointRow& row);
    bool has(std::size_t index) const { return rows_.count(index) != 0; }
    const std::map<std::size_t, Row>& rows() const { return rows_; }
    const std::vector<std::string>& columns() const { return columns_; }

    // RFC 4180 text, a header line, then one line per row by index.
    std::string csv() const;
    // Reads a sweep.csv back; throws InputError naming 'label' when it is
    // not one of this grid's (a header without its columns, a bad row).
    void read_csv(const std::string& text, const std::string& label);

private:
    void add_column(const std::string& column);
    void set_row(std::size_t index, Row row);

    std::vector<std::string> columns_;
    std::map<std::size_t, Row> rows_;
    // Each row's CSV line as last rendered, and the columns it was rendered
    // for: a sweep commits its CSV after every point, and re-rendering only
    // the new or re-columned rows keeps that linear in the points.
    struct Line {
        std::size_t columns_version = 0;
        std::string text;
    };
    mutable std::map<std::size_t, Line> lines_;
    std::size_t columns_version_ = 1;
};

// Splits RFC 4180 text into rows of fields (quoted fields may hold commas,
// quotes and line ends). Throws InputError naming 'label' on an unclosed quote.
std::vector<std::vector<std::string>> parse_csv(const std::string& text, const std::string& label);

// sweep.json: what the sweep is (axes, the options passed on to every
// point) and which shard of it a directory holds.
nlohmann::json manifest(const Grid& grid, const std::vector<std::string>& run_options, const Shard& shard);

}  // namespace cdvp
