#include "platform/host_memory.h"

#include <cstring>

#include "models/common/address_range.h"
#include "models/common/transaction.h"

namespace cdvp {

HostMemory::HostMemory(const sc_core::sc_module_name& name, uint64_t bytes)
    : sc_module(name), socket("socket"), bytes_(bytes) {
    socket.register_b_transport(this, &HostMemory::b_transport);
}

void HostMemory::b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& /*delay*/) {
    const uint64_t address = payload.get_address();
    const uint64_t length = payload.get_data_length();
    if (const tlm::tlm_response_status shape = check_plain_access(payload); shape != tlm::TLM_OK_RESPONSE) {
        payload.set_response_status(shape);
        return;
    }
    if (!range_within(address, length, 0, bytes_.size())) {
        payload.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
        return;
    }
    if (length > 0) {
        if (payload.get_command() == tlm::TLM_READ_COMMAND) std::memcpy(payload.get_data_ptr(), &bytes_[address], length);
        else if (payload.get_command() == tlm::TLM_WRITE_COMMAND) std::memcpy(&bytes_[address], payload.get_data_ptr(), length);
    }
    payload.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace cdvp
