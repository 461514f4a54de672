// A sweep directory's rows, checked rather than trusted, and the table file
// they are appended to. Every row read back is held to the grid (its index,
// point id and axis values), to the shard, to a known status and to its
// checksum over the row and the point's report; a row that does not match is
// refused naming the file, line and field, or, when asked, left out to be run
// again. Rows are appended one at a time and synced, so a sweep's own cost per
// point does not grow with the points done.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_manifest.h"
#include "sw/study/sweep_table.h"

namespace cdvp {

// DIR/sweep.json, DIR/sweep.csv, DIR/points and a point's report there.
std::string manifest_path(const std::string& dir);
std::string table_path(const std::string& dir);
std::string points_dir(const std::string& dir);
std::string report_path(const std::string& dir, const Point& point);
// DIR/software: where a sweep's points share their software timings unless told otherwise.
std::string software_timings_dir(const std::string& dir);

// The names in DIR but its lock file: what makes it not empty.
std::vector<std::string> directory_contents(const std::string& dir);

// What reading a directory's table found.
struct TableRead {
    std::vector<std::string> invalid;  // rows left out (with keep_going), one line each: FILE:LINE: why
    bool torn = false;                  // the last row was cut short (a killed sweep): left out
    bool rewrite = false;               // the file must be written again before rows are appended
                                        // (torn, rows left out, or rows out of point order)
};

// Reads DIR/sweep.csv (nothing when there is none) into 'table', checking
// every row of this grid and shard against it and, for a point that ran in
// a full record, against DIR/points/ID.json (a compact row's checksum is
// over the row alone). A row that does not match throws InputError
// naming the file, line and field, unless 'keep_going', which leaves it out
// (and its report: the point runs again).
TableRead read_table(const std::string& dir, const Grid& grid, const Shard& shard, SweepTable& table,
                     bool keep_going, RecordMode record = RecordMode::kFull);

// sweep.csv open for appending: one row at a time, synced; the whole file is
// written again (temporary, synced, renamed) only when the columns change or
// the rows must be put back in point order. Write failures throw
// SystemError (a full disk, an I/O error) or InputError, with the system's
// own error text.
class TableFile {
public:
    // 'table' holds the rows the file has; with 'rewrite', or when the file
    // is not there, it is written whole first.
    TableFile(std::string path, const SweepTable& table, bool rewrite);
    ~TableFile();
    TableFile(const TableFile&) = delete;
    TableFile& operator=(const TableFile&) = delete;

    // The row of 'index', just added to 'table'.
    // Synced unless `sync_now` is false (rows of points run in process come fast:
    // kept and written together, up to kPendingBytes, and synced by sync() at
    // most every few hundred milliseconds and at the end; rows a crash loses
    // are run again on resume).
    void append(const SweepTable& table, std::size_t index, bool sync_now = true);
    // Writes the rows kept, then syncs the file.
    void sync();
    // The whole table in point order, when anything was appended out of it.
    void finish(const SweepTable& table);

private:
    static constexpr std::size_t kPendingBytes = 64 * 1024;
    void rewrite(const SweepTable& table);
    void write_pending();

    std::string path_;
    std::string header_;  // the header line the file has
    std::size_t header_columns_ = 0;  // and its columns
    int fd_ = -1;
    std::size_t last_index_ = 0;
    bool in_order_ = true;  // the file's rows are in point order
    bool any_ = false;
    std::string pending_;  // appended rows not yet written
};

}  // namespace cdvp
