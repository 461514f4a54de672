// A run of Bullet's worlds (RunSpec's BulletWorlds): a Bullet scene stepped
// in a btDiscreteDynamicsWorld with the virtual board as its broad phase, and
// beside it the same scene on one of Bullet's own broad phases, timed. It is
// an ordinary run with a frame source that drives the platform itself (the
// board's world calls its broad phase from inside its step) and an observer
// that adds the report's "bullet" section and the summary's table: its
// settings, checks, budgets, reference check and report are every run's.
#pragma once

#include "sw/run/run.h"

namespace cdvp {

// The run, from its spec (frames: BulletWorlds). Throws InputError and the
// like as run() maps them.
RunOutcome run_bullet_worlds(const RunSpec& spec, RunObserver& observer);

}  // namespace cdvp
