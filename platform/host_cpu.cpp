#include "platform/host_cpu.h"

#include <exception>
#include <stdexcept>

#include "models/common/transaction.h"

namespace cdvp {

using namespace sc_core;

sc_time HostQuantumKeeper::compute_local_quantum() {
    if (quantum_ == SC_ZERO_TIME) return SC_ZERO_TIME;
    return quantum_ - sc_time::from_value(sc_time_stamp().value() % quantum_.value());
}

HostCpu::HostCpu(const sc_module_name& name, HostMemory& memory, const sc_event& interrupt, const sc_time& period,
                 const DriverConfig& config, std::shared_ptr<const BusTiming> bus, const sc_time& quantum)
    : sc_module(name),
      socket("socket"),
      memory_(memory),
      quantum_keeper_(quantum),
      interrupt_(interrupt),
      driver_(*this, period.value(), config, std::move(bus)) {
    if (sc_get_time_resolution() != sc_time(1, SC_FS)) {
        throw std::logic_error("the host port counts femtoseconds: call configure_kernel() before elaborating");
    }
    SC_THREAD(run);
    SC_METHOD(note_interrupt);
    sensitive << interrupt;
    dont_initialize();
}

std::string HostCpu::transport(tlm::tlm_command command, uint64_t address, void* data, uint32_t length) {
    tlm::tlm_generic_payload p;
    prepare_transaction(p, command, address, data, length);
    sc_time delay = quantum_keeper_.get_local_time();
    socket->b_transport(p, delay);
    quantum_keeper_.set_and_sync(delay);
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
SimTime HostCpu::now() const { return quantum_keeper_.get_current_time().value(); }
void HostCpu::wait(SimTime duration) {
    quantum_keeper_.inc(sc_time::from_value(duration));
    if (quantum_keeper_.need_sync()) quantum_keeper_.sync();
}

// An interrupt that came while the CPU ran ahead is taken at once, when the
// simulation has caught up: the handler runs late by up to a quantum, the
// loosely-timed error. Without a quantum the CPU is never ahead.
void HostCpu::wait_for_interrupt(SimTime timeout) {
    const sc_time asked = quantum_keeper_.get_current_time();
    const sc_time local = quantum_keeper_.get_local_time();
    if (local > SC_ZERO_TIME) {
        const sc_time before = sc_time_stamp();
        quantum_keeper_.sync();
        if (last_interrupt_ != sc_max_time() && last_interrupt_ >= before) return;
    }
    const sc_time waited = sc_time_stamp() - asked;
    const sc_time limit = sc_time::from_value(timeout);
    if (waited >= limit) return;
    sc_module::wait(limit - waited, interrupt_);
}

void HostCpu::wait_for_interrupt_since(SimTime since, SimTime timeout) {
    if (last_interrupt_ != sc_max_time() && last_interrupt_.value() >= since && last_interrupt_ != taken_interrupt_) {
        taken_interrupt_ = last_interrupt_;
        return;
    }
    wait_for_interrupt(timeout);
}

void HostCpu::submit(const std::vector<FloatBox>& boxes, HostRequest request) {
    boxes_ = &boxes;
    request_ = request;
    completed_ = false;
    pending_ = true;
    fault_ = FrameFault{};
    internal_error_ = nullptr;
    submitted_.notify(SC_ZERO_TIME);
}

void HostCpu::run() {
    quantum_keeper_.reset();
    for (;;) {
        // A frame submitted before the first sc_start is already pending when
        // the thread first runs, so test the flag before waiting.
        while (!pending_) sc_module::wait(submitted_);
        try {
            if (!opened_) {
                driver_.open();
                opened_ = true;
            }
            switch (request_) {
                case HostRequest::kFrame:
                    result_.phases = driver_.run_frame(*boxes_, result_.pairs);
                    completed_ = true;
                    break;
                case HostRequest::kSubmit:
                    completed_ = driver_.submit(*boxes_, result_.pairs, result_.phases);
                    break;
                case HostRequest::kFinish:
                    completed_ = driver_.finish(result_.pairs, result_.phases);
                    break;
            }
        } catch (const DeviceFault& e) {
            fault_ = FrameFault{FrameFault::Kind::kDevice, e.what()};
        } catch (const SimulatedTimeLimit& e) {
            fault_ = FrameFault{FrameFault::Kind::kTimeLimit, e.what()};
        } catch (const PairBudgetExceeded& e) {
            fault_ = FrameFault{FrameFault::Kind::kPairBudget, e.what(), e.found()};
        } catch (...) {
            internal_error_ = std::current_exception();
        }
        pending_ = false;
        // The frame started sweeps on: stop the kernel now, not when it
        // starves, so that the next frame's upload overlaps the sweep.
        if (request_ == HostRequest::kSubmit) sc_core::sc_pause();
    }
}

}  // namespace cdvp
