// The table of `cdvp sweep`: one row per point, built from the point's
// report (or its refusal), kept compactly in memory and written as
// sweep.csv. Plain C++, no processes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/study/sweep_grid.h"

namespace cdvp {

// The version of a sweep's files: its manifest's "format_version" and every
// row's format_version column (share/cdvp/schema/sweep-row.schema.json);
// raised when a column or field is renamed, removed or changes meaning. A
// resume or merge refuses a sweep of another version. 3: the first with the
// field (the manifest said "cdvp sweep 2" before).
constexpr uint64_t kSweepFormatVersion = 3;

using Row = std::map<std::string, std::string>;  // column -> value, for one row being built or checked

// Outcome of a point, as its child ended: ok (0), refused (2), fault (3).
// kFailed: cdvp failed inside (a bug, or a point killed by a signal); its
// row keeps the reason and the sweep goes on.
enum class PointStatus { kOk, kRefused, kFault, kFailed };
const char* to_string(PointStatus status);
std::optional<PointStatus> parse_point_status(const std::string& text);

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
// when it has them, else medians of the frames and their ratio), the child's
// wall time (point_wall_s) and the row's checksum over all of it and the
// report's bytes.
PointRow report_row(const Grid& grid, const Point& point, const std::string& report_text, double wall_seconds);
// The compact row of a point that ran (`cdvp sweep --record compact`): the
// axes, report_frames, frames_in_medians, the medians of the pairs, cycles,
// stalls, pauses, bytes and phases, the total's mean, p99 and maximum, each
// baseline's mean host time and speedup, computed as report_row computes
// them (so equal to the full row's same columns), and the wall time; its
// checksum is over the row alone. 'report' needs "frames" and "summary"
// only.
PointRow compact_row(const Grid& grid, const Point& point, const nlohmann::json& report, double wall_seconds);
// The row of a point refused or faulted: the axes, the child's reason, its
// wall time and the checksum.
PointRow failed_row(const Grid& grid, const Point& point, PointStatus status, const std::string& reason,
                    double wall_seconds);

// The "checksum" column: the first 16 hex digits of the SHA-256 of the row's
// other non-empty fields (by column name, so neither the columns' order nor
// empty columns count) and, for a point that ran, of its report's SHA-256
// (hex). A resume or merge recomputes it: an edited row or report does not
// match.
constexpr const char* kChecksumColumn = "checksum";
std::string row_checksum(const Row& row, const std::string* report_sha256);

// Columns whose values are measured, so differ from run to run: wall times,
// baseline times and speedups, and the checksum over them.
bool is_measured_column(const std::string& column);

class SweepTable;

// One stored row, read by column name.
class RowView {
public:
    RowView() = default;
    RowView(const SweepTable& table, const std::string& packed) : table_(&table), packed_(&packed) {}
    // The value, "" when the row has none.
    std::string get(const std::string& column) const;

private:
    const SweepTable* table_ = nullptr;
    const std::string* packed_ = nullptr;
};

// Rows by point index, and the columns in a stable order: point, index,
// status, reason, checksum, the axes in grid order, then the report's
// columns in the order first seen (settings, counts and phases), measured
// columns last. Each row is stored as its fields packed in one string (a
// row costs about its CSV line), so a sweep of 100,000 points stays small.
class SweepTable {
public:
    explicit SweepTable(const Grid& grid);

    // Adds (or replaces) the point's row; true when it brought new columns.
    bool add(std::size_t index, const PointRow& row);
    void erase(std::size_t index) { rows_.erase(index); }
    // Columns in this order, where the table does not have them yet (the
    // header of a file read back).
    void add_columns(const std::vector<std::string>& columns) {
        for (const std::string& column : columns) add_column(column);
    }
    bool has(std::size_t index) const { return rows_.count(index) != 0; }
    std::size_t size() const { return rows_.size(); }
    const std::vector<std::string>& columns() const { return columns_; }
    RowView row(std::size_t index) const { return RowView(*this, rows_.at(index)); }
    // Each row by index, in index order.
    template <class Visit>
    void for_each(Visit visit) const {
        for (const auto& [index, packed] : rows_) visit(index, RowView(*this, packed));
    }
    // The row as a PointRow, for another table of the same grid.
    PointRow point_row(std::size_t index) const;

    // RFC 4180 lines: the header, one row's line, and the whole table (the
    // header, then the rows by index); each line ends in '\n'.
    std::string header_line() const;
    std::string line(std::size_t index) const;
    std::string csv() const;

private:
    friend class RowView;
    uint32_t column_id(const std::string& column);
    void add_column(const std::string& column);
    // The packed row's values by column id.
    std::vector<std::string> unpack(const std::string& packed) const;

    std::vector<std::string> columns_;                  // in output order
    std::vector<std::string> names_;                    // by column id
    std::unordered_map<std::string, uint32_t> ids_;     // name -> column id
    std::map<std::size_t, std::string> rows_;           // index -> (id, value) pairs packed
};

}  // namespace cdvp
