// sweep.json: what a sweep is — its grid, the options every point is given,
// a digest of every file the points read, the version of cdvp that ran it —
// and which shard of it a directory holds. A resume or a merge compares the
// manifest with what it is asked to do and refuses any difference; a
// manifest that is not one is refused naming the file and the field.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "platform/settings/setting_names.h"
#include "sw/study/sweep_grid.h"

namespace cdvp {

// A file the points read: the option that names it, the value as given,
// the path it was read at, and its contents' digest.
struct SweepInput {
    std::string option;  // "--trace", "--board", "--config"
    std::string value;   // as the user gave it
    std::string path;    // where it was read (a spooled pipe: the spool)
    std::string sha256;
    uint64_t bytes = 0;
    // What a changed file may differ by and still be the same input: null,
    // or {"values": {NAME: number}, "tolerance": {NAME: fraction}} (a host
    // profile's reference times and their spreads). A file whose values all
    // moved by no more than the larger tolerance is not a change.
    nlohmann::json facts;
};
// Digests the file at 'input.path'. Throws InputError naming the option and
// value when it cannot be read.
SweepInput digest_input(std::string option, std::string value, std::string path);
// The same for a file's text already read from 'path'.
SweepInput digest_text(std::string option, std::string value, std::string path, const std::string& text);

// What a sweep keeps of each point: its whole report beside a row of every
// setting and figure (full), or a row of the figures alone and no report
// (compact: about 300 bytes a point, for sweeps of a million points).
enum class RecordMode { kFull, kCompact };
const char* to_string(RecordMode mode);
// "full" or "compact"; throws InputError naming 'label' otherwise.
RecordMode parse_record_mode(const std::string& text, const std::string& label);

struct Manifest {
    std::vector<Axis> axes;
    std::vector<std::string> run_options;  // as every point gets them
    std::vector<SweepInput> inputs;
    Shard shard;
    std::string cdvp_version;
    RecordMode record = RecordMode::kFull;  // a manifest without the field was written full
    std::string software_timings;           // where the points share their software timings ("": nowhere)

    nlohmann::json to_json() const;
};

// The manifest's "format" (what the file is) beside its "format_version"
// (kSweepFormatVersion).
constexpr const char* kManifestFormat = "cdvp sweep";

// DIR/sweep.json, or nothing when DIR has none. Throws InputError naming
// the file (and line and column, or the field) when it is not a manifest.
std::optional<Manifest> read_manifest(const std::string& path);

// What makes 'existing' another sweep than 'wanted' ("other values of m",
// "other options given to every point"), or an input file changed since
// ("--config cfg.json changed since the sweep began (sha256 ... then, ...
// now)"), or nothing when they are one sweep; shards are not compared.
struct SweepDifference {
    std::string what;
    bool input_changed = false;  // the same sweep, over a file that is not what it read
};
// names: how the face names the sweep's options (--record, record=); null:
// the command line's.
std::optional<SweepDifference> difference(const Manifest& existing, const Manifest& wanted,
                                          const SettingNames* names = nullptr);

}  // namespace cdvp
