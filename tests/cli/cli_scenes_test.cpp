// The generated scene families from the command line: cdvp run --scene NAME
// with a family's settings, a family's setting refused with another scene,
// and cdvp record writing each scene as a trace that cdvp run --trace
// replays pair for pair.
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using Scenes = Cli;

TEST_F(Scenes, PileRunsWithABaseline) {
    const Result r = run("run --scene pile --objects 300 --frames 5 --baseline sap -q --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json report = report_of(dir_ / "r.json");
    EXPECT_EQ(report["config"]["source"], "pile objects=300 seed=1 clusters=3");
    ASSERT_EQ(report["frames"].size(), 5u);
    EXPECT_GT(report["frames"][0]["pairs"].get<uint64_t>(), 150u) << "the landed half of the pile touches";
}

TEST_F(Scenes, EachFamilyRunsWithItsSettings) {
    for (const char* args : {"--scene heavy -c scene.heavy.size_ratio=20 -c scene.heavy.large_fraction=0.05",
                             "--scene planar -c scene.planar.aspect=4", "--scene brownian -c scene.brownian.jump=0.5",
                             "--scene pile -c scene.pile.clusters=1 --objects 1", "--scene heavy --objects 0"}) {
        const Result r = run(std::string("run ") + args + " --frames 3 -q --report r.json");
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        EXPECT_EQ(report_of(dir_ / "r.json")["frames"].size(), 3u) << args;
    }
    // Known ahead, a kinematic scene pipelines on two box banks.
    EXPECT_EQ(run("run --scene brownian --objects 200 --frames 4 --box-banks 2 -q").status, 0);
}

TEST_F(Scenes, AFamilysSettingIsRefusedWithAnotherSceneAndBadValuesNamed) {
    expect_refusal(run("run --scene heavy -c scene.pile.clusters=2 --frames 1"),
                   "cdvp run: -c scene.pile.clusters: goes with --scene pile, not --scene heavy\n");
    expect_refusal(run("run --scene spheres -c scene.brownian.jump=0.5 --frames 1"),
                   "cdvp run: -c scene.brownian.jump: goes with --scene brownian, not --scene spheres\n");
    expect_refusal(run("run --scene pyramid -c scene.planar.aspect=2 --frames 1"),
                   "cdvp run: -c scene.planar.aspect: goes with --scene planar, not --scene pyramid\n");
    expect_refusal(run("run --trace t.csv -c scene.heavy.size_ratio=3"), "cdvp run: -c scene.heavy.size_ratio");
    expect_refusal(run("run --scene heavy -c scene.heavy.size_ratio=0.5"), "cdvp run: -c scene.heavy.size_ratio: expected");
    expect_refusal(run("run --scene pile -c scene.pile.clusters=0"), "cdvp run: -c scene.pile.clusters: expected");
    expect_refusal(run("run --scene piles"), "cdvp run: --scene: expected spheres, pile, heavy, planar, brownian or one of");
    expect_refusal(run("record --scene pile -c scene.heavy.size_ratio=3 --out t.csv"),
                   "cdvp record: -c scene.heavy.size_ratio: goes with --scene heavy, not --scene pile\n");
    expect_refusal(run("record --scene pile -c board.m=3 --out t.csv"), "cdvp record: -c board.m: cdvp record writes");
    expect_refusal(run("record --scene nope --out t.csv"), "cdvp record: --scene: expected spheres, pile");
    EXPECT_EQ(files(), std::vector<std::string>{});
}

// `cdvp record --scene NAME` then `cdvp run --trace` finds the pairs `cdvp
// run --scene NAME` finds with the same settings, for every generated scene
// (the spheres stepped on the float32 pairs, as the run steps them).
TEST_F(Scenes, RecordedSceneReplaysPairForPair) {
    for (const char* scene : {"spheres --moving 0.5", "pile -c scene.pile.clusters=2", "heavy -c scene.heavy.size_ratio=10",
                              "planar -c scene.planar.aspect=3", "brownian --seed 4"}) {
        const std::string args = std::string("--scene ") + scene + " --objects 300 --frames 8";
        const Result recorded = run("record " + args + " --out t.csv -q");
        ASSERT_EQ(recorded.status, 0) << scene << ": " << recorded.err;
        ASSERT_EQ(run("run --trace t.csv -q --pairs-out a.csv").status, 0) << scene;
        ASSERT_EQ(run("run " + args + " -q --pairs-out b.csv").status, 0) << scene;
        const std::string pairs = slurp(dir_ / "a.csv");
        EXPECT_EQ(pairs, slurp(dir_ / "b.csv")) << scene << ": the scene is its recorded trace";
        EXPECT_GT(std::count(pairs.begin(), pairs.end(), '\n'), 8) << scene;
    }
    // On a fixed-point board the spheres step on the float32 pairs too.
    ASSERT_EQ(run("record --scene spheres --objects 400 --frames 10 --out s.csv -q").status, 0);
    ASSERT_EQ(run("run --trace s.csv --format fixed16 -q --pairs-out a.csv").status, 0);
    ASSERT_EQ(run("run --scene spheres --objects 400 --frames 10 --format fixed16 -q --pairs-out b.csv").status, 0);
    EXPECT_EQ(slurp(dir_ / "a.csv"), slurp(dir_ / "b.csv"));
    const Result said = run("record --scene pile --objects 10 --frames 2 --out p.csv");
    EXPECT_EQ(said.out, "recorded 2 frames of 7 boxes (the last) (pile) to p.csv\n");
}

}  // namespace
}  // namespace cdvp::test
