// What a model traced, so that a viewer's save file can group the signals
// by block and show each in a fitting format: each signal's scope (its
// block), full name, width in bits and display format; and the gate that
// keeps a block's traced values still outside the traced frames.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>

namespace cdvp {

// How a viewer should show a signal's values.
enum class WaveFormat : uint8_t {
    kBit,      // a single wire
    kDecimal,  // counts, sizes and box addresses
    kHex,      // bus addresses, as the register map writes them
    kBinary,   // per-lane masks: one digit a lane
    kNamed,    // a state: its value's name (see StateNames)
};

// Names a viewer shows for a state vector's values instead of numbers.
struct StateNames {
    std::string table;               // names the table (and its filter file): "controller"
    std::vector<std::string> names;  // the name of value k; empty: none (a one-hot state's other values)
};

struct TracedSignal {
    std::string group;  // the block, as the viewer's group title
    std::string name;   // the hierarchical name as traced ("platform.irq")
    int width = 1;
    WaveFormat format = WaveFormat::kBit;
    const StateNames* states = nullptr;  // kNamed only; static, not owned
};

// Traces value under name and records it in the list.
class WaveList {
public:
    WaveList(sc_core::sc_trace_file* file, std::string group) : file_(file), group_(std::move(group)) {}
    void group(std::string group) { group_ = std::move(group); }
    // A single wire.
    void add(const bool& value, const std::string& name) { add_signal(value, name, 1, WaveFormat::kBit); }
    // A vector of width bits, shown as format.
    template <class T>
    void add(const T& value, const std::string& name, int width, WaveFormat format) {
        add_signal(value, name, width, format);
    }
    // A state vector whose values the viewer shows by name.
    template <class T>
    void add(const T& value, const std::string& name, int width, const StateNames& states) {
        add_signal(value, name, width, WaveFormat::kNamed, &states);
    }
    const std::vector<TracedSignal>& signals() const { return signals_; }

private:
    template <class T>
    void add_signal(const T& value, const std::string& name, int width, WaveFormat format,
                    const StateNames* states = nullptr) {
        if (format == WaveFormat::kBit) sc_core::sc_trace(file_, value, name);
        else sc_core::sc_trace(file_, value, name, width);
        signals_.push_back({group_, name, width, format, states});
    }

    sc_core::sc_trace_file* file_;
    std::string group_;
    std::vector<TracedSignal> signals_;
};

// A block's waveform values as the trace file samples them. The model keeps
// `live` current at every change and calls show(); the traced copy follows
// only while the gate is open, so outside a window of traced frames
// (--vcd-frames) every signal holds its last traced value, and the window
// opens on the values of that moment.
template <class Values>
class GatedWaves {
public:
    Values live{};
    void show() {
        if (open_) shown_ = live;
    }
    void set_open(bool open) {
        open_ = open;
        show();
    }
    // What to trace: its address is stable for the block's lifetime.
    const Values& shown() const { return shown_; }

private:
    Values shown_{};
    bool open_ = true;
};

}  // namespace cdvp
