// RtlBoard for one Verilator-built variant of a board top (collision_board_top
// or grid_board_top): Model is the generated class (Vcdvp_rtl_<name>), Root
// its root (the public signals of probes.vlt), Probes how to read them. Included only by a variant's entry (rtl_model_entry.cpp.in),
// compiled with Verilator's headers: at build time for a built-in variant, on
// first use for the others (part of the RTL kit: standard and Verilator
// headers and rtl_board.h only).
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>
#include <vector>

#include "models/rtl_engine/rtl_board.h"
#include "verilated.h"
#include "verilated_vcd_c.h"

namespace cdvp {

// The signals both tops name alike (probes.vlt), read from Verilator's root
// of the top `top`.
#define CDVP_READ_BOARD_PROBES(r, top, p)                        \
    do {                                                          \
        (p).state = (r).top##__DOT__state;                        \
        (p).cycles = (r).top##__DOT__cycles;                      \
        (p).stalls = (r).top##__DOT__stalls;                      \
        (p).total_pairs = (r).top##__DOT__total_pairs;            \
        (p).buffered = (r).top##__DOT__buffered;                  \
        (p).fifo_level = (r).top##__DOT__fifo_level;              \
        (p).pair_valid = (r).top##__DOT__out_valid;               \
        (p).enable = (r).top##__DOT__enable;                      \
        (p).window = (r).top##__DOT__src_window;                  \
        (p).row = (r).top##__DOT__src_row;                        \
        (p).first_column = (r).top##__DOT__src_first;             \
        (p).valid_lanes = (r).top##__DOT__src_valid;              \
        (p).hits = (r).top##__DOT__pushed_hits;                   \
    } while (false)

// The seed's board (collision_board_top.v).
struct AllPairsTopProbes {
    template <class Root>
    static uint64_t read(const Root& r, RtlProbes& p) {
        CDVP_READ_BOARD_PROBES(r, collision_board_top, p);
        return r.collision_board_top__DOT__out_pair;
    }
};
// The grid board (grid_board_top.v), with its last sweep's registers.
struct GridTopProbes {
    template <class Root>
    static uint64_t read(const Root& r, RtlProbes& p) {
        CDVP_READ_BOARD_PROBES(r, grid_board_top, p);
        p.grid_dims = r.grid_board_top__DOT__sweep_dims;
        p.grid_large = r.grid_board_top__DOT__sweep_large;
        p.grid_overflow = r.grid_board_top__DOT__sweep_overflow;
        p.grid_excluded = r.grid_board_top__DOT__sweep_excluded;
        p.grid_busy = r.grid_board_top__DOT__sweep_busy;
        p.grid_entries = r.grid_board_top__DOT__sweep_entries;
        p.grid_slots = r.grid_board_top__DOT__sweep_slots;
        return r.grid_board_top__DOT__out_pair;
    }
};
#undef CDVP_READ_BOARD_PROBES

// Probes: AllPairsTopProbes or GridTopProbes, after the top compiled.
template <class Model, class Root, class Probes>
class VerilatedBoard final : public RtlBoard {
public:
    explicit VerilatedBoard(const RtlMemoryShape& shape)
        : shape_(shape), context_(std::make_unique<VerilatedContext>()) {
        context_->traceEverOn(true);
        model_ = std::make_unique<Model>(context_.get(), "board");
        if (shape_.has_ssram()) {
            ssram_.assign(kSsramBanks * shape_.capacity(), 0);
            answers_.assign(shape_.ssram_latency() + 1, Word{});
        }
        model_->clk = 0;
        model_->reset = 1;
        model_->eval();
        edge();
        edge();
        model_->reset = 0;
        model_->eval();
    }
    ~VerilatedBoard() override {
        if (trace_) trace_->close();
        model_->final();
        // Verilator erases the model's scopes from the thread's current
        // context, not the model's: make it this model's, or destroying one
        // of two live models locks up (or touches a freed context).
        Verilated::threadContextp(context_.get());
        trace_.reset();
        model_.reset();
    }

    void edge() override {
        Word read_now{};
        const bool tiled = !ssram_.empty();
        uint32_t write_mask = 0;
        uint32_t address = 0;
        Word write_words{};
        if (tiled) {
            // What the SSRAM sees before the edge: its address, reads and writes.
            address = model_->ssram_addr;
            write_mask = model_->ssram_we;
            for (uint32_t b = 0; b < kSsramBanks; ++b) write_words[b] = model_->ssram_wdata[b];
            read_now = ssram_word(address);
        }
        model_->clk = 1;
        model_->eval();
        dump(0);
        if (tiled) {
            for (uint32_t b = 0; b < kSsramBanks; ++b) {
                if (write_mask & (1u << b)) ssram_[b * shape_.capacity() + address] = write_words[b];
            }
            // A pipelined read answers tile_latency edges after its address.
            for (std::size_t s = answers_.size() - 1; s >= 2; --s) answers_[s] = answers_[s - 1];
            if (answers_.size() >= 2) answers_[1] = read_now;
            if (shape_.ssram_latency() > 0) drive_ssram(answers_[shape_.ssram_latency()]);
        }
        model_->clk = 0;
        model_->eval();
        if (tiled && shape_.ssram_latency() == 0) {
            // A flow-through SSRAM answers the address it sees in the same cycle.
            drive_ssram(ssram_word(model_->ssram_addr));
            model_->eval();
        }
        dump(period_fs_ / 2);
        time_fs_ += period_fs_;
    }

    void write(uint32_t address, uint32_t data) override {
        model_->addr = address;
        model_->wdata = data;
        model_->we = 1;
        edge();
        model_->we = 0;
        model_->eval();
    }

    void load_ssram(uint32_t coordinate, uint32_t index, uint32_t word) override {
        if (ssram_.empty() || coordinate >= kSsramBanks || index >= shape_.capacity()) {
            throw std::out_of_range("load_ssram: no such SSRAM word");
        }
        ssram_[coordinate * shape_.capacity() + index] = word;
    }

    RtlProbes probes() const override {
        RtlProbes p;
        const uint64_t pair = Probes::read(*model_->rootp, p);
        const uint64_t index_mask = (uint64_t{1} << shape_.address_bits) - 1;
        p.pair = IndexPair{static_cast<uint32_t>(pair >> shape_.address_bits), static_cast<uint32_t>(pair & index_mask)};
        return p;
    }

    void trace_to(const std::string& path, uint64_t period_fs) override {
        period_fs_ = period_fs;
        trace_ = std::make_unique<VerilatedVcdC>();
        model_->trace(trace_.get(), 99);
        // The platform's unit, whatever the model's timescale: times are dumped as given.
        trace_->set_time_unit("1fs");
        trace_->set_time_resolution("1fs");
        trace_->open(path.c_str());
        if (!trace_->isOpen()) throw std::runtime_error(path + ": cannot write the RTL's waveforms");
    }
    void set_time_fs(uint64_t time_fs) override { time_fs_ = std::max(time_fs, time_fs_); }
    void set_trace_open(bool open) override { trace_open_ = open; }
    void flush_trace() override {
        if (trace_) trace_->flush();
    }
    void close_trace() override {
        if (trace_) trace_->close();
        trace_.reset();
    }

private:
    static constexpr uint32_t kSsramBanks = 6;
    using Word = std::array<uint32_t, kSsramBanks>;

    Word ssram_word(uint64_t address) const {
        Word w{};
        for (uint32_t b = 0; b < kSsramBanks; ++b) w[b] = ssram_[b * shape_.capacity() + address];
        return w;
    }
    void drive_ssram(const Word& w) {
        for (uint32_t b = 0; b < kSsramBanks; ++b) model_->ssram_rdata[b] = w[b];
    }
    void dump(uint64_t offset_fs) {
        if (trace_ && trace_open_) trace_->dump(time_fs_ + offset_fs);
    }

    RtlMemoryShape shape_;
    std::unique_ptr<VerilatedContext> context_;
    std::unique_ptr<Model> model_;
    std::vector<uint32_t> ssram_;  // bank b, word i at b * capacity + i
    std::vector<Word> answers_;    // answers_[s]: the word read s edges ago
    std::unique_ptr<VerilatedVcdC> trace_;
    bool trace_open_ = true;
    uint64_t period_fs_ = 1000000;
    uint64_t time_fs_ = 0;  // the next rising edge's time in the waveforms
};

}  // namespace cdvp
