#include "sw/baselines/broad_phase.h"

#include <algorithm>
#include <stdexcept>

#include "sw/baselines/box_pruning.h"
#include "sw/baselines/brute_force.h"
#include "sw/baselines/bullet_broad_phase.h"
#include "sw/baselines/fcl_broad_phase.h"
#include "sw/baselines/hierarchical_grid.h"
#include "sw/baselines/ode_broad_phase.h"
#include "sw/baselines/parallel_sap.h"
#include "sw/baselines/soa_broad_phase.h"
#include "models/common/user_text.h"

namespace cdvp {

namespace {

// The existing scalar loop; stateless, so frame coherence does not apply.
class BruteBroadPhase : public BroadPhase {
public:
    std::string name() const override { return "brute"; }
    void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) override {
        brute_force_pairs(boxes, out, budget_);
    }
};

}  // namespace

std::vector<std::string> broad_phase_names() {
    return {"sap",      "dbvt",         "brute",    "soa",      "sap_mt",       "prune",   "prune_mt", "hgrid",
            "hgrid_mt", "fcl_tree",     "fcl_sap",  "fcl_interval", "fcl_hash", "ode_hash", "ode_quadtree",
            "ode_sap"};
}

// Every name but those ending in _mt.
std::vector<std::string> single_thread_broad_phase_names() {
    std::vector<std::string> names = broad_phase_names();
    names.erase(std::remove_if(names.begin(), names.end(),
                               [](const std::string& name) {
                                   return name.size() > 3 && name.compare(name.size() - 3, 3, "_mt") == 0;
                               }),
                names.end());
    return names;
}

std::unique_ptr<BroadPhase> make_broad_phase(const std::string& name, const BaselineOptions& options) {
    if (name == "sap") return make_bullet_broad_phase(BulletKind::sap);
    if (name == "dbvt") return make_bullet_broad_phase(BulletKind::dbvt);
    if (name == "brute") return std::make_unique<BruteBroadPhase>();
    if (name == "soa") return std::make_unique<SoaBroadPhase>();
    if (name == "sap_mt") return std::make_unique<ParallelSapBroadPhase>(options.threads);
    if (name == "prune" || name == "prune_mt") {
        return std::make_unique<BoxPruningBroadPhase>(options.threads, name == "prune_mt");
    }
    if (name == "hgrid" || name == "hgrid_mt") {
        return std::make_unique<HierarchicalGridBroadPhase>(options.threads, name == "hgrid_mt");
    }
    if (name == "fcl_tree") return make_fcl_broad_phase(FclKind::tree);
    if (name == "fcl_sap") return make_fcl_broad_phase(FclKind::sap);
    if (name == "fcl_interval") return make_fcl_broad_phase(FclKind::interval);
    if (name == "fcl_hash") return make_fcl_broad_phase(FclKind::hash);
    if (name == "ode_hash") return make_ode_broad_phase(OdeKind::hash);
    if (name == "ode_quadtree") return make_ode_broad_phase(OdeKind::quadtree);
    if (name == "ode_sap") return make_ode_broad_phase(OdeKind::sap);
    std::string expected;
    for (const std::string& known : broad_phase_names()) {
        expected += (expected.empty() ? "" : ", ") + known;
    }
    throw std::invalid_argument("unknown baseline '" + excerpt(name) + "'; expected one of: " + expected);
}

}  // namespace cdvp
