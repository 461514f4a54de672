#include "sw/run/software_timing.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <algorithm>
#include <filesystem>
#include <set>

#include <sys/stat.h>

#include "models/common/user_text.h"
#include "sw/output/text_file.h"
#include "sw/output/digest.h"
#include "sw/run/report_summary.h"

namespace cdvp {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "cdvp software timing";
constexpr int kFormatVersion = 1;

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

}  // namespace cdvp
