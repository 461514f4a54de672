#include "platform/virtual_board.h"

#include <stdexcept>

namespace cdvp {

using namespace sc_core;

namespace {
std::shared_ptr<const BusTiming> bus_or_ideal(const std::shared_ptr<const BusTiming>& bus) {
    return bus ? bus : std::make_shared<IdealBusTiming>();
}
}  // namespace

VirtualBoard::VirtualBoard(const sc_module_name& name, const PlatformConfig& config, uint32_t capacity,
                           const std::string& vcd_base)
    : sc_module(name),
      faults_(config.faults),
      board_("board", config.board, capacity),
      bridge_("bridge", bus_or_ideal(config.bus)),
      bus_("pci", bus_or_ideal(config.bus)),
      memory_("memory", BoardDriver::host_memory_bytes(capacity, config.board.collector.buffer_depth)),
      cpu_("cpu", memory_, bus_.interrupt_event(), board_.period(), config.driver, bus_or_ideal(config.bus)),
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
        board_.trace(trace_);
        sc_trace(trace_, fpga_irq_, std::string(this->name()) + ".irq");
        sc_trace(trace_, inta_, std::string(this->name()) + ".inta");
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
    throw DeviceFault(fault.message);
}

const FrameResult* VirtualBoard::try_run_frame(const std::vector<FloatBox>& boxes, uint64_t number,
                                               FrameFault& fault) {
    if (boxes.size() > board_.core().capacity()) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) +
                                    " boxes exceeds the board's capacity of " +
                                    std::to_string(board_.core().capacity()));
    }
    faults_.begin_frame(number);
    ++frames_;
    cpu_.submit(boxes);
    sc_start();  // returns when no activity is left: the frame is complete
    if (!cpu_.finished()) throw std::runtime_error("the simulation stopped before the frame completed");
    if (cpu_.internal_error()) std::rethrow_exception(cpu_.internal_error());
    fault = cpu_.fault();
    return fault ? nullptr : &cpu_.result();
}

}  // namespace cdvp
