#include "sw/study/sweep_table.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "models/common/user_text.h"
#include "sw/output/digest.h"
#include "sw/run/best_software.h"
#include "sw/run/report_summary.h"
#include "sw/study/figure_plan.h"
#include "sw/study/sweep_csv.h"

namespace cdvp {

namespace {

const std::vector<std::string> kFixedColumns{"point", "index", "status", "reason", kChecksumColumn, "format_version"};

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
}

std::string value_text(const nlohmann::json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_array()) {
        std::string joined;
        for (const auto& item : value) joined += (joined.empty() ? "" : "+") + value_text(item);
        return joined;
    }
    if (value.is_null()) return "";
    return value.dump();
}

void flatten(const nlohmann::json& value, const std::string& prefix, Row& row) {
    if (!value.is_object()) {
        row[prefix] = value_text(value);
        return;
    }
    for (const auto& [key, item] : value.items()) flatten(item, prefix + "." + key, row);
}

Row axis_row(const Grid& grid, const Point& point, PointStatus status, const std::string& reason) {
    Row row{{"point", point.id},
            {"index", std::to_string(point.index)},
            {"status", to_string(status)},
            {"reason", reason},
            {"format_version", std::to_string(kSweepFormatVersion)}};
    for (std::size_t a = 0; a < grid.axes().size(); ++a) row[grid.axes()[a].name] = point.values[a];
    return row;
}

void put_varint(std::string& out, std::size_t value) {
    while (value >= 0x80) {
        out += static_cast<char>((value & 0x7f) | 0x80);
        value >>= 7;
    }
    out += static_cast<char>(value);
}

std::size_t get_varint(const std::string& in, std::size_t& at) {
    std::size_t value = 0;
    for (unsigned shift = 0;; shift += 7) {
        const auto byte = static_cast<unsigned char>(in[at++]);
        value |= static_cast<std::size_t>(byte & 0x7f) << shift;
        if ((byte & 0x80) == 0) return value;
    }
}

// Visits the (column id, value) pairs of a packed row until 'visit' returns true.
template <class Visit>
void walk(const std::string& packed, Visit visit) {
    for (std::size_t at = 0; at < packed.size();) {
        const std::size_t id = get_varint(packed, at);
        const std::size_t size = get_varint(packed, at);
        if (visit(id, at, size)) return;
        at += size;
    }
}

}  // namespace

const char* to_string(PointStatus status) {
    switch (status) {
        case PointStatus::kOk: return "ok";
        case PointStatus::kRefused: return "refused";
        case PointStatus::kFault: return "fault";
        case PointStatus::kFailed: return "failed";
    }
    return "?";
}

std::optional<PointStatus> parse_point_status(const std::string& text) {
    for (PointStatus status : {PointStatus::kOk, PointStatus::kRefused, PointStatus::kFault, PointStatus::kFailed}) {
        if (text == to_string(status)) return status;
    }
    return std::nullopt;
}

std::string row_checksum(const Row& row, const std::string* report_sha256) {
    std::string fields;
    for (const auto& [column, value] : row) {
        if (column == kChecksumColumn || value.empty()) continue;
        fields += column;
        fields += '\0';
        fields += value;
        fields += '\0';
    }
    if (report_sha256 != nullptr) fields += *report_sha256;
    return sha256_hex(fields).substr(0, 16);
}

namespace {

// A row filled column by column, in the order the report first names each.
struct RowBuilder {
    Row row;
    std::vector<std::string> order;
    void put(const std::string& column, const std::string& value) {
        if (row.count(column) == 0) order.push_back(column);
        row[column] = value;
    }
};

void put_config(const nlohmann::json& report, RowBuilder& out) {
    for (const auto& [key, item] : report.at("config").items()) {
        // The point's own command line names its report's path, which differs
        // between shards of one sweep: the sweep's columns are its settings.
        if (key == "command_line") continue;
        Row one;
        flatten(item, "config." + key, one);
        for (const auto& [column, value] : one) out.put(column, value);
    }
}

// Which result columns a row keeps.
using ColumnFilter = bool (*)(const std::string& column);
bool every_column(const std::string&) { return true; }

// Medians over the frames from `first` on of every number a frame reports.
void put_frame_medians(const nlohmann::json& frames, std::size_t first, RowBuilder& out, ColumnFilter keep) {
    if (frames.empty()) return;
    for (const auto& [key, item] : frames[0].items()) {
        if (!item.is_number() || key == "frame" || !keep("median_" + key)) continue;
        std::vector<double> values;
        for (std::size_t k = first; k < frames.size(); ++k) values.push_back(frames[k].at(key).get<double>());
        out.put("median_" + key, number_text(median(values)));
    }
}

// The report's figures over the frames after the warm-up: the board's and
// the simulator's means, p50, p99 and maxima (simulated time plain, the
// simulator's _native_ns), and the load average at the end; none for a
// report of no frames, as no frame medians either.
void put_summary_figures(const nlohmann::json& summary, bool any_frame, RowBuilder& out, ColumnFilter keep) {
    for (const auto& [key, item] : summary.items()) {
        const bool figure = any_frame && (key.rfind("mean_", 0) == 0 || key.rfind("p50_", 0) == 0 ||
                                          key.rfind("p99_", 0) == 0 || key.rfind("max_", 0) == 0);
        if (figure && item.is_number() && keep(key)) out.put(key, number_text(item.get<double>()));
    }
    if (summary.contains("load_average_end") && keep("load_average_end")) {
        out.put("load_average_end", value_text(summary["load_average_end"]));
    }
}

// One baseline's figures on the modelled host, as the report summarises
// them over every --repeat run, under `name`.
void put_baseline(const std::string& name, const BaselineSummary& b, RowBuilder& out, ColumnFilter keep) {
    const std::pair<const char*, double> figures[] = {
        {"_mean_host_ns", b.host_ns.mean}, {"_p50_host_ns", b.host_ns.p50}, {"_p99_host_ns", b.host_ns.p99},
        {"_max_host_ns", b.host_ns.max},   {"_host_factor", b.host_factor}, {"_speedup", b.speedup},
        {"_energy_j", b.energy_j},         {"_energy_ratio", b.energy_ratio}};
    for (const auto& [suffix, value] : figures) {
        if (keep(name + suffix)) out.put(name + suffix, number_text(value));
    }
    // How far the figures can be trusted, and whose timing they are.
    const TimingQuality& q = b.quality;
    const std::pair<std::string, std::string> quality[] = {
        {"_timing_quality", q.verdict()},
        {"_timing_retimed", std::to_string(q.frames_retimed)},
        {"_timing_never_clean", std::to_string(q.never_clean)},
        {"_timing_repeat_spread", number_text(q.repeat_spread)},
        {"_timing_id", b.timing.empty() ? "own" : b.timing}};
    for (const auto& [suffix, value] : quality) {
        if (keep(name + suffix)) out.put(name + suffix, value);
    }
}

// Each baseline's figures; with more than one, the fastest's again as
// "best", and its name (the software each point's answer is held to).
void put_baselines(const ReportSummary& summary, RowBuilder& out, ColumnFilter keep) {
    for (const auto& [name, b] : summary.baselines) put_baseline(name, b, out, keep);
    if (summary.baselines.size() < 2 || summary.best_software.empty()) return;
    if (keep("best_baseline")) out.put("best_baseline", summary.best_software);
    put_baseline(kBestSoftware, summary.baselines.at(summary.best_software), out, keep);
}

// The figures of a report: its frame count, the medians over the frames after
// the warm-up, the summary's figures and each baseline's.
void put_results(const nlohmann::json& report, const Point& point, RowBuilder& out, ColumnFilter keep) {
    static const nlohmann::json kNoSummary = nlohmann::json::object();
    const auto& frames = report.at("frames");
    const auto at = report.find("summary");
    const nlohmann::json& summary = at != report.end() ? *at : kNoSummary;
    // Steady state: warm-up frames are left out (the incremental broad
    // phases build their structures in them): as many as the report says,
    // else the first; at least one frame stays.
    const std::size_t warmup = summary.value("warmup_frames", std::size_t{1});
    const std::size_t first = frames.size() > warmup ? warmup : frames.empty() ? 0 : frames.size() - 1;
    out.put("report_frames", std::to_string(frames.size()));
    out.put("frames_in_medians", std::to_string(frames.size() - first));
    if (summary.contains("too_few_frames")) out.put("too_few_frames", value_text(summary["too_few_frames"]));
    // A point run at a clock beyond its board's estimate (run.ignore_timing).
    if (summary.contains("timing_warning")) out.put("timing_warning", value_text(summary["timing_warning"]));
    put_frame_medians(frames, first, out, keep);
    put_summary_figures(summary, !frames.empty(), out, keep);
    if (!frames.empty()) put_baselines(summary_from_json(summary, "point " + point.id + "'s report"), out, keep);
}

// What a compact row keeps of a report's figures: the frame counts, the
// medians of the pairs, cycles, bytes and phases, the total's mean, p99 and
// maximum, and each baseline's mean on the modelled host and speedup.
bool is_compact_result(const std::string& column) {
    static const std::set<std::string> kept{
        "report_frames", "frames_in_medians", "too_few_frames", "timing_warning", "median_objects", "median_pairs",
        "median_reference_pairs", "median_extra_pairs", "median_sweep_cycles", "median_compute_cycles",
        "median_stall_cycles", "median_overflow_pauses", "median_boxes_sent", "median_upload_bytes",
        "median_readback_bytes", "median_upload_ns", "median_start_ns", "median_compute_ns", "median_irq_ns",
        "median_readback_ns", "median_driver_ns", "median_total_ns", "median_latency_ns", "mean_total_ns",
        "mean_energy_j", "mean_energy_static_j", "mean_energy_dynamic_j", "mean_energy_bus_j", "mean_energy_host_j",
        "mean_energy_per_pair_j",
        "p99_total_ns", "max_total_ns", "best_baseline"};
    return kept.count(column) != 0 || ends_with(column, "_mean_host_ns") || ends_with(column, "_speedup") ||
           ends_with(column, "_energy_j") || ends_with(column, "_energy_ratio") ||
           ends_with(column, "_timing_quality") || ends_with(column, "_timing_id");
}

}  // namespace

PointRow report_row(const Grid& grid, const Point& point, const std::string& report_text, double wall_seconds) {
    const nlohmann::json report = nlohmann::json::parse(report_text);
    RowBuilder out{axis_row(grid, point, PointStatus::kOk, ""), {}};
    put_config(report, out);
    put_results(report, point, out, every_column);
    out.put("point_wall_s", number_text(wall_seconds));
    const std::string report_sha256 = sha256_hex(report_text);
    out.row[kChecksumColumn] = row_checksum(out.row, &report_sha256);
    return {out.order, out.row};
}

PointRow compact_row(const Grid& grid, const Point& point, const nlohmann::json& report, double wall_seconds) {
    RowBuilder out{axis_row(grid, point, PointStatus::kOk, ""), {}};
    put_results(report, point, out, is_compact_result);
    out.put("point_wall_s", number_text(wall_seconds));
    out.row[kChecksumColumn] = row_checksum(out.row, nullptr);
    return {out.order, out.row};
}

PointRow failed_row(const Grid& grid, const Point& point, PointStatus status, const std::string& reason,
                    double wall_seconds) {
    Row row = axis_row(grid, point, status, reason);
    row["point_wall_s"] = number_text(wall_seconds);
    row[kChecksumColumn] = row_checksum(row, nullptr);
    return {{}, row};
}

// A baseline's energy (its host time x the host's power) and its ratio to
// the board's; the board's own energy (mean_energy_*, median_energy_*) is simulated.
bool is_baseline_energy_column(const std::string& column) {
    return (ends_with(column, "_energy_j") || ends_with(column, "_energy_ratio")) && column.rfind("mean_", 0) != 0 &&
           column.rfind("median_", 0) != 0;
}

// Measured: native times, modelled-host times (native x the host factor),
// speedups, the software's energy, and where and under what load they were taken.
bool is_measured_column(const std::string& column) {
    return column == "point_wall_s" || column == kChecksumColumn || column == "load_average_end" ||
           column.rfind("config.provenance.", 0) == 0 || column.rfind("config.budgets.", 0) == 0 ||
           ends_with(column, "_native_ns") || ends_with(column, "_host_ns") || ends_with(column, "_speedup") ||
           is_baseline_energy_column(column) || column.find("_timing_") != std::string::npos;
}

std::string RowView::get(const std::string& column) const {
    if (table_ == nullptr) return {};
    const auto id = table_->ids_.find(column);
    if (id == table_->ids_.end()) return {};
    std::string value;
    walk(*packed_, [&](std::size_t field, std::size_t at, std::size_t size) {
        if (field != id->second) return false;
        value = packed_->substr(at, size);
        return true;
    });
    return value;
}

SweepTable::SweepTable(const Grid& grid) {
    for (const std::string& column : kFixedColumns) add_column(column);
    for (const Axis& axis : grid.axes()) add_column(axis.name);
}

uint32_t SweepTable::column_id(const std::string& column) {
    add_column(column);
    return ids_.at(column);
}

void SweepTable::add_column(const std::string& column) {
    if (ids_.count(column) != 0) return;
    ids_.emplace(column, static_cast<uint32_t>(names_.size()));
    names_.push_back(column);
    // Measured columns go last, so the columns that must agree between runs
    // come first whatever order they are met in; the checksum stays with the
    // fixed columns.
    if (is_measured_column(column) && column != kChecksumColumn) {
        columns_.push_back(column);
        return;
    }
    auto at = std::find_if(columns_.begin(), columns_.end(),
                           [](const std::string& c) { return is_measured_column(c) && c != kChecksumColumn; });
    columns_.insert(at, column);
}

bool SweepTable::add(std::size_t index, const PointRow& row) {
    const std::size_t before = names_.size();
    for (const std::string& column : row.columns) add_column(column);
    std::string packed;
    for (const auto& [column, value] : row.values) {
        const uint32_t id = column_id(column);
        if (value.empty()) continue;
        put_varint(packed, id);
        put_varint(packed, value.size());
        packed += value;
    }
    rows_[index] = std::move(packed);
    return names_.size() != before;
}

std::vector<std::string> SweepTable::unpack(const std::string& packed) const {
    std::vector<std::string> values(names_.size());
    walk(packed, [&](std::size_t id, std::size_t at, std::size_t size) {
        values[id] = packed.substr(at, size);
        return false;
    });
    return values;
}

PointRow SweepTable::point_row(std::size_t index) const {
    PointRow row;
    const std::vector<std::string> values = unpack(rows_.at(index));
    for (const std::string& column : columns_) {
        row.columns.push_back(column);
        const std::string& value = values[ids_.at(column)];
        if (!value.empty()) row.values[column] = value;
    }
    return row;
}

std::string SweepTable::header_line() const {
    std::string text;
    for (std::size_t c = 0; c < columns_.size(); ++c) text += (c == 0 ? "" : ",") + csv_field(columns_[c]);
    return text + '\n';
}

std::string SweepTable::line(std::size_t index) const {
    const std::vector<std::string> values = unpack(rows_.at(index));
    std::string text;
    for (std::size_t c = 0; c < columns_.size(); ++c) {
        text += (c == 0 ? "" : ",") + csv_field(values[ids_.at(columns_[c])]);
    }
    return text + '\n';
}

std::string SweepTable::csv() const {
    std::string text = header_line();
    for (const auto& [index, packed] : rows_) text += line(index);
    return text;
}

}  // namespace cdvp
