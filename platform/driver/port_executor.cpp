#include "platform/driver/port_executor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "models/control_registers/control_registers.h"
#include "models/common/number_text.h"
#include "models/pci/dma_registers.h"
#include "models/pair_collector/pair_format.h"
#include "platform/driver/driver_text.h"
#include "platform/driver/quantiser.h"

namespace cdvp {

namespace {
// Host RAM layout: the six coordinate arrays, the pair area, the delta
// records (when deltas may be uploaded), then the DMA descriptors.
uint64_t coordinate_area(uint32_t capacity, uint32_t c) { return uint64_t{c} * 4 * capacity; }
uint64_t round8(uint64_t bytes) { return (bytes + 7) / 8 * 8; }
uint64_t pair_area_at(uint32_t capacity) { return round8(uint64_t{24} * capacity); }
// The pair words of a full buffer in the format, never more than the window.
uint64_t pair_area_bytes(uint32_t capacity, uint32_t buffer_depth, const DriverConfig& config) {
    const uint64_t words = worst_encoded_words(config.pair_format, buffer_depth, capacity);
    return round8(std::min<uint64_t>(4 * words, address_map::kPairBufferSize));
}
uint64_t delta_area_bytes(uint32_t capacity, const DriverConfig& config) {
    return config.upload == UploadMode::kFull ? 0 : round8(uint64_t{4} * address_map::kDeltaRecordWords * capacity);
}
uint64_t descriptor_area_at(uint32_t capacity, uint32_t buffer_depth, const DriverConfig& config) {
    return pair_area_at(capacity) + pair_area_bytes(capacity, buffer_depth, config) + delta_area_bytes(capacity, config);
}
// A chain of the six arrays, or of the delta stream in window-sized pieces
// (at most 7 for 4M boxes).
constexpr uint32_t kChainDescriptors = 8;
}  // namespace

uint64_t PortExecutor::host_memory_bytes(uint32_t capacity, uint32_t buffer_depth, const DriverConfig& config) {
    return descriptor_area_at(capacity, buffer_depth, config) + kChainDescriptors * sizeof(DmaDescriptor);
}

PortExecutor::PortExecutor(HostPort& port, SimTime period_fs, const DriverConfig& config,
                           std::shared_ptr<const BusTiming> bus)
    : port_(port),
      period_(period_fs),
      config_(config),
      bus_(bus_or_ideal(std::move(bus))) {}

void PortExecutor::open(uint32_t capacity, uint32_t buffer_depth, uint32_t parallelism, NumberFormat format,
                        const TileConfig& tiles, const std::optional<GridConfig>& grid) {
    capacity_ = capacity;
    buffer_depth_ = buffer_depth;
    format_ = format;
    time_.emplace(config_, *bus_, period_, parallelism, buffer_depth_, tiles);
    if (grid) time_->set_grid(*grid);
    if (port_.memory_size() < host_memory_bytes(capacity_, buffer_depth_, config_)) {
        throw std::runtime_error("host memory too small for the board's capacity and pair buffer");
    }
}

namespace {
// A port's error fails the frame.
void check_access(const std::string& error, const char* access, uint64_t address) {
    if (!error.empty()) throw DeviceFault(std::string("board ") + access + " at " + hex(address) + " failed: " + error);
}
}  // namespace

uint32_t PortExecutor::read(uint64_t address) {
    uint32_t value = 0;
    check_access(port_.read(address, &value, 4), "read", address);
    return value;
}

void PortExecutor::write(uint64_t address, uint32_t value) {
    check_access(port_.write(address, &value, 4), "write", address);
}

void PortExecutor::pio_write(uint64_t address, uint64_t host_address, uint32_t bytes) {
    check_access(port_.write(address, port_.memory(host_address), bytes), "write", address);
}

void PortExecutor::pio_read(uint64_t address, uint64_t host_address, uint32_t bytes) {
    check_access(port_.read(address, port_.memory(host_address), bytes), "read", address);
}

void PortExecutor::wait(SimTime duration) {
    const SimTime before = port_.now();
    port_.wait(duration);
    if (const SimTime moved = port_.now() - before; moved != duration) {
        throw PortContractError("the host port's clock moved " + std::to_string(moved) + " fs on a wait of " +
                                std::to_string(duration) +
                                " fs: a HostPort keeps time in whole femtoseconds (platform/driver/host_port.h)");
    }
}

void PortExecutor::cpu(double ns) {
    if (ns > 0) wait(fs_from_ns(ns));
}

// Compared in ns before converting: a timeout too long for 64-bit
// femtoseconds never reaches fs_from_ns.
SimTime PortExecutor::timeout_for(double worst_ns) const {
    const double timeout_ns = time_->timeout_ns(worst_ns);
    const double now_ns = ns_from_fs(port_.now());
    if (!(now_ns + timeout_ns <= ns_from_fs(kSimulatedTimeLimit))) {
        const auto [until_s, limit_s] =
            distinct_figures((now_ns + timeout_ns) * 1e-9, ns_from_fs(kSimulatedTimeLimit) * 1e-9, 3);
        throw SimulatedTimeLimit("a wait from " + simulated_seconds(now_ns) + " of simulated time could last until " +
                                 until_s + " s, past the limit of " + limit_s + " s" +
                                 " (2^63 fs, half SystemC's 64-bit femtosecond clock)");
    }
    return fs_from_ns(timeout_ns);
}

void PortExecutor::wait_for_interrupt(SimTime timeout, uint64_t) { port_.wait_for_interrupt(timeout); }

void PortExecutor::wait_for_interrupt_since(SimTime since, SimTime timeout, uint64_t) {
    const SimTime before = port_.now();
    port_.wait_for_interrupt_since(since, timeout);
    if (port_.now() != before) return;
    if (taken_at_ == before) {
        throw PortContractError("the host port returned at once twice for the interrupt at " + microseconds(before) +
                                ": a HostPort takes each interrupt once (platform/driver/host_port.h)");
    }
    taken_at_ = before;
}

// Between two polls: the configured gap, and never no time at all (on an
// untimed bus a poll costs nothing, and the loop would not let time pass);
// with back-off, growing by the factor each poll up to the largest gap.
uint32_t PortExecutor::poll(uint64_t address, uint32_t bits, SimTime deadline) {
    for (uint32_t polls = 0;; ++polls) {
        const uint32_t value = read(address);
        if ((value & bits) || port_.now() >= deadline) return value;
        wait(poll_gap_fs(config_, period_, polls));
    }
}

void PortExecutor::stage(const Frame& boxes) {
    objects_ = static_cast<uint32_t>(boxes.size());
    if (boxes.empty()) return;
    const Quantiser quantiser(format_, boxes);
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        quantiser.write_column(boxes, c, reinterpret_cast<uint32_t*>(port_.memory(coordinate_area(capacity_, c))));
    }
}

// The coordinate arrays as staged in host memory.
std::array<const uint32_t*, kCoordinates> PortExecutor::staged_columns() {
    std::array<const uint32_t*, kCoordinates> columns{};
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        columns[c] = reinterpret_cast<const uint32_t*>(port_.memory(coordinate_area(capacity_, c)));
    }
    return columns;
}

uint64_t PortExecutor::changed_boxes(const Frame&) {
    changed_.clear();
    return banks_.compare(staged_columns().data(), objects_, [this](uint32_t i) { changed_.push_back(i); });
}

void PortExecutor::keep_bank() { banks_.keep(staged_columns().data(), objects_); }

// The records (index, six words) of the changed boxes.
void PortExecutor::stage_delta_records() {
    auto* records = reinterpret_cast<uint32_t*>(port_.memory(host_address(HostArea::kDeltaRecords)));
    const std::array<const uint32_t*, kCoordinates> words = staged_columns();
    for (std::size_t k = 0; k < changed_.size(); ++k) {
        uint32_t* record = records + address_map::kDeltaRecordWords * k;
        record[0] = changed_[k];
        for (uint32_t c = 0; c < kCoordinates; ++c) record[1 + c] = words[c][changed_[k]];
    }
}

uint64_t PortExecutor::stage_chain(Chain chain, uint64_t count) {
    const uint64_t at = descriptor_area_at(capacity_, buffer_depth_, config_);
    auto* descriptors = reinterpret_cast<DmaDescriptor*>(port_.memory(at));
    if (chain == Chain::kCoordinateArrays) {
        const auto n = static_cast<uint32_t>(count);
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            const uint64_t next = c + 1 < kCoordinates ? at + (c + 1) * sizeof(DmaDescriptor) : 0;
            descriptors[c] = DmaDescriptor{coordinate_area(capacity_, c), next, address_map::coordinate_window(c), 4 * n};
        }
        return at;
    }
    const uint64_t bytes = address_map::kDeltaRecordBytes * count;
    const uint64_t records = host_address(HostArea::kDeltaRecords);
    const auto stream = static_cast<uint32_t>(address_map::kDeltaStream);
    uint32_t pieces = 0;
    for (uint64_t done = 0; done < bytes; ++pieces) {
        const auto piece = static_cast<uint32_t>(std::min<uint64_t>(bytes - done, address_map::kDeltaStreamSize));
        descriptors[pieces] = DmaDescriptor{records + done, 0, stream, piece};
        if (pieces > 0) descriptors[pieces - 1].next = at + pieces * sizeof(DmaDescriptor);
        done += piece;
    }
    return at;
}

uint64_t PortExecutor::host_address(HostArea area, uint32_t index) const {
    switch (area) {
        case HostArea::kCoordinates: return coordinate_area(capacity_, index);
        case HostArea::kPairs: return pair_area_at(capacity_);
        case HostArea::kDeltaRecords: return pair_area_at(capacity_) + pair_area_bytes(capacity_, buffer_depth_, config_);
    }
    return 0;
}

bool PortExecutor::pair_area_holds(uint64_t words) const {
    return 4 * words <= pair_area_bytes(capacity_, buffer_depth_, config_);
}

void PortExecutor::take_pairs(PairList& pairs, uint64_t words, uint32_t count, uint32_t objects) {
    const auto* data = reinterpret_cast<const uint32_t*>(port_.memory(host_address(HostArea::kPairs)));
    const std::size_t before = pairs.size();
    if (config_.pair_format == PairFormat::kList) {
        for (uint32_t k = 0; k < count; ++k) pairs.push_back({data[2 * k], data[2 * k + 1]});
    } else if (const std::string error = decode_pairs(config_.pair_format, data, words, objects, pairs);
               !error.empty() || pairs.size() - before != count) {
        throw DeviceFault("the pair read-back does not decode to the board's " + std::to_string(count) +
                          " pairs: " + (error.empty() ? std::to_string(pairs.size() - before) + " pairs" : error));
    }
}

}  // namespace cdvp
