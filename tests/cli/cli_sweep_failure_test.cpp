// A point whose cdvp run fails inside cdvp (exit 1, or killed by a signal)
// says nothing of the other points: its row is recorded as failed with the
// reason, the sweep goes on, and it ends with status 1 naming the first.
// The points run a stand-in for cdvp that fails at one point and is cdvp
// at the others (SweepSpec::cdvp_binary).
#include <sys/stat.h>

#include <string>
#include <vector>

#include "sw/cli/sweep_options.h"
#include "sw/run/exit_codes.h"
#include "sw/study/sweep.h"
#include "tests/cli/cli_support.h"
#include "tests/cli/sweep_rows.h"

namespace cdvp::test {
namespace {

using SweepFailure = Cli;

TEST_F(SweepFailure, APointThatFailsInsideCdvpIsRecordedAndTheSweepGoesOn) {
    const fs::path stand_in = write("cdvp-failing-at-7",
                                    "#!/bin/sh\n"
                                    "if echo \" $* \" | grep -Eq -- '--objects[= ]7 '; then\n"
                                    "  echo 'cdvp run: internal error (a cdvp bug): planted' >&2; exit 1\n"
                                    "fi\n"
                                    "if echo \" $* \" | grep -Eq -- '--objects[= ]8 '; then kill -9 $$; fi\n"
                                    "exec '" CDVP_BINARY "' \"$@\"\n");
    ASSERT_EQ(chmod(stand_in.c_str(), 0755), 0);
    const std::string out = (dir_ / "res").string();
    std::vector<std::string> args{"cdvp sweep", "--board", "adm-xrc-ii", "--set", "objects=5,7,8,9",
                                  "--frames", "1", "--out", out, "-q"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    std::optional<SweepSpec> spec = parse_sweep_options(static_cast<int>(argv.size()), argv.data());
    ASSERT_TRUE(spec);
    spec->cdvp_binary = stand_in.string();
    const SweepOutcome outcome = run_sweep(*spec);
    EXPECT_EQ(outcome.status, kExitInternal);
    EXPECT_EQ(outcome.points, 4u);
    EXPECT_EQ(outcome.ok, 2u);
    EXPECT_EQ(outcome.failed, 2u);
    EXPECT_EQ(outcome.first_failure, "board-adm-xrc-ii_objects-7: cdvp run failed (status 1): internal error (a cdvp bug): planted");
    const auto rows = sweep_rows(slurp(dir_ / "res" / "sweep.csv"), true);
    ASSERT_EQ(rows.size(), 4u);
    const std::vector<std::string> expected{"ok", "failed", "failed", "ok"};
    for (std::size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(rows[k].at("status"), expected[k]) << rows[k].at("point");
    EXPECT_EQ(rows[2].at("reason"), "cdvp run was killed by signal 9");
    // A resume keeps the rows, as it keeps refused ones: nothing to run again.
    const SweepOutcome again = run_sweep(*spec);
    EXPECT_EQ(again.run_now, 0u);
    EXPECT_EQ(again.failed, 2u);
}

}  // namespace
}  // namespace cdvp::test
