// Empty and degenerate workloads: no boxes, one box, and every box the same,
// on every preset, at every level and with either algorithm, run as users run
// them; and a sweep whose objects axis starts at 0 gives a row for every point.
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tests/cli/sweep_rows.h"

namespace cdvp::test {
namespace {

const std::vector<std::string> kPresets{"adm-xrc-ii", "adm-xrc-ii-64", "pcie-gen3-x8", "alveo-u250"};
const std::vector<std::string> kLevels{"fast", "cycle", "analytic", "auto"};
const std::vector<std::string> kAlgorithms{"", " -c board.algorithm=grid"};

using Degenerate = Cli;

// Six boxes on top of one another in each of two frames: every pair overlaps.
std::string identical_boxes_trace() {
    std::string text = "frame,id,min_x,min_y,min_z,max_x,max_y,max_z\n";
    for (int frame = 0; frame < 2; ++frame) {
        for (int id = 0; id < 6; ++id) text += std::to_string(frame) + "," + std::to_string(id) + ",1,2,3,4,5,6\n";
    }
    return text;
}

TEST_F(Degenerate, NoBoxesOneBoxAndIdenticalBoxesRunOnEveryPresetLevelAndAlgorithm) {
    write("same.csv", identical_boxes_trace());
    const std::vector<std::pair<std::string, uint64_t>> workloads{
        {"--scene spheres --objects 0 --frames 2", 0},
        {"--scene spheres --objects 1 --frames 2", 0},
        {"--trace same.csv", 2 * 15},
    };
    for (const std::string& preset : kPresets) {
        for (const std::string& level : kLevels) {
            for (const std::string& algorithm : kAlgorithms) {
                for (const auto& [workload, pairs] : workloads) {
                    const std::string args = "run --board " + preset + " --fidelity " + level + algorithm + " " +
                                             workload + " -q --report r.json";
                    const Result r = run(args);
                    ASSERT_EQ(r.status, 0) << args << ": " << r.err;
                    EXPECT_EQ(r.err, "") << args;
                    const nlohmann::json report = report_of(dir_ / "r.json");
                    uint64_t found = 0;
                    for (const auto& frame : report.at("frames")) found += frame.at("pairs").get<uint64_t>();
                    EXPECT_EQ(found, pairs) << args;
                }
            }
        }
    }
}

TEST_F(Degenerate, ASweepWhoseObjectsStartAtZeroHasARowForEveryPoint) {
    for (const std::string& preset : {std::string("adm-xrc-ii"), std::string("alveo-u250")}) {
        for (const std::string& level : {std::string("cycle"), std::string("analytic")}) {
            const std::string out = "res-" + preset + "-" + level;
            const Result r = run("sweep --board " + preset + " -c run.fidelity=" + level +
                                 " --set objects=0,1,100 --frames 3 --out " + out + " -q");
            ASSERT_EQ(r.status, 0) << preset << " " << level << ": " << r.err;
            const auto rows = sweep_rows(slurp(dir_ / out / "sweep.csv"), true);
            ASSERT_EQ(rows.size(), 3u) << preset << " " << level;
            for (const auto& row : rows) EXPECT_EQ(row.at("status"), "ok") << row.at("point") << ": " << row.at("reason");
        }
    }
}

}  // namespace
}  // namespace cdvp::test
