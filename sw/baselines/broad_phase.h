// The software broad phases the board is compared against, behind one
// interface so that tests and benchmarks treat them alike.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "models/common/aabb.h"
#include "models/common/pair_budget.h"

namespace cdvp {

class BroadPhase {
public:
    virtual ~BroadPhase() = default;
    virtual std::string name() const = 0;  // one of broad_phase_names()
    // The exact overlapping pairs of this frame (closed intervals, float32, the same test as
    // reference_pairs): each pair once, first < second (indices into boxes), in any order.
    // Consecutive calls with the same box count are the same objects moved, so incremental
    // methods keep their state (frame coherence); a different count rebuilds.
    // Throws PairBudgetExceeded before `out` outgrows the pair budget.
    virtual void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) = 0;
    // The threads a call runs on: above one, its wall time is what a user
    // pays (the threads run side by side), so it is timed by the wall clock.
    virtual unsigned threads() const { return 1; }

    // The most pairs find_pairs may collect (run.max_pairs; unlimited by default).
    void set_pair_budget(PairBudget budget) { budget_ = budget; }

protected:
    PairBudget budget_;
};

// How a baseline is built: the threads of a multi-threaded one (0: this
// machine's cores; run.threads), and where they were asked for, to name in
// the line that says the system would not start them all (--threads).
struct BaselineOptions {
    unsigned threads = 0;
    std::string threads_from = "threads";
};

// Names: "sap" (Bullet btAxisSweep3), "dbvt" (Bullet btDbvtBroadphase),
// "brute" (scalar all pairs), "soa" (vectorized all pairs), "sap_mt" (sweep
// and prune on options.threads threads), "prune" and "prune_mt" (box
// pruning: radix sort and SIMD sweep), "hgrid" and "hgrid_mt" (hierarchical
// grid), "fcl_tree", "fcl_sap", "fcl_interval", "fcl_hash" (FCL's managers:
// fcl_broad_phase.h), "ode_hash", "ode_quadtree", "ode_sap" (ODE's spaces:
// ode_broad_phase.h); a name ending in _mt runs on options.threads threads.
// Throws std::invalid_argument "unknown baseline 'x'; expected one of: sap,
// dbvt, ..." (every name) for others.
std::unique_ptr<BroadPhase> make_broad_phase(const std::string& name, const BaselineOptions& options = {});

// The names make_broad_phase accepts, in the order above.
std::vector<std::string> broad_phase_names();
// Of those, the ones that run on the calling thread alone (timed by thread
// CPU time; a multi-threaded one's time depends on the cores it gets).
std::vector<std::string> single_thread_broad_phase_names();

}  // namespace cdvp
