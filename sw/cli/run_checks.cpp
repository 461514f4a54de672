#include "sw/cli/run_checks.h"

#include <limits.h>

#include <algorithm>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "models/control_registers/control_registers.h"
#include "platform/fault_injection.h"
#include "models/common/user_text.h"
#include "sw/scene/scene.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

bool from_flag(const po::variables_map& vm, const char* flag) { return vm.count(flag) != 0 && !vm[flag].defaulted(); }

// Where the object count came from: the trace's largest frame, --objects or its default.
std::string objects_origin(const RunOptions& o, const po::variables_map& vm, uint64_t max_objects) {
    const std::string count = std::to_string(max_objects);
    if (vm.count("trace")) return count + " objects (the largest frame of --trace " + excerpt(o.trace) + ")";
    return count + " objects (" + (from_flag(vm, "objects") ? "--objects" : "the default of --objects") + ")";
}

// SystemC counts time in 64-bit femtoseconds (2^64 fs = 5.1 hours). A run
// whose generous estimate exceeds half of that is refused up front instead
// of overflowing the kernel's clock mid-run.
void check_simulated_time(const RunOptions& o, const po::variables_map& vm, const BoardConfig& board,
                          const ValueOrigins& origins, uint64_t max_objects, uint64_t frame_count) {
    constexpr double kBudgetSeconds = 9223.0;   // 2^63 fs
    constexpr double kPerBoxSeconds = 10e-6;    // PIO of a box on the slowest bus, with margin
    constexpr double kPerFrameSeconds = 1e-3;   // driver calls, interrupts, status reads, with margin
    const double frames = static_cast<double>(frame_count);
    const double frame_seconds = static_cast<double>(board.sweep_cycles(max_objects)) /
                                     (board.clock_mhz * 1e6) +
                                 static_cast<double>(max_objects) * kPerBoxSeconds + kPerFrameSeconds;
    const double total = frames * frame_seconds;
    if (total <= kBudgetSeconds) return;
    const std::string frames_origin =
        vm.count("trace") ? "the frames of --trace " + excerpt(o.trace)
                          : std::string(from_flag(vm, "frames") ? "--frames" : "the default of --frames");
    std::ostringstream message;
    message << "a run of " << frame_count << (frame_count == 1 ? " frame (" : " frames (") << frames_origin << ") of up to "
            << objects_origin(o, vm, max_objects) << " at " << origins.m << " and " << origins.clock
            << " would simulate about " << std::fixed << std::setprecision(0) << total << " s, more than the "
            << kBudgetSeconds
            << " s SystemC's 64-bit femtosecond time allows: use fewer objects or frames, or a larger m";
    throw InputError(message.str());
}

// The model keeps every block RAM word: six coordinate memories of m
// copies each (2m ports from dual-port RAMs). A fixed bound keeps a large
// scene and m from exhausting this machine's memory instead of failing
// clearly, whatever the machine.
void check_model_memory(const RunOptions& o, const po::variables_map& vm, const BoardConfig& board,
                        const ValueOrigins& origins, uint64_t max_objects) {
    constexpr uint64_t kMaxModelBytes = uint64_t{2} << 30;
    const uint64_t bytes = board.block_ram_bytes(max_objects);
    if (bytes <= kMaxModelBytes) return;
    std::ostringstream message;
    message << "the board model for " << objects_origin(o, vm, max_objects) << " at " << origins.m << " needs "
            << std::fixed << std::setprecision(1) << static_cast<double>(bytes) / (1 << 30)
            << " GiB of block RAM words (6 coordinate memories x m copies); at most 2 GiB: use fewer objects or a "
               "smaller m";
    throw InputError(message.str());
}

}  // namespace

void check_path_lengths(const RunOptions& o, const po::variables_map& vm) {
    const std::pair<const char*, const std::string*> paths[] = {
        {"trace", &o.trace}, {"board", &o.board_name}, {"pairs-out", &o.pairs_out}, {"report", &o.report}, {"vcd", &o.vcd}};
    for (const auto& [flag, path] : paths) {
        if (vm.count(flag) == 0 || path->size() < PATH_MAX) continue;
        throw InputError(std::string("--") + flag + ": expected a path of at most " + std::to_string(PATH_MAX - 1) +
                         " bytes, got '" + excerpt(*path) + "'");
    }
}

ValueOrigins ValueOrigins::of(const RunOptions& o, const po::variables_map& vm, const std::string& preset_path,
                              double clock_mhz) {
    const std::string m = std::to_string(o.board.m);
    std::ostringstream clock;
    clock << clock_mhz;
    const std::string clock_origin = from_flag(vm, "clock-mhz") ? "--clock-mhz " + clock.str()
                                     : preset_path.empty()      ? clock.str() + " MHz (the default of --clock-mhz)"
                                                                : clock.str() + " MHz (" + preset_path + ": board.clock_mhz)";
    return {preset_path, from_flag(vm, "m") ? "--m " + m : "m=" + m + " (the default of --m)", clock_origin};
}

// Board settings are checked by the model; its message names the setting as
// the preset does ("fifo_depth: expected ..."). The error names where the
// value came from: the flag if one set it, else the preset file and key.
void validate_board(const BoardConfig& config, const po::variables_map& vm, const ValueOrigins& origins) {
    try {
        config.validate();
    } catch (const std::invalid_argument& e) {
        static const std::pair<const char*, const char*> kFlags[] = {
            {"m", "m"}, {"clock_mhz", "clock-mhz"}, {"compare_latency_cycles", "compare-latency"},
            {"fifo_depth", "fifo-depth"}, {"drain_per_cycle", "drain-rate"}, {"pair_buffer_depth", "pair-buffer"}};
        std::string message = e.what();
        for (const auto& [setting, flag] : kFlags) {
            const std::string prefix = std::string(setting) + ":";
            if (message.rfind(prefix, 0) != 0) continue;
            const std::string rest = message.substr(prefix.size() - 1);
            // m is never a preset's: the board's parallelism is the user's choice.
            const bool flagged = origins.preset_path.empty() || std::strcmp(setting, "m") == 0 || from_flag(vm, flag);
            // The FIFO must hold one cycle's hits, so its check depends on m too.
            const std::string with_m = std::strcmp(setting, "fifo_depth") == 0 ? " (with " + origins.m + ")" : "";
            message = (flagged ? std::string("--") + flag : origins.preset_path + ": board." + setting) + rest + with_m;
            break;
        }
        throw InputError(message);
    }
}

std::vector<FaultSpec> fault_specs(const std::vector<std::string>& texts, const DriverConfig& driver) {
    std::vector<FaultSpec> specs;
    for (const std::string& text : texts) {
        for (const FaultSpec& spec : parse_fault_specs(text)) {
            const bool needs_dma = spec.kind == FaultKind::kTargetAbort || spec.kind == FaultKind::kMasterAbort ||
                                   spec.kind == FaultKind::kRetry || spec.kind == FaultKind::kDisconnect ||
                                   spec.kind == FaultKind::kDmaHang;
            if (needs_dma && !driver.use_dma) {
                throw InputError("--inject: '" + to_string(spec) + "' faults a DMA; it needs --transfer dma");
            }
            if (spec.kind == FaultKind::kLostIrq && !driver.use_interrupts) {
                throw InputError("--inject: '" + to_string(spec) + "' loses an interrupt; it needs --wait irq");
            }
            specs.push_back(spec);
        }
    }
    return specs;
}

void check_inject_frames(const std::vector<FaultSpec>& specs, std::optional<uint64_t> last_frame,
                         const std::function<bool(uint64_t)>& has_frame, const std::string& frames_origin) {
    for (const FaultSpec& spec : specs) {
        const std::string prefix = "--inject: '" + to_string(spec) + "': frame " + std::to_string(spec.frame);
        if (!last_frame) throw InputError(prefix + " never runs: the run has no frames (" + frames_origin + ")");
        if (spec.frame > *last_frame) {
            throw InputError(prefix + " is past the run's last frame " + std::to_string(*last_frame) + " (" +
                             frames_origin + ")");
        }
        if (!has_frame(spec.frame)) throw InputError(prefix + " is not one of the run's frames (" + frames_origin + ")");
    }
}

void check_scene_fits(const RunOptions& o, const po::variables_map& vm, const BoardConfig& board, uint32_t block_rams,
                      const ValueOrigins& origins, uint64_t max_objects, uint64_t frame_count) {
    check_model_memory(o, vm, board, origins, max_objects);
    check_simulated_time(o, vm, board, origins, max_objects, frame_count);
    const uint64_t needed = board.block_rams(max_objects);
    const uint64_t per_m = needed / board.m;  // block RAMs grow linearly with m
    if (block_rams == 0 || needed <= block_rams) return;
    // The FPGA's block RAM count is only ever a preset's.
    const uint64_t largest = block_rams / per_m;
    throw InputError(origins.preset_path + ": board.block_rams: " + std::to_string(block_rams) +
                     " block RAMs are too few for " + origins.m + " at " + objects_origin(o, vm, max_objects) +
                     ": they need 6 x m x ceil(N/512) = " + std::to_string(needed) +
                     (largest > 0 ? " (largest m that fits: " + std::to_string(largest) + ")"
                                  : " (not even m=1 fits: use fewer objects or a larger device)"));
}

}  // namespace cdvp
