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
    virtual std::string name() const = 0;  // "sap", "dbvt", "brute", "soa"
    // The exact overlapping pairs of this frame (closed intervals, float32, the same test as
    // reference_pairs): each pair once, first < second (indices into boxes), in any order.
    // Consecutive calls with the same box count are the same objects moved, so incremental
    // methods keep their state (frame coherence); a different count rebuilds.
    // Throws PairBudgetExceeded before `out` outgrows the pair budget.
    virtual void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) = 0;

    // The most pairs find_pairs may collect (run.max_pairs; unlimited by default).
    void set_pair_budget(PairBudget budget) { budget_ = budget; }

protected:
    PairBudget budget_;
};

// Names: "sap" (Bullet btAxisSweep3), "dbvt" (Bullet btDbvtBroadphase),
// "brute" (scalar all pairs), "soa" (vectorized all pairs). Throws
// std::invalid_argument "unknown baseline 'x'; expected one of: sap, dbvt, brute, soa"
// for others.
std::unique_ptr<BroadPhase> make_broad_phase(const std::string& name);

// The names make_broad_phase accepts, in the order above.
std::vector<std::string> broad_phase_names();

}  // namespace cdvp
