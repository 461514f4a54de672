// A workload's software timing kept apart from the run that measured it, so
// that every point of a sweep that runs the same workload divides by the same
// figure. The software's work depends on the boxes (the scene and its
// settings, or the trace's digest) and on the baselines, their repeats and
// warm-up, not on the board, m or the bus: a workload is those, digested into
// a key. DIR/KEY.json holds each baseline's per-frame CPU and wall times of
// every --repeat run and its timing quality; it is written once, by whichever
// point gets there first (link(2): never replaced), and read by the rest. A
// row names the timing it used as KEY@SHA (the first 8 hex digits of the
// file's SHA-256), and a resume checks that each named file is still that
// one (docs/timing.md).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/timing/timing_quality.h"

namespace cdvp {

struct SoftwareTiming {
    nlohmann::json workload;  // what the key digests
    std::string created;      // UTC, ISO 8601
    uint32_t retime_tries = 0;
    struct Baseline {
        std::vector<std::vector<double>> cpu_ns;   // [run][frame], warm-up frames included
        std::vector<std::vector<double>> wall_ns;  // the same frames' wall times
        TimingQuality quality;
    };
    std::map<std::string, Baseline> baselines;
};

// The key of a workload: the first 16 hex digits of the SHA-256 of its JSON.
std::string software_timing_key(const nlohmann::json& workload);
// DIR/KEY.json.
std::string software_timing_path(const std::string& dir, const std::string& key);
// What a row names: KEY@ the first 8 hex digits of the file's SHA-256.
std::string software_timing_id(const std::string& key, const std::string& file_sha256);

// The file's text (nlohmann's dump(1) and a line end).
std::string software_timing_text(const SoftwareTiming& timing);

// The largest timing file read: 1 GiB (what a resume or a merge reads of
// one); the largest of `runs` runs of `frames` frames of `baselines`
// baselines, what cdvp writes of them with room to spare.
constexpr std::size_t kMaxSoftwareTimingBytes = std::size_t{1} << 30;
std::size_t software_timing_max_bytes(std::size_t runs, std::size_t frames, std::size_t baselines);

// The text of the timing file at `path`, read as every input file is
// (read_input_file: a regular file, refused unread when it is a FIFO or a
// device or larger than `max_bytes`); nothing when there is no file.
std::optional<std::string> read_software_timing_text(const std::string& path,
                                                     std::size_t max_bytes = kMaxSoftwareTimingBytes);

// The timing at `path` for `workload`, with its file's SHA-256 in `sha256`;
// nothing when there is no file. Throws InputError "PATH: FIELD: what was
// expected, got what" for a file that is no regular file, larger than
// `max_bytes`, damaged, out of range (every time finite from 0 to
// kMaxTimeNs, every count fitting its type: sw/run/json_fields.h) or of
// another workload.
std::optional<SoftwareTiming> read_software_timing(const std::string& path, const nlohmann::json& workload,
                                                   std::string& sha256, std::size_t max_bytes = kMaxSoftwareTimingBytes);

// Adds `timing` to DIR under its key unless a timing is there already: the
// file's SHA-256 when this one was added, nothing when another was first
// (read that one). Throws SystemError or InputError, with the system's text,
// when DIR cannot be written.
std::optional<std::string> publish_software_timing(const std::string& dir, const SoftwareTiming& timing);

}  // namespace cdvp
