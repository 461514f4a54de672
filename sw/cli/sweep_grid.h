// The grid of `cdvp sweep`: axes parsed from the command line, expanded into
// points in a fixed order, each with a readable id and its `cdvp run`
// arguments. Plain C++, no processes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cdvp {

// One axis: a setting and the values it takes, in the order given.
struct Axis {
    std::string name;  // "board", "m", "objects", "bus.interrupt_ns", ...
    std::vector<std::string> values;
};

// Expands LIST: "a,b,c" (as written) and, with 'ranges', "A:B:xF" (A, A*F, A*F^2, ... up to B
// inclusive; F > 1) or "A:B:+S" (A, A+S, ... up to B inclusive; S > 0).
// Numbers of a range print as integers when they are whole, else with up to
// 12 significant digits. Throws InputError (one line naming 'label' and the
// list) for an empty item, a repeated value, a bad number or step, A > B,
// or more than kMaxAxisValues values.
constexpr std::size_t kMaxAxisValues = 100000;
std::vector<std::string> expand_list(const std::string& list, const std::string& label, bool ranges = true);

// "NAME=LIST" of --set into an axis; the same errors, and a missing '=' or a
// name that is not a flag or setting name ([a-z0-9_.-], starting with a letter).
Axis parse_set(const std::string& text);

// Which points of the grid a shard runs: those whose index % count == index_1 - 1.
struct Shard {
    uint64_t index_1 = 1;  // K of "K/N", from 1
    uint64_t count = 1;    // N
    bool whole() const { return count == 1; }
    bool runs(std::size_t point) const { return point % count == index_1 - 1; }
    std::string text() const { return std::to_string(index_1) + "/" + std::to_string(count); }
};
// "K/N" with 1 <= K <= N; throws InputError otherwise.
Shard parse_shard(const std::string& text);

struct Point {
    std::size_t index = 0;            // row-major over the axes, the first axis outermost
    std::string id;                   // e.g. "board-adm-xrc-ii_m-8_objects-200"
    std::vector<std::string> values;  // one per axis
};

class Grid {
public:
    // Refuses an empty grid, repeated axis names, and more than
    // kMaxPoints points (InputError).
    static constexpr std::size_t kMaxPoints = 1000000;
    explicit Grid(std::vector<Axis> axes);

    const std::vector<Axis>& axes() const { return axes_; }
    std::size_t size() const { return size_; }
    Point point(std::size_t index) const;

    // The arguments of `cdvp run` that set the point's axes: "--NAME V" for
    // a flag, "-c NAME=V" for a dotted setting name.
    std::vector<std::string> run_arguments(const Point& point) const;

private:
    std::string id_of(const std::vector<std::string>& values) const;

    std::vector<Axis> axes_;
    std::size_t size_ = 1;
};

// A setting name is dotted ("bus.interrupt_ns") and set with -c; a flag is not.
inline bool is_setting_name(const std::string& name) { return name.find('.') != std::string::npos; }

}  // namespace cdvp
