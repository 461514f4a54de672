#include "platform/host_cpu.h"

#include <exception>
#include <stdexcept>

#include "models/common/transaction.h"

namespace cdvp {

using namespace sc_core;

HostCpu::HostCpu(const sc_module_name& name, HostMemory& memory, const sc_event& interrupt, const sc_time& period,
                 const DriverConfig& config, std::shared_ptr<const BusTiming> bus)
    : sc_module(name),
      socket("socket"),
      memory_(memory),
      interrupt_(interrupt),
      driver_(*this, period.value(), config, std::move(bus)) {
    if (sc_get_time_resolution() != sc_time(1, SC_FS)) {
        throw std::logic_error("the host port counts femtoseconds: call configure_kernel() before elaborating");
    }
    SC_THREAD(run);
}

std::string HostCpu::transport(tlm::tlm_command command, uint64_t address, void* data, uint32_t length) {
    tlm::tlm_generic_payload p;
    prepare_transaction(p, command, address, data, length);
    sc_time delay = SC_ZERO_TIME;
    socket->b_transport(p, delay);
    sc_module::wait(delay);
    return p.is_response_error() ? p.get_response_string() : std::string();
}

std::string HostCpu::read(uint64_t address, void* data, uint32_t length) {
    return transport(tlm::TLM_READ_COMMAND, address, data, length);
}

std::string HostCpu::write(uint64_t address, const void* data, uint32_t length) {
    // The target reads the data only; TLM's data pointer is not const.
    return transport(tlm::TLM_WRITE_COMMAND, address, const_cast<void*>(data), length);
}

unsigned char* HostCpu::memory(uint64_t address) { return memory_.data(address); }
uint64_t HostCpu::memory_size() const { return memory_.size(); }
SimTime HostCpu::now() const { return sc_time_stamp().value(); }
SimTime HostCpu::end_of_time() const { return sc_max_time().value(); }
void HostCpu::wait(SimTime duration) { sc_module::wait(sc_time::from_value(duration)); }
void HostCpu::wait_for_interrupt(SimTime timeout) { sc_module::wait(sc_time::from_value(timeout), interrupt_); }

void HostCpu::submit(const std::vector<FloatBox>& boxes) {
    boxes_ = &boxes;
    pending_ = true;
    fault_ = FrameFault{};
    internal_error_ = nullptr;
    submitted_.notify(SC_ZERO_TIME);
}

void HostCpu::run() {
    for (;;) {
        // A frame submitted before the first sc_start is already pending when
        // the thread first runs, so test the flag before waiting.
        while (!pending_) sc_module::wait(submitted_);
        try {
            if (!opened_) {
                driver_.open();
                opened_ = true;
            }
            result_.phases = driver_.run_frame(*boxes_, result_.pairs);
        } catch (const DeviceFault& e) {
            fault_ = FrameFault{FrameFault::Kind::kDevice, e.what()};
        } catch (const SimulatedTimeLimit& e) {
            fault_ = FrameFault{FrameFault::Kind::kTimeLimit, e.what()};
        } catch (...) {
            internal_error_ = std::current_exception();
        }
        pending_ = false;
    }
}

}  // namespace cdvp
