// The communication strategies from the command line: a delta upload sends
// the moving spheres only and finds the same pairs, every pair format gives
// the same pair set, the report says what moved, and what a level or a scene
// cannot do is refused on one line (auto says why it ran the fast engine).
#include <algorithm>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

// The pairs file's lines after its header, sorted: the same set in any order.
std::vector<std::string> pair_lines(const fs::path& path) {
    std::istringstream in(slurp(path));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    if (!lines.empty()) lines.erase(lines.begin());
    std::sort(lines.begin(), lines.end());
    return lines;
}

TEST_F(Cli, DeltaUploadSendsTheMovingSpheresAndFindsTheSamePairs) {
    const std::string scene = "run --scene spheres --objects 300 --frames 4 --moving 0.25 --board adm-xrc-ii -q ";
    ASSERT_EQ(run(scene + "--pairs-out full.csv --report full.json").status, 0);
    for (const std::string upload : {"delta", "auto"}) {
        for (const std::string format : {"list", "counted", "bitmap"}) {
            const std::string what = upload + "/" + format;
            const Result r = run(scene + "--upload " + upload + " --pair-format " + format +
                                 " --pairs-out p.csv --report r.json");
            ASSERT_EQ(r.status, 0) << what << ": " << r.err;
            EXPECT_EQ(pair_lines(dir_ / "full.csv"), pair_lines(dir_ / "p.csv")) << what;
            const auto full = report_of(dir_ / "full.json")["frames"], frames = report_of(dir_ / "r.json")["frames"];
            ASSERT_EQ(frames.size(), 4u);
            for (std::size_t k = 1; k < frames.size(); ++k) {
                EXPECT_EQ(frames[k]["boxes_sent"], 75) << what << ": a quarter of 300 spheres move";
                EXPECT_EQ(frames[k]["upload_bytes"], 28 * 75) << what;
                EXPECT_LT(frames[k]["upload_ns"].get<double>(), full[k]["upload_ns"].get<double>()) << what;
                EXPECT_EQ(full[k]["boxes_sent"], 300);
                EXPECT_EQ(full[k]["readback_bytes"], 8 * full[k]["pairs"].get<uint64_t>());
            }
            // Frame 0: the board's memories hold nothing known yet; auto takes the cheaper full upload.
            EXPECT_EQ(frames[0]["boxes_sent"], 300) << what;
            EXPECT_EQ(frames[0]["upload_bytes"], upload == "auto" ? 24 * 300 : 28 * 300) << what;
        }
    }
}

// The analytic level models the strategies: the same pairs file, and the
// upload and read-back of every frame as the fast engine times them.
TEST_F(Cli, TheAnalyticLevelTimesTheStrategiesAsTheFastEngine) {
    const std::string scene = "run --scene spheres --objects 200 --frames 3 --moving 0.3 --board pcie-gen3-x8 -q "
                              "--upload auto --pair-format counted --interrupts board ";
    ASSERT_EQ(run(scene + "--pairs-out fast.csv --report fast.json").status, 0);
    const Result r = run(scene + "--fidelity analytic --pairs-out analytic.csv --report analytic.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "fast.csv"), slurp(dir_ / "analytic.csv"));
    const auto fast = report_of(dir_ / "fast.json")["frames"], analytic = report_of(dir_ / "analytic.json")["frames"];
    ASSERT_EQ(fast.size(), 3u);
    for (std::size_t k = 0; k < fast.size(); ++k) {
        for (const char* field : {"boxes_sent", "upload_bytes", "readback_bytes"}) {
            EXPECT_EQ(analytic[k][field], fast[k][field]) << k << " " << field;
        }
        for (const char* field : {"upload_ns", "readback_ns", "driver_ns"}) {
            EXPECT_NEAR(analytic[k][field].get<double>(), fast[k][field].get<double>(), 1e-6) << k << " " << field;
        }
    }
}

TEST_F(Cli, CommunicationSettingsASceneCannotHonourAreRefused) {
    const std::string scene = "run --scene spheres --objects 40 --frames 2 --board adm-xrc-ii ";
    expect_refusal(run(scene + "--pair-format table"), "cdvp run: --pair-format: ");
    expect_refusal(run("run --scene spheres --objects 12000 --frames 1 --pair-format bitmap"),
                   "cdvp run: --pair-format: a full pair buffer of 262144 pairs");
    expect_refusal(run("bullet --scene stack --frames 2 --moving 0.5"),
                   "cdvp bullet: --moving: only --scene spheres holds some of its spheres still");
}

}  // namespace
}  // namespace cdvp::test
