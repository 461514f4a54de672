// One place to set up a plain TLM-2.0 read or write (no byte enables,
// streaming width = length), as the initiators of the platform issue them.
#pragma once

#include <cstdint>

#include <tlm>

namespace cdvp {

inline void prepare_transaction(tlm::tlm_generic_payload& payload, tlm::tlm_command command, uint64_t address,
                                void* data, unsigned int length) {
    payload.set_command(command);
    payload.set_address(address);
    payload.set_data_ptr(static_cast<unsigned char*>(data));
    payload.set_data_length(length);
    payload.set_streaming_width(length);
    payload.set_byte_enable_ptr(nullptr);
    payload.set_byte_enable_length(0);
    payload.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
}

}  // namespace cdvp
