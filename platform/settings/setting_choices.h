// The choice settings' types: each an enum (or bool) declared once with its
// names, the one table that parses a choice's text (a preset, a config file,
// -c, a flag) and prints it (the settings table, --help, the report, the
// summary). Settings holds the typed values; only a setting's parser meets
// the text.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "models/board_spec/board_engine.h"
#include "models/pci/background_traffic.h"
#include "platform/driver/driver_config.h"

namespace cdvp {

// The host bus (bus.type): none, or the bus whose bus.* keys apply.
enum class BusType : uint8_t { kIdeal, kPci, kPcie };
// The level the host bus is timed at (bus.model): the closed formula, or
// transaction by transaction against background traffic (docs/bus_models.md).
enum class BusModel : uint8_t { kFormula, kTransaction };
// Where the boxes live (board.memory; platform/memory_plan.h resolves kAuto).
enum class BoxMemory : uint8_t { kAuto, kBlockRam, kSsram };
// The FPGA family whose synthesis results cost the board (device.family).
enum class DeviceFamily : uint8_t { kNone, kXc2v, kXcup };

template <class T>
struct ChoiceName {
    T value;
    const char* name;
};

// Choices<T>::names: every value of T with its name, in the order the
// settings table lists them ("dma or pio").
template <class T>
struct Choices;

template <>
struct Choices<BusType> {
    static constexpr ChoiceName<BusType> names[] = {
        {BusType::kIdeal, "ideal"}, {BusType::kPci, "pci"}, {BusType::kPcie, "pcie"}};
};
template <>
struct Choices<BusModel> {
    static constexpr ChoiceName<BusModel> names[] = {{BusModel::kFormula, "formula"}, {BusModel::kTransaction, "transaction"}};
};
// A background master's direction (bus.load_direction): it reads or writes host memory.
template <>
struct Choices<Direction> {
    static constexpr ChoiceName<Direction> names[] = {{Direction::kToHost, "to_host"}, {Direction::kToBoard, "to_board"}};
};
template <>
struct Choices<LoadArrivals> {
    static constexpr ChoiceName<LoadArrivals> names[] = {{LoadArrivals::kPeriodic, "periodic"}, {LoadArrivals::kRandom, "random"}};
};
template <>
struct Choices<BoxMemory> {
    static constexpr ChoiceName<BoxMemory> names[] = {
        {BoxMemory::kAuto, "auto"}, {BoxMemory::kBlockRam, "block_ram"}, {BoxMemory::kSsram, "ssram"}};
};
// What the board computes a sweep with (board.algorithm).
template <>
struct Choices<BoardAlgorithm> {
    static constexpr ChoiceName<BoardAlgorithm> names[] = {{BoardAlgorithm::kAllPairs, "all_pairs"},
                                                           {BoardAlgorithm::kGrid, "grid"}};
};
template <>
struct Choices<DeviceFamily> {
    static constexpr ChoiceName<DeviceFamily> names[] = {
        {DeviceFamily::kNone, "none"}, {DeviceFamily::kXc2v, "xc2v"}, {DeviceFamily::kXcup, "xcup"}};
};
template <>
struct Choices<Transfer> {
    static constexpr ChoiceName<Transfer> names[] = {{Transfer::kDma, "dma"}, {Transfer::kPio, "pio"}};
};
template <>
struct Choices<WaitMode> {
    static constexpr ChoiceName<WaitMode> names[] = {{WaitMode::kIrq, "irq"}, {WaitMode::kPoll, "poll"}};
};
template <>
struct Choices<UploadMode> {
    static constexpr ChoiceName<UploadMode> names[] = {
        {UploadMode::kFull, "full"}, {UploadMode::kDelta, "delta"}, {UploadMode::kAuto, "auto"}};
};
template <>
struct Choices<PairFormat> {
    static constexpr ChoiceName<PairFormat> names[] = {
        {PairFormat::kList, "list"}, {PairFormat::kCounted, "counted"}, {PairFormat::kBitmap, "bitmap"}};
};
template <>
struct Choices<InterruptPolicy> {
    static constexpr ChoiceName<InterruptPolicy> names[] = {{InterruptPolicy::kEvery, "every"},
                                                            {InterruptPolicy::kBoard, "board"}};
};
// The board's engine; the model's to_string(Fidelity) gives the same names.
template <>
struct Choices<Fidelity> {
    static constexpr ChoiceName<Fidelity> names[] = {{Fidelity::kCycle, "cycle"}, {Fidelity::kFast, "fast"}, {Fidelity::kRtl, "rtl"},
                                                     {Fidelity::kLockstep, "rtl-lockstep"}};
};
// The modelling level of a run (run.fidelity): one of the engines on the
// SystemC platform, or the analytic level's closed forms without a kernel
// (platform/analytic_platform.h).
// auto: the analytic level where its error is bounded or measured within
// run.max_error_percent, the fast engine elsewhere (sw/run/run_platform.h).
enum class ModelLevel : uint8_t { kCycle, kFast, kAnalytic, kAuto, kRtl };
template <>
struct Choices<ModelLevel> {
    static constexpr ChoiceName<ModelLevel> names[] = {{ModelLevel::kRtl, "rtl"},
                                                       {ModelLevel::kCycle, "cycle"},
                                                       {ModelLevel::kFast, "fast"},
                                                       {ModelLevel::kAnalytic, "analytic"},
                                                       {ModelLevel::kAuto, "auto"}};
};
// The engine a level runs on the platform (the analytic level runs none; auto the fast one beside it).
inline Fidelity engine_of(ModelLevel level, bool lockstep = false) {
    if (level == ModelLevel::kRtl) return lockstep ? Fidelity::kLockstep : Fidelity::kRtl;
    return level == ModelLevel::kCycle ? Fidelity::kCycle : Fidelity::kFast;
}
// A switch (run.ignore_capacity).
template <>
struct Choices<bool> {
    static constexpr ChoiceName<bool> names[] = {{false, "no"}, {true, "yes"}};
};

template <class T, class = void>
struct has_choices : std::false_type {};
template <class T>
struct has_choices<T, std::void_t<decltype(Choices<T>::names)>> : std::true_type {};

// A value's name.
template <class T>
const char* name_of(T value) {
    for (const ChoiceName<T>& c : Choices<T>::names) {
        if (c.value == value) return c.name;
    }
    return "unknown";
}

// The value a name names; nullopt for any other text.
template <class T>
std::optional<T> parse_choice(const std::string& text) {
    for (const ChoiceName<T>& c : Choices<T>::names) {
        if (text == c.name) return c.value;
    }
    return std::nullopt;
}

// Every name, in order.
template <class T>
std::vector<std::string> choice_names() {
    std::vector<std::string> names;
    for (const ChoiceName<T>& c : Choices<T>::names) names.emplace_back(c.name);
    return names;
}

}  // namespace cdvp
