// libFuzzer target: the board, its PCI bridge and host memory driven through
// their TLM sockets by a byte stream of register, memory, pair-buffer and DMA
// accesses (aligned or not, in range or not, descriptor chains).
// Invariants: no crash and no SystemC error; every input ends within a
// bounded simulated time; memory stays bounded (the bridge's one burst
// buffer); and every sweep the harness runs to completion holds exactly the
// reference pairs of the boxes in the coordinate memories.
// SystemC elaborates once per process: the design is built in
// LLVMFuzzerInitialize and reset through its own registers between inputs.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "models/board/collision_board.h"
#include "models/common/transaction.h"
#include "models/pci/pci_bridge.h"
#include "platform/host_memory.h"
#include "platform/kernel.h"
#include "sw/baselines/brute_force.h"

namespace cdvp {
namespace {

using namespace sc_core;
using R = ControlRegisters;
using D = DmaRegisters;
namespace am = address_map;

constexpr uint32_t kCapacity = 64;
// bus_fast_fuzzer builds this file with the fast engine behind the board's
// registers: the same invariants must hold for it.
#ifdef CDVP_FUZZ_FAST_ENGINE
constexpr Fidelity kFidelity = Fidelity::kFast;
#else
constexpr Fidelity kFidelity = Fidelity::kCycle;
#endif
constexpr uint64_t kHostBytes = 1 << 16;
constexpr std::size_t kMaxOps = 256;
constexpr double kInputTimeLimitMs = 200;  // simulated; a program that is not done by then hung

[[noreturn]] void finding(const char* what) {
    std::fprintf(stderr, "bus_fuzzer: %s\n", what);
    std::abort();
}

// Reads the input as a stream; past its end every value is 0.
class Bytes {
public:
    Bytes(const uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool empty() const { return at_ >= size_; }
    uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
    uint16_t u16() { return static_cast<uint16_t>(u8() | u8() << 8); }
    uint32_t u32() { return u16() | static_cast<uint32_t>(u16()) << 16; }
    uint64_t u64() { return u32() | uint64_t{u32()} << 32; }

private:
    const uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

BoardConfig fuzz_board() {
    BoardConfig config;
    config.m = 2;
    config.collector.fifo_depth = 8;
    config.collector.buffer_depth = 16;  // overflow pauses in most sweeps
    return config;
}

PcieConfig fast_bus() { return PcieConfig{}; }  // a 16 MiB DMA takes milliseconds, not a tenth of a second

struct Harness : sc_module {
    SC_HAS_PROCESS(Harness);
    tlm_utils::simple_initiator_socket<Harness> pio;
    sc_signal<bool> fpga_irq{"fpga_irq"};
    sc_signal<bool> inta{"inta"};
    CollisionBoard board;
    PciBridge bridge;
    HostMemory memory;

    const uint8_t* input = nullptr;
    std::size_t input_size = 0;
    bool finished = true;
    uint64_t sweeps_checked = 0;

    Harness(const sc_module_name& name)
        : sc_module(name),
          pio("pio"),
          board("board", fuzz_board(), kCapacity, kFidelity),
          bridge("bridge", std::make_shared<PcieTiming>(fast_bus())),
          memory("memory", kHostBytes) {
        pio.bind(bridge.pci_target);
        bridge.local_bus.bind(board.socket);
        bridge.pci_master.bind(memory.socket);
        board.irq.bind(fpga_irq);
        bridge.fpga_irq.bind(fpga_irq);
        bridge.inta.bind(inta);
        SC_THREAD(run);
    }

    sc_event go;

    void run() {
        for (;;) {
            while (finished) wait(go);
            Bytes bytes(input, input_size);
            for (std::size_t op = 0; op < kMaxOps && !bytes.empty(); ++op) step(bytes);
            reset();
            finished = true;
        }
    }

    tlm::tlm_response_status access(tlm::tlm_command command, uint64_t address, void* data, unsigned length,
                                    unsigned char* byte_enable = nullptr, unsigned enable_length = 0,
                                    unsigned streaming_width = 0) {
        tlm::tlm_generic_payload p;
        prepare_transaction(p, command, address, data, length);
        p.set_byte_enable_ptr(byte_enable);
        p.set_byte_enable_length(enable_length);
        if (streaming_width != 0) p.set_streaming_width(streaming_width);
        sc_time delay = SC_ZERO_TIME;
        pio->b_transport(p, delay);
        wait(delay);
        if (p.get_response_status() == tlm::TLM_INCOMPLETE_RESPONSE) finding("a target left a response incomplete");
        return p.get_response_status();
    }
    uint32_t read(uint64_t address) {
        uint32_t v = 0;
        access(tlm::TLM_READ_COMMAND, address, &v, 4);
        return v;
    }
    void write(uint64_t address, uint32_t v) { access(tlm::TLM_WRITE_COMMAND, address, &v, 4); }
    uint32_t debug_read(uint64_t address) {
        uint32_t v = 0;
        tlm::tlm_generic_payload p;
        prepare_transaction(p, tlm::TLM_READ_COMMAND, address, &v, 4);
        if (pio->transport_dbg(p) != 4) finding("a debug read of a coordinate failed");
        return v;
    }

    // A host address: mostly inside host memory, sometimes anywhere.
    static uint64_t host_address(Bytes& in) {
        const uint8_t pick = in.u8();
        if (pick < 160) return in.u16() & ~static_cast<uint64_t>(pick & 1 ? 0 : 3);
        if (pick < 200) return kHostBytes - (in.u8() & 0x3c);
        if (pick < 220) return (0xFFFF'FFFF'FFFF'FFFFull - in.u8()) & ~static_cast<uint64_t>(pick & 1 ? 3 : 7);
        return in.u64();
    }
    // A board address: a coordinate window, the pair buffer, or anywhere.
    static uint32_t local_address(Bytes& in) {
        const uint8_t pick = in.u8();
        const uint32_t offset = in.u16() % (4 * kCapacity + 64);
        if (pick < 150) return static_cast<uint32_t>(am::kCoordinateBase + (pick % 6) * am::kWindowSize + (offset & ~3u));
        if (pick < 200) return static_cast<uint32_t>(am::kPairBuffer + (offset & ~(pick & 1 ? 0u : 7u)));
        return in.u32();
    }
    static uint32_t length(Bytes& in) {
        const uint8_t pick = in.u8();
        if (pick < 200) return 4u * (in.u8() % 80);
        if (pick < 230) return in.u8();
        return in.u32();
    }

    void step(Bytes& in) {
        switch (in.u8() % 12) {
            case 0: write(4 * (in.u8() % 18), in.u32()); break;  // board registers, some unmapped
            case 1: read(4 * (in.u8() % 18)); break;
            case 2: write(D::kBase + 4 * (in.u8() % 12), in.u32()); break;  // DMA registers
            case 3: read(D::kBase + 4 * (in.u8() % 12)); break;
            case 4: {  // PIO burst into or out of the board
                std::vector<unsigned char> data(std::min<uint32_t>(length(in), 4096));
                for (auto& b : data) b = in.u8();
                const uint32_t address = local_address(in);
                access(in.u8() & 1 ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND, address, data.data(),
                       static_cast<unsigned>(data.size()));
                break;
            }
            case 5: {  // the CPU stores into its own memory
                const uint32_t at = in.u16();
                const uint32_t n = std::min<uint32_t>(in.u8(), kHostBytes - at);
                for (uint32_t k = 0; k < n; ++k) *memory.data(at + k) = in.u8();
                break;
            }
            case 6: {  // a descriptor, mostly well-formed
                const uint32_t at = in.u16() % (kHostBytes - sizeof(DmaDescriptor) + 1);
                DmaDescriptor d{host_address(in), 0, local_address(in), length(in)};
                const uint8_t next = in.u8();
                d.next = next < 64 ? uint64_t{0}
                         : next < 200 ? (at + sizeof d + 8 * (next % 4)) % kHostBytes
                                      : host_address(in);
                std::memcpy(memory.data(at), &d, sizeof d);
                break;
            }
            case 7: {  // a DMA set-up and START
                const uint64_t host = host_address(in);
                write(D::kBase + D::kHostAddressLo, static_cast<uint32_t>(host));
                write(D::kBase + D::kHostAddressHi, static_cast<uint32_t>(host >> 32));
                write(D::kBase + D::kLocalAddress, local_address(in));
                write(D::kBase + D::kBytes, length(in));
                const uint64_t chain = host_address(in);
                write(D::kBase + D::kChainLo, static_cast<uint32_t>(chain));
                write(D::kBase + D::kChainHi, static_cast<uint32_t>(chain >> 32));
                write(D::kBase + D::kControl, (in.u8() & 0x1f) | D::kStart);
                break;
            }
            case 8: wait(sc_time(100.0 * in.u8(), SC_NS), inta.posedge_event()); break;
            case 9: sweep(in.u8() % (kCapacity + 1)); break;
            case 10: {  // any address, length, byte enables and streaming width
                const uint64_t address = in.u8() & 1 ? in.u64() : D::kBase + in.u8();
                std::vector<unsigned char> data(in.u8() % 65);
                unsigned char enables[4] = {in.u8(), in.u8(), in.u8(), in.u8()};
                const uint8_t shape = in.u8();
                access(shape & 1 ? tlm::TLM_WRITE_COMMAND : shape & 2 ? tlm::TLM_READ_COMMAND : tlm::TLM_IGNORE_COMMAND,
                       address, data.data(), static_cast<unsigned>(data.size()), shape & 4 ? enables : nullptr,
                       shape & 4 ? 1 + shape % 4 : 0, shape & 8 ? 4 : 0);
                break;
            }
            case 11: {  // boxes by PIO: n boxes of small coordinates, so some overlap
                const uint32_t n = in.u8() % (kCapacity + 1);
                for (uint32_t c = 0; c < kCoordinates; ++c) {
                    std::vector<float> values(std::max<uint32_t>(n, 1));
                    for (uint32_t i = 0; i < n; ++i) values[i] = static_cast<float>(in.u8() % 16) + (c >= 3 ? 2.0f : 0.0f);
                    access(tlm::TLM_WRITE_COMMAND, am::kCoordinateBase + c * am::kWindowSize, values.data(), 4 * n);
                }
                break;
            }
        }
    }

    // Runs a sweep of n boxes to completion, draining every overflow, and
    // checks the pairs against the reference for the boxes it swept.
    void sweep(uint32_t n) {
        // No transfer may reach the board's registers or memories meanwhile.
        write(D::kBase + D::kControl, D::kAbort);
        wait(SC_ZERO_TIME);
        wait(SC_ZERO_TIME);
        write(R::kControl, R::kAbort);
        write(R::kObjectCount, n);
        write(R::kControl, R::kStart);
        if (!(read(R::kStatus) & (R::kBusy | R::kDone))) return;  // refused
        // The memories are locked while busy: what they hold now is what the sweep compares.
        std::vector<FloatBox> boxes(n);
        for (uint32_t i = 0; i < n; ++i) {
            for (uint32_t c = 0; c < kCoordinates; ++c) {
                const float v = ComparisonUnit::as_float(debug_read(am::kCoordinateBase + c * am::kWindowSize + 4 * i));
                (c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3]) = v;
            }
        }
        PairList pairs;
        for (uint32_t polls = 0;; ++polls) {
            if (polls == 100000) finding("a sweep of at most 64 boxes did not finish");
            const uint32_t status = read(R::kStatus);
            if (!(status & (R::kDone | R::kOverflow))) {
                wait(sc_time(1, SC_US), fpga_irq.posedge_event());
                continue;
            }
            const uint32_t count = read(R::kPairCount);
            std::vector<uint32_t> words(2 * count + 2);
            if (count > 0 && access(tlm::TLM_READ_COMMAND, am::kPairBuffer, words.data(), 8 * count) !=
                                 tlm::TLM_OK_RESPONSE) {
                finding("reading the buffered pairs failed");
            }
            for (uint32_t k = 0; k < count; ++k) pairs.push_back({words[2 * k], words[2 * k + 1]});
            if (status & R::kDone) break;
            write(R::kControl, R::kResume);
        }
        const uint64_t total = read(R::kTotalPairsLo) | uint64_t{read(R::kTotalPairsHi)} << 32;
        if (total != pairs.size()) finding("TOTAL_PAIRS differs from the pairs read back");
        if (sorted(pairs) != reference_pairs(boxes)) finding("a completed sweep's pairs differ from the reference");
        ++sweeps_checked;
    }

    // Back to the power-on state through the registers: no transfer, an idle
    // board with an empty pair buffer, zeroed memories and registers.
    void reset() {
        write(D::kBase + D::kControl, D::kAbort);
        write(R::kControl, R::kAbort);
        wait(SC_ZERO_TIME);
        wait(SC_ZERO_TIME);
        for (uint32_t offset : {D::kHostAddressLo, D::kHostAddressHi, D::kLocalAddress, D::kBytes, D::kChainLo,
                                D::kChainHi}) {
            write(D::kBase + offset, 0);
        }
        std::vector<uint32_t> zeros(kCapacity, 0);
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            access(tlm::TLM_WRITE_COMMAND, am::kCoordinateBase + c * am::kWindowSize, zeros.data(), 4 * kCapacity);
        }
        write(R::kObjectCount, 0);
        write(R::kControl, R::kStart);  // an empty sweep empties the pair buffer
        while (!(read(R::kStatus) & R::kDone)) wait(board.period());
        write(R::kControl, R::kAbort);
        if (bridge.dma_registers().status() != 0 || read(R::kStatus) != 0) finding("reset left a status bit set");
        std::memset(memory.data(0), 0, kHostBytes);
    }
};

Harness* harness = nullptr;

void fail_on_report(const sc_report& report, const sc_actions& actions) {
    if (report.get_severity() >= SC_WARNING) {
        std::fprintf(stderr, "bus_fuzzer: SystemC %s: %s\n", report.get_msg_type(), report.get_msg());
        std::abort();
    }
    sc_report_handler::default_handler(report, actions);
}

}  // namespace
}  // namespace cdvp

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
    cdvp::configure_kernel();
    sc_core::sc_report_handler::set_handler(cdvp::fail_on_report);
    cdvp::harness = new cdvp::Harness("harness");
    sc_core::sc_start(sc_core::SC_ZERO_TIME);  // elaborate
    cdvp::after_kernel_returns();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace sc_core;
    cdvp::Harness& h = *cdvp::harness;
    h.input = data;
    h.input_size = size;
    h.finished = false;
    h.go.notify(SC_ZERO_TIME);
    const sc_time limit = sc_time_stamp() + sc_time(cdvp::kInputTimeLimitMs, SC_MS);
    while (!h.finished && sc_time_stamp() < limit && sc_pending_activity()) sc_start(limit - sc_time_stamp());
    cdvp::after_kernel_returns();
    if (!h.finished) cdvp::finding("an input did not finish within its simulated time bound");
    return 0;
}

// libsystemc.so calls sc_main from its own main; libFuzzer's main wins in this executable.
int sc_main(int, char**) { return 0; }
