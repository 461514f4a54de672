#include "models/rtl_engine/rtl_waves.h"

#include <string>

namespace cdvp {

namespace {
int log2_ceiling(uint64_t value) {  // Verilog's $clog2
    int bits = 0;
    while ((uint64_t{1} << bits) < value) ++bits;
    return bits;
}
}  // namespace

const StateNames& rtl_controller_states() {
    static const StateNames states = [] {
        StateNames one_hot{"controller", std::vector<std::string>(RtlProbes::kDone + 1)};
        one_hot.names[RtlProbes::kIdle] = "idle";
        one_hot.names[RtlProbes::kSweep] = "sweep";
        one_hot.names[RtlProbes::kDrain] = "drain";
        one_hot.names[RtlProbes::kPaused] = "paused";
        one_hot.names[RtlProbes::kDone] = "done";
        return one_hot;
    }();
    return states;
}

std::vector<TracedSignal> rtl_waves(const RtlVariant& v) {
    const std::string top = "board." + v.top() + ".";
    const int aw = static_cast<int>(v.address_bits);
    const int lanes = static_cast<int>(2 * v.m - 1);
    const int buffer_bits = (v.buffer_depth > 1 ? log2_ceiling(v.buffer_depth) : 1) + 1;
    const int fifo_bits = log2_ceiling(uint64_t{v.fifo_depth} + 1);
    using F = WaveFormat;
    // The grid board's lanes read the cell buffer's positions (or the streamed
    // box), not an address generator's boxes; its boxes are in the SSRAM store.
    const std::string windows = v.grid ? "board: cell sweep" : "board: address generator";
    std::vector<TracedSignal> waves{
        {"board: host bus", "board.clk", 1, F::kBit},
        {"board: host bus", "board.addr", 28, F::kHex},
        {"board: host bus", "board.wdata", 32, F::kHex},
        {"board: host bus", "board.we", 1, F::kBit},
        {"board: host bus", "board.irq", 1, F::kBit},
        {"board: control", top + "state", 5, F::kNamed, &rtl_controller_states()},
        {"board: control", top + "enable", 1, F::kBit},
        {"board: control", top + "cycles", 64, F::kDecimal},
        {"board: control", top + "stalls", 64, F::kDecimal},
        {windows, top + "src_window", 1, F::kBit},
        {windows, top + "src_row", aw, F::kDecimal},
        {windows, top + "src_first", aw, F::kDecimal},
        {"board: comparison unit", top + "src_valid", lanes, F::kBinary},
        {"board: comparison unit", top + "pushed_hits", lanes, F::kBinary},
        {"board: pair collector", top + "fifo_level", fifo_bits, F::kDecimal},
        {"board: pair collector", top + "out_valid", 1, F::kBit},
        {"board: pair collector", top + "out_pair", 2 * aw, F::kHex},
        {"board: pair collector", top + "buffered", buffer_bits, F::kDecimal},
        {"board: pair collector", top + "total_pairs", 64, F::kDecimal},
    };
    if (v.grid) {
        // pass: 1 bounds, 2 setup, 3 count, 4 scan, 5 place, 6 cells, 7 large, 8 end (docs/grid_board.md).
        waves.push_back({"board: binning sequencer", top + "pass", 4, F::kDecimal});
        waves.push_back({"board: binning sequencer", top + "seq_box", aw + 1, F::kDecimal});
        waves.push_back({"board: binning sequencer", top + "seq_waiting", 1, F::kBit});
    }
    if (v.memory().has_ssram()) {
        const std::string store = v.grid ? "board: box store" : "board: tile loader";
        waves.push_back({store, "board.ssram_re", 1, F::kBit});
        waves.push_back({store, "board.ssram_addr", aw, F::kDecimal});
    }
    return waves;
}

}  // namespace cdvp
