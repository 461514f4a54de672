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

nlohmann::json report_of(const fs::path& path) { return nlohmann::json::parse(slurp(path)); }

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

TEST_F(Cli, CommunicationSettingsTheLevelOrSceneCannotHonourAreRefused) {
    const std::string scene = "run --scene spheres --objects 40 --frames 2 --board adm-xrc-ii ";
    expect_refusal(run(scene + "--fidelity analytic --upload delta"),
                   "cdvp run: --upload: the analytic level (--fidelity) times the paper's full upload, pair list, "
                   "interrupts and constant poll gap only");
    expect_refusal(run(scene + "--fidelity analytic -c driver.poll_backoff=2"),
                   "cdvp run: -c driver.poll_backoff: the analytic level");
    expect_refusal(run(scene + "--pair-format table"), "cdvp run: --pair-format: ");
    expect_refusal(run("run --scene spheres --objects 12000 --frames 1 --pair-format bitmap"),
                   "cdvp run: --pair-format: a full pair buffer of 262144 pairs");
    expect_refusal(run("bullet --scene stack --frames 2 --moving 0.5"),
                   "cdvp bullet: --moving: only --scene spheres holds some of its spheres still");
    const Result r = run(scene + "--fidelity auto --interrupts board --report auto.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("the fast engine on every frame: the analytic level does not model --interrupts"),
              std::string::npos) << r.out;
    EXPECT_EQ(report_of(dir_ / "auto.json")["fidelity_choice"]["fast_frames"], 2);
}

}  // namespace
}  // namespace cdvp::test
