#include "host_system.h"

#include <cstring>
#include <stdexcept>

namespace example {

using namespace sc_core;

namespace {
bool within(uint64_t address, uint64_t length, uint64_t base, uint64_t size) {
    return address >= base && length <= size && address - base <= size - length;
}
}  // namespace

HostRam::HostRam(const sc_module_name& name, uint64_t bytes) : sc_module(name), socket("socket"), bytes_(bytes) {
    socket.register_b_transport(this, &HostRam::b_transport);
}

void HostRam::b_transport(tlm::tlm_generic_payload& payload, sc_time&) {
    const uint64_t address = payload.get_address();
    const unsigned length = payload.get_data_length();
    if (!within(address, length, 0, bytes_.size())) {
        payload.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
        return;
    }
    if (payload.is_read()) std::memcpy(payload.get_data_ptr(), bytes_.data() + address, length);
    if (payload.is_write()) std::memcpy(bytes_.data() + address, payload.get_data_ptr(), length);
    payload.set_response_status(tlm::TLM_OK_RESPONSE);
}

Interconnect::Interconnect(const sc_module_name& name) : sc_module(name), initiators("initiators"), targets("targets") {
    initiators.register_b_transport(this, &Interconnect::b_transport);
}

void Interconnect::add_route(uint64_t base, uint64_t size, double read_ns_per_word, double write_ns_per_word) {
    routes_.push_back({base, size, read_ns_per_word, write_ns_per_word});
}

void Interconnect::b_transport(int, tlm::tlm_generic_payload& payload, sc_time& delay) {
    const uint64_t address = payload.get_address();
    for (std::size_t target = 0; target < routes_.size(); ++target) {
        const Route& route = routes_[target];
        if (!within(address, payload.get_data_length(), route.base, route.size)) continue;
        const double words = (payload.get_data_length() + 3) / 4;
        delay += sc_time(words * (payload.is_read() ? route.read_ns_per_word : route.write_ns_per_word), SC_NS);
        payload.set_address(address - route.base);
        targets[static_cast<int>(target)]->b_transport(payload, delay);
        payload.set_address(address);  // the initiator's address again, as TLM-2.0 asks
        return;
    }
    payload.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
}

HostProcessor::HostProcessor(const sc_module_name& name, HostRam& ram, const sc_time& interrupt_latency,
                             Program program)
    : sc_module(name),
      socket("socket"),
      irq("irq"),
      ram_(ram),
      interrupt_latency_(interrupt_latency),
      program_(std::move(program)) {
    // HostPort keeps time in whole femtoseconds (platform/driver/host_port.h):
    // now() is the kernel's time value at a 1 fs resolution.
    if (sc_get_time_resolution() != sc_time(1, SC_FS)) throw std::logic_error("set a 1 fs time resolution first");
    SC_THREAD(run);
    SC_METHOD(raise_handler);
    sensitive << irq.pos();
    dont_initialize();
    SC_METHOD(note_handler);
    sensitive << handler_;
    dont_initialize();
}

void HostProcessor::run() {
    keeper_.reset();
    try {
        program_(*this);
    } catch (...) {
        failure_ = std::current_exception();
    }
    keeper_.sync();
}

std::string HostProcessor::transport(tlm::tlm_command command, uint64_t address, void* data, uint32_t length) {
    tlm::tlm_generic_payload payload;
    payload.set_command(command);
    payload.set_address(kBoardBarBase + address);
    payload.set_data_ptr(static_cast<unsigned char*>(data));
    payload.set_data_length(length);
    payload.set_streaming_width(length);
    payload.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = keeper_.get_local_time();
    socket->b_transport(payload, delay);
    keeper_.set_and_sync(delay);
    return payload.is_response_error() ? payload.get_response_string() : std::string();
}

std::string HostProcessor::read(uint64_t address, void* data, uint32_t length) {
    return transport(tlm::TLM_READ_COMMAND, address, data, length);
}

std::string HostProcessor::write(uint64_t address, const void* data, uint32_t length) {
    return transport(tlm::TLM_WRITE_COMMAND, address, const_cast<void*>(data), length);  // only read by the target
}

cdvp::SimTime HostProcessor::now() const { return keeper_.get_current_time().value(); }

void HostProcessor::wait(cdvp::SimTime duration) {
    keeper_.inc(sc_time::from_value(duration));
    if (keeper_.need_sync()) keeper_.sync();
}

// The CPU may be ahead of the rest of the system: catch up first, and a
// handler that ran while it was ahead counts as this wait's interrupt.
void HostProcessor::wait_for_interrupt(cdvp::SimTime timeout) {
    const sc_time asked = keeper_.get_current_time();
    const sc_time before = sc_time_stamp();
    if (keeper_.get_local_time() > SC_ZERO_TIME) {
        keeper_.sync();
        if (last_handler_ != sc_max_time() && last_handler_ >= before) return;
    }
    const sc_time waited = sc_time_stamp() - asked;
    const sc_time limit = sc_time::from_value(timeout);
    if (waited < limit) sc_module::wait(limit - waited, handler_);
    keeper_.reset();
}

}  // namespace example
