// One place to set up a plain TLM-2.0 read or write (no byte enables,
// streaming width = length), as the initiators of the platform issue them,
// and one place to check that a target received such an access.
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

// The platform's targets take whole-word reads and writes only: a partial
// write (some byte lanes disabled) is refused rather than half-applied.
inline bool all_bytes_enabled(const tlm::tlm_generic_payload& payload) {
    const unsigned char* mask = payload.get_byte_enable_ptr();
    if (mask == nullptr) return true;
    const unsigned int mask_length = payload.get_byte_enable_length();
    if (mask_length == 0) return false;
    for (unsigned int k = 0; k < payload.get_data_length(); ++k) {
        if (mask[k % mask_length] != TLM_BYTE_ENABLED) return false;
    }
    return true;
}

// The response for an access a target cannot take whatever its address:
// TLM_OK_RESPONSE when it is a plain read or write.
inline tlm::tlm_response_status check_plain_access(const tlm::tlm_generic_payload& payload) {
    if (payload.get_command() == tlm::TLM_IGNORE_COMMAND) return tlm::TLM_COMMAND_ERROR_RESPONSE;
    if (!all_bytes_enabled(payload)) return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
    if (payload.get_streaming_width() != payload.get_data_length()) return tlm::TLM_BURST_ERROR_RESPONSE;
    return tlm::TLM_OK_RESPONSE;
}

}  // namespace cdvp
