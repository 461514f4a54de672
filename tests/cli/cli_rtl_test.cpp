// `cdvp run --fidelity rtl`: the board RTL under Verilator behind the
// platform, held to the clocked engine through the whole run (pairs, every
// phase of every frame), with --lockstep, its waveforms, and refusals.
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "tests/support/vcd_reader.h"

namespace cdvp::test {
namespace {

// A built test variant (m=8, fifo=15, buffer=128, capacity=1024): 600 boxes
// pause on a full pair buffer and stall on the small FIFO.
const std::string kScene =
    "--board adm-xrc-ii --m 8 --fifo-depth 15 --pair-buffer 128 --scene spheres --objects 600 --frames 3 -q";

nlohmann::json frames_without_wall_time(const nlohmann::json& report) {
    nlohmann::json frames = report.at("frames");
    for (auto& frame : frames) {
        for (auto it = frame.begin(); it != frame.end();) {
            it = it.key().find("wall") != std::string::npos ? frame.erase(it) : std::next(it);
        }
    }
    return frames;
}

TEST_F(Cli, RtlRunsThePlatformAsTheClockedEngineDoes) {
    const Result cycle = run("run " + kScene + " --fidelity cycle --pairs-out c.csv --report c.json");
    ASSERT_EQ(cycle.status, 0) << cycle.err;
    for (const std::string& level : {std::string("rtl"), std::string("rtl --lockstep")}) {
        const Result r = run("run " + kScene + " --fidelity " + level + " --pairs-out r.csv --report r.json");
        ASSERT_EQ(r.status, 0) << level << ": " << r.err;
        EXPECT_EQ(slurp(dir_ / "r.csv"), slurp(dir_ / "c.csv")) << level;
        const nlohmann::json clocked = report_of(dir_ / "c.json");
        const nlohmann::json rtl = report_of(dir_ / "r.json");
        EXPECT_EQ(frames_without_wall_time(rtl), frames_without_wall_time(clocked)) << level;
        uint64_t pauses = 0, stalls = 0;
        for (const auto& frame : rtl.at("frames")) {
            pauses += frame.value("overflow_pauses", uint64_t{0});
            stalls += frame.value("stall_cycles", uint64_t{0});
        }
        EXPECT_GT(stalls, 0u) << "the scene should stall the FIFO";
        EXPECT_GT(pauses, 0u) << "the scene should fill the pair buffer";
        EXPECT_EQ(rtl.at("config").value("fidelity", std::string()), "rtl");
    }
}

TEST_F(Cli, RtlRefusesABoardItCannotRunAndLockstepWithoutRtl) {
    Result r = run("run --board adm-xrc-ii --drain-rate 2 --fidelity rtl --scene spheres --objects 60 --frames 1 "
                   "--report r.json");
    expect_refusal(r, "cdvp run: --fidelity rtl at 60 objects", "two pairs a cycle");
    EXPECT_NE(r.err.find("moves one pair a cycle into the pair buffer; drain_per_cycle is 2"), std::string::npos) << r.err;
    r = run("run --board adm-xrc-ii --lockstep --scene spheres --objects 60 --frames 1 --report r.json");
    expect_refusal(r, "cdvp run: --lockstep: compares the RTL with the clocked engine", "lockstep on fast");
    EXPECT_TRUE(files().empty() || files() == std::vector<std::string>{".config"}) << "no output left behind";
}

TEST_F(Cli, RtlVariantsListsWhatRunsAndEachListedBoardRuns) {
    const Result list = run("rtl-variants --json");
    ASSERT_EQ(list.status, 0) << list.err;
    const nlohmann::json variants = nlohmann::json::parse(list.out);
    ASSERT_GE(variants.size(), 3u);
    bool paper = false;
    for (const auto& v : variants) {
        paper |= v.at("m") == 8 && v.at("format") == "float32" && v.at("fifo_depth") == 512 && v.at("capacity") == 512;
    }
    EXPECT_TRUE(paper) << "the paper's board at m = 8 is built: " << list.out;
    const auto& first = variants.front();
    const Result r = run("run --board adm-xrc-ii --fidelity rtl --scene spheres --frames 1 -q --objects " +
                         std::to_string(first.at("capacity").get<uint64_t>() / 2) + " --m " +
                         std::to_string(first.at("m").get<uint32_t>()) + " --fifo-depth " +
                         std::to_string(first.at("fifo_depth").get<uint32_t>()) + " --pair-buffer " +
                         std::to_string(first.at("buffer_depth").get<uint32_t>()));
    EXPECT_EQ(r.status, 0) << r.err;
    const Result text = run("rtl-variants");
    EXPECT_EQ(text.status, 0);
    EXPECT_NE(text.out.find(first.at("spec").get<std::string>()), std::string::npos) << text.out;
    expect_refusal(run("rtl-variants --yaml"), "cdvp rtl-variants: unknown option '--yaml'; expected --json");
}

TEST_F(Cli, RtlWaveformsAreTheRtlsOwnSignalsWithASaveFile) {
    const Result r = run("run --board adm-xrc-ii --fidelity rtl --scene spheres --objects 40 --frames 2 -q --vcd w.vcd");
    ASSERT_EQ(r.status, 0) << r.err;
    const Vcd vcd = read_vcd_text(slurp(dir_ / "w.vcd"));
    const std::string save = slurp(dir_ / "w.gtkw");
    std::istringstream lines(save);
    uint64_t named = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || std::string("@-[*^").find(line[0]) != std::string::npos) continue;
        ++named;
        EXPECT_EQ(vcd.id_of.count(line), 1u) << line << " is not in the RTL's VCD";
    }
    EXPECT_GE(named, 15u);
    EXPECT_NE(save.find("board.collision_board_top.fifo_level"), std::string::npos);
    EXPECT_NE(save.find("[markername] ASTART"), std::string::npos);
    // Both frames' sweeps: the controller leaves idle (one-hot 1) for sweep (2) twice.
    uint64_t starts = 0;
    const std::string& state = vcd.id_of.at("board.collision_board_top.state[4:0]");
    for (const VcdChange& c : vcd.changes) starts += c.id == state && std::stoul(c.value, nullptr, 2) == 2;
    EXPECT_EQ(starts, 2u);
}

}  // namespace
}  // namespace cdvp::test
