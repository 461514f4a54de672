#include "models/pci/pci_bridge.h"

#include <algorithm>
#include <cstring>
#include <unordered_set>

#include "models/common/address_range.h"
#include "models/common/transaction.h"

namespace cdvp {

using namespace sc_core;
using D = DmaRegisters;

PciBridge::PciBridge(const sc_module_name& name, std::shared_ptr<const BusTiming> timing)
    : sc_module(name),
      pci_target("pci_target"),
      pci_master("pci_master"),
      local_bus("local_bus"),
      fpga_irq("fpga_irq"),
      inta("inta"),
      timing_(std::move(timing)),
      buffer_(kBurstBytes) {
    pci_target.register_b_transport(this, &PciBridge::b_transport);
    pci_target.register_transport_dbg(this, &PciBridge::transport_dbg);
    declare_registers();
    SC_THREAD(dma_engine);
    SC_METHOD(drive_inta);
    sensitive << fpga_irq << inta_changed_;
}

void PciBridge::b_transport(tlm::tlm_generic_payload& payload, sc_time& delay) {
    if (starts_within(payload.get_address(), D::kBase, D::kSize)) {
        // The DMA engine's state is kept by its own process, so it can only
        // answer for the present: synchronise to the access's time first.
        if (delay > SC_ZERO_TIME) {
            wait(delay);
            delay = SC_ZERO_TIME;
        }
        payload.set_response_status(access_registers(payload));
        return;
    }
    local_bus->b_transport(payload, delay);  // the FPGA's own address map
}

unsigned int PciBridge::transport_dbg(tlm::tlm_generic_payload& payload) {
    return local_bus->transport_dbg(payload);
}

// Whole 32-bit registers only: a partial write is refused, never half-applied.
tlm::tlm_response_status PciBridge::access_registers(tlm::tlm_generic_payload& payload) {
    if (const tlm::tlm_response_status shape = check_plain_access(payload); shape != tlm::TLM_OK_RESPONSE) return shape;
    const uint64_t address = payload.get_address();
    if (payload.get_data_length() != 4 || address % 4 != 0) return tlm::TLM_BURST_ERROR_RESPONSE;
    if (!range_within(address, 4, D::kBase, D::kSize)) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
    const auto offset = static_cast<uint32_t>(address - D::kBase);
    uint32_t value = 0;
    RegisterResult result;
    if (payload.get_command() == tlm::TLM_READ_COMMAND) {
        result = registers_.read(offset, value);
        std::memcpy(payload.get_data_ptr(), &value, 4);
    } else {
        std::memcpy(&value, payload.get_data_ptr(), 4);
        result = registers_.write(offset, value);
    }
    switch (result) {
        case RegisterResult::kDone: return tlm::TLM_OK_RESPONSE;
        case RegisterResult::kRefused: return tlm::TLM_COMMAND_ERROR_RESPONSE;
        case RegisterResult::kUnmapped: break;
    }
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;
}

void PciBridge::declare_registers() {
    using A = RegisterAccess;
    auto field = [](const uint64_t& f) { return [&f] { return f; }; };
    // The set-up registers are locked while a transfer runs: it reads them.
    auto setup = [this](auto assign) {
        return [this, assign](auto v) {
            if (dma_.busy) return RegisterResult::kRefused;
            assign(v);
            return RegisterResult::kDone;
        };
    };
    auto store = [](uint64_t& f) { return [&f](uint64_t v) { f = v; }; };
    registers_.add_wide("DMA_HOST_ADDRESS", D::kHostAddressLo, D::kHostAddressHi, A::kReadWrite,
                        field(dma_.host_address), setup(store(dma_.host_address)));
    registers_.add("DMA_LOCAL_ADDRESS", D::kLocalAddress, A::kReadWrite, [this] { return dma_.local_address; },
                   setup([this](uint32_t v) { dma_.local_address = v; }));
    registers_.add("DMA_BYTES", D::kBytes, A::kReadWrite, [this] { return dma_.bytes; },
                   setup([this](uint32_t v) { dma_.bytes = v; }));
    registers_.add("DMA_CONTROL", D::kControl, A::kWriteOnly, {}, [this](uint32_t v) {
        write_control(v);
        return RegisterResult::kDone;
    });
    registers_.add("DMA_STATUS", D::kStatus, A::kReadWrite, [this] { return dma_.status(); }, [this](uint32_t v) {
        // Write one to clear.
        if (v & D::kDone) dma_.done = false;
        if (v & D::kError) clear_error();
        inta_changed_.notify(SC_ZERO_TIME);
        return RegisterResult::kDone;
    });
    registers_.add_wide("DMA_CHAIN", D::kChainLo, D::kChainHi, A::kReadWrite, field(dma_.chain_address),
                        setup(store(dma_.chain_address)));
    registers_.add("DMA_ERROR_CAUSE", D::kErrorCause, A::kReadOnly,
                   [this] { return static_cast<uint32_t>(dma_.cause); });
    registers_.add_wide("DMA_ERROR_ADDRESS", D::kErrorAddressLo, D::kErrorAddressHi, A::kReadOnly,
                        field(dma_.fault_address));
}

void PciBridge::clear_error() {
    dma_.error = false;
    dma_.cause = DmaFault::kNone;
    dma_.fault_address = 0;
}

void PciBridge::write_control(uint32_t value) {
    if (value & D::kAbort) {
        if (dma_.busy) {
            abort_requested_ = true;
            abort_.notify(SC_ZERO_TIME);
        }
        dma_.done = false;
        clear_error();
        inta_changed_.notify(SC_ZERO_TIME);
        return;
    }
    if (!(value & D::kStart)) return;
    if (dma_.busy) {
        // Refused, and said so; the transfer under way goes on.
        dma_.error = true;
        dma_.cause = DmaFault::kStartWhileBusy;
        dma_.fault_address = 0;
        inta_changed_.notify(SC_ZERO_TIME);
        return;
    }
    abort_requested_ = false;
    dma_.to_host = value & D::kToHost;
    dma_.interrupt_on_done = value & D::kInterruptOnDone;
    dma_.chain = value & D::kChain;
    dma_.busy = true;
    dma_.done = dma_.error = false;
    dma_.cause = DmaFault::kNone;
    dma_start_.notify(SC_ZERO_TIME);
}

PciBridge::Fault PciBridge::check_segment(uint64_t host_address, uint32_t local_address, uint32_t bytes) {
    if (bytes == 0 || bytes % 4 != 0 || bytes > D::kMaxSegmentBytes) return {DmaFault::kBadLength, host_address};
    if (host_address % 4 != 0) return {DmaFault::kMisaligned, host_address};
    if (local_address % 4 != 0) return {DmaFault::kMisaligned, local_address};
    // Addresses that wrap are no host memory and no board address at all.
    if (!range_within(host_address, bytes, 0, UINT64_MAX)) return {DmaFault::kMasterAbort, host_address};
    if (!range_within(local_address, bytes, 0, uint64_t{1} << 32)) return {DmaFault::kTargetAbort, local_address};
    return {};
}

PciBridge::Fault PciBridge::move_burst(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host) {
    auto transport = [&](tlm_utils::simple_initiator_socket<PciBridge>& socket, tlm::tlm_command command,
                         uint64_t address) {
        tlm::tlm_generic_payload p;
        prepare_transaction(p, command, address, buffer_.data(), bytes);
        sc_time delay = SC_ZERO_TIME;  // the segment's time is accounted as a whole
        socket->b_transport(p, delay);
        return p.get_response_status();
    };
    auto local_fault = [&](tlm::tlm_response_status response) -> Fault {
        if (response == tlm::TLM_OK_RESPONSE) return {};
        return {response == tlm::TLM_COMMAND_ERROR_RESPONSE ? DmaFault::kBoardRefused : DmaFault::kTargetAbort,
                local_address};
    };
    auto host_fault = [&](tlm::tlm_response_status response) -> Fault {
        if (response == tlm::TLM_OK_RESPONSE) return {};
        return {DmaFault::kMasterAbort, host_address};
    };
    auto local = [&](tlm::tlm_command command) -> Fault {
        if (fault_due(faults_, FaultKind::kTargetAbort)) return {DmaFault::kTargetAbort, local_address};
        return local_fault(transport(local_bus, command, local_address));
    };
    auto host = [&](tlm::tlm_command command) -> Fault {
        if (fault_due(faults_, FaultKind::kMasterAbort)) return {DmaFault::kMasterAbort, host_address};
        return host_fault(transport(pci_master, command, host_address));
    };
    if (to_host) {
        if (Fault f = local(tlm::TLM_READ_COMMAND)) return f;
        return host(tlm::TLM_WRITE_COMMAND);
    }
    if (Fault f = host(tlm::TLM_READ_COMMAND)) return f;
    return local(tlm::TLM_WRITE_COMMAND);
}

// A retry ends a transaction at its first data phase with no data moved: it
// costs a one-word transaction, and the whole transaction follows. A
// disconnect ends it after half its data: the rest needs a transaction of its own.
double PciBridge::transaction_ns(uint32_t bytes, Direction direction) {
    double ns = timing_->dma_ns(bytes, direction);
    const uint32_t first = static_cast<uint32_t>(std::min<uint64_t>(bytes, timing_->dma_transaction_bytes(direction)));
    if (fault_due(faults_, FaultKind::kRetry)) {
        ns += timing_->dma_ns(4, direction);
        ++repeated_;
    }
    if (fault_due(faults_, FaultKind::kDisconnect)) {
        const uint32_t half = first / 8 * 4;
        ns += half == 0 ? timing_->dma_ns(4, direction)
                        : timing_->dma_ns(half, direction) + timing_->dma_ns(first - half, direction) -
                              timing_->dma_ns(first, direction);
        ++repeated_;
    }
    return ns;
}

// The data move in bursts through one bounded buffer, at once; the segment's
// duration is the bus arithmetic's (the slower of PCI and local bus). After
// a fault only the bytes moved before it are charged.
PciBridge::Fault PciBridge::transfer_segment(uint64_t host_address, uint32_t local_address, uint32_t bytes,
                                             bool to_host, double& ns) {
    if (Fault f = check_segment(host_address, local_address, bytes)) return f;
    const Direction direction = to_host ? Direction::kToHost : Direction::kToBoard;
    for (uint32_t done = 0; done < bytes;) {
        const uint32_t burst = std::min(bytes - done, kBurstBytes);
        if (Fault f = move_burst(host_address + done, local_address + done, burst, to_host)) {
            if (done > 0) ns += timing_->dma_ns(done, direction);
            return f;
        }
        done += burst;
    }
    ns += transaction_ns(bytes, direction);
    ++segments_;
    waves_.live.bytes += bytes;
    show_waves();
    return {};
}

PciBridge::Fault PciBridge::fetch_descriptor(uint64_t address, DmaDescriptor& descriptor) {
    if (address % 8 != 0) return {DmaFault::kMisaligned, address};
    tlm::tlm_generic_payload p;
    prepare_transaction(p, tlm::TLM_READ_COMMAND, address, &descriptor, sizeof descriptor);
    sc_time delay = SC_ZERO_TIME;
    if (fault_due(faults_, FaultKind::kMasterAbort)) return {DmaFault::kDescriptorFault, address};
    pci_master->b_transport(p, delay);
    if (p.is_response_error()) return {DmaFault::kDescriptorFault, address};
    return {};
}

// Register mode moves one segment; chain mode first fetches each descriptor,
// a 24-byte bus-master read of its own. A chain may not revisit a descriptor.
PciBridge::Fault PciBridge::run_transfer(double& ns) {
    if (!dma_.chain) return transfer_segment(dma_.host_address, dma_.local_address, dma_.bytes, dma_.to_host, ns);
    std::unordered_set<uint64_t> visited;
    for (uint64_t next = dma_.chain_address; next != 0;) {
        if (visited.size() == D::kMaxDescriptors) return {DmaFault::kChainTooLong, next};
        if (!visited.insert(next).second) return {DmaFault::kChainLoop, next};
        DmaDescriptor d{};
        if (Fault f = fetch_descriptor(next, d)) return f;
        ++waves_.live.descriptors;
        show_waves();
        ns += transaction_ns(sizeof d, Direction::kToBoard);
        if (Fault f = transfer_segment(d.host_address, d.local_address, d.bytes, dma_.to_host, ns)) return f;
        next = d.next;
    }
    return {};
}

void PciBridge::finish(const Fault& fault) {
    ++transfers_;
    waves_.live.busy = false;
    waves_.live.error = static_cast<bool>(fault);
    show_waves();
    dma_.busy = false;
    dma_.done = !fault;
    if (fault) {  // otherwise a refused START's error stays visible
        dma_.error = true;
        dma_.cause = fault.cause;
        dma_.fault_address = fault.address;
    }
    inta_changed_.notify(SC_ZERO_TIME);
}

// Data move when the transfer starts; its bus time passes afterwards. An
// ABORT before the start moves nothing; one during the bus time ends it
// early (the data already moved stay where they are).
void PciBridge::dma_engine() {
    for (;;) {
        wait(dma_start_);
        waves_.live = Waves{true, dma_.to_host, false, 0, 0};
        show_waves();
        if (!abort_requested_) {
            if (fault_due(faults_, FaultKind::kDmaHang)) {
                wait(abort_);  // never completes: only the host's ABORT ends it
            } else {
                double ns = 0;
                const Fault fault = run_transfer(ns);
                wait(sc_time(ns, SC_NS), abort_);
                if (!abort_requested_) {
                    finish(fault);
                    continue;
                }
            }
        }
        // Aborted: idle, with the status the host cleared by aborting.
        ++transfers_;
        waves_.live.busy = false;
        show_waves();
        dma_.busy = false;
        abort_requested_ = false;
        inta_changed_.notify(SC_ZERO_TIME);
    }
}

const StateNames PciBridge::kDmaStates{"dma", {"idle", "to_board", "to_host", "failed"}};

void PciBridge::show_waves() {
    Waves& live = waves_.live;
    live.state = live.busy ? (live.to_host ? 2 : 1) : (live.error ? 3 : 0);
    waves_.show();
}

void PciBridge::add_waves(WaveList& waves) const {
    const std::string p = std::string(name()) + ".dma.";
    const Waves& shown = waves_.shown();
    waves.group("bridge: DMA engine");
    waves.add(shown.state, p + "state", 2, kDmaStates);
    waves.add(shown.busy, p + "busy");
    waves.add(shown.to_host, p + "to_host");
    waves.add(shown.bytes, p + "bytes", 32, WaveFormat::kDecimal);
    waves.add(shown.descriptors, p + "descriptors", 11, WaveFormat::kDecimal);
    waves.add(shown.error, p + "error");
}

void PciBridge::drive_inta() {
    inta.write(fpga_irq.read() || ((dma_.done || dma_.error) && dma_.interrupt_on_done));
}

}  // namespace cdvp
