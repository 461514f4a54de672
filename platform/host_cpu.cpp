#include "platform/host_cpu.h"

#include <exception>

namespace cdvp {

using namespace sc_core;

HostCpu::HostCpu(const sc_module_name& name, HostMemory& memory, const sc_event& interrupt, const sc_time& period,
                 const DriverConfig& config, std::shared_ptr<const BusTiming> bus)
    : sc_module(name),
      socket("socket"),
      driver_([this](tlm::tlm_generic_payload& p, sc_time& d) { socket->b_transport(p, d); }, memory, interrupt,
              period, config, std::move(bus)) {
    SC_THREAD(run);
}

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
        while (!pending_) wait(submitted_);
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
