// What a model traced, so that a viewer's save file can group the signals
// by block: each signal's scope (its block), full name and width in bits.
#pragma once

#include <string>
#include <vector>

#include <systemc>

namespace cdvp {

struct TracedSignal {
    std::string group;  // the block, as the viewer's group title
    std::string name;   // the full hierarchical name in the VCD
    int width = 1;
};

// Traces value under name and records it in the list.
class WaveList {
public:
    WaveList(sc_core::sc_trace_file* file, std::string group) : file_(file), group_(std::move(group)) {}
    void group(std::string group) { group_ = std::move(group); }
    template <class T>
    void add(const T& value, const std::string& name, int width = 1) {
        if (width == 1) sc_core::sc_trace(file_, value, name);
        else sc_core::sc_trace(file_, value, name, width);
        signals_.push_back({group_, name, width});
    }
    const std::vector<TracedSignal>& signals() const { return signals_; }

private:
    sc_core::sc_trace_file* file_;
    std::string group_;
    std::vector<TracedSignal> signals_;
};

}  // namespace cdvp
