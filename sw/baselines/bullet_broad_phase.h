// Bullet 3.24's broad phases as baselines: the incremental sweep and prune
// (btAxisSweep3) and the dynamic AABB tree (btDbvtBroadphase). Bullet stays
// out of this header so that users of cdvp_baselines need no Bullet includes.
#pragma once

#include <memory>

#include "sw/baselines/broad_phase.h"

namespace cdvp {

enum class BulletKind { sap, dbvt };

// "sap": btAxisSweep3 (bt32BitAxisSweep3 above 16383 boxes), ray-cast
// accelerator disabled, world bounds from the first frame of each box count.
// "dbvt": btDbvtBroadphase. Both keep their proxies while the box count stays
// the same, and filter Bullet's conservative pair set by the exact test.
std::unique_ptr<BroadPhase> make_bullet_broad_phase(BulletKind kind);

}  // namespace cdvp
