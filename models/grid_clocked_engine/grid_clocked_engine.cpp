#include "models/grid_clocked_engine/grid_clocked_engine.h"

#include <algorithm>

#include "models/block_ram/block_ram.h"

namespace cdvp {

const char* to_string(GridClockedEngine::Pass pass) {
    switch (pass) {
        case GridClockedEngine::Pass::kIdle: return "idle";
        case GridClockedEngine::Pass::kBounds: return "bounds";
        case GridClockedEngine::Pass::kSetup: return "setup";
        case GridClockedEngine::Pass::kCount: return "count";
        case GridClockedEngine::Pass::kScan: return "scan";
        case GridClockedEngine::Pass::kPlace: return "place";
        case GridClockedEngine::Pass::kCells: return "cells";
        case GridClockedEngine::Pass::kLarge: return "large";
        case GridClockedEngine::Pass::kEnd: return "end";
    }
    return "unknown";
}

GridClockedEngine::GridClockedEngine(const BoardConfig& config, uint32_t capacity)
    : config_((config.validate(), config)),
      slots_(config.grid_slots()),
      buffer_(config.m, config.grid.cell_capacity, slots_, config.format),
      lanes_(config.lanes(), config.compare, config.format),
      row_register_(make_coordinate_memories(1, 1)),
      pipeline_(BlockRam::kReadLatencyCycles + config.compare.latency_cycles, config.collector),
      bounds_(config.format) {
    kind_.reserve(capacity);
}

void GridClockedEngine::start(const CoordinateStore& store, uint32_t objects) {
    store_ = &store;
    objects_ = objects;
    stats_ = GridSweepStats{};
    large_.clear();
    kind_.assign(objects, kBinned);
    end_issued_ = false;
    slots_issued_ = 0;
    waiting_ = false;
    pipeline_.start();
    enter(objects < 2 ? Pass::kEnd : Pass::kBounds);  // fewer than two boxes: no sweep
}

uint64_t GridClockedEngine::segment_edges() {
    while (pipeline_.state() == SweepState::kRunning) step();
    return pipeline_.edges();
}

bool GridClockedEngine::segment_finishes() {
    segment_edges();
    return pipeline_.state() == SweepState::kDone;
}

void GridClockedEngine::advance_to(uint64_t edges) {
    while (pipeline_.state() == SweepState::kRunning && pipeline_.edges() < edges) step();
}

const GridClockedEngine::Slot GridClockedEngine::kNoSlot{};

void GridClockedEngine::step() {
    pipeline_.step([this] { return issue(); },
                   [this](PairCollector& collector, const Slot& slot) {
                       pushed_hits_ = slot.hits;
                       collector.push_pairs(slot.pairs.data(), slot.count);
                   });
}

bool GridClockedEngine::keys_of(uint32_t i, uint32_t (&keys)[kCoordinates]) const {
    const NumberFormat format = config_.format;
    bool excluded = false;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        const uint32_t word = (*store_)[c][i];
        excluded |= format.excluded(word);
        keys[c] = format.key(word);
    }
    return excluded;
}

void GridClockedEngine::enter(Pass pass) {
    pass_ = pass;
    pass_slot_ = 0;
    switch (pass) {
        case Pass::kBounds: bounds_ = GridBounds(config_.format); break;
        case Pass::kScan:
            stats_.large_boxes = static_cast<uint32_t>(large_.size());
            stats_.cell_entries = table_.entries();
            table_.begin_scan();
            break;
        case Pass::kCells:
            stats_.busy_cells = static_cast<uint32_t>(table_.busy_cells().size());
            block_ = blocks_loaded_ = 0;
            in_block_ = false;
            if (table_.busy_cells().empty()) return enter(Pass::kLarge);
            buffer_.begin(0, table_.list(table_.busy_cells()[0]), table_.busy_cells()[0].count);
            break;
        case Pass::kLarge:
            tile_ = tile_begin_ = 0;
            if (large_.empty()) return enter(Pass::kEnd);
            begin_tile();
            break;
        default: break;
    }
}

GridClockedEngine::Slot GridClockedEngine::issue() {
    waiting_ = false;
    Slot slot;
    switch (pass_) {
        case Pass::kIdle: return slot;
        case Pass::kBounds: slot = bounds_slot(); break;
        case Pass::kSetup: slot = setup_slot(); break;
        case Pass::kCount: slot = bin_slot(false); break;
        case Pass::kScan: slot = scan_slot(); break;
        case Pass::kPlace: slot = bin_slot(true); break;
        case Pass::kCells: slot = cells_slot(); break;
        case Pass::kLarge: slot = large_slot(); break;
        case Pass::kEnd:
            if (end_issued_) return slot;
            end_issued_ = true;
            stats_.slots = slots_issued_;
            slot.kind = Slot::kEnd;
            return slot;
    }
    ++slots_issued_;
    return slot;
}

// Pass 1: box i's last word lands in slot i q + q - 1 + l; the bounds unit takes it then.
GridClockedEngine::Slot GridClockedEngine::bounds_slot() {
    const uint64_t q = slots_.cycles_per_box, l = slots_.latency;
    const uint64_t s = pass_slot_++;
    if (s + 1 >= l + q && (s + 1 - l) % q == 0) {
        box_ = static_cast<uint32_t>((s + 1 - l) / q - 1);
        uint32_t keys[kCoordinates];
        if (!keys_of(box_, keys)) bounds_.add(keys);
    }
    if (pass_slot_ == slots_.bounds(objects_)) enter(Pass::kSetup);
    return Slot{};
}

GridClockedEngine::Slot GridClockedEngine::setup_slot() {
    if (++pass_slot_ < GridSlots::setup()) return Slot{};
    grid_ = bounds_.geometry(config_.grid, config_.grid.dims_for(objects_));
    stats_.dims = grid_.dims();
    table_.reset(grid_.cells(), config_.grid.cell_capacity, config_.grid.entry_capacity);
    enter(Pass::kCount);
    return Slot{};
}

void GridClockedEngine::next_box(bool place) {
    uint32_t keys[kCoordinates];
    box_cells_ = 0;
    if (!place) {
        if (keys_of(box_, keys)) {
            kind_[box_] = kExcluded;
        } else if (grid_.classify(keys, config_.grid.max_span, range_) == BoxClass::kCandidate) {
            box_cells_ = range_.cells();
        } else {
            kind_[box_] = kLarge;  // inverted or spanning
        }
    } else if (kind_[box_] == kBinned) {
        keys_of(box_, keys);
        grid_.classify(keys, config_.grid.max_span, range_);
        box_cells_ = range_.cells();
    }
    box_left_ = slots_.box(box_cells_);
}

// A box's last slot: pass 2 counts it in all its cells or none (then it is
// large), pass 3 writes it into each.
void GridClockedEngine::commit_box(bool place) {
    if (place) {
        if (kind_[box_] == kBinned) table_.place(box_, range_, grid_);
        return;
    }
    if (kind_[box_] == kExcluded) {
        ++stats_.excluded_boxes;
        return;
    }
    if (box_cells_ != 0 && !table_.count(range_, grid_)) {
        kind_[box_] = kLarge;
        ++stats_.overflow_boxes;
    }
    if (kind_[box_] == kLarge) large_.push_back(box_);
}

// Passes 2 and 3: the pipeline fills (l + F slots), then each box takes q
// slots, or one a cell when it covers more.
GridClockedEngine::Slot GridClockedEngine::bin_slot(bool place) {
    const uint64_t fill = slots_.pass(0);
    const uint64_t s = pass_slot_++;
    if (s < fill) return Slot{};
    if (s == fill) {
        box_ = 0;
        next_box(place);
    }
    if (--box_left_ == 0) {
        commit_box(place);
        if (++box_ == objects_) {
            enter(place ? Pass::kCells : Pass::kScan);
        } else {
            next_box(place);
        }
    }
    return Slot{};
}

GridClockedEngine::Slot GridClockedEngine::scan_slot() {
    table_.scan_cell(pass_slot_++);
    if (pass_slot_ == table_.cells()) enter(Pass::kPlace);
    return Slot{};
}

// The busy cells: cell k's triangle reads one half while cell k+1 loads into
// the other, its load begun in the slot cell k's first window issues.
GridClockedEngine::Slot GridClockedEngine::cells_slot() {
    const std::vector<BusyCell>& busy = table_.busy_cells();
    if (!in_block_ && blocks_loaded_ > block_) {
        in_block_ = true;
        row_ = 0;
        column_ = 1;
        cell_number_ = busy[block_].cell;
        if (block_ + 1 < busy.size()) {
            buffer_.begin((block_ + 1) % 2, table_.list(busy[block_ + 1]), busy[block_ + 1].count);
        }
    }
    if (buffer_.tick(*store_, grid_)) ++blocks_loaded_;
    if (!in_block_) {
        waiting_ = true;
        return Slot{};
    }
    const uint32_t n = busy[block_].count;
    const uint32_t lanes = config_.lanes();
    const PortWindow window{row_, column_, std::min(lanes, n - column_)};
    const Slot slot = compare_cell(block_ % 2, window);
    column_ += lanes;
    if (column_ >= n) {
        ++row_;
        column_ = row_ + 1;
        if (row_ + 1 >= n) {
            in_block_ = false;
            if (++block_ == busy.size()) enter(Pass::kLarge);
        }
    }
    return slot;
}

void GridClockedEngine::begin_tile() {
    tile_count_ = std::min<uint32_t>(static_cast<uint32_t>(large_.size()) - tile_begin_, config_.grid.cell_capacity);
    buffer_.begin(0, large_.data() + tile_begin_, tile_count_);
    pass_slot_ = 0;
    rank_ = 0;
    box_ = 0;
    box_left_ = 0;
}

// A large tile: its load, the stream's first read, then every box j in turn
// against the tile's boxes (a large j against those after it).
GridClockedEngine::Slot GridClockedEngine::large_slot() {
    const uint64_t s = pass_slot_++;
    const uint64_t lead = slots_.tile_lead(tile_count_);
    if (s < lead) {
        buffer_.tick(*store_, grid_);
        return Slot{};
    }
    if (box_left_ == 0) {
        // Box j's first slot: its words in the row register, its columns.
        first_column_ = tile_count_;
        if (kind_[box_] == kBinned) {
            first_column_ = 0;
        } else if (kind_[box_] == kLarge) {
            const uint32_t after = ++rank_;
            first_column_ = after <= tile_begin_ ? 0 : std::min(after - tile_begin_, tile_count_);
        }
        columns_left_ = tile_count_ - first_column_;
        for (uint32_t c = 0; c < kCoordinates; ++c) row_register_[c].write(0, (*store_)[c][box_]);
        box_left_ = slots_.stream_box(columns_left_);
    }
    Slot slot;
    if (columns_left_ > 0) {
        const uint32_t valid = std::min(config_.lanes(), columns_left_);
        slot = compare_row(PortWindow{box_, first_column_, valid});
        first_column_ += valid;
        columns_left_ -= valid;
    }
    if (--box_left_ == 0 && ++box_ == objects_) {
        ++tile_;
        tile_begin_ += tile_count_;
        if (tile_begin_ < large_.size()) {
            begin_tile();
        } else {
            enter(Pass::kEnd);
        }
    }
    return slot;
}

// The window's addresses on the ports: port 0 of `rows` on the row, ports
// 1..valid of `columns` on the columns; a sweep slot to fill with its hits.
GridClockedEngine::Slot GridClockedEngine::read_window(CoordinateMemories& rows, uint32_t row_address,
                                                       CoordinateMemories& columns, const PortWindow& window) {
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        rows[c].clock_read(0, row_address);
        for (uint32_t lane = 0; lane < window.valid_lanes; ++lane) {
            columns[c].clock_read(lane + 1, window.first_column + lane);
        }
    }
    last_issue_ = window;
    Slot slot;
    slot.kind = Slot::kSweep;
    slot.window = window;
    return slot;
}

GridClockedEngine::Slot GridClockedEngine::compare_cell(uint32_t half, const PortWindow& window) {
    CellBuffer::Half& h = buffer_.half(half);
    Slot slot = read_window(h.boxes, window.row, h.boxes, window);
    const uint32_t dims = grid_.dims();
    const uint32_t here[3] = {cell_number_ % dims, cell_number_ / dims % dims, cell_number_ / dims / dims};
    uint64_t hits = lanes_.evaluate(h.boxes, window.valid_lanes);
    while (hits != 0) {
        const auto lane = static_cast<uint32_t>(__builtin_ctzll(hits));
        hits &= hits - 1;
        const uint32_t row = window.row, column = window.first_column + lane;
        const uint8_t row_first[3] = {h.first[0][row], h.first[1][row], h.first[2][row]};
        const uint8_t column_first[3] = {h.first[0][column], h.first[1][column], h.first[2][column]};
        if (!home_cell_keeps(row_first, column_first, here)) continue;
        slot.hits |= 1ull << lane;
        slot.pairs[slot.count++] = {h.index[row], h.index[column]};
    }
    return slot;
}

GridClockedEngine::Slot GridClockedEngine::compare_row(const PortWindow& window) {
    CellBuffer::Half& h = buffer_.half(0);
    Slot slot = read_window(row_register_, 0, h.boxes, window);
    slot.hits = lanes_.evaluate(row_register_, h.boxes, window.valid_lanes);
    for (uint64_t hits = slot.hits; hits != 0; hits &= hits - 1) {
        const uint32_t l = h.index[window.first_column + static_cast<uint32_t>(__builtin_ctzll(hits))];
        slot.pairs[slot.count++] = {std::min(window.row, l), std::max(window.row, l)};
    }
    return slot;
}

}  // namespace cdvp
