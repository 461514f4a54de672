#include "sw/study/sweep_software_timings.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <map>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "sw/output/digest.h"
#include "sw/run/software_timing.h"
#include "sw/study/sweep_table.h"

namespace cdvp {

namespace {

constexpr const char* kIdSuffix = "_timing_id";

}  // namespace

namespace {

// DIR/KEY@SHA.json is there and is that file: a merge kept it.
bool kept_beside(const std::string& dir, const std::string& id) {
    const std::optional<std::string> text = read_software_timing_text(dir + "/" + id + ".json");
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
        const std::optional<std::string> text = read_software_timing_text(file.string());
        if (!text) throw InputError(path_text(file.string()) + ": gone while the merge read it");
        const std::string name = file.filename().string();
        const std::string key = name.substr(0, name.find_first_of("@."));
        const std::string sha = sha256_hex(*text);
        const std::optional<std::string> there = read_software_timing_text(software_timing_path(into, key));
        if (!there) {
            write_new_file(software_timing_path(into, key), *text);
        } else if (sha256_hex(*there) != sha) {
            const std::string id = software_timing_id(key, sha);
            if (!read_software_timing_text(into + "/" + id + ".json")) write_new_file(into + "/" + id + ".json", *text);
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
                const std::optional<std::string> text = read_software_timing_text(path);
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
