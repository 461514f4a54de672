// ODE 0.16's collision spaces as baselines: "ode_hash" (dHashSpace, a
// multi-resolution hash grid), "ode_quadtree" (dQuadTreeSpace) and "ode_sap"
// (dSweepAndPruneSpace). Each box is a geom of a user class (dCreateGeomClass)
// whose AABB callback returns the box's bounds, so ODE sees exactly our boxes;
// the geoms are created once per box count, marked moved each frame, and
// dSpaceCollide's near callback gathers the candidate pairs. Debian builds
// ODE with dReal = double (ode.pc: precision=dDOUBLE; checked at compile time).
//
// Exactness (sw/baselines/library_broad_phase.h): ODE sees each box widened
// outward by one double ulp; every candidate passes the float32 closed-interval
// test. NaN and inverted boxes stay out of ODE and are tested here against
// every box. Infinite bounds go to ODE, which handles them as its planes'
// (hash: the big-box list; sap: its list of infinite geoms; quadtree: the root).
//
// Settings, from the first frame of each box count. ode_hash: ODE puts a box
// at the level whose cells (edge 2^level) are no smaller than the box, the
// levels from the smallest finite box's size (at most 3 below the median's)
// to the largest's (at most 10 above it; larger boxes go to ODE's big-box
// list, tested against all). It quantizes bounds to int cells, so a box with
// a bound beyond 2^30 of the smallest cells is tested here; and it keeps an n
// by n bit matrix of the pairs it tested (n^2/8 bytes a frame), whose int
// index overflows past 131,000 boxes: more are refused. ode_quadtree: the
// root block spans the finite bounds and a quarter of their span more, the
// depth making the smallest blocks about four median boxes wide (at most 8
// levels: ODE allocates every block up front). ode_sap: sorted first on the
// axis the boxes' centres spread most along.
#pragma once

#include <memory>

#include "sw/baselines/broad_phase.h"

namespace cdvp {

enum class OdeKind { hash, quadtree, sap };

std::unique_ptr<BroadPhase> make_ode_broad_phase(OdeKind kind);

}  // namespace cdvp
