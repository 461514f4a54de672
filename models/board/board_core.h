// The board as plain C++: its host-visible side (registers, coordinate store,
// pair buffer window, status) in front of an engine that computes sweeps.
#pragma once

#include <cstdint>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "models/board_spec/board_config.h"
#include "models/board_spec/board_engine.h"
#include "models/common/register_bank.h"
#include "models/control_registers/control_registers.h"
#include "models/pair_collector/pair_format.h"

namespace cdvp {

// Time is counted in clock edges of the current segment (from START or RESUME
// to the next pause or done): the SystemC shell calls advance_to() with the
// edges elapsed before every host access and at the segment's end, which
// segment_edges() gives. Status bits derive from one phase variable.
class BoardCore {
public:
    // capacity: boxes the coordinate memories hold (their depth); budget: the
    // most pairs the engine may find in a sweep (see make_engine).
    BoardCore(const BoardConfig& config, uint32_t capacity, Fidelity fidelity = Fidelity::kCycle,
              PairBudget budget = {});

    const BoardConfig& config() const { return config_; }
    uint32_t capacity() const { return capacity_; }
    // Block RAM primitives of the six coordinate memories.
    uint32_t block_rams() const;
    BoardEngine& engine() { return *engine_; }
    const BoardEngine& engine() const { return *engine_; }
    const RegisterBank& register_bank() const { return registers_; }

    // Host side. A read returns false for an unmapped offset.
    bool read_register(uint32_t offset, uint32_t& value);
    // A refused write (OBJECT_COUNT during a sweep) also sets ERROR.
    RegisterResult write_register(uint32_t offset, uint32_t value);
    // Coordinate memory writes are refused (kRefused, ERROR set) while busy,
    // kUnmapped past capacity.
    RegisterResult write_coordinate(Coordinate coordinate, uint32_t index, uint32_t word);
    // A run of `count` words (little-endian, as on the bus) from box `first`
    // on: a burst's worth, checked once; refused whole while busy.
    RegisterResult write_coordinates(Coordinate coordinate, uint32_t first, const unsigned char* words, uint32_t count);
    // A word of the host's bank (HOST_BANK), as the host reads it back.
    uint32_t read_coordinate(Coordinate coordinate, uint32_t index) const {
        return banks_[host_bank_][coordinate][index];
    }
    // With two banks: the bank the host writes, which START sweeps and then
    // hands over, the other becoming the host's.
    uint32_t host_bank() const { return host_bank_; }
    // `count` words of the delta stream (little-endian): they complete
    // records (address_map::kDeltaRecordWords words each) in order, and each
    // whole record is written into the memories. Refused whole while busy; a
    // record whose index is past the capacity is dropped with ERROR.
    RegisterResult write_delta(const unsigned char* words, uint32_t count);
    // The pair buffer as the host reads it now (PAIR_BANK's).
    uint32_t buffered_pairs();
    const IndexPair& buffered_pair(uint32_t index) { return shown_pairs()[index]; }
    PairFormat pair_format() const { return pair_format_; }
    // The pair buffer window: the buffered pairs in PAIR_FORMAT, as host
    // words; `count` words from word `first` on, all within window_words().
    uint64_t window_words();
    void copy_window_words(uint64_t first, uint64_t count, unsigned char* out);
    // Reports an error status (ERROR with this cause, and the interrupt);
    // a sweep under way goes on.
    void raise_error(ControlRegisters::BoardError cause);

    // The status as the host sees it now.
    struct Status {
        bool busy, done, overflow, error;
        uint32_t error_cause;
        bool interrupt;
        uint32_t bits() const;
    };
    Status status() const;
    // The interrupt line: high from done, overflow or an error until the host
    // acknowledges (so a shared line can fall between events).
    bool interrupt() const { return irq_pending_; }
    SweepCounters counters();

    // Clock side.
    SweepState phase() const { return phase_; }
    bool running() const { return phase_ == SweepState::kRunning; }
    // Counts START and RESUME commands taken: a new segment began when it changes.
    uint64_t segments_started() const { return segments_started_; }
    uint64_t edges() const { return edges_; }
    // Edges of the current segment in all (the engine computes them).
    uint64_t segment_edges() { return engine_->segment_edges(); }
    // The clock has run to `edges` edges of the segment; at its last edge the
    // board pauses or finishes. Never goes back.
    void advance_to(uint64_t edges);
    // One clock edge.
    void step() { advance_to(edges_ + 1); }

private:
    void declare_registers();
    void declare_grid_registers();
    void start();
    void resume();
    void abort();
    // The window's encoding of the buffer now (counted and bitmap formats),
    // re-encoded only when the buffer or the format changed.
    const std::vector<uint32_t>& encoded_window();
    // The first of the buffered pairs PAIR_BANK shows, and the boxes of their sweep.
    const IndexPair* shown_pairs();
    uint32_t shown_objects() const;
    // Whether the host may write box memory now: not into a bank being swept.
    bool host_bank_busy() const { return status().busy && config_.box_banks == 1; }

    BoardConfig config_;
    uint32_t capacity_;
    std::unique_ptr<BoardEngine> engine_;
    RegisterBank registers_;
    std::vector<CoordinateStore> banks_;  // box_banks of them
    uint32_t host_bank_ = 0;
    // Two banks: the pairs of the sweep before the current one (the previous
    // pair buffer), its boxes, and which buffer PAIR_BANK shows.
    std::vector<IndexPair> previous_pairs_;
    uint32_t previous_objects_ = 0;
    uint32_t last_objects_ = 0;  // the boxes of the last START's sweep
    uint32_t pair_bank_ = ControlRegisters::kCurrentPairs;

    SweepState phase_ = SweepState::kIdle;
    uint32_t object_count_ = 0;
    bool error_ = false;
    uint32_t error_cause_ = ControlRegisters::kNoError;
    bool irq_pending_ = false;
    PairFormat pair_format_ = PairFormat::kList;
    // The delta stream's record being assembled, and the records written.
    std::array<uint32_t, address_map::kDeltaRecordWords> delta_record_{};
    uint32_t delta_filled_ = 0;
    uint32_t delta_records_ = 0;
    struct EncodedKey {
        uint64_t segment = 0, pairs = 0;
        uint32_t objects = 0, bank = 0;
        PairFormat format = PairFormat::kList;
        bool operator==(const EncodedKey& o) const {
            return segment == o.segment && pairs == o.pairs && objects == o.objects && bank == o.bank &&
                   format == o.format;
        }
    };
    std::optional<EncodedKey> encoded_key_;
    std::vector<uint32_t> encoded_;
    uint64_t segments_started_ = 0;
    uint64_t edges_ = 0;
    // The counters while the clock is stopped (paused, done, aborted).
    SweepCounters held_;
    // A grid board's last finished sweep, as its grid registers show it.
    GridSweepStats grid_stats_;
};

}  // namespace cdvp
