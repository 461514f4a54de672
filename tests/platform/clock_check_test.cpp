// The board clock against its device's estimated Fmax (platform/device_fit):
// the speed grade from the device's name, the estimate as the slowest of the
// pieces the clock is held to and the whole board timed as one design (the
// pieces alone where no whole-board row is stored), the refusal naming where
// the clock came from and the piece or path, and run.ignore_timing turning it
// into a warning.
#include "platform/device_fit.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <map>
#include <sstream>
#include <string>

#include "models/common/number_text.h"
#include "models/common/user_text.h"
#include "models/resources/timing_model.h"
#include "platform/settings/board_preset.h"
#include "platform/settings/config_file.h"

namespace cdvp {
namespace {

constexpr uint64_t kBoxes = 500;

SettingValues preset(const std::string& name, const std::vector<std::string>& overrides = {}) {
    SettingValues values;
    values.apply(load_board_preset(name).values);
    std::vector<Assignment> layer;
    for (const std::string& text : overrides) layer.push_back(parse_override(text));
    values.apply(layer);
    return values;
}

std::string refusal(const SettingValues& values) {
    try {
        check_clock(values, kBoxes);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(SpeedGrade, ComesFromTheDeviceNameElseTheFamilysSlowest) {
    DeviceSettings device;
    device.family = DeviceFamily::kXc2v;
    device.name = "XC2V6000-4";
    EXPECT_EQ(speed_grade_of(device).grade, 4u);
    EXPECT_TRUE(speed_grade_of(device).named);
    device.name = "XC2V6000-6";
    EXPECT_EQ(speed_grade_of(device).grade, 6u);
    device.name = "XC2V6000";
    EXPECT_EQ(speed_grade_of(device).grade, 4u);
    EXPECT_FALSE(speed_grade_of(device).named);
    device.name = "XC2V6000-9";
    EXPECT_THROW(speed_grade_of(device), std::invalid_argument);
    device.family = DeviceFamily::kXcup;
    device.name = "XCVU9P";
    EXPECT_EQ(speed_grade_of(device).grade, 1u);
    device.name = "XCVU9P-L2";  // not a grade: a letter before the digits
    EXPECT_FALSE(speed_grade_of(device).named);
}

double slowest_ns(const std::vector<PieceTiming>& pieces) {
    double slowest = 0;
    for (const PieceTiming& piece : pieces) slowest = std::max(slowest, piece.path.ns);
    return slowest;
}

TEST(DeviceFitTiming, TheEstimateIsTheSlowestPieceTheClockIsHeldTo) {
    const DeviceFit fit = fit_on_device(preset("adm-xrc-ii").settings(), kBoxes);
    EXPECT_EQ(fit.speed_grade.grade, 4u);
    // The lane, address generator, pair FIFO and controller, and the whole
    // board as one design: its row is stored at the preset's default m.
    ASSERT_EQ(fit.timing.pieces.size(), 5u);
    EXPECT_EQ(fit.timing.pieces.back().key, "whole_board");
    EXPECT_EQ(fit.timing.whole_board_missing, "");
    EXPECT_TRUE(fit.timing.awaiting_pipelining.empty());
    EXPECT_DOUBLE_EQ(fit.timing.fmax_mhz(), 1e3 / slowest_ns(fit.timing.pieces));
    EXPECT_EQ(fit.timing.pieces[0].piece, "float32 comparison lane at compare latency 2");
    EXPECT_EQ(fit.clock_mhz, 66.0);
    // A faster grade of the same part is faster.
    const DeviceFit fast = fit_on_device(preset("adm-xrc-ii", {"device.name=XC2V6000-6"}).settings(), kBoxes);
    EXPECT_GT(fast.timing.fmax_mhz(), fit.timing.fmax_mhz());
    // Fixed-point lanes are faster than float32 ones.
    const DeviceFit fixed = fit_on_device(preset("adm-xrc-ii", {"board.format=fixed16"}).settings(), kBoxes);
    EXPECT_LT(fixed.timing.pieces[0].path.ns, fit.timing.pieces[0].path.ns);
}

TEST(DeviceFitTiming, AGridBoardIsHeldToItsCellLoaderAndReportsItsOtherPiecesTheSeedsBoardToNone) {
    const DeviceFit grid = fit_on_device(preset("adm-xrc-ii", {"board.algorithm=grid"}).settings(), kBoxes);
    std::map<std::string, bool> held;  // key: whether the clock is held to it
    for (const PieceTiming& piece : grid.timing.pieces) held[piece.key] = true;
    for (const PieceTiming& piece : grid.timing.awaiting_pipelining) held[piece.key] = false;
    const bool pipelined = !kGridPiecesAwaitPipelining;
    for (const char* key : {"lane", "cell_loader", "controller"}) EXPECT_TRUE(held.at(key)) << key;
    // The FIFO behind the unregistered one-cell filter with them.
    for (const char* key : {"cell_function", "sequencer", "one_cell_filter", "pair_fifo"}) {
        EXPECT_EQ(held.at(key), pipelined) << key;
    }
    EXPECT_DOUBLE_EQ(grid.timing.fmax_mhz(), 1e3 / slowest_ns(grid.timing.pieces));
    const TimingTable& table = TimingTable::stored();
    EXPECT_GE(slowest_ns(grid.timing.pieces), table.cell_loader("xc2v", 4, "float32").ns);
    // The report lists them all (config.resources.timing), and which wait to be pipelined.
    const nlohmann::json report = timing_json(grid);
    for (const char* key : {"cell_function", "cell_loader", "sequencer", "one_cell_filter", "pair_fifo"}) {
        EXPECT_TRUE(report["pieces"].contains(key)) << key;
        EXPECT_FALSE(report["pieces"][key].contains("holds_clock")) << key;
    }
    EXPECT_EQ(report.contains("awaiting_pipelining"), kGridPiecesAwaitPipelining);
    // The seed's board has none of them.
    const DeviceFit seed = fit_on_device(preset("adm-xrc-ii").settings(), kBoxes);
    for (const PieceTiming& piece : seed.timing.pieces) {
        EXPECT_TRUE(piece.key != "cell_function" && piece.key != "cell_loader" && piece.key != "sequencer" &&
                    piece.key != "one_cell_filter")
            << piece.key;
    }
}

TEST(ClockCheck, AClockBeyondTheEstimateIsRefusedNamingItsOriginTheEstimateAndThePiece) {
    const SettingValues fine = preset("adm-xrc-ii");
    EXPECT_EQ(refusal(fine), "");
    const DeviceFit fit = fit_on_device(fine.settings(), kBoxes);
    char fmax[32];
    std::snprintf(fmax, sizeof fmax, "%.1f MHz", fit.timing.fmax_mhz());
    const std::string error = refusal(preset("adm-xrc-ii", {"board.clock_mhz=500"}));
    EXPECT_EQ(error.rfind("board.clock_mhz: 500.0 MHz is beyond the " + std::string(fmax) +
                              " the board reaches on the XC2V6000-4 (speed grade -4): its " +
                              fit.timing.limiting().piece + " takes ",
                          0),
              0u)
        << error;
    EXPECT_NE(error.find("(synthesis timing for xc2v); run.ignore_timing=yes runs it anyway"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
    // Without a speed grade in the name the family's slowest is assumed, and said.
    EXPECT_NE(refusal(preset("adm-xrc-ii", {"board.clock_mhz=500", "device.name=XC2V6000"}))
                  .find("(speed grade -4, the family's slowest)"),
              std::string::npos);
    // No device family: nothing to estimate, nothing refused.
    EXPECT_EQ(refusal(preset("adm-xrc-ii", {"board.clock_mhz=500", "device.family=none"})), "");
}

TEST(ClockCheck, AGridBoardsRefusalNamesTheGridPieceThatLimitsIt) {
    // On the XC2V6000-4 the float32 cell loader's own logic (10.40 ns) is slower than the lane
    // (10.15 ns): one of the grid's own pieces sets its Fmax.
    const TimingTable& table = TimingTable::stored();
    const double loader = table.cell_loader("xc2v", 4, "float32").ns;
    ASSERT_GT(loader, table.lane("xc2v", 4, "float32", 2).ns);
    const DeviceFit grid = fit_on_device(preset("adm-xrc-ii", {"board.algorithm=grid"}).settings(), kBoxes);
    const PieceTiming& limit = grid.timing.limiting();
    EXPECT_GE(limit.path.ns, loader);
    char expected[160];
    std::snprintf(expected, sizeof expected, "the board reaches on the XC2V6000-4 (speed grade -4): its %s takes %.2f ns a cycle",
                  limit.piece.c_str(), limit.path.ns);
    const std::string error = refusal(preset("adm-xrc-ii", {"board.algorithm=grid", "board.clock_mhz=500"}));
    EXPECT_NE(error.find(expected), std::string::npos) << error;
    EXPECT_DOUBLE_EQ(grid.timing.fmax_mhz(), 1e3 / limit.path.ns);
    // The preset's 66 MHz is within it.
    EXPECT_EQ(refusal(preset("adm-xrc-ii", {"board.algorithm=grid"})), "");
}

// The whole board as one design is slower than any of its pieces on the
// paper's board (paths between the pieces): a clock between the two is
// refused naming it, though every piece alone would meet it.
TEST(ClockCheck, AClockBeyondTheWholeBoardButWithinEveryPieceIsRefusedNamingTheWholeBoard) {
    const DeviceFit fit = fit_on_device(preset("adm-xrc-ii").settings(), kBoxes);
    ASSERT_EQ(fit.timing.limiting().key, "whole_board");
    std::vector<PieceTiming> pieces = fit.timing.pieces;
    pieces.pop_back();
    const double pieces_mhz = 1e3 / slowest_ns(pieces);
    const double between = (fit.timing.fmax_mhz() + pieces_mhz) / 2;
    ASSERT_GT(between, fit.timing.fmax_mhz());
    const std::string error =
        refusal(preset("adm-xrc-ii", {"board.clock_mhz=" + std::to_string(between)}));
    EXPECT_NE(error.find("(speed grade -4): its whole board as one design (longest path: "), std::string::npos)
        << error;
    EXPECT_NE(error.find("; run.ignore_timing=yes runs it anyway"), std::string::npos) << error;
    const nlohmann::json report = timing_json(fit);
    EXPECT_EQ(report["fmax_from"], "every piece and the whole board as one design");
    EXPECT_EQ(report["pieces"]["whole_board"]["path_ns"], fit.timing.limiting().path.ns);
}

// A board the whole-board table has no row for (boxes in SSRAM tiles, an m
// past the stored ones) is held to its pieces alone, and its report says so.
TEST(ClockCheck, WithoutAWholeBoardRowTheFmaxIsThePiecesAndTheReportSaysSo) {
    const DeviceFit tiled = fit_on_device(preset("adm-xrc-ii", {"board.memory=ssram"}).settings(), kBoxes);
    ASSERT_EQ(tiled.timing.pieces[1].key, "tile_walker");
    EXPECT_EQ(tiled.timing.whole_board_missing,
              "no whole-board timing of the all-pairs board with its boxes in SSRAM tiles");
    for (const PieceTiming& piece : tiled.timing.pieces) EXPECT_NE(piece.key, "whole_board");
    EXPECT_DOUBLE_EQ(tiled.timing.fmax_mhz(), 1e3 / slowest_ns(tiled.timing.pieces));
    const nlohmann::json report = timing_json(tiled);
    EXPECT_EQ(report["fmax_from"],
              "the pieces alone: no whole-board timing of the all-pairs board with its boxes in SSRAM tiles");
    EXPECT_FALSE(report["pieces"].contains("whole_board"));
    EXPECT_NE(timing_summary(tiled).find("; from the pieces alone: no whole-board timing of "), std::string::npos)
        << timing_summary(tiled);
}

TEST(ClockCheck, IgnoreTimingWarnsInsteadAndAnUnknownGradeIsRefused) {
    const std::optional<std::string> warning =
        check_clock(preset("adm-xrc-ii", {"board.clock_mhz=500", "run.ignore_timing=yes"}), kBoxes);
    ASSERT_TRUE(warning.has_value());
    EXPECT_EQ(warning->rfind("board.clock_mhz: 500.0 MHz is beyond the ", 0), 0u) << *warning;
    EXPECT_NE(warning->find("; running it anyway (run.ignore_timing=yes)"), std::string::npos) << *warning;
    EXPECT_EQ(refusal(preset("adm-xrc-ii", {"device.name=XC2V6000-7"})),
              "device.name: speed grade -7 of XC2V6000-7: the xc2v timing has -4, -5 or -6");
}

// A clock a hair past the estimate reads as past it: the two figures are
// printed to the decimals that tell them apart, on either board and preset.
TEST(ClockCheck, TheRefusalsFiguresDifferAsTheValuesDo) {
    for (const char* board : {"adm-xrc-ii", "adm-xrc-ii-64", "alveo-u250", "pcie-gen3-x8"}) {
        for (const char* algorithm : {"all_pairs", "grid"}) {
            SCOPED_TRACE(std::string(board) + " " + algorithm);
            const SettingValues fitted = preset(board, {std::string("board.algorithm=") + algorithm});
            if (!has_device_family(fitted.settings())) continue;
            const double fmax = fit_on_device(fitted.settings(), kBoxes).timing.fmax_mhz();
            char above[48];
            std::snprintf(above, sizeof above, "%.17g", fmax + 0.004);
            const std::string error =
                refusal(preset(board, {std::string("board.algorithm=") + algorithm,
                                       std::string("board.clock_mhz=") + above}));
            const std::size_t beyond = error.find(" MHz is beyond the ");
            ASSERT_NE(beyond, std::string::npos) << error;
            const std::size_t start = error.find(": ") + 2;
            const std::string clock = error.substr(start, beyond - start);
            const std::size_t from = beyond + 19;
            const std::string estimate = error.substr(from, error.find(" MHz", from) - from);
            EXPECT_NE(clock, estimate) << error;
            EXPECT_GT(std::stod(clock), std::stod(estimate)) << error;
        }
    }
    const auto [a, b] = distinct_figures(96.2, 96.19, 1);
    EXPECT_EQ(a + " " + b, "96.20 96.19");
    const auto [c, d] = distinct_figures(500, 96.19, 1);
    EXPECT_EQ(c + " " + d, "500.0 96.2");
    const auto [e, f] = distinct_figures(7, 7, 1);
    EXPECT_EQ(e + " " + f, "7.0 7.0");
}

}  // namespace
}  // namespace cdvp
