// The grid of `cdvp sweep`: axes parsed from the command line, expanded into
// points in a fixed order, each with an id that is unique and short enough
// for a file name by construction, and its `cdvp run` arguments. Plain C++,
// no processes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cdvp {

// One axis: a setting and the values it takes, in the order given.
struct Axis {
    std::string name;  // as the user gave it, and the CSV column: "board", "m", "bus.interrupt_ns", ...
    std::vector<std::string> values;
    // What the axis sets, whatever its spelling: a setting's dotted name
    // ("board.m" for m and board.m alike) or a flag of cdvp run that is no
    // setting ("board", "trace"). Empty: the name itself.
    std::string key = {};
    // The flag of cdvp run a point is given each value by ("--FLAG=V"); empty:
    // the setting, by "-c KEY=V". Left empty with an empty key: the name
    // when it has no dot.
    std::string flag = {};
};

// Expands LIST: "a,b,c" (as written) and, with 'ranges', "A:B:xF" (A, A*F, A*F^2, ... up to B
// inclusive; F > 1) or "A:B:+S" (A, A+S, ... up to B inclusive; S > 0).
// A range whose A and step are whole numbers steps exactly in 64-bit
// integers and prints every value in full; any other steps in doubles, B
// counting as reached up to 1e-9 of a step, and prints whole values as
// integers, others with up to 12 significant digits. Throws InputError (one
// line naming 'label' and the list) for an empty item, a repeated value, a
// bad number or step, A > B, or more than kMaxAxisValues values (a range's
// count is known, and refused, before any value is made).
constexpr std::size_t kMaxAxisValues = 100000;
std::vector<std::string> expand_list(const std::string& list, const std::string& label, bool ranges = true);
// "A:B:xF" or "A:B:+S" alone (sw/study/sweep_range.cpp); the same errors.
std::vector<std::string> expand_range(const std::string& list, const std::string& label);
// How a refusal says a count of values or points: in full while a long
// double holds it exactly (below 1e19), else to 3 significant digits.
std::string count_text(long double count);

// The first of `keys` that an earlier one equals, as {its place, the earlier
// one's}; nothing when all differ. One pass through a hash set, so a list's
// cost grows as N: every repeated-value check of an axis (as written, or as
// its setting reads it) goes through here.
std::optional<std::pair<std::size_t, std::size_t>> first_repeat(const std::vector<std::string>& keys);

// "NAME=LIST" of --set into an axis; the same errors, and a missing '=' or a
// name that is not a flag or setting name ([a-z0-9_.-], starting with a
// letter).
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

// Point ids: NAME-FRAGMENT for each axis, joined by '_'. A value's fragment
// is its text (a file by its name without .json or .csv) with anything but
// letters, digits, '.', '+' and '-' made '-', so it holds no '_' and no '~';
// a fragment longer than kMaxFragmentBytes, or one that two values of the
// axis share, is cut and given '~' and 8 hex digits of the value's SHA-256
// (and '~' and its place in the list should two of those meet). An id longer
// than kMaxIdBytes is cut and ends in "~p" and the point's index. Each step
// keeps ids apart, so no two points of a grid share one, and every id fits a
// file name with room for a temporary's suffix.
constexpr std::size_t kMaxFragmentBytes = 40;
constexpr std::size_t kMaxIdBytes = 200;

// Refuses axes of more than Grid::kMaxPoints points together, with their
// count ("the grid has 3200000 points, more than 1000000"): from the axes'
// sizes alone, so that a sweep checks it before any work a value or a point
// costs.
void check_grid_size(const std::vector<Axis>& axes);

class Grid {
public:
    // Refuses an empty grid, two axes of one key, and more than
    // kMaxPoints points (InputError).
    static constexpr std::size_t kMaxPoints = 1000000;
    explicit Grid(std::vector<Axis> axes);

    const std::vector<Axis>& axes() const { return axes_; }
    std::size_t size() const { return size_; }
    Point point(std::size_t index) const;
    // The id fragment of each value of axis 'a', in the order of its values.
    const std::vector<std::string>& fragments(std::size_t a) const { return fragments_[a]; }
    // The axis that sets 'key' (a setting's dotted name or a flag), if any.
    const Axis* find(const std::string& key) const;

    // The arguments of `cdvp run` that set the point's axes, each one word
    // so that no value is ever taken for an option: "--NAME=V" for a flag,
    // "-c" "KEY=V" for a setting.
    std::vector<std::string> run_arguments(const Point& point) const;

private:
    std::vector<Axis> axes_;
    std::vector<std::vector<std::string>> fragments_;
    std::size_t size_ = 1;
};

// A setting name is dotted ("bus.interrupt_ns") and set with -c; a flag is not.
inline bool is_setting_name(const std::string& name) { return name.find('.') != std::string::npos; }

}  // namespace cdvp
