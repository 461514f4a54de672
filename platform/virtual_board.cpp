#include "platform/virtual_board.h"

#include <cmath>
#include <stdexcept>

#include "models/rtl_engine/rtl_waves.h"
#include "platform/gtkw_save_file.h"
#include "platform/kernel.h"

namespace cdvp {

using namespace sc_core;

namespace {
// The run's pair budget bounds the driver's read-back.
DriverConfig driver_for(const PlatformConfig& config) {
    DriverConfig driver = config.driver;
    driver.pair_budget = config.pair_budget;
    return driver;
}

}  // namespace

VirtualBoard::VirtualBoard(const sc_module_name& name, const PlatformConfig& config, uint32_t capacity,
                           const std::string& vcd_base)
    : sc_module(name),
      faults_(config.faults),
      pair_budget_(config.pair_budget),
      board_("board", config.board, capacity, config.fidelity, config.pair_budget),
      bridge_("bridge", bus_or_ideal(config.bus)),
      bus_("pci", bus_or_ideal(config.bus)),
      memory_("memory", BoardDriver::host_memory_bytes(capacity, config.board.collector.buffer_depth, config.driver)),
      cpu_("cpu", memory_, bus_.interrupt_event(), board_.period(), driver_for(config), bus_or_ideal(config.bus),
           sc_time(config.quantum_ns, SC_NS)),
      fpga_irq_("fpga_irq"),
      inta_("inta") {
    cpu_.socket.bind(bus_.cpu_socket);
    bus_.board_socket.bind(bridge_.pci_target);
    bridge_.pci_master.bind(bus_.master_socket);
    bus_.memory_socket.bind(memory_.socket);
    bridge_.local_bus.bind(board_.socket);
    board_.irq.bind(fpga_irq_);
    bridge_.fpga_irq.bind(fpga_irq_);
    bridge_.inta.bind(inta_);
    bus_.inta.bind(inta_);
    if (!faults_.empty()) {
        board_.set_fault_plan(&faults_);
        bridge_.set_fault_plan(&faults_);
        bus_.set_fault_plan(&faults_);
    }
    if (!vcd_base.empty() && (config.fidelity == Fidelity::kRtl || config.fidelity == Fidelity::kLockstep)) {
        // The RTL's own signals, from Verilator, in place of the platform's.
        traced_ = board_.trace_rtl(vcd_base + ".vcd");
        rtl_traced_ = true;
    } else if (!vcd_base.empty()) {
        trace_ = sc_create_vcd_trace_file(vcd_base.c_str());
        if (trace_ == nullptr) throw std::runtime_error(vcd_base + ".vcd: cannot create waveform file");
        trace_->set_time_unit(1, SC_FS);  // the kernel's resolution: every edge lands exactly
        SC_METHOD(show_interrupts);
        sensitive << fpga_irq_ << inta_;
        dont_initialize();
        WaveList waves(trace_, "interrupts");
        waves.add(interrupts_.shown().irq, std::string(this->name()) + ".irq");
        waves.add(interrupts_.shown().inta, std::string(this->name()) + ".inta");
        bus_.add_waves(waves);
        bridge_.add_waves(waves);
        board_.add_waves(waves);
        traced_ = waves.signals();
    }
}

VirtualBoard::VirtualBoard(const sc_module_name& name, const BoardConfig& board, uint32_t capacity,
                           const std::string& vcd_base)
    : VirtualBoard(name, PlatformConfig{board, nullptr, DriverConfig{}, {}}, capacity, vcd_base) {}

VirtualBoard::~VirtualBoard() { close_trace(); }

void VirtualBoard::close_trace() {
    board_.close_rtl_trace();
    if (trace_ != nullptr) {
        sc_close_vcd_trace_file(trace_);
        trace_ = nullptr;
    }
}

const FrameResult& VirtualBoard::run_frame(const std::vector<FloatBox>& boxes) { return run_frame(boxes, frames_); }

const FrameResult& VirtualBoard::run_frame(const std::vector<FloatBox>& boxes, uint64_t number) {
    FrameFault fault;
    const FrameResult* result = try_run_frame(boxes, number, fault);
    if (result != nullptr) return *result;
    if (fault.kind == FrameFault::Kind::kTimeLimit) throw SimulatedTimeLimit(fault.message);
    if (fault.kind == FrameFault::Kind::kPairBudget) {
        throw PairBudgetExceeded(fault.pairs_found, pair_budget_.max_pairs());
    }
    throw DeviceFault(fault.message);
}

const FrameResult* VirtualBoard::try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                               FrameFault& fault) {
    return run_request(boxes, number, HostRequest::kFrame, fault);
}

const FrameResult* VirtualBoard::try_submit_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                                  FrameFault& fault) {
    if (!pipelined()) throw std::logic_error("try_submit_frame: the board has one box bank; use try_run_frame");
    return run_request(boxes, number, HostRequest::kSubmit, fault);
}

const FrameResult* VirtualBoard::try_finish_frames(FrameFault& fault) {
    static const std::vector<FloatBox> none;
    return run_request(none, frames_, HostRequest::kFinish, fault);
}

const FrameResult* VirtualBoard::run_request(const std::vector<FloatBox>& boxes, uint64_t number,
                                             HostRequest request, FrameFault& fault) {
    if (boxes.size() > board_.core().capacity()) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) +
                                    " boxes exceeds the board's capacity of " +
                                    std::to_string(board_.core().capacity()));
    }
    const bool tracing = trace_ != nullptr || rtl_traced_;
    const bool traced = tracing && number >= trace_first_ && number <= trace_last_;
    if (tracing) set_tracing(traced);
    const bool first_traced = traced && !first_traced_begin_;
    if (first_traced) first_traced_begin_ = sc_time_stamp();
    if (request != HostRequest::kFinish) {
        faults_.begin_frame(number);
        ++frames_;
    }
    cpu_.submit(boxes, request);
    sc_start();  // returns when no activity is left (or, kSubmit, when the frame has started)
    after_kernel_returns();
    if (first_traced) first_traced_end_ = sc_time_stamp();
    if (!cpu_.finished()) throw std::runtime_error("the simulation stopped before the frame completed");
    if (cpu_.internal_error()) std::rethrow_exception(cpu_.internal_error());
    // A lockstep engine's models parted: the run is wrong from there on (a cdvp bug).
    if (std::string divergence = board_.core().engine().divergence(); !divergence.empty()) {
        throw std::runtime_error(std::move(divergence));
    }
    fault = cpu_.fault();
    return fault || !cpu_.completed() ? nullptr : &cpu_.result();
}

void VirtualBoard::set_trace_window(uint64_t first, uint64_t last) {
    trace_first_ = first;
    trace_last_ = last;
}

void VirtualBoard::set_tracing(bool on) {
    board_.set_tracing(on);
    bridge_.set_tracing(on);
    bus_.set_tracing(on);
    interrupts_.set_open(on);
}

void VirtualBoard::show_interrupts() {
    interrupts_.live = Interrupts{fpga_irq_.read(), inta_.read()};
    interrupts_.show();
}

std::vector<const StateNames*> VirtualBoard::state_tables(bool rtl_waves) {
    if (rtl_waves) return {&rtl_controller_states()};
    return {&CollisionBoard::kControllerStates, &PciBridge::kDmaStates};
}

namespace {
// Femtoseconds, the platform's VCD unit, whatever the kernel's resolution.
uint64_t in_fs(const sc_time& t) {
    return t.value() * static_cast<uint64_t>(std::llround(sc_get_time_resolution().to_seconds() * 1e15));
}
}  // namespace

void VirtualBoard::write_gtkw(std::ostream& out, const std::string& dump_path,
                              const std::map<std::string, std::string>& filter_paths) const {
    SaveFile save{dump_path, traced_, {}, filter_paths};
    if (rtl_traced_) save.top_scope.clear();  // the RTL's names are full
    if (first_traced_begin_ && first_traced_end_) {
        save.view.begin_fs = in_fs(*first_traced_begin_);
        save.view.end_fs = in_fs(*first_traced_end_);
        if (const auto& start = board_.first_traced_start()) save.view.markers.push_back({"START", in_fs(*start)});
        if (const auto& done = board_.first_traced_done()) save.view.markers.push_back({"DONE", in_fs(*done)});
        // The RTL's dump holds the board alone: open on its first sweep, a
        // twentieth of it either side, not on the bus transfers around it.
        if (rtl_traced_ && save.view.markers.size() == 2) {
            const uint64_t start = save.view.markers[0].at_fs, done = save.view.markers[1].at_fs;
            const uint64_t margin = (done - start) / 20;
            save.view.begin_fs = start > margin ? start - margin : 0;
            save.view.end_fs = done + margin;
        }
    }
    write_save_file(out, save);
}

}  // namespace cdvp

// libsystemc.so refers to the program's sc_main (its own main calls it). A
// program that links the platform but elaborates no design before its own
// main returns (a study, a Python module, a benchmark, a run at the
// analytic level) need not write one: this weak one stands in, and a
// program's own sc_main takes its place.
extern "C" __attribute__((weak)) int sc_main(int, char*[]) { return 1; }
