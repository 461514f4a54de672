// `cdvp run --vcd`: the waveforms, their GTKWave save file and state names,
// read as a viewer reads them (GTKWave itself: tests/waves).
#include <gtest/gtest.h>

#include <sstream>

#include "tests/cli/cli_support.h"
#include "tests/support/vcd_reader.h"

using cdvp::test::Result;
using cdvp::test::slurp;
using Cli = cdvp::test::Cli;
namespace fs = std::filesystem;

namespace {

// The signal lines of a save file: everything but flags, groups, filters and settings.
std::vector<std::string> saved_signals(const std::string& save) {
    std::istringstream lines(save);
    std::vector<std::string> signals;
    for (std::string line; std::getline(lines, line);) {
        if (!line.empty() && std::string("@-[*^").find(line[0]) == std::string::npos) signals.push_back(line);
    }
    return signals;
}

// The number after "[key] " in a save file.
uint64_t setting(const std::string& save, const std::string& key) {
    const std::size_t at = save.find("[" + key + "] ");
    return at == std::string::npos ? UINT64_MAX : std::stoull(save.substr(at + key.size() + 3));
}

// The first time at or after `from` when `name` takes `value`.
uint64_t first_time(const cdvp::test::Vcd& vcd, const std::string& name, const std::string& value, uint64_t from = 0) {
    const std::string& id = vcd.id_of.at(name);
    for (const cdvp::test::VcdChange& c : vcd.changes) {
        if (c.id == id && c.value == value && c.time >= from) return c.time;
    }
    return UINT64_MAX;
}

const std::string kControl = "SystemC.platform.board.control.";

TEST_F(Cli, SaveFileNamesEverySignalAsTheViewerResolvesIt) {
    const Result r = run("run --trace " + trace("small.csv") + " --m 2 --vcd waves.vcd --quiet");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"waves.controller-states.txt", "waves.dma-states.txt", "waves.gtkw",
                                                 "waves.vcd"}))
        << "no temporary left behind";
    const std::string save = slurp(dir_ / "waves.gtkw");
    const std::string here = fs::canonical(dir_).string();
    EXPECT_NE(save.find("[dumpfile] \"" + here + "/waves.vcd\""), std::string::npos) << save;
    const cdvp::test::Vcd vcd = cdvp::test::read_vcd_text(slurp(dir_ / "waves.vcd"));
    const std::vector<std::string> signals = saved_signals(save);
    EXPECT_EQ(signals.size(), vcd.id_of.size()) << "every traced signal, once";
    for (const std::string& name : signals) EXPECT_EQ(vcd.id_of.count(name), 1u) << name << " is not in the VCD";
    for (const char* group : {"-board: control", "-board: address generator", "-board: comparison unit",
                              "-board: pair collector", "-bridge: DMA engine", "-PCI bus", "-interrupts"}) {
        EXPECT_NE(save.find(group), std::string::npos) << group;
    }
    // Named states through translate filters; box addresses in decimal (flags 0x24).
    EXPECT_NE(save.find("^2 " + here + "/waves.controller-states.txt\n" + kControl + "state[1:0]"), std::string::npos);
    EXPECT_NE(save.find("^1 " + here + "/waves.dma-states.txt\nSystemC.platform.bridge.dma.state[1:0]"),
              std::string::npos);
    EXPECT_EQ(slurp(dir_ / "waves.controller-states.txt"), "0 idle\n1 running\n2 paused\n3 done\n");
    EXPECT_EQ(slurp(dir_ / "waves.dma-states.txt"), "0 idle\n1 to_board\n2 to_host\n3 failed\n");
    EXPECT_NE(save.find("@24\nSystemC.platform.board.address_generator.address_0["), std::string::npos);
    const std::string command = "vcd2fst '" + (dir_ / "waves.vcd").string() + "' '" + (dir_ / "waves.fst").string() +
                                "' > /dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0);
}

// One state bit set at every moment, from time 0 on: the controller is idle
// before START, and each command's state shows when it is taken.
TEST_F(Cli, ControllerStateBitsFromTimeZero) {
    ASSERT_EQ(run("run --scene spheres --objects 30 --frames 2 --m 2 --board adm-xrc-ii --vcd w.vcd -q").status, 0);
    const cdvp::test::Vcd vcd = cdvp::test::read_vcd_text(slurp(dir_ / "w.vcd"));
    EXPECT_EQ(vcd.value_at(kControl + "idle", 0), "1");
    EXPECT_EQ(vcd.value_at(kControl + "state[1:0]", 0), "0");
    const std::string save = slurp(dir_ / "w.gtkw");
    const uint64_t start = first_time(vcd, kControl + "running", "1");
    ASSERT_NE(start, UINT64_MAX);
    EXPECT_EQ(first_time(vcd, kControl + "idle", "0"), start) << "idle until START";
    std::map<std::string, bool> state_bits;  // by identifier
    for (const char* state : {"idle", "running", "paused", "done"}) state_bits[vcd.id_of.at(kControl + state)] = false;
    for (std::size_t k = 0; k < vcd.changes.size(); ++k) {
        const cdvp::test::VcdChange& c = vcd.changes[k];
        if (state_bits.count(c.id)) state_bits[c.id] = c.value == "1";
        if (k + 1 < vcd.changes.size() && vcd.changes[k + 1].time == c.time) continue;  // the moment is not over
        int set = 0;
        for (const auto& bit : state_bits) set += bit.second ? 1 : 0;
        ASSERT_EQ(set, 1) << "state bits at " << c.time << " fs";
    }
    // The first view: markers at that START and the DONE after it, the frame inside it.
    const uint64_t done = first_time(vcd, kControl + "done", "1");
    EXPECT_NE(save.find(" " + std::to_string(start) + " " + std::to_string(start) + " " + std::to_string(done) + " -1"),
              std::string::npos)
        << save.substr(0, 400);
    EXPECT_NE(save.find("[markername] ASTART\n[markername] BDONE\n"), std::string::npos);
    EXPECT_LE(setting(save, "timestart"), first_time(vcd, "SystemC.platform.bridge.dma.busy", "1"));
}

TEST_F(Cli, WaveformsAsFst) {
    const Result r = run("run --trace " + trace("small.csv") + " --m 2 --vcd w.fst --vcd-format fst -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"w.controller-states.txt", "w.dma-states.txt", "w.fst", "w.gtkw"}))
        << "the scratch VCD is gone";
    EXPECT_EQ(slurp(dir_ / "w.fst").rfind(std::string(1, '\0'), 0), 0u) << "an FST begins with its header block (0)";
    EXPECT_GT(fs::file_size(dir_ / "w.fst"), 200u);
    EXPECT_NE(slurp(dir_ / "w.gtkw").find("[dumpfile] \"" + fs::canonical(dir_).string() + "/w.fst\""),
              std::string::npos);
    cdvp::test::expect_refusal(run("run --trace " + trace("small.csv") + " --vcd w.vcd --vcd-format lxt"),
                               "cdvp run: --vcd-format: expected vcd or fst, got 'lxt'");
    cdvp::test::expect_refusal(run("run --trace " + trace("small.csv") + " --vcd-format fst"),
                               "cdvp run: --vcd-format: the format of --vcd; give --vcd too");
    cdvp::test::expect_refusal(run("run --trace " + trace("small.csv") + " --vcd x.fst --vcd-format fst", "PATH=/none"),
                               "cdvp run: --vcd-format fst: needs vcd2fst on PATH");
    EXPECT_FALSE(fs::exists(dir_ / "x.fst"));
}

// A window of frames: only those are clocked edge by edge into the VCD.
TEST_F(Cli, WaveformsOfAWindowOfFrames) {
    const std::string scene = "run --scene spheres --objects 60 --frames 4 --m 2 -q";
    ASSERT_EQ(run(scene + " --vcd all.vcd --pairs-out all.csv").status, 0);
    ASSERT_EQ(run(scene + " --vcd one.vcd --vcd-frames 2:2 --pairs-out one.csv").status, 0);
    EXPECT_EQ(slurp(dir_ / "one.csv"), slurp(dir_ / "all.csv"));
    const auto all = fs::file_size(dir_ / "all.vcd"), one = fs::file_size(dir_ / "one.vcd");
    EXPECT_LT(one * 2, all) << "one frame of four traced";
    EXPECT_GT(one, 10000u) << "the window's frame is traced";
    // The view opens on frame 2, not at the run's start.
    EXPECT_GT(setting(slurp(dir_ / "one.gtkw"), "timestart"), setting(slurp(dir_ / "all.gtkw"), "timestart"));
    for (const char* bad : {"--vcd-frames 1:1", "--vcd one.vcd --vcd-frames 3:1", "--vcd one.vcd --vcd-frames 2",
                            "--vcd one.vcd --vcd-frames -1:2", "--vcd one.vcd --vcd-frames 4:9"}) {
        const Result r = run(scene + " " + bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_EQ(r.err.rfind("cdvp run: --vcd-frames: ", 0), 0u) << bad << ": " << r.err;
    }
}

// cdvp bullet --vcd: the board under a Bullet world, traced as cdvp run
// traces it, with the same save file and state names.
TEST_F(Cli, BulletTracesItsBoardAsRunDoes) {
    const std::string bullet = "bullet --scene stack --objects 10 --frames 2 --m 2 --board adm-xrc-ii -q ";
    const Result r = run(bullet + "--vcd w.vcd --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"r.json", "w.controller-states.txt", "w.dma-states.txt", "w.gtkw",
                                                 "w.vcd"}))
        << "no temporary left behind";
    const std::string text = slurp(dir_ / "w.vcd");
    EXPECT_NE(text.find("$timescale\n     1 fs\n$end"), std::string::npos) << text.substr(0, 200);
    const cdvp::test::Vcd vcd = cdvp::test::read_vcd_text(text);
    const std::string save = slurp(dir_ / "w.gtkw");
    EXPECT_NE(save.find("[dumpfile] \"" + fs::canonical(dir_).string() + "/w.vcd\""), std::string::npos) << save;
    const std::vector<std::string> signals = saved_signals(save);
    EXPECT_EQ(signals.size(), vcd.id_of.size()) << "every traced signal, once";
    for (const std::string& name : signals) EXPECT_EQ(vcd.id_of.count(name), 1u) << name << " is not in the VCD";
    EXPECT_GT(signals.size(), 20u);
    EXPECT_EQ(vcd.value_at(kControl + "idle", 0), "1");
    const uint64_t start = first_time(vcd, kControl + "running", "1");
    ASSERT_NE(start, UINT64_MAX) << "the board ran";
    EXPECT_NE(save.find("[markername] ASTART\n[markername] BDONE\n"), std::string::npos);
    EXPECT_EQ(slurp(dir_ / "w.controller-states.txt"), "0 idle\n1 running\n2 paused\n3 done\n");
    EXPECT_NE(slurp(dir_ / "r.json").find("\"fidelity\": \"cycle\""), std::string::npos) << "--vcd clocks the board";
    cdvp::test::expect_refusal(run(bullet + "--vcd x.vcd --fidelity fast"),
                               "cdvp bullet: --vcd: waveforms need the clocked engine or the RTL; --fidelity asks for fast");
    cdvp::test::expect_refusal(run(bullet + "--vcd x.vcd --vcd-frames 5:6"),
                               "cdvp bullet: --vcd-frames: 5:6 starts after the run's last frame 1");
    cdvp::test::expect_refusal(run(bullet + "--vcd-format fst"), "cdvp bullet: --vcd-format: the format of --vcd");
    EXPECT_FALSE(fs::exists(dir_ / "x.vcd"));
}

}  // namespace
