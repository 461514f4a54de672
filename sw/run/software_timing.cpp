#include "sw/run/software_timing.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <algorithm>
#include <filesystem>
#include <set>

#include <sys/stat.h>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "sw/output/digest.h"
#include "sw/run/json_fields.h"
#include "sw/run/machine_info.h"
#include "sw/run/report_summary.h"

namespace cdvp {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "cdvp software timing";
constexpr int kFormatVersion = 1;

[[noreturn]] void refuse(const std::string& path, const std::string& field, const std::string& why) {
    throw InputError(path + ": " + field + ": " + why);
}

// A list of runs of frame times, each run as many frames as the first, each
// time finite from 0 to kMaxTimeNs.
std::vector<std::vector<double>> runs_of(const json& value, const std::string& path, const std::string& field) {
    if (!value.is_array() || value.empty()) refuse(path, field, "expected a list of runs, each a list of frame times");
    std::vector<std::vector<double>> runs;
    for (const json& run : value) {
        if (!run.is_array()) refuse(path, field, "expected a list of runs, each a list of frame times");
        std::vector<double>& times = runs.emplace_back();
        for (const json& t : run) times.push_back(json_time_ns(t, path + ": " + field));
        if (times.size() != runs.front().size()) refuse(path, field, "expected as many frames in every run");
    }
    return runs;
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

std::size_t software_timing_max_bytes(std::size_t runs, std::size_t frames, std::size_t baselines) {
    // The workload and each baseline's quality, then each time of dump(1): a
    // line of its indentation, up to 24 characters of a double and ",\n".
    constexpr long double kFixedBytes = 1 << 20, kBaselineBytes = 4096, kTimeBytes = 40;
    const long double bytes =
        kFixedBytes + static_cast<long double>(baselines) *
                          (kBaselineBytes + 2 * kTimeBytes * static_cast<long double>(runs) * static_cast<long double>(frames));
    return bytes < kMaxSoftwareTimingBytes ? static_cast<std::size_t>(bytes) : kMaxSoftwareTimingBytes;
}

std::optional<std::string> read_software_timing_text(const std::string& path, std::size_t max_bytes) {
    return read_input_file({path, "a software timing cdvp wrote", max_bytes, true});
}

std::optional<SoftwareTiming> read_software_timing(const std::string& path, const json& workload, std::string& sha256,
                                                   std::size_t max_bytes) {
    const std::optional<std::string> text = read_software_timing_text(path, max_bytes);
    if (!text) return std::nullopt;
    json document;
    try {
        document = json::parse(*text);
    } catch (const json::parse_error& e) {
        refuse(path, "(the file)", std::string("not JSON (") + e.what() + "); expected a software timing cdvp wrote");
    }
    if (!document.is_object() || json_field(document, "format") != kFormat) {
        refuse(path, "format", std::string("expected \"") + kFormat + "\"");
    }
    if (json_field(document, "format_version") != kFormatVersion) {
        refuse(path, "format_version", "expected " + std::to_string(kFormatVersion));
    }
    if (json_field(document, "workload") != workload) {
        refuse(path, "workload", "another workload's timing than this run's (" + json_found(json_field(document, "workload")) +
                                     "); expected " + excerpt(workload.dump()));
    }
    SoftwareTiming t;
    t.workload = workload;
    if (json_field(document, "created").is_string()) t.created = document["created"].get<std::string>();
    t.retime_tries = json_count<uint32_t>(json_field(document, "retime_tries"), path + ": retime_tries");
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
        out.quality = timing_quality_from_json(json_field(b, "timing_quality"), path + ": " + field + ".timing_quality");
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

}  // namespace cdvp
