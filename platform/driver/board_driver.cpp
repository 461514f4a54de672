#include "platform/driver/board_driver.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"
#include "models/pci/dma_registers.h"
#include "platform/driver/quantiser.h"

namespace cdvp {

using R = ControlRegisters;
using D = DmaRegisters;

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
constexpr uint64_t kDeltaRecordBytes = 4 * address_map::kDeltaRecordWords;

std::string hex(uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "0x%" PRIx64, value);
    return text;
}

std::string mebibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g MiB", static_cast<double>(bytes) / (1 << 20));
    return text;
}

std::string microseconds(SimTime t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g us", ns_from_fs(t) * 1e-3);
    return text;
}

}  // namespace

uint64_t BoardDriver::host_memory_bytes(uint32_t capacity, uint32_t buffer_depth, const DriverConfig& config) {
    return descriptor_area_at(capacity, buffer_depth, config) + kChainDescriptors * sizeof(DmaDescriptor);
}

uint64_t BoardDriver::pair_area() const { return pair_area_at(capacity_); }
uint64_t BoardDriver::delta_area() const { return pair_area() + pair_area_bytes(capacity_, buffer_depth_, config_); }
uint64_t BoardDriver::descriptor_area() const { return descriptor_area_at(capacity_, buffer_depth_, config_); }

BoardDriver::BoardDriver(HostPort& port, SimTime period_fs, const DriverConfig& config,
                         std::shared_ptr<const BusTiming> bus)
    : port_(port),
      period_(period_fs),
      config_(config),
      bus_(bus ? std::move(bus) : std::make_shared<IdealBusTiming>()) {}

void BoardDriver::pio_read(uint64_t address, void* data, uint32_t length) {
    if (const std::string error = port_.read(address, data, length); !error.empty()) {
        throw DeviceFault("board read at " + hex(address) + " failed: " + error);
    }
}

void BoardDriver::pio_write(uint64_t address, const void* data, uint32_t length) {
    if (const std::string error = port_.write(address, data, length); !error.empty()) {
        throw DeviceFault("board write at " + hex(address) + " failed: " + error);
    }
}

uint32_t BoardDriver::read(uint64_t address) {
    uint32_t value = 0;
    pio_read(address, &value, 4);
    return value;
}

void BoardDriver::write(uint64_t address, uint32_t value) { pio_write(address, &value, 4); }

uint64_t BoardDriver::read_counter(uint32_t low_offset) {
    const uint64_t low = read(low_offset);
    return low | uint64_t{read(low_offset + 4)} << 32;
}

void BoardDriver::open() {
    const uint32_t id = read(R::kId);
    if (id != R::kIdValue && id != R::kGridIdValue) throw std::runtime_error("no collision board answers at the BAR");
    const bool grid_board = id == R::kGridIdValue;
    capacity_ = read(R::kCapacity);
    buffer_depth_ = read(R::kPairBufferDepth);
    parallelism_ = read(R::kParallelism);
    format_ = NumberFormat::from_register(read(R::kFormat));
    // Where the boxes sit bounds a sweep's cycles (the timeouts): block RAM,
    // or SSRAM swept in tiles; a grid board's SSRAM and grid.
    TileConfig tiles;
    tiles.boxes = read(R::kTileBoxes);
    if (tiles.tiled() || grid_board) {
        const uint32_t timing = read(R::kTileTiming);
        tiles.load_latency_cycles = timing & R::kTileTimingLatencyMask;
        tiles.cycles_per_box = timing >> R::kTileTimingCyclesShift;
    }
    time_.emplace(config_, *bus_, period_, parallelism_, buffer_depth_, tiles);
    if (grid_board) {
        GridConfig grid;
        grid.dims = read(R::kGridDims);
        grid.cell_capacity = read(R::kGridCellCapacity);
        grid.max_span = read(R::kGridMaxSpan);
        time_->set_grid(grid);
    }
    if (port_.memory_size() < host_memory_bytes(capacity_, buffer_depth_, config_)) {
        throw std::runtime_error("host memory too small for the board's capacity and pair buffer");
    }
    // Two banks pipeline frames; the host's bank is where the next upload goes.
    box_banks_ = read(R::kBoxBanks);
    host_bank_ = read(R::kHostBank);
    if (box_banks_ < 1 || box_banks_ > shadow_.size() || host_bank_ >= box_banks_) {
        throw std::runtime_error("the board reports " + std::to_string(box_banks_) + " box banks and host bank " +
                                 std::to_string(host_bank_));
    }
    pair_bank_ = read(R::kPairBank);
    show_pair_bank(R::kCurrentPairs);
    in_flight_.reset();
    // The pair format stays set across frames and aborts.
    write(R::kPairFormat, static_cast<uint32_t>(config_.pair_format));
    if (read(R::kPairFormat) != static_cast<uint32_t>(config_.pair_format)) {
        throw std::runtime_error("the board refused pair format " + std::to_string(static_cast<int>(config_.pair_format)));
    }
    forget_shadows();
}

void BoardDriver::charge(Phase phase) {
    account_->spent[phase] += ns_from_fs(port_.now() - mark_);
    mark_ = port_.now();
}

void BoardDriver::show_pair_bank(uint32_t bank) {
    if (pair_bank_ == bank) return;
    write(R::kPairBank, bank);
    pair_bank_ = bank;
}

void BoardDriver::cpu_work(double ns) {
    if (ns > 0) port_.wait(fs_from_ns(ns));
    charge(kDriver);
}

// Between two polls: the configured gap, and never no time at all (on an
// untimed bus a poll costs nothing, and the loop would not let time pass);
// with back-off, growing by the factor each poll up to the largest gap.
void BoardDriver::poll_pause(uint32_t polls) {
    const SimTime gap = fs_from_ns(config_.poll_gap_ns);
    const SimTime base = gap > 0 ? gap : period_;
    if (config_.poll_backoff <= 1.0) {
        port_.wait(base);
        return;
    }
    const double grown = ns_from_fs(base) * std::pow(config_.poll_backoff, std::min<uint32_t>(polls, 64));
    port_.wait(fs_from_ns(std::max(ns_from_fs(base), std::min(grown, config_.poll_gap_max_ns))));
}

// Compared in ns before converting: a timeout too long for 64-bit
// femtoseconds never reaches fs_from_ns.
SimTime BoardDriver::timeout_for(double worst_ns) const {
    const double timeout_ns = time_->timeout_ns(worst_ns);
    const double now_ns = ns_from_fs(port_.now());
    if (!(now_ns + timeout_ns <= ns_from_fs(kSimulatedTimeLimit))) {
        throw SimulatedTimeLimit("a wait from " + simulated_seconds(now_ns) + " of simulated time could last until " +
                                 simulated_seconds(now_ns + timeout_ns) + ", past the limit of " +
                                 simulated_seconds(ns_from_fs(kSimulatedTimeLimit)) +
                                 " (2^63 fs, half SystemC's 64-bit femtosecond clock)");
    }
    return fs_from_ns(timeout_ns);
}

// By interrupt: each interrupt (the line is shared) or the timeout is
// followed by one status read. By polling: status reads until the deadline.
uint32_t BoardDriver::wait_for(uint64_t status_address, uint32_t bits, SimTime timeout, const char* what,
                               bool by_interrupt, bool check_first) {
    const SimTime deadline = port_.now() + timeout;
    // A sweep in flight shares the line with a DMA: an event of the board's
    // that came while the host was busy keeps the line up, and the DMA's
    // completion would raise no edge. The handler acknowledges it first.
    const bool shared_with_sweep = by_interrupt && in_flight_ && status_address != R::kStatus;
    if (shared_with_sweep) acknowledge_board_event();
    bool look_now = check_first;
    SimTime looked = port_.now();
    for (uint32_t polls = 0;; ++polls) {
        // After a status read that did not show the event, an interrupt
        // that came during it was for what it could not see yet: look again
        // instead of waiting for another.
        if (by_interrupt && !look_now) {
            if (polls > 0 || check_first) port_.wait_for_interrupt_since(looked, deadline - port_.now());
            else port_.wait_for_interrupt(deadline - port_.now());
        }
        look_now = false;
        noticed_ = port_.now();  // the handler runs: the status read is readback work
        looked = port_.now();
        const uint32_t value = read(status_address);
        if (!by_interrupt) noticed_ = port_.now();  // a poll notices when its read returns
        const bool late = port_.now() >= deadline;
        if (value & bits) {
            if (late && by_interrupt) ++account_->timeouts_recovered;  // the interrupt was lost
            return value;
        }
        if (late) {
            throw DeviceFault(std::string(what) + " timed out: no completion within " + microseconds(timeout) +
                              " of simulated time");
        }
        if (!by_interrupt) poll_pause(polls);
        // Woken by the board's event, not the DMA's: acknowledge it and look
        // at the DMA again.
        if (shared_with_sweep) look_now = acknowledge_board_event();
    }
}

bool BoardDriver::acknowledge_board_event() {
    if (!(read(R::kStatus) & R::kInterrupt)) return false;
    write(R::kControl, R::kAcknowledge);
    return true;
}

bool BoardDriver::dma_by_interrupt() const {
    return config_.wait == WaitMode::kIrq && config_.interrupts == InterruptPolicy::kEvery;
}

// Starts the bridge's DMA engine (registers already set) and waits for it
// by interrupt or polling; a fault the engine reports fails the frame.
void BoardDriver::run_dma(uint32_t control, double worst_ns) {
    const SimTime timeout = timeout_for(worst_ns);
    write(D::kBase + D::kControl, control | D::kStart | (dma_by_interrupt() ? uint32_t{D::kInterruptOnDone} : 0u));
    const uint32_t status = wait_for(D::kBase + D::kStatus, D::kDone | D::kError, timeout, "DMA", dma_by_interrupt());
    if (status & D::kError) dma_fault();
    write(D::kBase + D::kStatus, D::kDone);  // clear done: the shared line falls
}

void BoardDriver::dma_fault() {
    const auto cause = static_cast<DmaFault>(read(D::kBase + D::kErrorCause));
    const uint64_t address = read_counter(D::kBase + D::kErrorAddressLo);
    if (cause == DmaFault::kMasterAbort && address >= port_.memory_size()) {
        throw DeviceFault("DMA fault: host address " + hex(address) + " beyond host memory (" +
                          mebibytes(port_.memory_size()) + ")");
    }
    throw DeviceFault(std::string("DMA fault: ") + describe(cause) + " at address " + hex(address));
}

void BoardDriver::dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host) {
    write(D::kBase + D::kHostAddressLo, static_cast<uint32_t>(host_address));
    write(D::kBase + D::kHostAddressHi, static_cast<uint32_t>(host_address >> 32));
    write(D::kBase + D::kLocalAddress, local_address);
    write(D::kBase + D::kBytes, bytes);
    const Direction direction = to_host ? Direction::kToHost : Direction::kToBoard;
    run_dma(to_host ? uint32_t{D::kToHost} : 0u, time_->dma_worst_ns(bytes, direction));
}

namespace {
uint32_t coordinate_window(uint32_t c) {
    return static_cast<uint32_t>(address_map::kCoordinateBase + c * address_map::kWindowSize);
}
}  // namespace

void BoardDriver::upload(const std::vector<FloatBox>& boxes) {
    FramePhases& phases = account_->phases;
    const auto n = static_cast<uint32_t>(boxes.size());
    if (n == 0) return;
    // In the board's format: float32 bit patterns, or fixed-point codes over
    // the frame's bounds, rounded outward.
    const Quantiser quantiser(format_, boxes);
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        quantiser.write_column(boxes, c, reinterpret_cast<uint32_t*>(port_.memory(coordinate_area(capacity_, c))));
    }
    // Packing and comparing with the board's copy, done natively above.
    cpu_work(config_.call_ns + config_.ns_per_box * n);
    bool delta = false;
    std::vector<uint32_t> changed;
    if (config_.upload != UploadMode::kFull) {
        changed = changed_boxes(n);
        delta = upload_as_delta(config_, *bus_, n, changed.size());
    }
    if (delta) {
        upload_delta(changed);
        phases.boxes_sent = static_cast<uint32_t>(changed.size());
        phases.upload_bytes = kDeltaRecordBytes * changed.size();
    } else {
        upload_full(n);
        phases.boxes_sent = n;
        phases.upload_bytes = uint64_t{24} * n;
    }
    charge(kUpload);
    if (config_.upload == UploadMode::kFull) return;
    // The host's bank holds these words now (the frame's faults invalidate them).
    BankShadow& bank = shadow_[host_bank_];
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        const auto* words = reinterpret_cast<const uint32_t*>(port_.memory(coordinate_area(capacity_, c)));
        bank.words[c].assign(words, words + n);
    }
    bank.objects = n;
    bank.valid = true;
}

std::vector<uint32_t> BoardDriver::changed_boxes(uint32_t objects) const {
    std::vector<uint32_t> changed;
    const BankShadow& bank = shadow_[host_bank_];
    const uint32_t known = bank.valid ? std::min(objects, bank.objects) : 0;
    const uint32_t* words[kCoordinates];
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        words[c] = reinterpret_cast<const uint32_t*>(port_.memory(coordinate_area(capacity_, c)));
    }
    for (uint32_t i = 0; i < objects; ++i) {
        bool same = i < known;
        for (uint32_t c = 0; same && c < kCoordinates; ++c) same = words[c][i] == bank.words[c][i];
        if (!same) changed.push_back(i);
    }
    return changed;
}

void BoardDriver::upload_full(uint32_t n) {
    if (config_.transfer != Transfer::kDma) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            pio_write(coordinate_window(c), port_.memory(coordinate_area(capacity_, c)), 4 * n);
        }
        return;
    }
    // One scatter-gather chain of six descriptors: one set-up, one interrupt.
    const uint64_t chain = descriptor_area();
    auto* descriptors = reinterpret_cast<DmaDescriptor*>(port_.memory(chain));
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        const uint64_t next = c + 1 < kCoordinates ? chain + (c + 1) * sizeof(DmaDescriptor) : 0;
        descriptors[c] = DmaDescriptor{coordinate_area(capacity_, c), next, coordinate_window(c), 4 * n};
    }
    write(D::kBase + D::kChainLo, static_cast<uint32_t>(chain));
    write(D::kBase + D::kChainHi, static_cast<uint32_t>(chain >> 32));
    run_dma(D::kChain, time_->upload_worst_ns(n));
}

// The records (index, six words) in host RAM, then one chain of
// window-sized pieces into the stream, or programmed writes of them.
void BoardDriver::upload_delta(const std::vector<uint32_t>& changed) {
    if (changed.empty()) return;
    auto* records = reinterpret_cast<uint32_t*>(port_.memory(delta_area()));
    const uint32_t* words[kCoordinates];
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        words[c] = reinterpret_cast<const uint32_t*>(port_.memory(coordinate_area(capacity_, c)));
    }
    for (std::size_t k = 0; k < changed.size(); ++k) {
        uint32_t* record = records + address_map::kDeltaRecordWords * k;
        record[0] = changed[k];
        for (uint32_t c = 0; c < kCoordinates; ++c) record[1 + c] = words[c][changed[k]];
    }
    const uint64_t bytes = kDeltaRecordBytes * changed.size();
    const auto stream = static_cast<uint32_t>(address_map::kDeltaStream);
    if (config_.transfer != Transfer::kDma) {
        for (uint64_t done = 0; done < bytes;) {
            const auto piece = static_cast<uint32_t>(std::min<uint64_t>(bytes - done, address_map::kDeltaStreamSize));
            pio_write(stream, port_.memory(delta_area() + done), piece);
            done += piece;
        }
        return;
    }
    const uint64_t chain = descriptor_area();
    auto* descriptors = reinterpret_cast<DmaDescriptor*>(port_.memory(chain));
    uint32_t count = 0;
    for (uint64_t done = 0; done < bytes; ++count) {
        const auto piece = static_cast<uint32_t>(std::min<uint64_t>(bytes - done, address_map::kDeltaStreamSize));
        descriptors[count] = DmaDescriptor{delta_area() + done, 0, stream, piece};
        if (count > 0) descriptors[count - 1].next = chain + count * sizeof(DmaDescriptor);
        done += piece;
    }
    write(D::kBase + D::kChainLo, static_cast<uint32_t>(chain));
    write(D::kBase + D::kChainHi, static_cast<uint32_t>(chain >> 32));
    run_dma(D::kChain, time_->delta_worst_ns(changed.size()));
}

uint32_t BoardDriver::wait_for_board(uint32_t objects, bool check_first) {
    const SimTime waiting_from = mark_;
    const SimTime timeout = timeout_for(time_->board_worst_ns(objects));
    const uint32_t status = wait_for(R::kStatus, R::kDone | R::kOverflow | R::kError, timeout, "board",
                                     config_.wait == WaitMode::kIrq, check_first);
    mark_ = noticed_;
    if (config_.wait == WaitMode::kIrq) write(R::kControl, R::kAcknowledge);
    if (status & R::kError) {
        throw DeviceFault(std::string("board error status: ") + R::describe(read(R::kErrorCause)));
    }
    // The segment ran cycles x period from its command. The host waited
    // from waiting_from to noticing it: the part of the sweep within that
    // is compute, the rest the notification's lag; the sweep before it ran
    // beside the host's work on other frames (pipelined), hidden.
    const uint64_t cycles = read_counter(R::kCyclesLo);
    FrameAccount& account = *account_;
    const double compute = ns_from_fs(period_ * (cycles - account.cycles_seen));
    account.cycles_seen = cycles;
    const double waited = ns_from_fs(mark_ - waiting_from);
    const double ran_before = waiting_from > account.segment_start ? ns_from_fs(waiting_from - account.segment_start) : 0;
    const double exposed = std::clamp(compute - ran_before, 0.0, waited);
    account.spent[kCompute] += exposed;
    account.spent[kIrq] += waited - exposed;
    account.phases.overlap_ns += compute - exposed;
    return status;
}

// PAIR_COUNT bounds the pairs before any is copied; in an encoded format
// PAIR_WORDS gives the words to move, and the decoded pairs must be as many.
void BoardDriver::read_pairs(PairList& pairs, uint32_t objects) {
    FramePhases& phases = account_->phases;
    const uint32_t count = read(R::kPairCount);
    if (count == 0) return;
    config_.pair_budget.check(uint64_t{pairs.size()} + count);
    const bool list = config_.pair_format == PairFormat::kList;
    const uint64_t words = list ? 2 * uint64_t{count} : read(R::kPairWords);
    if (4 * words > pair_area_bytes(capacity_, buffer_depth_, config_)) {
        throw DeviceFault("the board's pair window holds " + std::to_string(words) + " words, more than " +
                          std::to_string(count) + " pairs can encode to");
    }
    const uint64_t area = pair_area();
    const auto bytes = static_cast<uint32_t>(4 * words);
    if (config_.transfer == Transfer::kDma) {
        dma(area, static_cast<uint32_t>(address_map::kPairBuffer), bytes, true);
    } else {
        pio_read(address_map::kPairBuffer, port_.memory(area), bytes);
    }
    charge(kReadback);
    phases.readback_bytes += bytes;
    const auto* data = reinterpret_cast<const uint32_t*>(port_.memory(area));
    const std::size_t before = pairs.size();
    if (list) {
        for (uint32_t k = 0; k < count; ++k) pairs.push_back({data[2 * k], data[2 * k + 1]});
    } else if (const std::string error = decode_pairs(config_.pair_format, data, words, objects, pairs);
               !error.empty() || pairs.size() - before != count) {
        throw DeviceFault("the pair read-back does not decode to the board's " + std::to_string(count) +
                          " pairs: " + (error.empty() ? std::to_string(pairs.size() - before) + " pairs" : error));
    }
    cpu_work(config_.ns_per_pair * count);
}

void BoardDriver::check_capacity(const std::vector<FloatBox>& boxes) const {
    if (boxes.size() > capacity_) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) + " boxes exceeds the board's capacity of " +
                                    std::to_string(capacity_));
    }
}

FramePhases BoardDriver::run_frame(const std::vector<FloatBox>& boxes, PairList& pairs) {
    check_capacity(boxes);
    if (in_flight_) throw std::logic_error("run_frame with a pipelined frame in flight: finish() it first");
    try {
        return frame(boxes, pairs);
    } catch (const std::exception&) {
        fail_frames(pairs);
        throw;
    }
}

void BoardDriver::fail_frames(PairList& pairs) {
    pairs.clear();  // never a partial set
    in_flight_.reset();
    in_flight_pairs_.clear();
    forget_shadows();  // what the board's memories hold is not known now
    recover();
}

void BoardDriver::recover() {
    try {
        write(D::kBase + D::kControl, D::kAbort);
        write(R::kControl, R::kAbort);
        // Let an aborted transfer's engine settle before the next frame.
        port_.wait(0);
        port_.wait(0);
        if (box_banks_ > 1) host_bank_ = read(R::kHostBank);
    } catch (const DeviceFault&) {
        // The next frame's accesses report the board's state.
    }
}

void BoardDriver::open_account(FrameAccount& account, uint32_t objects) {
    account = FrameAccount{};
    account.objects = objects;
    account.began = port_.now();
    account_ = &account;
    mark_ = account.began;
}

FramePhases BoardDriver::close_account(FrameAccount& account, bool pipelined_frame) {
    FramePhases phases = account.phases;
    phases.upload_ns = account.spent[kUpload];
    phases.start_ns = account.spent[kStart];
    phases.compute_ns = account.spent[kCompute];
    phases.irq_ns = account.spent[kIrq];
    phases.readback_ns = account.spent[kReadback];
    phases.driver_ns = account.spent[kDriver];
    phases.latency_ns = ns_from_fs(port_.now() - account.began);
    // One frame at a time, the host worked on it throughout; pipelined, the
    // host's time on it is what was charged to it.
    double charged = 0;
    for (double spent : account.spent) charged += spent;
    phases.total_ns = pipelined_frame ? charged : phases.latency_ns;
    phases.timeouts_recovered = account.timeouts_recovered;
    return phases;
}

void BoardDriver::start_sweep(FrameAccount& account) {
    write(R::kObjectCount, account.objects);
    write(R::kControl, R::kStart);
    charge(kStart);
    account.segment_start = mark_;
    account.cycles_seen = 0;
    if (box_banks_ > 1) host_bank_ = 1 - host_bank_;  // START hands the bank over
}

uint64_t BoardDriver::finish_sweep(FrameAccount& account, PairList& pairs, bool check_first, bool defer_last) {
    for (bool first = true;; first = false) {
        const uint32_t status = wait_for_board(account.objects, check_first && first);
        if (status & R::kOverflow) {
            show_pair_bank(R::kCurrentPairs);
            read_pairs(pairs, account.objects);
            ++account.phases.overflow_pauses;
            write(R::kControl, R::kResume);
            charge(kReadback);
            account.segment_start = mark_;
            continue;
        }
        if (!(status & R::kDone)) throw DeviceFault("board interrupt with unexpected status " + hex(status));
        if (!defer_last) {
            show_pair_bank(R::kCurrentPairs);
            read_pairs(pairs, account.objects);
        }
        break;
    }
    account.phases.compute_cycles = account.cycles_seen;
    account.phases.stall_cycles = read_counter(R::kStallsLo);
    return read_counter(R::kTotalPairsLo);
}

void BoardDriver::check_found(uint64_t found, const PairList& pairs) {
    if (found != pairs.size()) {
        throw DeviceFault("the board found " + std::to_string(found) + " pairs but " + std::to_string(pairs.size()) +
                          " were read back");
    }
}

FramePhases BoardDriver::frame(const std::vector<FloatBox>& boxes, PairList& pairs) {
    pairs.clear();
    FrameAccount account;
    open_account(account, static_cast<uint32_t>(boxes.size()));
    upload(boxes);
    start_sweep(account);
    const uint64_t found = finish_sweep(account, pairs, false, false);
    charge(kReadback);
    check_found(found, pairs);
    return close_account(account, false);
}

}  // namespace cdvp
