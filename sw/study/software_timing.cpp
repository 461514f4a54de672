#include "sw/study/software_timing.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <algorithm>
#include <filesystem>
#include <set>

#include <sys/stat.h>

#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/digest.h"
#include "sw/study/report_summary.h"
#include "sw/study/sweep_table.h"

namespace cdvp {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "cdvp software timing";
constexpr int kFormatVersion = 1;
constexpr const char* kIdSuffix = "_timing_id";

[[noreturn]] void refuse(const std::string& path, const std::string& field, const std::string& why) {
    throw InputError(path + ": " + field + ": " + why);
}

// A list of runs of frame times, each run as many frames as the first.
std::vector<std::vector<double>> runs_of(const json& value, const std::string& path, const std::string& field) {
    if (!value.is_array() || value.empty()) refuse(path, field, "expected a list of runs, each a list of frame times");
    std::vector<std::vector<double>> runs;
    for (const json& run : value) {
        if (!run.is_array()) refuse(path, field, "expected a list of runs, each a list of frame times");
        std::vector<double>& times = runs.emplace_back();
        for (const json& t : run) {
            if (!t.is_number() || !(t.get<double>() >= 0)) refuse(path, field, "expected times of 0 ns or more");
            times.push_back(t.get<double>());
        }
        if (times.size() != runs.front().size()) refuse(path, field, "expected as many frames in every run");
    }
    return runs;
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm parts{};
    gmtime_r(&now, &parts);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
    return text;
}

bool ends_with(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string software_timing_key(const json& workload) { return sha256_hex(workload.dump()).substr(0, 16); }

std::string software_timing_path(const std::string& dir, const std::string& key) { return dir + "/" + key + ".json"; }

std::string software_timing_id(const std::string& key, const std::string& file_sha256) {
    return key + "@" + file_sha256.substr(0, 8);
}

std::string software_timing_text(const SoftwareTiming& t) {
    json baselines = json::object();
    for (const auto& [name, b] : t.baselines) {
        baselines[name] = {{"cpu_native_ns", b.cpu_ns}, {"wall_native_ns", b.wall_ns}, {"timing_quality", to_json(b.quality)}};
    }
    const json document = {{"format", kFormat},
                           {"format_version", kFormatVersion},
                           {"key", software_timing_key(t.workload)},
                           {"created", t.created.empty() ? utc_now() : t.created},
                           {"workload", t.workload},
                           {"retime_tries", t.retime_tries},
                           {"baselines", baselines}};
    return document.dump(1) + '\n';
}

std::optional<SoftwareTiming> read_software_timing(const std::string& path, const json& workload, std::string& sha256) {
    const std::optional<std::string> text = read_whole_file(path);
    if (!text) {
        if (errno == ENOENT) return std::nullopt;
        throw_os_error(path + ": cannot read the software timing", errno);
    }
    json document;
    try {
        document = json::parse(*text);
    } catch (const json::parse_error& e) {
        refuse(path, "(the file)", std::string("not JSON (") + e.what() + "); expected a software timing cdvp wrote");
    }
    if (!document.is_object() || document.value("format", "") != kFormat) {
        refuse(path, "format", std::string("expected \"") + kFormat + "\"");
    }
    if (document.value("format_version", 0) != kFormatVersion) {
        refuse(path, "format_version", "expected " + std::to_string(kFormatVersion));
    }
    if (!document.contains("workload") || document["workload"] != workload) {
        refuse(path, "workload", "another workload's timing than this run's (" + excerpt(document.value("workload", json()).dump()) +
                                     "); expected " + excerpt(workload.dump()));
    }
    SoftwareTiming t;
    t.workload = workload;
    t.created = document.value("created", "");
    if (!document.contains("retime_tries") || !document["retime_tries"].is_number_unsigned()) {
        refuse(path, "retime_tries", "expected a count");
    }
    t.retime_tries = document["retime_tries"].get<uint32_t>();
    if (!document.contains("baselines") || !document["baselines"].is_object()) refuse(path, "baselines", "expected an object");
    for (const auto& [name, b] : document["baselines"].items()) {
        const std::string field = "baselines." + name;
        if (!b.is_object()) refuse(path, field, "expected an object");
        SoftwareTiming::Baseline& out = t.baselines[name];
        out.cpu_ns = runs_of(b.value("cpu_native_ns", json()), path, field + ".cpu_native_ns");
        out.wall_ns = runs_of(b.value("wall_native_ns", json()), path, field + ".wall_native_ns");
        if (out.wall_ns.size() != out.cpu_ns.size() || out.wall_ns.front().size() != out.cpu_ns.front().size()) {
            refuse(path, field + ".wall_native_ns", "expected the runs and frames of cpu_native_ns");
        }
        out.quality = timing_quality_from_json(b.value("timing_quality", json()), path + ": " + field);
    }
    sha256 = sha256_hex(*text);
    return t;
}

std::optional<std::string> publish_software_timing(const std::string& dir, const SoftwareTiming& timing) {
    const std::string text = software_timing_text(timing);
    const std::string path = software_timing_path(dir, software_timing_key(timing.workload));
    // Written whole beside it, synced, then linked in: a reader sees the
    // whole file or none, and a second writer's link fails (EEXIST) rather
    // than replacing the first's.
    const std::string temporary = path + ".part-" + std::to_string(getpid());
    const int fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw_os_error(temporary + ": cannot write the software timing", errno);
    std::size_t written = 0;
    while (written < text.size()) {
        const ssize_t n = write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : EIO;
            close(fd);
            unlink(temporary.c_str());
            throw_os_error(temporary + ": cannot write the software timing", error);
        }
        written += static_cast<std::size_t>(n);
    }
    if (fsync(fd) != 0 || close(fd) != 0) {
        const int error = errno;
        unlink(temporary.c_str());
        throw_os_error(temporary + ": cannot write the software timing", error);
    }
    const int linked = link(temporary.c_str(), path.c_str());
    const int error = errno;
    unlink(temporary.c_str());
    if (linked == 0) return sha256_hex(text);
    if (error == EEXIST) return std::nullopt;
    throw_os_error(path + ": cannot add the software timing", error);
}

namespace {

// DIR/KEY@SHA.json is there and is that file: a merge kept it.
bool kept_beside(const std::string& dir, const std::string& id) {
    const std::optional<std::string> text = read_whole_file(dir + "/" + id + ".json");
    return text && sha256_hex(*text).substr(0, 8) == id.substr(id.find('@') + 1);
}

void write_new_file(const std::string& path, const std::string& text) {
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw_os_error("--out: " + path + ": cannot write", errno);
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t put = write(fd, text.data() + done, text.size() - done);
        if (put < 0 && errno == EINTR) continue;
        if (put < 0) {
            const int error = errno;
            close(fd);
            throw_os_error("--out: " + path + ": cannot write", error);
        }
        done += static_cast<std::size_t>(put);
    }
    if (close(fd) != 0) throw_os_error("--out: " + path + ": cannot write", errno);
}

}  // namespace

std::vector<std::string> merge_software_timings(const std::string& from, const std::string& into) {
    std::vector<std::string> notes;
    std::error_code error;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(from, error)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && ends_with(name, ".json") && name.find(".part-") == std::string::npos) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    if (!files.empty() && mkdir(into.c_str(), 0755) != 0 && errno != EEXIST) {
        throw_os_error("--out: " + into + ": cannot create", errno);
    }
    for (const std::filesystem::path& file : files) {
        const std::optional<std::string> text = read_whole_file(file.string());
        if (!text) throw_os_error(file.string() + ": cannot read", errno);
        const std::string name = file.filename().string();
        const std::string key = name.substr(0, name.find_first_of("@."));
        const std::string sha = sha256_hex(*text);
        const std::optional<std::string> there = read_whole_file(software_timing_path(into, key));
        if (!there) {
            write_new_file(software_timing_path(into, key), *text);
        } else if (sha256_hex(*there) != sha) {
            const std::string id = software_timing_id(key, sha);
            if (!read_whole_file(into + "/" + id + ".json")) write_new_file(into + "/" + id + ".json", *text);
            notes.push_back("workload " + key + " was timed by more than one shard: the rows of " + from +
                            "'s timing name " + id + " (kept beside " + key + ".json); give the shards one "
                            "--software-timings DIR to share one timing");
        }
    }
    return notes;
}

std::optional<std::string> check_software_timings(const std::string& dir, const SweepTable& table) {
    std::vector<std::string> id_columns;
    for (const std::string& column : table.columns()) {
        if (ends_with(column, kIdSuffix)) id_columns.push_back(column);
    }
    if (id_columns.empty()) return std::nullopt;
    std::map<std::string, std::string> sha_of;  // key -> the file's SHA-256 prefix (empty: no file)
    std::optional<std::string> refusal;
    table.for_each([&](std::size_t, const RowView& row) {
        for (const std::string& column : id_columns) {
            if (refusal) return;
            const std::string id = row.get(column);
            const std::size_t at = id.find('@');
            if (id.empty() || at == std::string::npos) continue;
            const std::string key = id.substr(0, at);
            const std::string path = software_timing_path(dir, key);
            auto known = sha_of.find(key);
            if (known == sha_of.end()) {
                const std::optional<std::string> text = read_whole_file(path);
                known = sha_of.emplace(key, text ? sha256_hex(*text).substr(0, 8) : "").first;
            }
            if (known->second != id.substr(at + 1) && !kept_beside(dir, id)) {
                refusal = path + ": " +
                          (known->second.empty() ? "missing" : "changed (sha256 " + known->second + "...)") +
                          ", but point " + row.get("point") + "'s " + column + " is " + id +
                          ": the points still to run would divide by another software timing; expected that file "
                          "back, or a new --out";
            }
        }
    });
    return refusal;
}

}  // namespace cdvp
