// Bullet's own broad phases, made in one place for the baselines
// (sw/baselines) and for the worlds that run on Bullet's broad phases beside
// the board's (sw/bullet). Each caller sizes them by its own rule: a baseline
// holds exactly a frame's boxes, a world leaves room for proxies it adds.
// This header includes Bullet; sw/baselines/bullet_broad_phase.h does not.
#pragma once

#include <BulletCollision/BroadphaseCollision/btBroadphaseInterface.h>

#include <cstdint>
#include <memory>

#include "sw/baselines/bullet_broad_phase.h"

namespace cdvp {

// sap: btAxisSweep3 for up to 16,384 handles (its default), bt32BitAxisSweep3
// above; ray_accelerator false drops the DBVT shadow it keeps for ray casts.
// dbvt: btDbvtBroadphase (needs neither bounds nor a handle count).
// Throws std::invalid_argument for more handles than bt32BitAxisSweep3 takes.
std::unique_ptr<btBroadphaseInterface> make_bt_broadphase(BulletKind kind, const btVector3& world_min,
                                                              const btVector3& world_max, uint64_t handles,
                                                              bool ray_accelerator);

}  // namespace cdvp
