#include "tests/oracle/cgal_oracle.h"

#include <CGAL/box_intersection_d.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

// CGAL uses its number type's limits (for double: -DBL_MAX and DBL_MAX) as
// sentinels of its segment tree, so box bounds must lie strictly between
// them: an infinite slab, or a bound of +-DBL_MAX, is outside what CGAL
// allows on double. Overlap of closed intervals depends only on the order of
// the bounds, so the boxes go to CGAL as long double, an order-preserving
// exact embedding: every double is kept as is and +-inf becomes
// +-LDBL_MAX / 2, beyond every double and inside CGAL's sentinels.
namespace CGAL::Box_intersection_d {
template <>
struct box_limits<long double> {
    static long double inf() { return -sup(); }
    static long double sup() { return std::numeric_limits<long double>::max(); }
};
}  // namespace CGAL::Box_intersection_d

namespace cdvp::oracle {

namespace {

static_assert(std::numeric_limits<long double>::max_exponent > std::numeric_limits<double>::max_exponent,
              "the oracle needs a long double wider than double to embed infinities");

using OracleBox = CGAL::Box_intersection_d::Box_with_info_d<long double, 3, uint32_t,
                                                            CGAL::Box_intersection_d::ID_EXPLICIT>;

long double embed(double v) {
    if (std::isnan(v)) throw std::invalid_argument("cgal_pairs: NaN bound");
    if (std::isinf(v)) return (v < 0 ? -1 : 1) * (std::numeric_limits<long double>::max() / 2);
    return v;
}

}  // namespace

PairList cgal_pairs(const std::vector<Box>& boxes) {
    std::vector<OracleBox> oracle_boxes;
    oracle_boxes.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        long double lo[3];
        long double hi[3];
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = embed(boxes[i].min[axis]);
            hi[axis] = embed(boxes[i].max[axis]);
        }
        oracle_boxes.emplace_back(lo, hi, static_cast<uint32_t>(i));
    }
    PairList pairs;
    auto report = [&pairs](const OracleBox& a, const OracleBox& b) {
        const uint32_t x = a.info();
        const uint32_t y = b.info();
        pairs.push_back(x < y ? IndexPair{x, y} : IndexPair{y, x});
    };
    CGAL::box_self_intersection_d(oracle_boxes.begin(), oracle_boxes.end(), report, std::ptrdiff_t{10},
                                  CGAL::Box_intersection_d::CLOSED);
    return sorted(std::move(pairs));
}

}  // namespace cdvp::oracle
