// The binning stage's combinational part: the cell function and the
// classification of a box (docs/grid_board.md, "The cell function" and
// "Classifying a box"). Both engines and the analytic level call these, as
// the hardware has one cell-function unit per bound.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "models/grid_binning/grid_config.h"
#include "models/number_format/number_format.h"

namespace cdvp {

// One axis of the grid: a bound v lies in cell floor(fl32(fl32(v - lo) * scale)), clamped.
struct GridAxis {
    float lo = 0.0f;
    float scale = 0.0f;  // cells per unit, >= 0
};

// The cells a box covers on each axis, inclusive: cells lo[a] .. hi[a].
struct CellRange {
    std::array<uint8_t, 3> lo{}, hi{};
    uint64_t cells() const {
        return uint64_t{hi[0] - lo[0] + 1u} * (hi[1] - lo[1] + 1u) * (hi[2] - lo[2] + 1u);
    }
};

// What pass 2 makes of a box before it looks at the cell counts.
enum class BoxClass : uint8_t {
    kCandidate,  // binned when its cells and the entry memory have room
    kExcluded,   // a NaN bound (float32): meets nothing
    kInverted,   // min above max on some axis: swept against every box
    kSpanning,   // more cells than max_span: swept against every box
};

// The keys, NaN flags and cells of a run of boxes, bound by bound (pass 2 of
// the fast engine: each bound's arithmetic over the run in one loop, which
// the compiler vectorizes).
struct BoundRun {
    static constexpr uint32_t kBoxes = 256;
    uint32_t key[6][kBoxes];   // NumberFormat::key of each word, Coordinate order
    uint32_t cell[6][kBoxes];  // GridGeometry::cell of each key on its axis
    uint32_t excluded[kBoxes];  // nonzero: a word the format excludes (a NaN)
};

// The grid of one sweep: its cells a side and each axis's origin and scale.
class GridGeometry {
public:
    GridGeometry() = default;
    GridGeometry(NumberFormat format, uint32_t dims, const std::array<GridAxis, 3>& axes);

    uint32_t dims() const { return dims_; }
    uint64_t cells() const { return uint64_t{dims_} * dims_ * dims_; }
    const GridAxis& axis(uint32_t a) const { return axes_[a]; }
    // The cell of a bound on an axis, from its key (NumberFormat::key):
    // monotone in the key, so a <= b gives cell(a) <= cell(b).
    uint32_t cell(uint32_t axis, uint32_t key) const {
        if (infinities_) {
            if (key <= minus_infinity_) return 0;
            if (key >= plus_infinity_) return dims_ - 1;
        }
        return cell_of_value(format_.approximate(key), axes_[axis], dims_);
    }
    uint64_t linear(uint32_t x, uint32_t y, uint32_t z) const { return x + uint64_t{dims_} * (y + uint64_t{dims_} * z); }

    // Box keys in Coordinate order (min x, y, z, max x, y, z) into its
    // class and, for candidates, its cells (max_span bounds the cells).
    // Inline: the fast engine classifies every box of a frame.
    BoxClass classify(const uint32_t (&keys)[6], uint32_t max_span, CellRange& range) const {
        return classify_by([&](uint32_t c) { return keys[c]; }, [&](uint32_t c) { return cell(c % 3, keys[c]); },
                           max_span, range);
    }

    // Boxes begin .. begin + n - 1 (n <= BoundRun::kBoxes) from their words
    // (words[c][i]: word c of box i): their keys, NaN flags and cells.
    void fill_run(const uint32_t* const* words, uint32_t begin, uint32_t n, BoundRun& run) const;
    // classify() of box k of a run whose words the format does not exclude.
    BoxClass classify_run(const BoundRun& run, uint32_t k, uint32_t max_span, CellRange& range) const {
        return classify_by([&](uint32_t c) { return run.key[c][k]; }, [&](uint32_t c) { return run.cell[c][k]; },
                           max_span, range);
    }

    // The float32 arithmetic of the hardware's cell-function unit.
    static uint32_t cell_of_value(float v, const GridAxis& axis, uint32_t dims) {
        const float offset = v - axis.lo;
        const float position = offset * axis.scale;
        if (!(position > 0.0f)) return 0;  // below the origin, -0, or 0 x inf
        if (position >= static_cast<float>(dims)) return dims - 1;
        return static_cast<uint32_t>(position);
    }

private:
    // classify() from each bound's key and cell (c in Coordinate order).
    template <class KeyOf, class CellOf>
    static BoxClass classify_by(KeyOf key, CellOf cell_of, uint32_t max_span, CellRange& range) {
        for (uint32_t a = 0; a < 3; ++a) {
            if (key(a) > key(a + 3)) return BoxClass::kInverted;
        }
        uint64_t cells = 1;
        for (uint32_t a = 0; a < 3; ++a) {
            const uint32_t lo = cell_of(a), hi = cell_of(a + 3);
            range.lo[a] = static_cast<uint8_t>(lo);
            range.hi[a] = static_cast<uint8_t>(hi);
            cells *= hi - lo + 1;
        }
        return cells > max_span ? BoxClass::kSpanning : BoxClass::kCandidate;
    }

    NumberFormat format_;
    uint32_t dims_ = 1;
    std::array<GridAxis, 3> axes_{};
    // float32: keys at or past these are the infinities; fixedK has none.
    bool infinities_ = false;
    uint32_t minus_infinity_ = 0;
    uint32_t plus_infinity_ = UINT32_MAX;
};

// The one-cell rule (docs/grid_board.md, "Reporting each pair once"): a hit
// of two binned boxes in the cell `here` stands when, on every axis, one of
// them starts there (its first cell). The filter beside the lanes applies it.
inline bool home_cell_keeps(const uint8_t (&row_first)[3], const uint8_t (&column_first)[3],
                            const uint32_t (&here)[3]) {
    bool keep = true;
    for (uint32_t a = 0; a < 3; ++a) keep &= row_first[a] == here[a] || column_first[a] == here[a];
    return keep;
}

// Pass 1: the least and greatest finite box centre on each axis over the
// boxes not excluded; then the sweep's grid. Centres, not bounds, so that one
// huge box (a ground slab) does not stretch the grid over the whole scene:
// bounds beyond the centres' range clamp into the edge cells.
class GridBounds {
public:
    explicit GridBounds(NumberFormat format = NumberFormat::float32()) : format_(format) {}
    // A box's keys (Coordinate order); the caller leaves out excluded boxes.
    void add(const uint32_t (&keys)[6]) {
        for (uint32_t a = 0; a < 3; ++a) take(a, centre_of(format_.approximate(keys[a]), format_.approximate(keys[a + 3])));
    }
    // add() of boxes begin .. begin + n - 1 (n <= BoundRun::kBoxes) from
    // their words (words[c][i]: word c of box i), excluded ones left out:
    // the centres over the run in one loop an axis, which the compiler vectorizes.
    void add_run(const uint32_t* const* words, uint32_t begin, uint32_t n);
    // The grid: origin at the least centre; scale dims / (greatest - least),
    // or 1 / cell_size when that is set; 0 where the axis has no extent.
    GridGeometry geometry(const GridConfig& config, uint32_t dims) const;
    // The float32 arithmetic of the bounds unit: (min + max) x 0.5.
    static float centre_of(float lo, float hi) { return (lo + hi) * 0.5f; }

private:
    // A box's centre on axis a into the least and greatest.
    void take(uint32_t a, float centre) {
        if (!(centre - centre == 0.0f)) return;  // an infinity or NaN: no bound of the grid
        least_[a] = std::min(least_[a], centre);
        greatest_[a] = std::max(greatest_[a], centre);
    }
    NumberFormat format_;
    std::array<float, 3> least_{kNone, kNone, kNone};
    std::array<float, 3> greatest_{-kNone, -kNone, -kNone};
    static constexpr float kNone = 3.402823466e38f;  // FLT_MAX: no centre seen below it
};

// Whether a box's stored words hold a word its format excludes (float32 NaN).
inline bool excluded_box(NumberFormat format, const uint32_t (&words)[6]) {
    bool any = false;
    for (uint32_t word : words) any |= format.excluded(word);
    return any;
}

}  // namespace cdvp
