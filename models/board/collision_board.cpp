#include "models/board/collision_board.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "models/common/address_range.h"
#include "models/common/transaction.h"
#include "models/grid_clocked_engine/grid_clocked_engine.h"
#include "models/rtl_engine/lockstep_engine.h"
#include "models/rtl_engine/rtl_engine.h"
#include "models/rtl_engine/rtl_waves.h"

namespace cdvp {

using namespace sc_core;

CollisionBoard::CollisionBoard(const sc_module_name& name, const BoardConfig& config, uint32_t capacity,
                               Fidelity fidelity, PairBudget budget)
    : sc_module(name),
      socket("socket"),
      irq("irq"),
      core_(config, capacity, fidelity, budget),
      period_(1.0 / config.clock_mhz, SC_US) {
    socket.register_b_transport(this, &CollisionBoard::b_transport);
    socket.register_transport_dbg(this, &CollisionBoard::transport_dbg);
    SC_METHOD(on_clock_event);
    sensitive << clock_event_;
    dont_initialize();
    SC_METHOD(clock_fall);
    sensitive << fall_;
    dont_initialize();
    SC_METHOD(on_state_change);
    sensitive << state_changed_;
    dont_initialize();
    SC_METHOD(drive_irq);
    sensitive << irq_changed_;
    // Sized once, before trace() takes the addresses of the traced copy.
    waves_.live.address.assign(2 * config.m, 0);
    waves_.show();
}

const StateNames CollisionBoard::kControllerStates{"controller", {"idle", "running", "paused", "done"}};

namespace {
// Bits needed to show values 0..max in a waveform.
int bits_for(uint64_t max) {
    int bits = 1;
    while (bits < 64 && (max >> bits) != 0) ++bits;
    return bits;
}
}  // namespace

void CollisionBoard::add_waves(WaveList& waves) {
    traced_engine_ = dynamic_cast<ClockedEngine*>(&core_.engine());
    traced_grid_ = dynamic_cast<GridClockedEngine*>(&core_.engine());
    if (traced_engine_ == nullptr && traced_grid_ == nullptr) throw std::logic_error("waveforms need the clocked engine");
    // The waveforms start from the board as it is (idle), not from zeros.
    sample_trace();
    const std::string p = std::string(name()) + ".";
    const BoardConfig& config = core_.config();
    const Waves& shown = waves_.shown();
    waves.group("board: control");
    waves.add(shown.clk, p + "clk");
    waves.add(shown.state, p + "control.state", 2, kControllerStates);
    for (std::size_t k = 0; k < shown.in_state.size(); ++k) {
        waves.add(shown.in_state[k], p + "control." + kControllerStates.names[k]);
    }
    waves.add(shown.stall, p + "control.stall");
    waves.group("board: address generator");
    // Address ports may point one window past the last box (invalid lanes).
    const int address_bits = bits_for(uint64_t{core_.capacity()} + config.lanes());
    for (size_t port = 0; port < shown.address.size(); ++port) {
        waves.add(shown.address[port], p + "address_generator.address_" + std::to_string(port), address_bits,
                  WaveFormat::kDecimal);
    }
    waves.group("board: comparison unit");
    const int lanes = static_cast<int>(config.lanes());
    waves.add(shown.lane_valid, p + "comparison.lane_valid", lanes, WaveFormat::kBinary);
    waves.add(shown.lane_hit, p + "comparison.lane_hit", lanes, WaveFormat::kBinary);
    waves.group("board: pair collector");
    waves.add(shown.fifo_level, p + "collector.fifo_level", bits_for(config.collector.fifo_depth), WaveFormat::kDecimal);
    waves.add(shown.pair_count, p + "collector.pair_count", bits_for(config.collector.buffer_depth),
              WaveFormat::kDecimal);
    if (traced_grid_ != nullptr) {
        waves.group("board: grid sequencer");
        waves.add(shown.grid_pass, p + "grid.pass", 4, WaveFormat::kDecimal);
        for (uint32_t k = 1; k < GridClockedEngine::kPasses; ++k) {
            waves.add(shown.in_pass[k], p + "grid." + to_string(static_cast<GridClockedEngine::Pass>(k)));
        }
        waves.add(shown.grid_box, p + "grid.box", bits_for(core_.capacity()), WaveFormat::kDecimal);
        waves.add(shown.grid_cell, p + "grid.cell", 24, WaveFormat::kDecimal);
        waves.add(shown.grid_tile, p + "grid.tile", bits_for(core_.capacity()), WaveFormat::kDecimal);
        waves.add(shown.loading, p + "grid.loading");
        waves.add(shown.wait, p + "grid.wait");
        return;
    }
    if (!config.tiles.tiled()) return;
    waves.group("board: tile loader");
    const int tile_bits = bits_for(uint64_t{core_.capacity()} / config.tiles.boxes + 1);
    waves.add(shown.row_tile, p + "tiles.row_tile", tile_bits, WaveFormat::kDecimal);
    waves.add(shown.column_tile, p + "tiles.column_tile", tile_bits, WaveFormat::kDecimal);
    waves.add(shown.loading, p + "tiles.loading");
    waves.add(shown.wait, p + "tiles.wait");
}

std::vector<TracedSignal> CollisionBoard::trace_rtl(const std::string& path) {
    traced_rtl_ = dynamic_cast<RtlEngine*>(&core_.engine());
    if (auto* lockstep = dynamic_cast<LockstepEngine*>(&core_.engine())) traced_rtl_ = &lockstep->rtl();
    if (traced_rtl_ == nullptr) throw std::logic_error("RTL waveforms need the rtl engine");
    // In femtoseconds, the platform's waveforms' unit.
    const auto fs_per_unit = static_cast<uint64_t>(std::llround(sc_get_time_resolution().to_seconds() * 1e15));
    traced_rtl_->trace_to(path, [this, fs_per_unit] { return access_time_.value() * fs_per_unit; });
    return rtl_waves(traced_rtl_->variant());
}

void CollisionBoard::close_rtl_trace() {
    if (traced_rtl_ != nullptr) traced_rtl_->close_trace();
}

void CollisionBoard::set_tracing(bool on) {
    if ((traced_engine_ == nullptr && traced_grid_ == nullptr && traced_rtl_ == nullptr) || on == tracing_on_) return;
    tracing_on_ = on;
    if (core_.running()) throw std::logic_error("tracing switched during a sweep");
    if (traced_rtl_ != nullptr) {
        traced_rtl_->set_trace_open(on);
        return;
    }
    waves_.set_open(on);
}

void CollisionBoard::b_transport(tlm::tlm_generic_payload& payload, sc_time& delay) {
    // Host accesses take no board time here; the bus in front of the board
    // annotates its own timing, and the access happens at now + delay.
    if (const tlm::tlm_response_status shape = check_plain_access(payload); shape != tlm::TLM_OK_RESPONSE) {
        payload.set_response_status(shape);
        return;
    }
    const sc_time at = sc_time_stamp() + delay;
    access_time_ = at;
    sync(at);
    const uint64_t segments_before = core_.segments_started();
    const SweepState phase_before = core_.phase();
    payload.set_response_status(
        access(payload.get_command(), payload.get_address(), payload.get_data_ptr(), payload.get_data_length()));
    if (payload.get_command() == tlm::TLM_WRITE_COMMAND) schedule_clock(segments_before, at);
    // The waveforms see a command's new state when it takes effect, not at
    // the next clock edge (which an abort or a finished sweep never has).
    if (clocked_edge_by_edge() && core_.phase() != phase_before) state_changed_.notify(delay);
    if (traced_rtl_ != nullptr && tracing_on_ && core_.running() && !first_traced_start_) first_traced_start_ = at;
    // A command or the synchronisation may have moved the line.
    if (core_.interrupt() != irq.read()) irq_changed_.notify(delay);
}

unsigned int CollisionBoard::transport_dbg(tlm::tlm_generic_payload& payload) {
    // Debug reads only: a debug write must not start the clock behind the simulation's back.
    if (payload.get_command() != tlm::TLM_READ_COMMAND) return 0;
    sync(sc_time_stamp());
    const bool ok = access(tlm::TLM_READ_COMMAND, payload.get_address(), payload.get_data_ptr(),
                           payload.get_data_length()) == tlm::TLM_OK_RESPONSE;
    return ok ? payload.get_data_length() : 0;
}

namespace {
tlm::tlm_response_status response_for(RegisterResult result) {
    switch (result) {
        case RegisterResult::kDone: return tlm::TLM_OK_RESPONSE;
        case RegisterResult::kRefused: return tlm::TLM_COMMAND_ERROR_RESPONSE;
        case RegisterResult::kUnmapped: break;
    }
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;
}
}  // namespace

tlm::tlm_response_status CollisionBoard::access(tlm::tlm_command command, uint64_t address, unsigned char* data,
                                                unsigned int length) {
    namespace am = address_map;
    using R = ControlRegisters;
    if (length == 0 || length % 4 != 0 || address % 4 != 0) return tlm::TLM_BURST_ERROR_RESPONSE;
    const bool write = command == tlm::TLM_WRITE_COMMAND;
    const uint64_t words = length / 4;
    auto word_at = [data](uint64_t k) {
        uint32_t w;
        std::memcpy(&w, data + 4 * k, 4);
        return w;
    };
    auto set_word = [data](uint64_t k, uint32_t w) { std::memcpy(data + 4 * k, &w, 4); };

    if (range_within(address, length, am::kRegisters, am::kRegistersSize)) {
        if (words != 1) return tlm::TLM_BURST_ERROR_RESPONSE;
        const auto offset = static_cast<uint32_t>(address - am::kRegisters);
        if (write) {
            if (offset == R::kControl && (word_at(0) & R::kStart) && fault_due(faults_, FaultKind::kBoardError)) {
                core_.raise_error(R::kInjectedError);
                return tlm::TLM_OK_RESPONSE;
            }
            return response_for(core_.write_register(offset, word_at(0)));
        }
        uint32_t value = 0;
        if (!core_.read_register(offset, value)) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
        set_word(0, value);
        return tlm::TLM_OK_RESPONSE;
    }
    if (range_within(address, length, am::kCoordinateBase, kCoordinates * am::kWindowSize)) {
        const uint64_t offset = address - am::kCoordinateBase;
        const auto coordinate = static_cast<Coordinate>(offset / am::kWindowSize);
        const uint64_t first = offset % am::kWindowSize / 4;
        // One window per access, and only the boxes the memories hold.
        if (first + words > core_.capacity()) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
        if (write) {
            return response_for(core_.write_coordinates(coordinate, static_cast<uint32_t>(first), data,
                                                        static_cast<uint32_t>(words)));
        }
        for (uint64_t k = 0; k < words; ++k) set_word(k, core_.read_coordinate(coordinate, static_cast<uint32_t>(first + k)));
        return tlm::TLM_OK_RESPONSE;
    }
    if (range_within(address, length, am::kPairBuffer, am::kPairBufferSize)) {
        if (write) return tlm::TLM_COMMAND_ERROR_RESPONSE;
        const uint64_t first = (address - am::kPairBuffer) / 4;
        // Only the words the buffer's pairs encode to: reading more is an address error.
        if (first + words > core_.window_words()) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
        core_.copy_window_words(first, words, data);
        return tlm::TLM_OK_RESPONSE;
    }
    if (range_within(address, length, am::kDeltaStream, am::kDeltaStreamSize)) {
        if (!write) return tlm::TLM_COMMAND_ERROR_RESPONSE;
        return response_for(core_.write_delta(data, static_cast<uint32_t>(words)));
    }
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;
}

void CollisionBoard::sync(const sc_time& at) {
    // An access annotated behind the segment's start (a loosely-timed
    // initiator) sees the board as it was at the start.
    if (!core_.running() || at <= segment_start_) return;
    core_.advance_to((at - segment_start_).value() / period_.value());
}

void CollisionBoard::schedule_clock(uint64_t segments_before, const sc_time& at) {
    if (core_.segments_started() == segments_before) {
        if (!core_.running()) clock_event_.cancel();  // aborted, or the command was refused
        return;
    }
    segment_start_ = at;
    clock_event_.cancel();
    const sc_time lead = at - sc_time_stamp();
    if (clocked_edge_by_edge()) {
        clock_event_.notify(lead + period_);  // the first edge comes one period after the command
        return;
    }
    const uint64_t edges = core_.segment_edges();
    // A segment that would end past the simulator's last instant never ends;
    // the driver's own time limit reports it.
    if (edges <= (sc_max_time() - at).value() / period_.value()) {
        clock_event_.notify(lead + sc_time::from_value(edges * period_.value()));
    }
}

void CollisionBoard::on_clock_event() {
    sync(sc_time_stamp());
    if (clocked_edge_by_edge()) {
        waves_.live.clk = true;
        fall_.notify(period_ / 2);
        sample_trace();
        if (core_.phase() == SweepState::kDone && !first_traced_done_) first_traced_done_ = sc_time_stamp();
        if (core_.running()) {
            const uint64_t next = core_.edges() + 1;
            clock_event_.notify(segment_start_ + sc_time::from_value(next * period_.value()) - sc_time_stamp());
            return;
        }
    }
    if (traced_rtl_ != nullptr && tracing_on_ && core_.phase() == SweepState::kDone && !first_traced_done_) {
        first_traced_done_ = sc_time_stamp();
    }
    irq_changed_.notify(SC_ZERO_TIME);
}

// The interrupt line's only driver, so both the host's commands and the
// clocked process can change it.
void CollisionBoard::drive_irq() { irq.write(core_.interrupt()); }

void CollisionBoard::clock_fall() {
    waves_.live.clk = false;
    waves_.show();
}

void CollisionBoard::on_state_change() {
    sync(sc_time_stamp());
    sample_trace();
    if (core_.running() && !first_traced_start_) first_traced_start_ = sc_time_stamp();
}

template <class Engine>
void CollisionBoard::sample_datapath(const Engine& engine) {
    Waves& w = waves_.live;
    const PortWindow& issue = engine.last_issue();
    w.address[0] = issue.row;
    for (size_t port = 1; port < w.address.size(); ++port) {
        w.address[port] = issue.first_column + static_cast<uint32_t>(port) - 1;
    }
    const auto& out = engine.compare_output();
    const bool sweeping = out.kind == Engine::Slot::kSweep && out.window.valid_lanes > 0;
    w.lane_valid = sweeping ? (~0ull >> (64 - out.window.valid_lanes)) : 0;
    w.lane_hit = sweeping ? out.hits : 0;
    w.fifo_level = engine.fifo_level();
    w.stall = engine.stalled();
    w.loading = engine.loading();
    w.wait = engine.waiting();
}

void CollisionBoard::sample_trace() {
    Waves& w = waves_.live;
    w.state = static_cast<uint32_t>(core_.phase());
    for (std::size_t k = 0; k < w.in_state.size(); ++k) w.in_state[k] = w.state == k;
    w.pair_count = core_.buffered_pairs();
    if (traced_grid_ != nullptr) {
        const GridClockedEngine& grid = *traced_grid_;
        sample_datapath(grid);
        w.grid_pass = static_cast<uint32_t>(grid.pass());
        for (std::size_t k = 0; k < w.in_pass.size(); ++k) w.in_pass[k] = w.grid_pass == k;
        w.grid_box = grid.box();
        w.grid_cell = grid.cell();
        w.grid_tile = grid.tile();
    } else {
        const ClockedEngine& engine = *traced_engine_;
        sample_datapath(engine);
        w.row_tile = engine.row_tile();
        w.column_tile = engine.column_tile();
    }
    waves_.show();
}

}  // namespace cdvp
