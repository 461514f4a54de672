// RtlBoard for one Verilator-built variant of collision_board_top: Model is
// the generated class (Vcdvp_rtl_<name>), Root its root (the public signals
// of probes.vlt). Included only by a variant's entry (rtl_model_entry.cpp.in),
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

template <class Model, class Root>
class VerilatedBoard final : public RtlBoard {
public:
    explicit VerilatedBoard(const RtlMemoryShape& shape)
        : shape_(shape), context_(std::make_unique<VerilatedContext>()) {
        context_->traceEverOn(true);
        model_ = std::make_unique<Model>(context_.get(), "board");
        if (shape_.tile_boxes > 0) {
            ssram_.assign(kSsramBanks * shape_.capacity(), 0);
            answers_.assign(shape_.tile_latency + 1, Word{});
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
            if (shape_.tile_latency > 0) drive_ssram(answers_[shape_.tile_latency]);
        }
        model_->clk = 0;
        model_->eval();
        if (tiled && shape_.tile_latency == 0) {
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
        const Root& r = *model_->rootp;
        RtlProbes p;
        p.state = r.collision_board_top__DOT__state;
        p.cycles = r.collision_board_top__DOT__cycles;
        p.stalls = r.collision_board_top__DOT__stalls;
        p.total_pairs = r.collision_board_top__DOT__total_pairs;
        p.buffered = r.collision_board_top__DOT__buffered;
        p.fifo_level = r.collision_board_top__DOT__fifo_level;
        p.pair_valid = r.collision_board_top__DOT__out_valid;
        const uint64_t pair = r.collision_board_top__DOT__out_pair;
        const uint64_t index_mask = (uint64_t{1} << shape_.address_bits) - 1;
        p.pair = IndexPair{static_cast<uint32_t>(pair >> shape_.address_bits), static_cast<uint32_t>(pair & index_mask)};
        p.enable = r.collision_board_top__DOT__enable;
        p.window = r.collision_board_top__DOT__src_window;
        p.row = r.collision_board_top__DOT__src_row;
        p.first_column = r.collision_board_top__DOT__src_first;
        p.valid_lanes = r.collision_board_top__DOT__src_valid;
        p.hits = r.collision_board_top__DOT__pushed_hits;
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
