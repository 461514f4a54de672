// The driver's sequence (driver_sequence.h) performed through a HostPort:
// each register access, transfer and wait on the host the driver runs on,
// the boxes, records, chains and pairs in host memory, each box bank's words
// kept for delta uploads, the waits' deadlines, and the port's contract
// (host_port.h) checked where the driver can see it. BoardDriver runs on it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "models/common/aabb.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/number_format/number_format.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/bank_copies.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/driver_sequence.h"
#include "platform/driver/frame_time.h"
#include "platform/driver/host_port.h"

namespace cdvp {

class PortExecutor {
public:
    using Frame = std::vector<FloatBox>;
    using Pairs = PairList;
    // A phase is summed in ns, each span converted as it is charged.
    using Time = double;
    static Time span(SimTime fs) { return ns_from_fs(fs); }
    static double ns(Time time) { return time; }

    // bus: the timing the timeouts are derived from (null: an ideal bus).
    PortExecutor(HostPort& port, SimTime period_fs, const DriverConfig& config, std::shared_ptr<const BusTiming> bus);

    // Host RAM the driver needs for a board of this capacity and pair buffer
    // (the pair area for config's pair format, the delta records' area when
    // it may upload deltas).
    static uint64_t host_memory_bytes(uint32_t capacity, uint32_t buffer_depth, const DriverConfig& config);
    // The board as BoardDriver::open reads it: the host memory it needs (too
    // little fails), the timeouts, the bank the next upload goes to; every
    // bank's words unknown.
    // A grid board's grid (its ID says so) bounds its sweeps instead of the tiles.
    void open(uint32_t capacity, uint32_t buffer_depth, uint32_t parallelism, NumberFormat format,
              const TileConfig& tiles, const std::optional<GridConfig>& grid = std::nullopt);
    uint32_t capacity() const { return capacity_; }
    NumberFormat format() const { return format_; }
    void set_host_bank(uint32_t bank) { banks_.set_host_bank(bank); }
    // What the board's memories hold is not known (after a fault).
    void forget_banks() { banks_.forget(); }

    // The bus and the host's clock. A port's error fails the frame (DeviceFault).
    uint32_t read(uint64_t address);
    void write(uint64_t address, uint32_t value);
    void pio_write(uint64_t address, uint64_t host_address, uint32_t bytes);
    void pio_read(uint64_t address, uint64_t host_address, uint32_t bytes);
    SimTime now() const { return port_.now(); }
    void cpu(double ns);
    // How long a wait whose worst case is worst(FrameTime) may take; throws
    // SimulatedTimeLimit for a deadline past kSimulatedTimeLimit.
    template <class Worst>
    SimTime timeout(Worst worst) const {
        return timeout_for(worst(*time_));
    }
    SimTime deadline_after(SimTime timeout) const { return port_.now() + timeout; }
    void wait_for_interrupt(SimTime timeout, uint64_t awaited);
    void wait_for_interrupt_since(SimTime since, SimTime timeout, uint64_t awaited);
    // Reads the register until any of bits shows or the deadline passes,
    // pausing between reads (back-off); returns the last value.
    uint32_t poll(uint64_t address, uint32_t bits, SimTime deadline);
    uint64_t memory_size() const { return port_.memory_size(); }
    const BusTiming& bus() const { return *bus_; }

    // The host's data.
    uint32_t objects(const Frame& boxes) const { return static_cast<uint32_t>(boxes.size()); }
    void stage(const Frame& boxes);
    // Boxes whose words differ from the host bank's copy (all when it is unknown).
    uint64_t changed_boxes(const Frame& boxes);
    void keep_bank();
    void stage_delta_records();
    // Writes the chain's descriptors; returns its address.
    uint64_t stage_chain(Chain chain, uint64_t count);
    uint64_t host_address(HostArea area, uint32_t index = 0) const;
    bool pair_area_holds(uint64_t words) const;
    void take_pairs(PairList& pairs, uint64_t words, uint32_t count, uint32_t objects);
    void banks_swapped() { banks_.hand_over(); }

private:
    SimTime timeout_for(double worst_ns) const;
    std::array<const uint32_t*, kCoordinates> staged_columns();
    // HostPort::wait, held to the port's contract.
    void wait(SimTime duration);

    HostPort& port_;
    SimTime period_;
    DriverConfig config_;
    std::shared_ptr<const BusTiming> bus_;
    uint32_t capacity_ = 0;
    uint32_t buffer_depth_ = 0;
    NumberFormat format_;
    std::optional<FrameTime> time_;  // from open(), once the board's m and pair buffer are known
    uint32_t objects_ = 0;           // the frame staged last
    std::vector<uint32_t> changed_;  // its boxes that differ from the host bank's copy
    // When wait_for_interrupt_since last returned at once: each interrupt is taken once.
    std::optional<SimTime> taken_at_;
    BankCopies banks_;
};

}  // namespace cdvp
