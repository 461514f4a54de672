#include "models/pci/pci_bridge.h"

#include <cstring>
#include <stdexcept>
#include <vector>

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
      timing_(std::move(timing)) {
    pci_target.register_b_transport(this, &PciBridge::b_transport);
    pci_target.register_transport_dbg(this, &PciBridge::transport_dbg);
    SC_THREAD(dma_engine);
    SC_METHOD(drive_inta);
    sensitive << fpga_irq << inta_changed_;
}

void PciBridge::b_transport(tlm::tlm_generic_payload& payload, sc_time& delay) {
    const uint64_t address = payload.get_address();
    if (address >= D::kBase && address < D::kBase + D::kSize) {
        payload.set_response_status(access_registers(payload) ? tlm::TLM_OK_RESPONSE
                                                              : tlm::TLM_ADDRESS_ERROR_RESPONSE);
        return;
    }
    local_bus->b_transport(payload, delay);  // the FPGA's own address map
}

unsigned int PciBridge::transport_dbg(tlm::tlm_generic_payload& payload) {
    return local_bus->transport_dbg(payload);
}

bool PciBridge::access_registers(tlm::tlm_generic_payload& payload) {
    if (payload.get_data_length() != 4) return false;
    const auto offset = static_cast<uint32_t>(payload.get_address() - D::kBase);
    uint32_t value = 0;
    if (payload.get_command() == tlm::TLM_READ_COMMAND) {
        switch (offset) {
            case D::kHostAddressLo: value = static_cast<uint32_t>(dma_.host_address); break;
            case D::kHostAddressHi: value = static_cast<uint32_t>(dma_.host_address >> 32); break;
            case D::kLocalAddress: value = dma_.local_address; break;
            case D::kBytes: value = dma_.bytes; break;
            case D::kControl: value = 0; break;
            case D::kStatus: value = (dma_.busy ? uint32_t{D::kBusy} : 0u) | (dma_.done ? uint32_t{D::kDone} : 0u); break;
            case D::kChainLo: value = static_cast<uint32_t>(dma_.chain_address); break;
            case D::kChainHi: value = static_cast<uint32_t>(dma_.chain_address >> 32); break;
            default: return false;
        }
        std::memcpy(payload.get_data_ptr(), &value, 4);
        return true;
    }
    std::memcpy(&value, payload.get_data_ptr(), 4);
    switch (offset) {
        case D::kHostAddressLo: dma_.host_address = (dma_.host_address & ~0xffffffffull) | value; break;
        case D::kHostAddressHi: dma_.host_address = (dma_.host_address & 0xffffffffull) | uint64_t{value} << 32; break;
        case D::kLocalAddress: dma_.local_address = value; break;
        case D::kBytes: dma_.bytes = value; break;
        case D::kChainLo: dma_.chain_address = (dma_.chain_address & ~0xffffffffull) | value; break;
        case D::kChainHi: dma_.chain_address = (dma_.chain_address & 0xffffffffull) | uint64_t{value} << 32; break;
        case D::kStatus:
            if (value & D::kDone) dma_.done = false;
            inta_changed_.notify(SC_ZERO_TIME);
            break;
        case D::kControl:
            if ((value & D::kStart) && !dma_.busy) {
                dma_.to_host = value & D::kToHost;
                dma_.interrupt_on_done = value & D::kInterruptOnDone;
                dma_.chain = value & D::kChain;
                dma_.busy = true;
                dma_.done = false;
                dma_start_.notify(SC_ZERO_TIME);
            }
            break;
        default: return false;
    }
    return true;
}

void PciBridge::move(tlm::tlm_command command, tlm_utils::simple_initiator_socket<PciBridge>& socket,
                     uint64_t address, unsigned char* data, unsigned int length) {
    tlm::tlm_generic_payload p;
    prepare_transaction(p, command, address, data, length);
    sc_time delay = SC_ZERO_TIME;
    socket->b_transport(p, delay);
    if (p.is_response_error()) {
        SC_REPORT_ERROR("cdvp/pci_bridge", ("DMA access failed: " + p.get_response_string()).c_str());
    }
}

double PciBridge::transfer_segment(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host) {
    buffer_.resize(bytes);
    if (bytes > 0) {
        if (to_host) {
            move(tlm::TLM_READ_COMMAND, local_bus, local_address, buffer_.data(), bytes);
            move(tlm::TLM_WRITE_COMMAND, pci_master, host_address, buffer_.data(), bytes);
        } else {
            move(tlm::TLM_READ_COMMAND, pci_master, host_address, buffer_.data(), bytes);
            move(tlm::TLM_WRITE_COMMAND, local_bus, local_address, buffer_.data(), bytes);
        }
    }
    ++segments_;
    return timing_->dma_ns(bytes, to_host ? Direction::kToHost : Direction::kToBoard);
}

// A segment's data move at once; its duration is the bus arithmetic's (the
// slower of PCI and local bus). In chain mode each descriptor is first
// fetched from host memory, a 24-byte bus-master read of its own.
void PciBridge::dma_engine() {
    for (;;) {
        wait(dma_start_);
        double ns = 0;
        if (!dma_.chain) {
            ns = transfer_segment(dma_.host_address, dma_.local_address, dma_.bytes, dma_.to_host);
        } else {
            constexpr uint64_t kMaxDescriptors = 1u << 16;  // a chain that loops must not hang the host
            uint64_t walked = 0;
            for (uint64_t next = dma_.chain_address; next != 0; ++walked) {
                if (walked == kMaxDescriptors) {
                    SC_REPORT_ERROR("cdvp/pci_bridge", "DMA descriptor chain longer than 65536 (a loop?)");
                    break;
                }
                DmaDescriptor d{};
                move(tlm::TLM_READ_COMMAND, pci_master, next, reinterpret_cast<unsigned char*>(&d), sizeof d);
                ns += timing_->dma_ns(sizeof d, Direction::kToBoard);
                ns += transfer_segment(d.host_address, d.local_address, d.bytes, dma_.to_host);
                next = d.next;
            }
        }
        wait(sc_time(ns, SC_NS));
        ++transfers_;
        dma_.busy = false;
        dma_.done = true;
        inta_changed_.notify(SC_ZERO_TIME);
    }
}

void PciBridge::drive_inta() { inta.write(fpga_irq.read() || (dma_.done && dma_.interrupt_on_done)); }

}  // namespace cdvp
