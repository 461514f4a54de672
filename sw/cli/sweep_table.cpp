#include "sw/cli/sweep_table.h"

#include <algorithm>
#include <cstdio>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

const std::vector<std::string> kFixedColumns{"point", "index", "status", "reason"};

bool ends_with(const std::string& text, const std::string& end) {
    return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string number_text(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

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
    Row row{{"point", point.id}, {"index", std::to_string(point.index)}, {"status", to_string(status)}, {"reason", reason}};
    for (std::size_t a = 0; a < grid.axes().size(); ++a) row[grid.axes()[a].name] = point.values[a];
    return row;
}

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace

const char* to_string(PointStatus status) {
    switch (status) {
        case PointStatus::kOk: return "ok";
        case PointStatus::kRefused: return "refused";
        case PointStatus::kFault: return "fault";
    }
    return "?";
}

PointRow report_row(const Grid& grid, const Point& point, const nlohmann::json& report, double wall_seconds) {
    Row row = axis_row(grid, point, PointStatus::kOk, "");
    std::vector<std::string> order;  // the report's own order of its columns
    auto put = [&](const std::string& column, const std::string& value) {
        if (row.count(column) == 0) order.push_back(column);
        row[column] = value;
    };
    for (const auto& [key, item] : report.at("config").items()) {
        // The point's own command line names its report's path, which differs
        // between shards of one sweep: the sweep's columns are its settings.
        if (key == "command_line") continue;
        Row one;
        flatten(item, "config." + key, one);
        for (const auto& [column, value] : one) put(column, value);
    }
    const auto& frames = report.at("frames");
    const nlohmann::json summary = report.value("summary", nlohmann::json::object());
    // Steady state: warm-up frames are left out (the incremental broad
    // phases build their structures in them): as many as the report says,
    // else the first; at least one frame stays.
    const std::size_t warmup = summary.value("warmup_frames", std::size_t{1});
    const std::size_t first = frames.size() > warmup ? warmup : frames.empty() ? 0 : frames.size() - 1;
    put("report_frames", std::to_string(frames.size()));
    put("frames_in_medians", std::to_string(frames.size() - first));
    if (summary.contains("too_few_frames")) put("too_few_frames", value_text(summary["too_few_frames"]));
    std::vector<std::string> numbers, baselines;
    if (!frames.empty()) {
        for (const auto& [key, item] : frames[0].items()) {
            if (item.is_number() && key != "frame") numbers.push_back(key);
        }
        if (const auto at = frames[0].find("baselines"); at != frames[0].end()) {
            for (const auto& [name, item] : at->items()) baselines.push_back(name);
        }
    }
    auto frame_median = [&](auto value_of) {
        std::vector<double> values;
        for (std::size_t k = first; k < frames.size(); ++k) values.push_back(value_of(frames[k]));
        return median(values);
    };
    for (const std::string& key : numbers) {
        put("median_" + key, number_text(frame_median([&](const auto& f) { return f.at(key).template get<double>(); })));
    }
    const double board_ns = frames.empty() ? 0 : frame_median([](const auto& f) { return f.at("total_ns").template get<double>(); });
    for (const std::string& name : baselines) {
        // The report's own medians and spread when it has them (they span
        // every --repeat run), else medians of the frames.
        const nlohmann::json timed = summary.value("baselines", nlohmann::json::object()).value(name, nlohmann::json::object());
        if (timed.contains("median_scaled_ns") && timed.contains("speedup")) {
            put(name + "_median_ns", number_text(timed["median_scaled_ns"].get<double>()));
            for (const char* quantile : {"p10", "p90"}) {
                const std::string key = std::string(quantile) + "_scaled_ns";
                if (timed.contains(key)) put(name + "_" + quantile + "_ns", number_text(timed[key].get<double>()));
            }
            put(name + "_speedup", number_text(timed["speedup"].get<double>()));
            continue;
        }
        const double ns = frame_median([&](const auto& f) { return f.at("baselines").at(name).at("scaled_ns").template get<double>(); });
        put(name + "_median_ns", number_text(ns));
        put(name + "_speedup", number_text(board_ns > 0 ? ns / board_ns : 0));
    }
    put("point_wall_s", number_text(wall_seconds));
    return {order, row};
}

PointRow failed_row(const Grid& grid, const Point& point, PointStatus status, const std::string& reason,
                    double wall_seconds) {
    Row row = axis_row(grid, point, status, reason);
    row["point_wall_s"] = number_text(wall_seconds);
    return {{}, row};
}

bool is_timing_column(const std::string& column) {
    return column == "median_sim_wall_ns" || column == "point_wall_s" || ends_with(column, "_median_ns") ||
           ends_with(column, "_p10_ns") || ends_with(column, "_p90_ns") || ends_with(column, "_speedup");
}

SweepTable::SweepTable(const Grid& grid) : columns_(kFixedColumns) {
    for (const Axis& axis : grid.axes()) columns_.push_back(axis.name);
}

void SweepTable::add_column(const std::string& column) {
    if (std::find(columns_.begin(), columns_.end(), column) != columns_.end()) return;
    // Timing columns go last, so the columns that must agree between runs
    // come first whatever order they are met in.
    ++columns_version_;
    if (is_timing_column(column)) {
        columns_.push_back(column);
        return;
    }
    auto at = std::find_if(columns_.begin(), columns_.end(), [](const std::string& c) { return is_timing_column(c); });
    columns_.insert(at, column);
}

void SweepTable::set_row(std::size_t index, Row row) {
    rows_[index] = std::move(row);
    lines_.erase(index);
}

void SweepTable::add(std::size_t index, const PointRow& row) {
    for (const std::string& column : row.columns) add_column(column);
    for (const auto& [column, value] : row.values) add_column(column);
    set_row(index, row.values);
}

std::string SweepTable::csv() const {
    std::string text;
    for (std::size_t c = 0; c < columns_.size(); ++c) text += (c == 0 ? "" : ",") + csv_field(columns_[c]);
    text += '\n';
    for (const auto& [index, row] : rows_) {
        Line& line = lines_[index];
        if (line.columns_version != columns_version_) {
            line.text.clear();
            for (std::size_t c = 0; c < columns_.size(); ++c) {
                const auto value = row.find(columns_[c]);
                line.text += (c == 0 ? "" : ",") + (value == row.end() ? std::string() : csv_field(value->second));
            }
            line.text += '\n';
            line.columns_version = columns_version_;
        }
        text += line.text;
    }
    return text;
}

void SweepTable::read_csv(const std::string& text, const std::string& label) {
    const std::vector<std::vector<std::string>> lines = parse_csv(text, label);
    if (lines.empty()) return;
    const std::vector<std::string>& header = lines[0];
    for (std::size_t c = 0; c < columns_.size(); ++c) {
        if (c >= header.size() || header[c] != columns_[c]) {
            throw InputError(label + ":1: expected the column '" + excerpt(columns_[c]) + "' of this sweep's grid");
        }
    }
    for (const std::string& column : header) add_column(column);
    for (std::size_t k = 1; k < lines.size(); ++k) {
        const std::vector<std::string>& fields = lines[k];
        const std::string where = label + ":" + std::to_string(k + 1);
        if (fields.size() != header.size()) throw InputError(where + ": expected " + std::to_string(header.size()) + " fields");
        Row row;
        for (std::size_t c = 0; c < header.size(); ++c) {
            if (!fields[c].empty()) row[header[c]] = fields[c];
        }
        const std::string& index = fields[1];
        if (index.empty() || index.size() > 9 || index.find_first_not_of("0123456789") != std::string::npos) {
            throw InputError(where + ": expected a point index, got '" + excerpt(index) + "'");
        }
        set_row(std::stoul(index), row);
    }
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text, const std::string& label) {
    std::vector<std::vector<std::string>> lines;
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (quoted) {
            if (c == '"' && k + 1 < text.size() && text[k + 1] == '"') {
                field += '"';
                ++k;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.push_back(field);
            field.clear();
        } else if (c == '\n') {
            fields.push_back(field);
            lines.push_back(fields);
            fields.clear();
            field.clear();
        } else if (c != '\r') {
            field += c;
        }
    }
    if (quoted) throw InputError(label + ": a quoted field is not closed");
    if (!field.empty() || !fields.empty()) {
        fields.push_back(field);
        lines.push_back(fields);
    }
    return lines;
}

nlohmann::json manifest(const Grid& grid, const std::vector<std::string>& run_options, const Shard& shard) {
    nlohmann::json axes = nlohmann::json::array();
    for (const Axis& axis : grid.axes()) axes.push_back({{"name", axis.name}, {"values", axis.values}});
    return {{"format", "cdvp sweep 1"},
            {"axes", axes},
            {"run_options", run_options},
            {"points", grid.size()},
            {"shard", shard.text()}};
}

}  // namespace cdvp
