// A sweep's shared software timings (sw/run/software_timing.h) as its table
// and its shards see them: a resume checks that every timing a row names is
// still the file it was, and a merge brings each shard's timings along.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace cdvp {

class SweepTable;

// For each row's NAME_timing_id of the form KEY@SHA, that DIR/KEY.json is
// there and is still that file (or, for a merge of shards that timed one
// workload each, that DIR/KEY@SHA.json keeps it); the first row whose is not,
// as one line naming the file, the row's point and what was expected.
std::optional<std::string> check_software_timings(const std::string& dir, const SweepTable& table);

// A merge's: every timing of FROM into INTO: KEY.json where INTO has none,
// nothing where it has the same, KEY@SHA.json beside it where another shard
// timed the workload differently (its rows name that one). One note a
// workload timed twice. Throws SystemError or InputError when INTO cannot be
// written.
std::vector<std::string> merge_software_timings(const std::string& from, const std::string& into);

}  // namespace cdvp
