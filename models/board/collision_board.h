// SystemC shell of the collision board: TLM-2.0 target socket, interrupt line,
// and the board's clock. The clock is computed from simulated time, as a timer
// peripheral computes its counter: one event per segment (START or RESUME to
// the next pause or done), and before each host access the board is brought
// to the edges elapsed since the segment began. Only while waveforms are
// traced does an event fire at every edge.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "models/board/board_core.h"
#include "models/clocked_engine/clocked_engine.h"
#include "models/common/fault_plan.h"
#include "models/common/wave_list.h"

namespace cdvp {

class RtlEngine;
class GridClockedEngine;

class CollisionBoard : public sc_core::sc_module {
public:
    SC_HAS_PROCESS(CollisionBoard);

    // Registers, coordinate memories and pair buffer (see address_map).
    tlm_utils::simple_target_socket<CollisionBoard> socket;
    // High while done or overflow: the host has work.
    sc_core::sc_out<bool> irq;

    CollisionBoard(const sc_core::sc_module_name& name, const BoardConfig& config, uint32_t capacity,
                   Fidelity fidelity = Fidelity::kCycle, PairBudget budget = {});

    const BoardCore& core() const { return core_; }
    // Faults to inject (board-error); null for none. Not owned.
    void set_fault_plan(FaultPlan* plan) { faults_ = plan; }
    const sc_core::sc_time& period() const { return period_; }

    using sc_core::sc_module::trace;
    // Adds the board's waveforms, scoped by block, to a trace file (before
    // the first sc_start). Needs the clocked engine (throws std::logic_error
    // otherwise). Without this call the board does no per-edge work at all.
    void add_waves(WaveList& waves);
    // The rtl and rtl-lockstep engines: the RTL's own signals, every one,
    // into `path` (Verilator's VCD in picoseconds of simulated time; each
    // command at the time the host's access takes effect). Returns the
    // signals a save file shows first. Throws std::logic_error for other engines.
    std::vector<TracedSignal> trace_rtl(const std::string& path);
    // Closes the RTL's waveform file (its last edges written).
    void close_rtl_trace();
    // Traced boards only: whether the following sweeps are clocked edge by
    // edge and sampled (a window of frames), or run as untraced ones do and
    // leave the waveforms holding. Switch between sweeps only.
    void set_tracing(bool on);
    // When the first traced sweep's START and DONE were taken, once seen.
    const std::optional<sc_core::sc_time>& first_traced_start() const { return first_traced_start_; }
    const std::optional<sc_core::sc_time>& first_traced_done() const { return first_traced_done_; }
    // The controller's states as the waveforms name them, in SweepState order.
    static const StateNames kControllerStates;

private:
    void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    unsigned int transport_dbg(tlm::tlm_generic_payload& payload);
    // Returns the TLM response for an access of len bytes at address.
    tlm::tlm_response_status access(tlm::tlm_command command, uint64_t address, unsigned char* data,
                                    unsigned int length);
    // Brings the board to the edges elapsed from the segment's start to `at`.
    void sync(const sc_core::sc_time& at);
    // After a host command taken at `at`: schedules the clock for a new
    // segment, or stops it.
    void schedule_clock(uint64_t segments_before, const sc_core::sc_time& at);
    void on_clock_event();  // the segment's end (or, traced, one rising edge)
    void clock_fall();      // traced clock only: the falling edge
    void on_state_change();  // traced only: a host command moved the controller
    void drive_irq();
    // Reads the controller and datapath into the waveforms.
    void sample_trace();
    bool clocked_edge_by_edge() const { return (traced_engine_ != nullptr || traced_grid_ != nullptr) && tracing_on_; }
    // The datapath's probes both clocked engines give alike.
    template <class Engine>
    void sample_datapath(const Engine& engine);

    BoardCore core_;
    sc_core::sc_time period_;
    sc_core::sc_time segment_start_;  // when the last START or RESUME was taken
    sc_core::sc_event clock_event_;
    sc_core::sc_event fall_;
    sc_core::sc_event irq_changed_;
    sc_core::sc_event state_changed_;
    FaultPlan* faults_ = nullptr;
    ClockedEngine* traced_engine_ = nullptr;  // set by add_waves() (the seed's board)
    GridClockedEngine* traced_grid_ = nullptr;  // set by add_waves() (the grid board)
    RtlEngine* traced_rtl_ = nullptr;         // set by trace_rtl()
    sc_core::sc_time access_time_;            // when the host access being served takes effect
    bool tracing_on_ = true;
    std::optional<sc_core::sc_time> first_traced_start_, first_traced_done_;

    // Waveform mirrors, updated at each traced edge and state change.
    struct Waves {
        bool clk = false;
        uint32_t state = 0;  // 0 idle, 1 running, 2 paused (overflow), 3 done
        std::array<bool, 4> in_state{};  // one bit per state, by name
        std::vector<uint32_t> address;  // 2m memory ports
        uint64_t lane_valid = 0;
        uint64_t lane_hit = 0;
        uint32_t fifo_level = 0;
        bool stall = false;
        uint32_t pair_count = 0;
        // A tiled board's loader: the block's tiles, a load under way, a bubble waiting for one.
        uint32_t row_tile = 0;
        uint32_t column_tile = 0;
        bool loading = false;
        bool wait = false;
        // The grid board's sequencer: its pass (GridClockedEngine::Pass, and
        // one bit a pass), the box it is at, the busy cell swept, the large tile.
        uint32_t grid_pass = 0;
        std::array<bool, 9> in_pass{};
        uint32_t grid_box = 0;
        uint32_t grid_cell = 0;
        uint32_t grid_tile = 0;
    };
    GatedWaves<Waves> waves_;
};

}  // namespace cdvp
