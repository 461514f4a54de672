// The independent oracle: CGAL's box_self_intersection_d on the scene's
// original doubles, closed boxes (touching boxes intersect).
#pragma once

#include <vector>

#include "models/common/aabb.h"
#include "sw/scene/scene.h"

namespace cdvp::oracle {

// Every pair i < j of boxes that intersect as closed double intervals on all
// three axes, sorted, each once. Infinite bounds are allowed.
PairList cgal_pairs(const std::vector<Box>& boxes);

}  // namespace cdvp::oracle
