#include "platform/simple_host.h"

#include <stdexcept>

#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"

namespace cdvp {

using namespace sc_core;
using R = ControlRegisters;

SimpleHost::SimpleHost(const sc_module_name& name) : sc_module(name), socket("socket"), irq("irq") {
    SC_THREAD(run);
}

void SimpleHost::submit(const std::vector<FloatBox>& boxes) {
    boxes_ = &boxes;
    pending_ = true;
    error_.clear();
    submitted_.notify(SC_ZERO_TIME);
}

void SimpleHost::run() {
    for (;;) {
        // A frame submitted before the first sc_start is already pending when
        // the thread first runs, so test the flag before waiting.
        while (!pending_) wait(submitted_);
        try {
            process_frame();
        } catch (const std::exception& e) {
            error_ = e.what();
        }
        pending_ = false;
    }
}

void SimpleHost::transfer(tlm::tlm_command command, uint64_t address, void* data, unsigned int length) {
    tlm::tlm_generic_payload payload;
    payload.set_command(command);
    payload.set_address(address);
    payload.set_data_ptr(static_cast<unsigned char*>(data));
    payload.set_data_length(length);
    payload.set_streaming_width(length);
    payload.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = SC_ZERO_TIME;
    socket->b_transport(payload, delay);
    if (payload.is_response_error()) {
        throw std::runtime_error("board access at 0x" + std::to_string(address) + " failed: " +
                                 payload.get_response_string());
    }
    wait(delay);
}

uint32_t SimpleHost::read_word(uint64_t address) {
    uint32_t value = 0;
    transfer(tlm::TLM_READ_COMMAND, address, &value, 4);
    return value;
}

uint64_t SimpleHost::read_counter(uint32_t low_offset) {
    const uint64_t low = read_word(low_offset);
    return low | static_cast<uint64_t>(read_word(low_offset + 4)) << 32;
}

void SimpleHost::read_pair_buffer() {
    const uint32_t count = read_word(R::kPairCount);
    if (count == 0) return;
    std::vector<uint32_t> words(2 * static_cast<size_t>(count));
    transfer(tlm::TLM_READ_COMMAND, address_map::kPairBuffer, words.data(), 8 * count);
    for (uint32_t k = 0; k < count; ++k) result_.pairs.push_back({words[2 * k], words[2 * k + 1]});
}

void SimpleHost::process_frame() {
    const std::vector<FloatBox>& boxes = *boxes_;
    const auto n = static_cast<uint32_t>(boxes.size());
    result_ = FrameResult{};
    if (n > 0) {
        // One burst per coordinate memory.
        std::vector<uint32_t> words(n);
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            for (uint32_t i = 0; i < n; ++i) {
                const FloatBox& b = boxes[i];
                words[i] = ComparisonUnit::as_bits(c < 3 ? b.min[c] : b.max[c - 3]);
            }
            transfer(tlm::TLM_WRITE_COMMAND, address_map::kCoordinateBase + c * address_map::kWindowSize,
                     words.data(), 4 * n);
        }
    }
    write_word(R::kObjectCount, n);
    result_.started = sc_time_stamp();
    write_word(R::kControl, R::kStart);
    if (read_word(R::kStatus) & R::kError) throw std::runtime_error("the board refused to start");
    for (;;) {
        wait(irq.posedge_event());
        const uint32_t status = read_word(R::kStatus);
        read_pair_buffer();
        if (status & R::kOverflow) {
            ++result_.overflow_pauses;
            write_word(R::kControl, R::kResume);
            continue;
        }
        if (status & R::kDone) break;
        throw std::runtime_error("interrupt with unexpected status " + std::to_string(status));
    }
    result_.compute_cycles = read_counter(R::kCyclesLo);
    result_.stall_cycles = read_counter(R::kStallsLo);
    const uint64_t found = read_counter(R::kTotalPairsLo);
    if (found != result_.pairs.size()) {
        throw std::runtime_error("the board found " + std::to_string(found) + " pairs but " +
                                 std::to_string(result_.pairs.size()) + " were read back");
    }
    result_.finished = sc_time_stamp();
}

}  // namespace cdvp
