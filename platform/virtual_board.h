// The virtual platform: host PC (CPU thread with driver, host memory) and the
// collision board (PCI bridge, local bus, FPGA), joined by the PCI bus.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <systemc>

#include "models/board/collision_board.h"
#include "models/common/wave_list.h"
#include "models/fast_engine/pair_memo.h"
#include "models/pci/pci_bridge.h"
#include "models/pci/pci_bus.h"
#include "platform/frame_platform.h"
#include "platform/host_cpu.h"
#include "platform/host_memory.h"

namespace cdvp {

struct PlatformConfig {
    BoardConfig board;
    // The host bus; null means an ideal one (no communication cost), which
    // leaves only the board's compute time.
    std::shared_ptr<const BusTiming> bus;
    DriverConfig driver;
    // Faults to inject (docs/faults.md); empty for none.
    std::vector<FaultSpec> faults;
    // The board's engine: clocked (edge by edge) or fast (result-oriented);
    // both give the same pairs, cycles and times. Waveforms need the clocked one.
    Fidelity fidelity = Fidelity::kCycle;
    // How far the host CPU may run ahead of the rest of the simulation, in
    // ns; 0 synchronises at every access (exact). See HostCpu.
    double quantum_ns = 0.0;
    // The most pairs a frame may hold, in the fast engine's search and the
    // driver's read-back (models/common/pair_budget.h); unlimited by default.
    PairBudget pair_budget{};
    // Pairs found before, shared by the runs of one process (a sweep's
    // analytic points); the analytic level asks it first. Null: none kept.
    std::shared_ptr<PairMemo> pair_memo{};
};

// Elaborate once, then run any number of frames: each run_frame() hands the
// boxes to the CPU thread and simulates until all is idle again (the board's
// clock does not tick between frames, so the kernel simply starves).
class VirtualBoard : public sc_core::sc_module, public FramePlatform {
public:
    SC_HAS_PROCESS(VirtualBoard);

    // capacity: the most boxes any frame will hold (sizes the coordinate memories).
    // vcd_base: when not empty, waveforms go to vcd_base + ".vcd".
    VirtualBoard(const sc_core::sc_module_name& name, const PlatformConfig& config, uint32_t capacity,
                 const std::string& vcd_base = "");
    // The board alone on an ideal bus.
    VirtualBoard(const sc_core::sc_module_name& name, const BoardConfig& board, uint32_t capacity,
                 const std::string& vcd_base = "");
    ~VirtualBoard() override;

    // Runs the frame numbered 'number' (a trace's own frame number: the
    // number --inject's frame=N selects). Returns the result, or null with
    // fault set when the simulated system faulted; never partial pairs.
    const FrameResult* try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) override;
    // The same, throwing DeviceFault, SimulatedTimeLimit or PairBudgetExceeded for a fault (for
    // callers that never run under AddressSanitizer's checks of the main
    // stack, such as tests). Without a number, frames are numbered 0, 1, 2, ...
    const FrameResult& run_frame(const std::vector<FloatBox>& boxes);
    const FrameResult& run_frame(const std::vector<FloatBox>& boxes, uint64_t number);

    // Frames pipelined, on a board with two box banks (config.board.box_banks
    // = 2): try_submit_frame runs the host until frame `number` has started
    // and the frame before it is read back, and returns that frame's result
    // (null, fault unset, on the first call; null with fault set for a
    // fault, which ends every frame in flight); the board sweeps on between
    // calls. try_finish_frames completes the frame in flight (null, fault
    // unset, when none is). A trace window counts the calls' numbers.
    bool pipelined() const override { return board_.core().config().box_banks > 1; }
    const FrameResult* try_submit_frame(const std::vector<FloatBox>& boxes, uint64_t number, FrameFault& fault) override;
    const FrameResult* try_finish_frames(FrameFault& fault) override;
    const FaultPlan& faults() const { return faults_; }
    // Flushes and closes the waveform file (also done by the destructor).
    void close_trace();
    // Traces only frames numbered first..last (a window): the others run as
    // untraced ones do, and every signal keeps its value through them.
    void set_trace_window(uint64_t first, uint64_t last);
    // A GTKWave save file for the waveforms in dump_path (the VCD, or an FST
    // made from it): every traced signal by its full name, grouped by block,
    // in a fitting format, state vectors translated by the filter files
    // (filter_paths, by table: see state_tables()), opening on the first
    // traced frame with markers at its START and DONE.
    void write_gtkw(std::ostream& out, const std::string& dump_path,
                    const std::map<std::string, std::string>& filter_paths) const;
    // The named-state tables the waveforms use, each a translate filter
    // file: the platform's (the controller's and the DMA engine's), or with
    // rtl_waves (--fidelity rtl) the RTL controller's alone.
    static std::vector<const StateNames*> state_tables(bool rtl_waves);

    const CollisionBoard& board() const { return board_; }
    const PciBridge& bridge() const { return bridge_; }
    const BusTiming& bus_timing() const override { return bus_.timing(); }

private:
    FaultPlan faults_;
    PairBudget pair_budget_;
    uint64_t frames_ = 0;
    CollisionBoard board_;
    PciBridge bridge_;
    PciBus bus_;
    HostMemory memory_;
    HostCpu cpu_;
    sc_core::sc_signal<bool> fpga_irq_;
    sc_core::sc_signal<bool> inta_;
    void show_interrupts();
    void set_tracing(bool on);
    // Runs the CPU thread on a request for frame `number`; the result as try_run_frame's.
    const FrameResult* run_request(const std::vector<FloatBox>& boxes, uint64_t number, HostRequest request,
                                   FrameFault& fault);

    sc_core::sc_trace_file* trace_ = nullptr;
    bool rtl_traced_ = false;  // the RTL's waveforms (Verilator's VCD) instead
    std::vector<TracedSignal> traced_;
    uint64_t trace_first_ = 0;
    uint64_t trace_last_ = UINT64_MAX;
    // The interrupt lines as traced: gated like the blocks' waveforms.
    struct Interrupts {
        bool irq = false, inta = false;
    };
    GatedWaves<Interrupts> interrupts_;
    // When the first traced frame began and ended: the save file's first view.
    std::optional<sc_core::sc_time> first_traced_begin_, first_traced_end_;
};

}  // namespace cdvp
