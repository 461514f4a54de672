#include "platform/virtual_board.h"

#include <stdexcept>

#include "platform/kernel.h"

namespace cdvp {

using namespace sc_core;

namespace {
std::shared_ptr<const BusTiming> bus_or_ideal(const std::shared_ptr<const BusTiming>& bus) {
    return bus ? bus : std::make_shared<IdealBusTiming>();
}
// The driver knows the board's memory as it knows the bitstream it loaded.
DriverConfig driver_for(const PlatformConfig& config) {
    DriverConfig driver = config.driver;
    driver.tiles = config.board.tiles;
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
      memory_("memory", BoardDriver::host_memory_bytes(capacity, config.board.collector.buffer_depth)),
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
    if (!vcd_base.empty()) {
        trace_ = sc_create_vcd_trace_file(vcd_base.c_str());
        if (trace_ == nullptr) throw std::runtime_error(vcd_base + ".vcd: cannot create waveform file");
        trace_->set_time_unit(1, SC_FS);  // the kernel's resolution: every edge lands exactly
        WaveList waves(trace_, "interrupts");
        waves.add(fpga_irq_, std::string(this->name()) + ".irq");
        waves.add(inta_, std::string(this->name()) + ".inta");
        bus_.trace(waves);
        bridge_.trace(waves);
        board_.trace(waves);
        traced_ = waves.signals();
    }
}

VirtualBoard::VirtualBoard(const sc_module_name& name, const BoardConfig& board, uint32_t capacity,
                           const std::string& vcd_base)
    : VirtualBoard(name, PlatformConfig{board, nullptr, DriverConfig{}, {}}, capacity, vcd_base) {}

VirtualBoard::~VirtualBoard() { close_trace(); }

void VirtualBoard::close_trace() {
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
    if (boxes.size() > board_.core().capacity()) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) +
                                    " boxes exceeds the board's capacity of " +
                                    std::to_string(board_.core().capacity()));
    }
    if (trace_ != nullptr) board_.set_tracing(number >= trace_first_ && number <= trace_last_);
    faults_.begin_frame(number);
    ++frames_;
    cpu_.submit(boxes);
    sc_start();  // returns when no activity is left: the frame is complete
    after_kernel_returns();
    if (!cpu_.finished()) throw std::runtime_error("the simulation stopped before the frame completed");
    if (cpu_.internal_error()) std::rethrow_exception(cpu_.internal_error());
    fault = cpu_.fault();
    return fault ? nullptr : &cpu_.result();
}

void VirtualBoard::set_trace_window(uint64_t first, uint64_t last) {
    trace_first_ = first;
    trace_last_ = last;
}

// GTKWave's save-file format: a group opens with flags 0x800200 and its
// title, closes with 0x1000200; @28 shows a bit, @22 a vector in hex. A
// vector is named with its bit range, as the VCD declares it.
void VirtualBoard::write_gtkw(std::ostream& out, const std::string& vcd_path) const {
    out << "[dumpfile] \"" << vcd_path << "\"\n[timestart] 0\n";
    std::string open_group;
    auto close = [&] {
        if (!open_group.empty()) out << "@1000200\n-" << open_group << '\n';
    };
    for (const TracedSignal& signal : traced_) {
        if (signal.group != open_group) {
            close();
            open_group = signal.group;
            out << "@800200\n-" << open_group << '\n';
        }
        if (signal.width == 1) out << "@28\n" << signal.name << '\n';
        else out << "@22\n" << signal.name << '[' << signal.width - 1 << ":0]\n";
    }
    close();
}

}  // namespace cdvp
