#include "sw/study/sweep_manifest.h"

#include <cmath>
#include <cstdio>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "models/common/nesting_limit.h"
#include "sw/study/child_runs.h"
#include "sw/study/sweep_table.h"
#include "sw/output/digest.h"

namespace cdvp {

namespace {

using nlohmann::json;

// sweep.json lists every value of every axis: 100,000 values of a long path
// stay far below this.
constexpr std::size_t kMaxManifestBytes = std::size_t{256} << 20;

json parse_manifest_text(const std::string& text, const std::string& path) {
    const std::string label = path_text(path);
    check_json_nesting(label, text, "a sweep manifest");  // before the parser builds anything deep
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
        throw InputError(text_position(label, text, nul) + ": a NUL byte; expected the manifest cdvp sweep writes");
    }
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError(text_position(label, text, e.byte == 0 ? 0 : e.byte - 1) +
                         ": not JSON; expected the manifest cdvp sweep writes");
    }
}

// Checked access to the manifest's fields: a missing or mistyped field is
// refused naming it.
class Fields {
public:
    explicit Fields(std::string path) : path_(std::move(path)) {}

    const json& at(const json& object, const std::string& key, const std::string& where) const {
        if (!object.is_object() || !object.contains(key)) refuse(where + key, "is missing");
        return object[key];
    }
    std::string text(const json& object, const std::string& key, const std::string& where = "") const {
        const json& value = at(object, key, where);
        if (!value.is_string()) refuse(where + key, "expected a string");
        return value.get<std::string>();
    }
    uint64_t count(const json& object, const std::string& key, const std::string& where = "") const {
        const json& value = at(object, key, where);
        if (!value.is_number_unsigned()) refuse(where + key, "expected a whole number");
        return value.get<uint64_t>();
    }
    std::vector<std::string> texts(const json& object, const std::string& key, const std::string& where = "") const {
        const json& value = at(object, key, where);
        if (!value.is_array()) refuse(where + key, "expected a list of strings");
        std::vector<std::string> items;
        for (const json& item : value) {
            if (!item.is_string()) refuse(where + key, "expected a list of strings");
            items.push_back(item.get<std::string>());
        }
        return items;
    }
    const json& list(const json& object, const std::string& key) const {
        const json& value = at(object, key, "");
        if (!value.is_array()) refuse(key, "expected a list");
        return value;
    }
    [[noreturn]] void refuse(const std::string& field, const std::string& why) const {
        throw InputError(path_text(path_) + ": field '" + excerpt(field) + "': " + why +
                         "; expected the manifest cdvp sweep writes");
    }

private:
    std::string path_;
};

json input_json(const SweepInput& input) {
    json j = {{"option", input.option}, {"value", input.value}, {"path", input.path}, {"sha256", input.sha256},
              {"bytes", input.bytes}};
    if (!input.facts.is_null()) j["facts"] = input.facts;
    return j;
}

}  // namespace

const char* to_string(RecordMode mode) { return mode == RecordMode::kCompact ? "compact" : "full"; }

RecordMode parse_record_mode(const std::string& text, const std::string& label) {
    if (text == "full") return RecordMode::kFull;
    if (text == "compact") return RecordMode::kCompact;
    throw InputError(label + ": expected full or compact, got '" + excerpt(text) + "'");
}

SweepInput digest_input(std::string option, std::string value, std::string path) {
    const std::optional<FileDigest> digest = digest_file(path);
    if (!digest) {
        throw InputError(option + ": " + excerpt(value) + ": cannot read: " + errno_reason(errno));
    }
    return {std::move(option), std::move(value), std::move(path), digest->sha256, digest->bytes, nullptr};
}

SweepInput digest_text(std::string option, std::string value, std::string path, const std::string& text) {
    return {std::move(option), std::move(value), std::move(path), sha256_hex(text), text.size(), nullptr};
}

json Manifest::to_json() const {
    const Grid grid(axes);
    json axes_json = json::array();
    for (std::size_t a = 0; a < grid.axes().size(); ++a) {
        const Axis& axis = grid.axes()[a];
        axes_json.push_back({{"name", axis.name}, {"key", axis.key}, {"flag", axis.flag}, {"values", axis.values},
                             {"ids", grid.fragments(a)}});
    }
    json inputs_json = json::array();
    for (const SweepInput& input : inputs) inputs_json.push_back(input_json(input));
    return {{"format", kManifestFormat},
            {"format_version", kSweepFormatVersion},
            {"cdvp", cdvp_version},
            {"axes", axes_json},
            {"run_options", run_options},
            {"inputs", inputs_json},
            {"points", grid.size()},
            {"shard", shard.text()},
            {"record", to_string(record)},
            {"software_timings", software_timings},
            {"point_ids", "NAME-ID of each axis joined by '_', ID from 'ids' (docs/sweep.md)"}};
}

std::optional<Manifest> read_manifest(const std::string& path) {
    struct stat status {};
    if (lstat(path.c_str(), &status) != 0) {
        if (errno == ENOENT) return std::nullopt;
        throw InputError(path_text(path) + ": cannot read: " + errno_reason(errno));
    }
    if (!S_ISREG(status.st_mode)) throw InputError(path_text(path) + ": expected a regular file (a sweep's manifest)");
    if (static_cast<uint64_t>(status.st_size) > kMaxManifestBytes) {
        throw InputError(path_text(path) + ": " + std::to_string(status.st_size) + " bytes; expected the manifest cdvp "
                         "sweep writes (at most " + std::to_string(kMaxManifestBytes) + ")");
    }
    // Read as every input file is: a name swapped for a FIFO since the check above is refused, not waited on.
    const json document =
        parse_manifest_text(*read_input_file({path, "the manifest cdvp sweep writes", kMaxManifestBytes}), path);
    const Fields fields(path);
    if (!document.is_object()) fields.refuse("(top level)", "expected an object");
    const std::string format = fields.text(document, "format");
    if (format != kManifestFormat) {
        fields.refuse("format", "'" + excerpt(format) + "' is not '" + kManifestFormat +
                                    "' (a sweep of another cdvp version: give a new --out)");
    }
    if (const uint64_t version = fields.count(document, "format_version"); version != kSweepFormatVersion) {
        fields.refuse("format_version", std::to_string(version) + " is not " + std::to_string(kSweepFormatVersion) +
                                            " (a sweep of another cdvp version: give a new --out)");
    }
    Manifest manifest;
    manifest.cdvp_version = fields.text(document, "cdvp");
    const json& axes = fields.list(document, "axes");
    for (std::size_t a = 0; a < axes.size(); ++a) {
        const std::string where = "axes[" + std::to_string(a) + "].";
        manifest.axes.push_back({fields.text(axes[a], "name", where), fields.texts(axes[a], "values", where),
                                 fields.text(axes[a], "key", where), fields.text(axes[a], "flag", where)});
        if (manifest.axes.back().key.empty()) fields.refuse(where + "key", "expected a setting or flag name");
    }
    manifest.run_options = fields.texts(document, "run_options");
    const json& inputs = fields.list(document, "inputs");
    for (std::size_t k = 0; k < inputs.size(); ++k) {
        const std::string where = "inputs[" + std::to_string(k) + "].";
        manifest.inputs.push_back({fields.text(inputs[k], "option", where), fields.text(inputs[k], "value", where),
                                   fields.text(inputs[k], "path", where), fields.text(inputs[k], "sha256", where),
                                   fields.count(inputs[k], "bytes", where), nullptr});
        if (inputs[k].contains("facts")) manifest.inputs.back().facts = inputs[k]["facts"];
    }
    if (document.contains("software_timings")) manifest.software_timings = fields.text(document, "software_timings");
    if (document.contains("record")) {
        const std::string record = fields.text(document, "record");
        if (record != "full" && record != "compact") fields.refuse("record", "expected full or compact");
        manifest.record = parse_record_mode(record, "record");
    }
    try {
        manifest.shard = parse_shard(fields.text(document, "shard"));
        const Grid grid(manifest.axes);
        if (fields.count(document, "points") != grid.size()) fields.refuse("points", "does not match the axes");
        for (std::size_t a = 0; a < grid.axes().size(); ++a) {
            const std::string where = "axes[" + std::to_string(a) + "].";
            if (fields.texts(axes[a], "ids", where) != grid.fragments(a)) {
                fields.refuse(where + "ids", "not the ids of the axis's values");
            }
        }
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.rfind(path_text(path) + ":", 0) == 0) throw;
        throw InputError(path_text(path) + ": " + message);
    }
    return manifest;
}

namespace {

// Which of a changed input's values moved by more than its tolerance, in
// words ("sap's reference_native_ns moved 4.2% (1.06e+05 then, 1.1e+05 now),
// more than the 1.3% it may"); nothing when none did or neither has facts.
std::optional<std::string> moved_beyond_tolerance(const json& then, const json& now) {
    if (then.is_null() || now.is_null()) return std::nullopt;
    const auto number = [](const json& facts, const char* part, const std::string& name) {
        const json& values = facts.value(part, json::object());
        return values.is_object() && values.contains(name) && values[name].is_number() ? values[name].get<double>() : -1.0;
    };
    const json values = then.value("values", json::object());  // kept: items() of a temporary would dangle
    for (const auto& [name, ignored] : values.items()) {
        const double before = number(then, "values", name), after = number(now, "values", name);
        const double tolerance = std::max(number(then, "tolerance", name), number(now, "tolerance", name));
        if (!(before > 0) || !(after > 0)) return name + " is not in both";
        const double moved = after / before - 1;
        if (std::fabs(moved) <= tolerance) continue;
        char text[256];
        std::snprintf(text, sizeof text, "%s moved %+.1f%% (%.4g then, %.4g now), more than the %.1f%% it may (its recorded spread)",
                      name.c_str(), 100 * moved, before, after, 100 * std::max(tolerance, 0.0));
        return std::string(text);
    }
    return std::nullopt;
}

}  // namespace

std::optional<SweepDifference> difference(const Manifest& existing, const Manifest& wanted, const SettingNames* names) {
    const auto option = [names](const std::string& key) { return names != nullptr ? names->input(key) : "--" + key; };
    const auto other = [](std::string what) { return std::optional<SweepDifference>({std::move(what), false}); };
    if (existing.cdvp_version != wanted.cdvp_version) {
        return other("a sweep of cdvp " + excerpt(existing.cdvp_version) + ", this is " + wanted.cdvp_version);
    }
    if (existing.axes.size() != wanted.axes.size()) return other("other axes");
    for (std::size_t a = 0; a < existing.axes.size(); ++a) {
        const Axis& e = existing.axes[a];
        const Axis& w = wanted.axes[a];
        if (e.name != w.name || e.key != w.key || e.flag != w.flag) return other("other axes");
        if (e.values != w.values) return other("other values of " + excerpt(w.name));
    }
    if (existing.run_options != wanted.run_options) return other("other options given to every point");
    if (existing.record != wanted.record) {
        return other(option("record") + " " + to_string(existing.record) + ", not " + to_string(wanted.record));
    }
    if (existing.software_timings != wanted.software_timings) {
        return other("software timings shared through '" + excerpt(existing.software_timings) + "', not '" +
                     excerpt(wanted.software_timings) + "' (" + option("software-timings") + ")");
    }
    if (existing.inputs.size() != wanted.inputs.size()) return other("other input files");
    for (std::size_t k = 0; k < existing.inputs.size(); ++k) {
        const SweepInput& e = existing.inputs[k];
        const SweepInput& w = wanted.inputs[k];
        if (e.option != w.option || e.value != w.value) return other("other input files");
        if (e.sha256 != w.sha256) {
            if (const std::optional<std::string> moved = moved_beyond_tolerance(e.facts, w.facts)) {
                return SweepDifference{w.option + " " + excerpt(w.value) + " changed since the sweep began: " + *moved,
                                       true};
            }
            if (!e.facts.is_null() && !w.facts.is_null()) continue;  // within what it may differ by
            return SweepDifference{w.option + " " + excerpt(w.value) + " changed since the sweep began (" +
                                       std::to_string(e.bytes) + " bytes, sha256 " + e.sha256.substr(0, 12) +
                                       "... then; " + std::to_string(w.bytes) + " bytes, sha256 " +
                                       w.sha256.substr(0, 12) + "... now)",
                                   true};
        }
    }
    return std::nullopt;
}

}  // namespace cdvp
