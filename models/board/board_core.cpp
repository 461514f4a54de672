#include "models/board/board_core.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "models/block_ram/block_ram.h"
#include "models/board/engine_factory.h"

namespace cdvp {

BoardCore::BoardCore(const BoardConfig& config, uint32_t capacity, Fidelity fidelity, PairBudget budget)
    : config_((config.validate(), config)), capacity_(capacity) {
    if (capacity > address_map::kMaxObjects) {
        throw std::invalid_argument("board capacity " + std::to_string(capacity) + " exceeds the address map's " +
                                    std::to_string(address_map::kMaxObjects) + " boxes");
    }
    engine_ = make_engine(fidelity, config_, capacity, budget);
    banks_.resize(config_.box_banks);
    for (CoordinateStore& bank : banks_) {
        for (auto& words : bank) words.assign(capacity, 0);
    }
    declare_registers();
}

uint32_t BoardCore::block_rams() const { return static_cast<uint32_t>(config_.block_rams(capacity_)); }

void BoardCore::declare_registers() {
    using R = ControlRegisters;
    using A = RegisterAccess;
    auto constant = [](uint32_t v) { return [v] { return v; }; };
    auto counter = [this](uint64_t SweepCounters::*field) { return [this, field] { return counters().*field; }; };
    registers_.add("ID", R::kId, A::kReadOnly, constant(config_.grid_board() ? R::kGridIdValue : R::kIdValue));
    registers_.add("CONTROL", R::kControl, A::kWriteOnly, {}, [this](uint32_t v) {
        if (v & R::kAbort) abort();
        else if (v & R::kStart) start();
        else if (v & R::kResume) resume();
        else if (v & R::kAcknowledge) irq_pending_ = false;
        return RegisterResult::kDone;
    });
    registers_.add("STATUS", R::kStatus, A::kReadOnly, [this] { return status().bits(); });
    registers_.add("OBJECT_COUNT", R::kObjectCount, A::kReadWrite, [this] { return object_count_; },
              [this](uint32_t v) {
                  // The sweep uses the count it started with; read-back must agree.
                  if (status().busy) {
                      raise_error(R::kWriteWhileBusy);
                      return RegisterResult::kRefused;
                  }
                  object_count_ = v;
                  return RegisterResult::kDone;
              });
    registers_.add("PAIR_COUNT", R::kPairCount, A::kReadOnly, [this] { return buffered_pairs(); });
    registers_.add_wide("CYCLES", R::kCyclesLo, R::kCyclesHi, A::kReadOnly, counter(&SweepCounters::cycles));
    registers_.add_wide("STALLS", R::kStallsLo, R::kStallsHi, A::kReadOnly, counter(&SweepCounters::stalls));
    registers_.add_wide("TOTAL_PAIRS", R::kTotalPairsLo, R::kTotalPairsHi, A::kReadOnly,
                   counter(&SweepCounters::total_pairs));
    registers_.add("PARALLELISM", R::kParallelism, A::kReadOnly, constant(config_.m));
    registers_.add("CAPACITY", R::kCapacity, A::kReadOnly, constant(capacity_));
    registers_.add("PAIR_BUFFER_DEPTH", R::kPairBufferDepth, A::kReadOnly, constant(config_.collector.buffer_depth));
    registers_.add("ERROR_CAUSE", R::kErrorCause, A::kReadOnly, [this] { return error_cause_; });
    registers_.add("FORMAT", R::kFormat, A::kReadOnly, constant(config_.format.register_value()));
    // The memory the bitstream was built with: the driver bounds a sweep's cycles by it.
    const TileConfig& tiles = config_.tiles;
    registers_.add("TILE_BOXES", R::kTileBoxes, A::kReadOnly, constant(tiles.boxes));
    // A grid board's boxes always sit in SSRAM: its timing, untiled.
    registers_.add("TILE_TIMING", R::kTileTiming, A::kReadOnly,
                   constant(tiles.tiled() || config_.grid_board()
                                ? (tiles.load_latency_cycles & R::kTileTimingLatencyMask) |
                                      tiles.cycles_per_box << R::kTileTimingCyclesShift
                                : 0));
    registers_.add("PAIR_FORMAT", R::kPairFormat, A::kReadWrite, [this] { return uint32_t{static_cast<uint8_t>(pair_format_)}; },
                   [this](uint32_t v) {
                       if (status().busy || v >= kPairFormats) {
                           raise_error(status().busy ? R::kWriteWhileBusy : R::kBadPairFormat);
                           return RegisterResult::kRefused;
                       }
                       pair_format_ = static_cast<PairFormat>(v);
                       return RegisterResult::kDone;
                   });
    registers_.add("PAIR_WORDS", R::kPairWords, A::kReadOnly, [this] { return static_cast<uint32_t>(window_words()); });
    registers_.add("DELTA_RECORDS", R::kDeltaRecords, A::kReadOnly, [this] { return delta_records_; });
    registers_.add("BOX_BANKS", R::kBoxBanks, A::kReadOnly, constant(config_.box_banks));
    registers_.add("HOST_BANK", R::kHostBank, A::kReadOnly, [this] { return host_bank_; });
    registers_.add("PAIR_BANK", R::kPairBank, A::kReadWrite, [this] { return pair_bank_; }, [this](uint32_t v) {
        if (v > R::kPreviousPairs) {
            raise_error(R::kBadPairBank);
            return RegisterResult::kRefused;
        }
        pair_bank_ = v;
        return RegisterResult::kDone;
    });
    if (config_.grid_board()) declare_grid_registers();
}

void BoardCore::declare_grid_registers() {
    using R = ControlRegisters;
    using A = RegisterAccess;
    auto constant = [](uint32_t v) { return [v] { return v; }; };
    auto last = [this](auto GridSweepStats::*field) { return [this, field] { return static_cast<uint32_t>(grid_stats_.*field); }; };
    const GridConfig& grid = config_.grid;
    uint32_t cell_size = 0;
    std::memcpy(&cell_size, &grid.cell_size, sizeof cell_size);
    registers_.add("GRID_DIMS", R::kGridDims, A::kReadOnly, constant(grid.dims));
    registers_.add("GRID_CELL_CAPACITY", R::kGridCellCapacity, A::kReadOnly, constant(grid.cell_capacity));
    registers_.add("GRID_MAX_SPAN", R::kGridMaxSpan, A::kReadOnly, constant(grid.max_span));
    registers_.add("GRID_CELL_SIZE", R::kGridCellSize, A::kReadOnly, constant(cell_size));
    registers_.add("GRID_ENTRY_CAPACITY", R::kGridEntryCapacity, A::kReadOnly,
                   constant(static_cast<uint32_t>(std::min<uint64_t>(grid.entry_capacity, UINT32_MAX))));
    registers_.add("GRID_SWEEP_DIMS", R::kGridSweepDims, A::kReadOnly, last(&GridSweepStats::dims));
    registers_.add("GRID_LARGE_BOXES", R::kGridLargeBoxes, A::kReadOnly, last(&GridSweepStats::large_boxes));
    registers_.add("GRID_OVERFLOW_BOXES", R::kGridOverflowBoxes, A::kReadOnly, last(&GridSweepStats::overflow_boxes));
    registers_.add("GRID_CELL_ENTRIES", R::kGridCellEntries, A::kReadOnly, last(&GridSweepStats::cell_entries));
    registers_.add("GRID_BUSY_CELLS", R::kGridBusyCells, A::kReadOnly, last(&GridSweepStats::busy_cells));
    registers_.add("GRID_EXCLUDED_BOXES", R::kGridExcludedBoxes, A::kReadOnly, last(&GridSweepStats::excluded_boxes));
}

bool BoardCore::read_register(uint32_t offset, uint32_t& value) {
    return registers_.read(offset, value) == RegisterResult::kDone;
}

RegisterResult BoardCore::write_register(uint32_t offset, uint32_t value) { return registers_.write(offset, value); }

RegisterResult BoardCore::write_coordinate(Coordinate coordinate, uint32_t index, uint32_t word) {
    if (index >= capacity_) return RegisterResult::kUnmapped;
    if (host_bank_busy()) {
        raise_error(ControlRegisters::kWriteWhileBusy);
        return RegisterResult::kRefused;
    }
    banks_[host_bank_][coordinate][index] = word & config_.format.word_mask();
    return RegisterResult::kDone;
}

RegisterResult BoardCore::write_coordinates(Coordinate coordinate, uint32_t first, const unsigned char* words,
                                             uint32_t count) {
    if (first > capacity_ || count > capacity_ - first) return RegisterResult::kUnmapped;
    if (host_bank_busy()) {
        raise_error(ControlRegisters::kWriteWhileBusy);
        return RegisterResult::kRefused;
    }
    uint32_t* stored = banks_[host_bank_][coordinate].data() + first;
    std::memcpy(stored, words, std::size_t{count} * sizeof(uint32_t));
    // The memories are as wide as the format: they keep a word's low bits.
    const uint32_t mask = config_.format.word_mask();
    if (mask != ~0u) {
        for (uint32_t k = 0; k < count; ++k) stored[k] &= mask;
    }
    return RegisterResult::kDone;
}

RegisterResult BoardCore::write_delta(const unsigned char* words, uint32_t count) {
    if (host_bank_busy()) {
        raise_error(ControlRegisters::kWriteWhileBusy);
        return RegisterResult::kRefused;
    }
    const uint32_t mask = config_.format.word_mask();
    for (uint32_t k = 0; k < count; ++k) {
        std::memcpy(&delta_record_[delta_filled_], words + 4 * std::size_t{k}, 4);
        if (++delta_filled_ < address_map::kDeltaRecordWords) continue;
        delta_filled_ = 0;
        const uint32_t index = delta_record_[0];
        if (index >= capacity_) {
            raise_error(ControlRegisters::kDeltaIndex);
            continue;
        }
        for (uint32_t c = 0; c < kCoordinates; ++c) banks_[host_bank_][c][index] = delta_record_[1 + c] & mask;
        ++delta_records_;
    }
    return RegisterResult::kDone;
}

uint32_t BoardCore::Status::bits() const {
    using R = ControlRegisters;
    return (busy ? uint32_t{R::kBusy} : 0u) | (done ? uint32_t{R::kDone} : 0u) |
           (overflow ? uint32_t{R::kOverflow} : 0u) | (error ? uint32_t{R::kError} : 0u) |
           (interrupt ? uint32_t{R::kInterrupt} : 0u);
}

BoardCore::Status BoardCore::status() const {
    return Status{phase_ == SweepState::kRunning || phase_ == SweepState::kPaused, phase_ == SweepState::kDone,
                  phase_ == SweepState::kPaused, error_, error_cause_, irq_pending_};
}

SweepCounters BoardCore::counters() { return running() ? engine_->counters_after(edges_) : held_; }

uint32_t BoardCore::buffered_pairs() {
    if (pair_bank_ == ControlRegisters::kPreviousPairs) return static_cast<uint32_t>(previous_pairs_.size());
    return counters().buffered;
}

const IndexPair* BoardCore::shown_pairs() {
    if (pair_bank_ == ControlRegisters::kPreviousPairs) return previous_pairs_.data();
    return &engine_->buffer_entry(0);
}

uint32_t BoardCore::shown_objects() const {
    return pair_bank_ == ControlRegisters::kPreviousPairs ? previous_objects_ : object_count_;
}

const std::vector<uint32_t>& BoardCore::encoded_window() {
    const uint32_t pairs = buffered_pairs();
    const EncodedKey key{segments_started_, pairs, shown_objects(), pair_bank_, pair_format_};
    if (!encoded_key_ || !(*encoded_key_ == key)) {
        encoded_.clear();
        if (pairs > 0) encode_pairs(pair_format_, shown_pairs(), pairs, shown_objects(), encoded_);
        encoded_key_ = key;
    }
    return encoded_;
}

uint64_t BoardCore::window_words() {
    if (pair_format_ == PairFormat::kList) return 2 * uint64_t{buffered_pairs()};
    return encoded_window().size();
}

void BoardCore::copy_window_words(uint64_t first, uint64_t count, unsigned char* out) {
    static_assert(sizeof(IndexPair) == 8, "a pair is two words, first then second");
    if (count == 0) return;
    if (pair_format_ != PairFormat::kList) {
        std::memcpy(out, encoded_window().data() + first, 4 * count);
        return;
    }
    // The list is the buffer itself: no copy of it.
    const auto* pairs = reinterpret_cast<const unsigned char*>(shown_pairs() + first / 2);
    std::memcpy(out, pairs + 4 * (first % 2), 4 * count);
}

void BoardCore::raise_error(ControlRegisters::BoardError cause) {
    error_ = true;
    error_cause_ = cause;
    irq_pending_ = true;
}

void BoardCore::advance_to(uint64_t edges) {
    if (!running() || edges <= edges_) return;
    if (!engine_->ended_by(edges)) {
        edges_ = edges;
        return;
    }
    edges_ = engine_->segment_edges();
    held_ = engine_->counters_after(edges_);
    phase_ = engine_->segment_finishes() ? SweepState::kDone : SweepState::kPaused;
    // The grid registers show a sweep once it is done.
    if (phase_ == SweepState::kDone) grid_stats_ = engine_->grid_stats();
    irq_pending_ = true;
}

// ABORT: the sweep stops where it is; the pair buffer keeps what it holds.
void BoardCore::abort() {
    if (running()) {
        held_ = engine_->counters_after(edges_);
        engine_->abort(edges_);
    }
    phase_ = SweepState::kIdle;
    delta_filled_ = 0;  // a record cut off by the abort is dropped
    error_ = irq_pending_ = false;
    error_cause_ = ControlRegisters::kNoError;
}

// START is refused (error bit) while a sweep is under way or when the object
// count exceeds the memories' depth; the previous results stay readable then.
void BoardCore::start() {
    using R = ControlRegisters;
    if (status().busy || object_count_ > capacity_) {
        raise_error(status().busy ? R::kStartWhileBusy : R::kTooManyObjects);
        return;
    }
    // The memories must hold whole records, and the window must hold the
    // buffer's encoding at its fullest.
    if (delta_filled_ != 0) {
        raise_error(R::kDeltaIncomplete);
        return;
    }
    const uint64_t worst = worst_encoded_words(pair_format_, config_.collector.buffer_depth, object_count_,
                                               config_.row_pieces(object_count_));
    if (worst > address_map::kPairBufferSize / 4) {
        raise_error(R::kPairWindowFull);
        return;
    }
    delta_records_ = 0;
    const uint32_t swept = host_bank_;
    if (config_.box_banks > 1) {
        // The pair buffers swap: the last sweep's pairs stay readable in the
        // previous one while this sweep fills the other; the host's box
        // writes go to the other bank from now on.
        previous_pairs_.clear();
        if (held_.buffered > 0) {
            const IndexPair* first = &engine_->buffer_entry(0);
            previous_pairs_.assign(first, first + held_.buffered);
        }
        previous_objects_ = last_objects_;
        host_bank_ = 1 - host_bank_;
    }
    last_objects_ = object_count_;
    engine_->start(banks_[swept], object_count_);
    edges_ = 0;
    error_ = irq_pending_ = false;
    error_cause_ = ControlRegisters::kNoError;
    phase_ = SweepState::kRunning;
    ++segments_started_;
}

// RESUME after an overflow: the host has read every buffered pair.
void BoardCore::resume() {
    if (phase_ != SweepState::kPaused) {
        raise_error(ControlRegisters::kResumeNotPaused);
        return;
    }
    engine_->resume();
    edges_ = 0;
    irq_pending_ = false;
    phase_ = SweepState::kRunning;
    ++segments_started_;
}

}  // namespace cdvp
