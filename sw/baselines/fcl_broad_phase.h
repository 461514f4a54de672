// FCL 0.7's broad-phase collision managers as baselines (double precision),
// each wrapping one manager: "fcl_tree" (DynamicAABBTreeCollisionManager),
// "fcl_sap" (SaPCollisionManager), "fcl_interval" (IntervalTreeCollisionManager,
// whose self-collision sweeps its sorted endpoints on the widest axis) and
// "fcl_hash" (SpatialHashingCollisionManager). A box is a CollisionObject
// whose world AABB is set to the box itself, so FCL sees exactly our bounds;
// the objects are registered once per box count and moved with the
// manager's update(); collide()'s callback gathers the candidate pairs.
//
// Exactness (sw/baselines/library_broad_phase.h): FCL sees each box widened
// outward by one double ulp (float to double is exact), so ties between equal
// ends cannot drop a touching pair; every candidate passes the float32
// closed-interval test. NaN and inverted boxes stay out of FCL and are tested
// here against every box. An infinite bound reaches FCL as +-1e100: its tree
// sorts leaves by centre (inf - inf is NaN) and hung on the infinite scenes.
// FCL's SaP moves a box's end points correctly only when both ends of an axis
// move the same way: another move reaches it in two (down to a point below
// both boxes, then up). Its SaP and interval managers' unregisterObject
// corrupt their lists: a frame where a box leaves builds the manager again.
//
// fcl_hash's configuration, from the first frame of each box count as an
// engineer would set it: the cell edge is the median of the boxes' largest
// extents (most boxes then span one or two cells an axis); the scene limit is,
// per axis, the bounds of the boxes within Tukey's fences (the quartiles
// widened by their distance), enlarged by a quarter of its span (at least a
// cell) for motion; the cell edge is raised if the limit would exceed 2^20
// cells an axis (FCL hashes cell coordinates as int); the table has eight
// buckets a box, one for each cell a box covers at most (FCL's default of
// 1000 buckets took five times as long at 10,000 boxes). Boxes beyond the limit are FCL's own affair
// (its outside lists). FCL puts a box in every cell it covers and has no list
// for large ones, so boxes spanning more than 8 cells an axis, and those with
// an infinite bound, are tested here instead.
#pragma once

#include <memory>

#include "sw/baselines/broad_phase.h"

namespace cdvp {

enum class FclKind { tree, sap, interval, hash };

std::unique_ptr<BroadPhase> make_fcl_broad_phase(FclKind kind);

}  // namespace cdvp
