// A sweep.csv as rows of column -> value, for the tests that read one.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_table.h"

namespace cdvp::test {

// untimed: the measured columns (wall times, load) left out, so that two
// sweeps of one grid compare equal.
inline std::vector<std::map<std::string, std::string>> sweep_rows(const std::string& csv, bool untimed) {
    const auto lines = parse_csv(csv, "sweep.csv");
    std::vector<std::map<std::string, std::string>> rows;
    for (std::size_t k = 1; k < lines.size(); ++k) {
        std::map<std::string, std::string> row;
        for (std::size_t c = 0; c < lines[0].size() && c < lines[k].size(); ++c) {
            if (!untimed || !is_measured_column(lines[0][c])) row[lines[0][c]] = lines[k][c];
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace cdvp::test
