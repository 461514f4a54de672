// The board driven through its TLM socket and interrupt line by a test bench.
#include "models/board/collision_board.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include <tlm_utils/simple_initiator_socket.h>

#include "models/common/transaction.h"

namespace cdvp {
namespace {

using namespace sc_core;
using R = ControlRegisters;

// A test bench: an initiator socket, the interrupt line, and a thread that
// runs the test body and records what it saw.
struct Bench : sc_module {
    SC_HAS_PROCESS(Bench);
    tlm_utils::simple_initiator_socket<Bench> socket;
    sc_signal<bool> irq;
    CollisionBoard board;
    std::function<void(Bench&)> body;

    Bench(const sc_module_name& name, const BoardConfig& config, uint32_t capacity)
        : sc_module(name), socket("socket"), irq("irq"), board("board", config, capacity) {
        socket.bind(board.socket);
        board.irq.bind(irq);
        SC_THREAD(run);
    }
    void run() { body(*this); }

    tlm::tlm_response_status access(tlm::tlm_command command, uint64_t address, void* data, unsigned length,
                                    unsigned char* byte_enable = nullptr) {
        tlm::tlm_generic_payload p;
        prepare_transaction(p, command, address, data, length);
        p.set_byte_enable_ptr(byte_enable);
        p.set_byte_enable_length(byte_enable ? length : 0);
        sc_time delay = SC_ZERO_TIME;
        socket->b_transport(p, delay);
        wait(delay);
        return p.get_response_status();
    }
    uint32_t read(uint64_t address) {
        uint32_t v = 0;
        EXPECT_EQ(access(tlm::TLM_READ_COMMAND, address, &v, 4), tlm::TLM_OK_RESPONSE) << std::hex << address;
        return v;
    }
    void write(uint64_t address, uint32_t v) {
        EXPECT_EQ(access(tlm::TLM_WRITE_COMMAND, address, &v, 4), tlm::TLM_OK_RESPONSE) << std::hex << address;
    }
    void load(const std::vector<FloatBox>& boxes) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            for (uint32_t i = 0; i < boxes.size(); ++i) {
                const float v = c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3];
                write(address_map::kCoordinateBase + c * address_map::kWindowSize + 4 * i, ComparisonUnit::as_bits(v));
            }
        }
    }
};

void run_bench(const BoardConfig& config, uint32_t capacity, std::function<void(Bench&)> body) {
    Bench bench("bench", config, capacity);
    bench.body = std::move(body);
    sc_start();
}

TEST(CollisionBoard, InterruptRisesOnDoneAndCycleCounterMatchesTime) {
    BoardConfig config;
    config.m = 2;
    run_bench(config, 16, [&](Bench& b) {
        std::vector<FloatBox> boxes(16, FloatBox{{0, 0, 0}, {1, 1, 1}});
        b.load(boxes);
        EXPECT_EQ(b.read(R::kId), R::kIdValue);
        b.write(R::kObjectCount, 16);
        const sc_time started = sc_time_stamp();
        b.write(R::kControl, R::kStart);
        EXPECT_EQ(b.read(R::kStatus) & R::kBusy, uint32_t{R::kBusy});
        wait(b.irq.posedge_event());
        const uint32_t cycles = b.read(R::kCyclesLo);
        EXPECT_EQ(b.read(R::kStatus), uint32_t{R::kDone | R::kInterrupt}) << "done, holding the line";
        EXPECT_EQ(cycles, AddressGenerator::sweep_cycles(16, 2) + config.pipeline_latency() + b.read(R::kStallsLo));
        // The interrupt comes with the last clock edge: cycles periods after start.
        EXPECT_EQ(sc_time_stamp() - started, b.board.period() * cycles);
        EXPECT_EQ(b.read(R::kPairCount), 120u);
        EXPECT_EQ(b.read(R::kTotalPairsLo), 120u);
        // Pair k is two words: first index, then second.
        std::vector<uint32_t> words(240);
        EXPECT_EQ(b.access(tlm::TLM_READ_COMMAND, address_map::kPairBuffer, words.data(), 960), tlm::TLM_OK_RESPONSE);
        for (uint32_t k = 0; k < 120; ++k) EXPECT_LT(words[2 * k], words[2 * k + 1]);
        // A new start clears done and lowers the line.
        b.write(R::kControl, R::kStart);
        wait(SC_ZERO_TIME);
        wait(SC_ZERO_TIME);
        EXPECT_FALSE(b.irq.read());
        wait(b.irq.posedge_event());
        EXPECT_EQ(b.read(R::kPairCount), 120u);
    });
    EXPECT_FALSE(sc_pending_activity()) << "the clock must stop when the board is idle";
}

TEST(CollisionBoard, OverflowInterruptsAndResumes) {
    BoardConfig config;
    config.m = 3;
    config.collector.buffer_depth = 10;
    run_bench(config, 12, [&](Bench& b) {
        b.load(std::vector<FloatBox>(12, FloatBox{{0, 0, 0}, {1, 1, 1}}));
        b.write(R::kObjectCount, 12);
        b.write(R::kControl, R::kStart);
        uint32_t pairs = 0, pauses = 0;
        for (;;) {
            wait(b.irq.posedge_event());
            const uint32_t status = b.read(R::kStatus);
            pairs += b.read(R::kPairCount);
            if (status & R::kOverflow) {
                EXPECT_EQ(b.read(R::kPairCount), 10u);
                ++pauses;
                b.write(R::kControl, R::kResume);
                continue;
            }
            EXPECT_EQ(status, uint32_t{R::kDone | R::kInterrupt});
            b.write(R::kControl, R::kAcknowledge);
            EXPECT_EQ(b.read(R::kStatus), uint32_t{R::kDone}) << "ACKNOWLEDGE lowers the line, done stays";
            break;
        }
        EXPECT_EQ(pairs, 66u);
        EXPECT_EQ(pauses, 6u);
    });
}

TEST(CollisionBoard, RejectsBadAccesses) {
    BoardConfig config;
    config.m = 1;
    run_bench(config, 4, [&](Bench& b) {
        uint32_t v = 0;
        uint64_t two[2] = {};
        unsigned char enables[4] = {0xff, 0, 0xff, 0};
        EXPECT_EQ(b.access(tlm::TLM_READ_COMMAND, 0x0800'0000, &v, 4), tlm::TLM_ADDRESS_ERROR_RESPONSE);
        EXPECT_EQ(b.access(tlm::TLM_READ_COMMAND, 0x3F0, &v, 4), tlm::TLM_ADDRESS_ERROR_RESPONSE);
        EXPECT_EQ(b.access(tlm::TLM_READ_COMMAND, R::kStatus, two, 8), tlm::TLM_BURST_ERROR_RESPONSE);
        EXPECT_EQ(b.access(tlm::TLM_READ_COMMAND, R::kStatus + 1, &v, 4), tlm::TLM_BURST_ERROR_RESPONSE);
        EXPECT_EQ(b.access(tlm::TLM_WRITE_COMMAND, R::kControl, &v, 4, enables), tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
        EXPECT_EQ(b.access(tlm::TLM_WRITE_COMMAND, address_map::kPairBuffer, &v, 4), tlm::TLM_COMMAND_ERROR_RESPONSE);
        EXPECT_EQ(b.access(tlm::TLM_READ_COMMAND, address_map::kPairBuffer, &v, 4), tlm::TLM_ADDRESS_ERROR_RESPONSE)
            << "reading past the buffered pairs";
        EXPECT_EQ(b.access(tlm::TLM_WRITE_COMMAND, address_map::kCoordinateBase + 16, &v, 4),
                  tlm::TLM_ADDRESS_ERROR_RESPONSE)
            << "box 4 is past the capacity of 4";
        // Debug reads see the memories without time passing.
        b.write(address_map::kCoordinateBase + 3 * address_map::kWindowSize + 8, 0x3f800000);
        tlm::tlm_generic_payload p;
        p.set_command(tlm::TLM_READ_COMMAND);
        p.set_address(address_map::kCoordinateBase + 3 * address_map::kWindowSize + 8);
        p.set_data_ptr(reinterpret_cast<unsigned char*>(&v));
        p.set_data_length(4);
        EXPECT_EQ(b.socket->transport_dbg(p), 4u);
        EXPECT_EQ(v, 0x3f800000u);
    });
}

}  // namespace
}  // namespace cdvp
