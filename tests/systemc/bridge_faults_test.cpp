// Hostile guests: the bridge, host memory and board driven through their TLM
// sockets with payloads a buggy driver could issue. Every fault must become a
// TLM error response, an error cause and an interrupt, never a kernel error.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>

#include <tlm_utils/simple_initiator_socket.h>

#include "models/board/collision_board.h"
#include "models/common/transaction.h"
#include "models/pci/pci_bridge.h"
#include "platform/host_memory.h"

namespace cdvp {
namespace {

using namespace sc_core;
using R = ControlRegisters;
using D = DmaRegisters;
namespace am = address_map;

constexpr uint64_t kHostBytes = 1 << 16;
constexpr uint64_t kNearTop = 0xFFFF'FFFF'FFFF'FFF0ull;

// The host's view: PIO into the bridge's BAR; and a host memory of its own to probe.
struct BridgeBench : sc_module {
    SC_HAS_PROCESS(BridgeBench);
    tlm_utils::simple_initiator_socket<BridgeBench> pio;
    tlm_utils::simple_initiator_socket<BridgeBench> memory_port;
    sc_signal<bool> fpga_irq{"fpga_irq"};
    sc_signal<bool> inta{"inta"};
    CollisionBoard board;
    PciBridge bridge;
    HostMemory memory;
    HostMemory probed;  // host memory alone, for the test's own accesses
    std::function<void(BridgeBench&)> body;

    BridgeBench(const sc_module_name& name, uint32_t capacity, std::shared_ptr<const BusTiming> timing)
        : sc_module(name),
          pio("pio"),
          memory_port("memory_port"),
          board("board", small_board(), capacity),
          bridge("bridge", std::move(timing)),
          memory("memory", kHostBytes),
          probed("probed", kHostBytes) {
        pio.bind(bridge.pci_target);
        bridge.local_bus.bind(board.socket);
        bridge.pci_master.bind(memory.socket);
        memory_port.bind(probed.socket);
        board.irq.bind(fpga_irq);
        bridge.fpga_irq.bind(fpga_irq);
        bridge.inta.bind(inta);
        SC_THREAD(run);
    }
    static BoardConfig small_board() {
        BoardConfig config;
        config.m = 1;
        return config;
    }
    void run() { body(*this); }

    tlm::tlm_response_status access(tlm_utils::simple_initiator_socket<BridgeBench>& socket, tlm::tlm_command command,
                                    uint64_t address, void* data, unsigned length,
                                    unsigned char* byte_enable = nullptr) {
        tlm::tlm_generic_payload p;
        prepare_transaction(p, command, address, data, length);
        p.set_byte_enable_ptr(byte_enable);
        p.set_byte_enable_length(byte_enable ? 4 : 0);
        sc_time delay = SC_ZERO_TIME;
        socket->b_transport(p, delay);
        wait(delay);
        return p.get_response_status();
    }
    uint32_t read(uint64_t address) {
        uint32_t v = 0;
        EXPECT_EQ(access(pio, tlm::TLM_READ_COMMAND, address, &v, 4), tlm::TLM_OK_RESPONSE) << std::hex << address;
        return v;
    }
    void write(uint64_t address, uint32_t v) {
        EXPECT_EQ(access(pio, tlm::TLM_WRITE_COMMAND, address, &v, 4), tlm::TLM_OK_RESPONSE) << std::hex << address;
    }
    void set_dma(uint64_t host, uint32_t local, uint32_t bytes) {
        write(D::kBase + D::kHostAddressLo, static_cast<uint32_t>(host));
        write(D::kBase + D::kHostAddressHi, static_cast<uint32_t>(host >> 32));
        write(D::kBase + D::kLocalAddress, local);
        write(D::kBase + D::kBytes, bytes);
    }
    // Starts the engine, waits for it to finish (done or error) and returns the status.
    uint32_t run_dma(uint32_t control) {
        write(D::kBase + D::kControl, control | D::kStart | D::kInterruptOnDone);
        while (read(D::kBase + D::kStatus) & D::kBusy) wait(inta.value_changed_event());
        wait(SC_ZERO_TIME);
        return read(D::kBase + D::kStatus);
    }
    DmaFault cause() { return static_cast<DmaFault>(read(D::kBase + D::kErrorCause)); }
    uint64_t fault_address() {
        const uint64_t low = read(D::kBase + D::kErrorAddressLo);
        return low | uint64_t{read(D::kBase + D::kErrorAddressHi)} << 32;
    }
    void clear_error() { write(D::kBase + D::kStatus, D::kDone | D::kError); }
    // One DMA expected to fault with this cause: error bit, interrupt, cause,
    // then cleared. Returns the faulting address.
    uint64_t expect_fault(uint32_t control, DmaFault expected, const char* what) {
        const uint32_t status = run_dma(control);
        EXPECT_EQ(status, uint32_t{D::kError}) << what;
        EXPECT_TRUE(inta.read()) << what << ": a fault interrupts";
        EXPECT_EQ(cause(), expected) << what << ": " << describe(cause());
        const uint64_t address = fault_address();
        clear_error();
        wait(SC_ZERO_TIME);
        EXPECT_EQ(inta.read(), fpga_irq.read()) << what << ": clearing the error lowers the bridge's share of the line";
        return address;
    }
};

void run_bench(uint32_t capacity, std::function<void(BridgeBench&)> body,
               std::shared_ptr<const BusTiming> timing = std::make_shared<IdealBusTiming>()) {
    BridgeBench bench("bench", capacity, std::move(timing));
    bench.body = std::move(body);
    sc_start();
}

uint32_t coordinate(uint32_t c) { return static_cast<uint32_t>(am::kCoordinateBase + c * am::kWindowSize); }

TEST(HostMemory, RejectsAccessesThatWrapAroundOrRunPastTheEnd) {
    run_bench(4, [](BridgeBench& b) {
        unsigned char data[16] = {};
        EXPECT_EQ(b.access(b.memory_port, tlm::TLM_READ_COMMAND, kNearTop, data, 16), tlm::TLM_ADDRESS_ERROR_RESPONSE)
            << "address + length wraps to 0";
        EXPECT_EQ(b.access(b.memory_port, tlm::TLM_WRITE_COMMAND, kNearTop, data, 16), tlm::TLM_ADDRESS_ERROR_RESPONSE);
        EXPECT_EQ(b.access(b.memory_port, tlm::TLM_READ_COMMAND, kHostBytes - 12, data, 16),
                  tlm::TLM_ADDRESS_ERROR_RESPONSE);
        EXPECT_EQ(b.access(b.memory_port, tlm::TLM_READ_COMMAND, kHostBytes - 16, data, 16), tlm::TLM_OK_RESPONSE);
        unsigned char partial[4] = {0xff, 0, 0xff, 0xff};
        EXPECT_EQ(b.access(b.memory_port, tlm::TLM_WRITE_COMMAND, 0, data, 4, partial),
                  tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
    });
}

TEST(BridgeFaults, HostAddressNearTheTopOfTheAddressSpaceIsAMasterAbort) {
    run_bench(4, [](BridgeBench& b) {
        for (uint32_t control : {0u, uint32_t{D::kToHost}}) {
            b.set_dma(kNearTop, coordinate(0), 16);
            EXPECT_EQ(b.expect_fault(control, DmaFault::kMasterAbort, "host address near 2^64"), kNearTop);
        }
        b.set_dma(kHostBytes - 8, coordinate(0), 16);
        b.expect_fault(0, DmaFault::kMasterAbort, "past the end of host memory");
    });
}

TEST(BridgeFaults, BadLengthsAreRefusedBeforeAnythingIsAllocatedOrMoved) {
    run_bench(4, [](BridgeBench& b) {
        const auto started = std::chrono::steady_clock::now();
        b.set_dma(0, coordinate(0), 0xFFFF'FFFC);
        b.expect_fault(0, DmaFault::kBadLength, "4 GiB");
        EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(1)) << "refused, not attempted";
        for (uint32_t bytes : {0u, 6u, D::kMaxSegmentBytes + 4}) {
            b.set_dma(0, coordinate(0), bytes);
            b.expect_fault(0, DmaFault::kBadLength, "zero, odd or too long");
        }
        b.set_dma(2, coordinate(0), 4);
        b.expect_fault(0, DmaFault::kMisaligned, "host address not 4-aligned");
        b.set_dma(0, coordinate(0) + 2, 4);
        b.expect_fault(0, DmaFault::kMisaligned, "local address not 4-aligned");
        b.set_dma(0, 0xFFFF'FFFC, 8);
        b.expect_fault(0, DmaFault::kTargetAbort, "local address wraps past 2^32");
    });
}

TEST(BridgeFaults, TheBoardsRefusalsAreTargetAbortsWithTheLocalAddress) {
    run_bench(4, [](BridgeBench& b) {
        b.set_dma(0, coordinate(0), 32);
        EXPECT_EQ(b.expect_fault(0, DmaFault::kTargetAbort, "8 boxes into a board of 4"), coordinate(0));
        b.set_dma(0, static_cast<uint32_t>(am::kPairBuffer), 8);
        b.expect_fault(D::kToHost, DmaFault::kTargetAbort, "a pair when the buffer holds none");
        b.set_dma(0, static_cast<uint32_t>(am::kPairBuffer), 8);
        b.expect_fault(0, DmaFault::kBoardRefused, "writing the read-only pair buffer");
        // A sweep runs for a while (m = 1, 4 boxes); meanwhile DMA into the board is refused.
        b.write(R::kObjectCount, 4);
        b.write(R::kControl, R::kStart);
        b.set_dma(0, coordinate(0), 16);
        b.expect_fault(0, DmaFault::kBoardRefused, "coordinates while the board is busy");
        EXPECT_TRUE(b.fpga_irq.read()) << "the board's own error interrupts too";
        EXPECT_EQ(b.read(R::kStatus) & R::kError, uint32_t{R::kError});
        EXPECT_EQ(b.read(R::kErrorCause), uint32_t{R::kWriteWhileBusy});
    });
}

TEST(BridgeFaults, DescriptorChainsThatLoopMisalignOrLeaveHostMemoryFault) {
    run_bench(4, [](BridgeBench& b) {
        auto put = [&](uint64_t at, DmaDescriptor d) { std::memcpy(b.memory.data(at), &d, sizeof d); };
        auto run_chain = [&](uint64_t first, DmaFault expected, const char* what) {
            b.write(D::kBase + D::kChainLo, static_cast<uint32_t>(first));
            b.write(D::kBase + D::kChainHi, static_cast<uint32_t>(first >> 32));
            return b.expect_fault(D::kChain, expected, what);
        };
        run_chain(kNearTop, DmaFault::kDescriptorFault, "descriptor near 2^64");
        run_chain(kHostBytes, DmaFault::kDescriptorFault, "descriptor beyond host memory");
        run_chain(0x104, DmaFault::kMisaligned, "descriptor not 8-aligned");
        put(0x100, {0x1000, 0x200, coordinate(0), 16});
        put(0x200, {0x1000, 0x100, coordinate(1), 16});
        EXPECT_EQ(run_chain(0x100, DmaFault::kChainLoop, "two descriptors pointing at each other"), 0x100u);
        put(0x200, {kNearTop, 0, coordinate(1), 16});
        run_chain(0x100, DmaFault::kMasterAbort, "a descriptor's host address near 2^64");
        // A chain of distinct descriptors longer than the bound.
        const uint64_t base = 0x2000;
        for (uint64_t k = 0; k <= D::kMaxDescriptors; ++k) {
            put(base + 24 * k, {0x1000, base + 24 * (k + 1), coordinate(0), 4});
        }
        run_chain(base, DmaFault::kChainTooLong, "1025 descriptors");
        // After all that, a good chain still runs.
        put(0x100, {0x1000, 0, coordinate(2), 16});
        b.write(D::kBase + D::kChainLo, 0x100);
        b.write(D::kBase + D::kChainHi, 0);
        EXPECT_EQ(b.run_dma(D::kChain), uint32_t{D::kDone});
    });
}

TEST(BridgeFaults, StartWhileBusyIsRefusedWithAnErrorAndTheTransferGoesOn) {
    run_bench(1024, [](BridgeBench& b) {
        for (uint32_t k = 0; k < 1024; ++k) std::memcpy(b.memory.data(4 * k), &k, 4);
        b.set_dma(0, coordinate(0), 4096);
        b.write(D::kBase + D::kControl, D::kStart);
        wait(SC_ZERO_TIME);
        ASSERT_EQ(b.read(D::kBase + D::kStatus), uint32_t{D::kBusy}) << "4 KiB take time on PCI";
        uint32_t bytes = 8;
        EXPECT_EQ(b.access(b.pio, tlm::TLM_WRITE_COMMAND, D::kBase + D::kBytes, &bytes, 4),
                  tlm::TLM_COMMAND_ERROR_RESPONSE)
            << "set-up registers are locked while a transfer runs";
        b.write(D::kBase + D::kControl, D::kStart);
        EXPECT_EQ(b.read(D::kBase + D::kStatus), uint32_t{D::kBusy | D::kError});
        EXPECT_EQ(b.cause(), DmaFault::kStartWhileBusy);
        while (b.read(D::kBase + D::kStatus) & D::kBusy) wait(10, SC_US);
        EXPECT_EQ(b.read(D::kBase + D::kStatus), uint32_t{D::kDone | D::kError}) << "the first transfer completed";
        EXPECT_EQ(b.read(coordinate(0) + 4 * 1000), 1000u);
    }, std::make_shared<PciTiming>(PciConfig{}));
}

TEST(BridgeFaults, RegisterWritesHonourByteEnablesAndWidth) {
    run_bench(4, [](BridgeBench& b) {
        b.write(D::kBase + D::kBytes, 0x1234);
        uint32_t value = 0xFFFF'FFFF;
        unsigned char low_half[4] = {0xff, 0xff, 0, 0};
        EXPECT_EQ(b.access(b.pio, tlm::TLM_WRITE_COMMAND, D::kBase + D::kBytes, &value, 4, low_half),
                  tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
        EXPECT_EQ(b.read(D::kBase + D::kBytes), 0x1234u) << "a refused partial write changes nothing";
        unsigned char all[4] = {0xff, 0xff, 0xff, 0xff};
        EXPECT_EQ(b.access(b.pio, tlm::TLM_WRITE_COMMAND, D::kBase + D::kBytes, &value, 4, all), tlm::TLM_OK_RESPONSE);
        EXPECT_EQ(b.read(D::kBase + D::kBytes), 0xFFFF'FFFFu);
        uint64_t wide = 0;
        EXPECT_EQ(b.access(b.pio, tlm::TLM_WRITE_COMMAND, D::kBase + D::kBytes, &wide, 8),
                  tlm::TLM_BURST_ERROR_RESPONSE);
        EXPECT_EQ(b.access(b.pio, tlm::TLM_READ_COMMAND, D::kBase + D::kBytes + 2, &value, 4),
                  tlm::TLM_BURST_ERROR_RESPONSE);
        EXPECT_EQ(b.access(b.pio, tlm::TLM_READ_COMMAND, D::kBase + 0xFC, &value, 4), tlm::TLM_ADDRESS_ERROR_RESPONSE);
        EXPECT_EQ(b.access(b.pio, tlm::TLM_READ_COMMAND, kNearTop, &value, 4), tlm::TLM_ADDRESS_ERROR_RESPONSE);
    });
}

TEST(BoardFaults, ObjectCountIsLockedWhileASweepRuns) {
    run_bench(64, [](BridgeBench& b) {
        b.write(R::kObjectCount, 64);
        b.write(R::kControl, R::kStart);
        uint32_t count = 3;
        EXPECT_EQ(b.access(b.pio, tlm::TLM_WRITE_COMMAND, R::kObjectCount, &count, 4), tlm::TLM_COMMAND_ERROR_RESPONSE);
        EXPECT_EQ(b.read(R::kObjectCount), 64u) << "read-back equals the count the sweep uses";
        EXPECT_EQ(b.read(R::kStatus), uint32_t{R::kBusy | R::kError | R::kInterrupt});
        EXPECT_EQ(b.read(R::kErrorCause), uint32_t{R::kWriteWhileBusy});
        wait(SC_ZERO_TIME);
        EXPECT_TRUE(b.fpga_irq.read()) << "an error interrupts";
        b.write(R::kControl, R::kAbort);
        wait(SC_ZERO_TIME);
        EXPECT_EQ(b.read(R::kStatus), 0u);
        EXPECT_FALSE(b.fpga_irq.read());
        b.write(R::kObjectCount, 3);
        EXPECT_EQ(b.read(R::kObjectCount), 3u);
    });
    EXPECT_FALSE(sc_pending_activity()) << "an aborted sweep stops the clock";
}

}  // namespace
}  // namespace cdvp
