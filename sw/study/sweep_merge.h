// Merges the shards of one sweep into one directory, as if the sweep had run
// there whole (so it can be resumed there too). All or nothing: the merge is
// built in a staging directory beside OUT and swapped into place in one
// rename, so a merge that fails leaves OUT as it was.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace cdvp {

struct MergeSpec {
    std::string out;                  // new, empty, or a merge of the same sweep (its rows are kept)
    std::vector<std::string> shards;  // directories of `cdvp sweep --shard K/N` runs of one sweep and one N (at least one)
    bool quiet = false;               // no notes on stderr
    bool plots = true;                // false: the data files without the figures
    std::string program = "cdvp merge";
};

struct MergeOutcome {
    int status = 0;           // 0, or 1 when gnuplot failed (OUT left as it was)
    std::size_t points = 0;   // rows merged
    std::size_t grid = 0;     // points in the grid
    std::string answer;       // the merged sweep's answer in short (SweepOutcome::answer)
};

// Every row is checked against the grid, its shard and its report first; a row
// that does not match is refused (InputError) naming the file, line and field.
MergeOutcome merge_sweeps(const MergeSpec& spec);

}  // namespace cdvp
