#include "sw/study/sweep_state.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/output/digest.h"
#include "sw/study/directory_lock.h"
#include "sw/study/sweep_csv.h"

namespace cdvp {

std::string manifest_path(const std::string& dir) { return dir + "/sweep.json"; }
std::string table_path(const std::string& dir) { return dir + "/sweep.csv"; }
std::string points_dir(const std::string& dir) { return dir + "/points"; }
std::string report_path(const std::string& dir, const Point& point) {
    return points_dir(dir) + "/" + point.id + ".json";
}

namespace {

bool exists(const std::string& path) {
    struct stat status {};
    return lstat(path.c_str(), &status) == 0;
}

std::string quoted(const std::string& value) { return "'" + excerpt(value) + "'"; }

// What is wrong with one row of the table ("field 'm': ..."), or nothing.
class RowCheck {
public:
    RowCheck(const std::string& dir, const Grid& grid, const Shard& shard, RecordMode record)
        : dir_(dir), grid_(grid), shard_(shard), record_(record) {}

    // The row's index once it is known to be one of the grid's.
    std::optional<std::string> problem(const Row& row, std::size_t& index) const {
        const std::string index_text = value(row, "index");
        if (index_text.empty() || index_text.size() > 9 || index_text.find_first_not_of("0123456789") != std::string::npos) {
            return "field 'index': expected a point's number, got " + quoted(index_text);
        }
        index = std::stoul(index_text);
        if (index >= grid_.size()) {
            return "field 'index': " + index_text + " is not a point of this grid (0 to " +
                   std::to_string(grid_.size() - 1) + ")";
        }
        if (!shard_.runs(index)) return "field 'index': point " + index_text + " is not in shard " + shard_.text();
        const Point point = grid_.point(index);
        if (value(row, "point") != point.id) {
            return "field 'point': expected " + quoted(point.id) + " (point " + index_text + "), got " +
                   quoted(value(row, "point"));
        }
        for (std::size_t a = 0; a < grid_.axes().size(); ++a) {
            const std::string& name = grid_.axes()[a].name;
            if (value(row, name) != point.values[a]) {
                return "field '" + excerpt(name) + "': expected " + quoted(point.values[a]) + " (point " + index_text +
                       "), got " + quoted(value(row, name));
            }
        }
        if (value(row, "format_version") != std::to_string(kSweepFormatVersion)) {
            return "field 'format_version': expected " + std::to_string(kSweepFormatVersion) +
                   " (a row of this cdvp version), got " + quoted(value(row, "format_version"));
        }
        const std::optional<PointStatus> status = parse_point_status(value(row, "status"));
        if (!status) return "field 'status': expected ok, refused or fault, got " + quoted(value(row, "status"));
        if (*status != PointStatus::kOk && value(row, "reason").empty()) {
            return "field 'reason': empty; a " + value(row, "status") + " point gives its reason";
        }
        std::optional<std::string> report;  // its digest
        if (*status == PointStatus::kOk && record_ == RecordMode::kFull) {
            const std::string path = report_path(dir_, point);
            struct stat status_of {};
            if (lstat(path.c_str(), &status_of) == 0 && !S_ISREG(status_of.st_mode)) {
                return "the point's report " + path_text(path) + " is not a regular file";
            }
            const std::optional<FileDigest> digest = digest_file(path);
            if (!digest) return "the point's report " + path_text(path) + " cannot be read: " + std::strerror(errno);
            report = digest->sha256;
        }
        if (value(row, kChecksumColumn) != row_checksum(row, report ? &*report : nullptr)) {
            return std::string("field 'checksum': does not match the row") + (report ? " and its report" : "") +
                   " (changed since the sweep wrote them)";
        }
        return std::nullopt;
    }

private:
    static std::string value(const Row& row, const std::string& column) {
        const auto at = row.find(column);
        return at == row.end() ? std::string() : at->second;
    }

    const std::string& dir_;
    const Grid& grid_;
    const Shard& shard_;
    RecordMode record_;
};

// The header must start with the grid's own columns, each once.
void check_header(const std::vector<std::string>& header, const SweepTable& fresh, const std::string& label) {
    const std::vector<std::string>& expected = fresh.columns();
    for (std::size_t c = 0; c < expected.size(); ++c) {
        if (c >= header.size() || header[c] != expected[c]) {
            throw InputError(label + ":1: expected the column '" + excerpt(expected[c]) + "' of this sweep's grid" +
                             (c < header.size() ? ", got '" + excerpt(header[c]) + "'" : std::string()));
        }
    }
    std::map<std::string, std::size_t> seen;
    for (const std::string& column : header) {
        if (column.empty()) throw InputError(label + ":1: an empty column name");
        if (!seen.emplace(column, 0).second) throw InputError(label + ":1: the column '" + excerpt(column) + "' is given twice");
    }
}

}  // namespace

std::string software_timings_dir(const std::string& dir) { return dir + "/software"; }

std::vector<std::string> directory_contents(const std::string& dir) {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
        const std::string name = entry.path().filename().string();
        if (name != DirectoryLock::kFileName) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

TableRead read_table(const std::string& dir, const Grid& grid, const Shard& shard, SweepTable& table,
                     bool keep_going, RecordMode record) {
    const std::string path = table_path(dir);
    const std::string label = path_text(path);
    TableRead result;
    if (!exists(path)) return result;
    struct stat status {};
    if (lstat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode)) {
        throw InputError(label + ": expected a regular file (the sweep's table)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw_os_error(label + ": cannot read", errno);
    CsvRecords records(in, label);
    std::vector<std::string> header;
    if (!records.next(header) || !records.complete()) {
        result.rewrite = true;  // empty, or cut short in its header: no row was ever in it
        return result;
    }
    check_header(header, SweepTable(grid), label);
    table.add_columns(header);
    const RowCheck check(dir, grid, shard, record);
    std::map<std::size_t, std::size_t> lines;  // index -> the line its row is on
    std::vector<std::size_t> conflicted;
    for (std::vector<std::string> fields; records.next(fields);) {
        if (!records.complete()) {
            result.torn = result.rewrite = true;  // a sweep killed while it appended this row
            break;
        }
        const std::string where = label + ":" + std::to_string(records.line()) + ": ";
        auto refuse = [&](const std::string& why) {
            if (!keep_going) throw InputError(where + why);
            result.invalid.push_back(where + why);
            result.rewrite = true;
        };
        if (fields.size() != header.size()) {
            refuse("expected " + std::to_string(header.size()) + " fields, got " + std::to_string(fields.size()));
            continue;
        }
        Row row;
        for (std::size_t c = 0; c < header.size(); ++c) {
            if (!fields[c].empty()) row[header[c]] = fields[c];
        }
        std::size_t index = 0;
        if (const std::optional<std::string> problem = check.problem(row, index)) {
            refuse(*problem);
            continue;
        }
        if (const auto first = lines.find(index); first != lines.end()) {
            refuse("field 'index': point " + std::to_string(index) + " is also on line " + std::to_string(first->second));
            conflicted.push_back(index);
            continue;
        }
        // Rows a killed sweep of several jobs appended as they finished: put
        // back in point order before anything is appended to them.
        if (!lines.empty() && index < lines.rbegin()->first) result.rewrite = true;
        lines.emplace(index, records.line());
        table.add(index, PointRow{{}, row});
    }
    for (std::size_t index : conflicted) table.erase(index);  // neither row is trusted: run it again
    return result;
}

TableFile::TableFile(std::string path, const SweepTable& table, bool rewrite_first) : path_(std::move(path)) {
    if (!rewrite_first && exists(path_)) {
        std::ifstream in(path_, std::ios::binary);
        std::string first;
        std::getline(in, first);
        header_ = first + "\n";
    }
    table.for_each([&](std::size_t index, const RowView&) { last_index_ = index; });
    if (header_ != table.header_line()) {
        rewrite(table);
        return;
    }
    header_columns_ = table.columns().size();
    fd_ = open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) throw_os_error("--out: " + path_text(path_) + ": cannot write", errno);
}

TableFile::~TableFile() {
    if (fd_ >= 0) {
        try {  // a sweep ended by an error keeps the rows it recorded
            write_pending();
        } catch (const std::exception&) {
        }
        close(fd_);
    }
}

void TableFile::rewrite(const SweepTable& table) {
    pending_.clear();  // the table holds them
    if (fd_ >= 0) close(fd_);
    fd_ = -1;
    commit_text_file(path_, table.csv(), "--out");
    header_ = table.header_line();
    header_columns_ = table.columns().size();
    in_order_ = true;
    fd_ = open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) throw_os_error("--out: " + path_text(path_) + ": cannot write", errno);
}

void TableFile::append(const SweepTable& table, std::size_t index, bool sync_now) {
    if (index < last_index_) in_order_ = false;
    last_index_ = std::max(last_index_, index);
    // A table only gains columns: as many as the header has, the same ones.
    if (table.columns().size() != header_columns_ && header_ != table.header_line()) {
        rewrite(table);  // new columns: every row gets them (the rows in point order again)
        return;
    }
    pending_ += table.line(index);
    // On disk before the next point starts: a crash keeps every row reported done.
    if (sync_now) {
        sync();
    } else if (pending_.size() >= kPendingBytes) {
        write_pending();
    }
}

void TableFile::write_pending() {
    for (std::size_t done = 0; done < pending_.size();) {
        const ssize_t put = write(fd_, pending_.data() + done, pending_.size() - done);
        if (put < 0 && errno == EINTR) continue;
        if (put < 0) throw_os_error("--out: " + path_text(path_) + ": cannot write", errno);
        done += static_cast<std::size_t>(put);
    }
    pending_.clear();
}

void TableFile::sync() {
    write_pending();
    if (fdatasync(fd_) != 0) throw_os_error("--out: " + path_text(path_) + ": cannot write", errno);
}

void TableFile::finish(const SweepTable& table) {
    if (!in_order_) {
        rewrite(table);
    } else {
        write_pending();
    }
}

}  // namespace cdvp
