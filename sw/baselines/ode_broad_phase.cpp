#include "sw/baselines/ode_broad_phase.h"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "sw/baselines/library_broad_phase.h"

namespace cdvp {

// The widened float bounds are doubles; a single-precision ODE would round
// them back inward.
static_assert(std::is_same_v<dReal, double>, "ODE built with dReal = double (Debian's libode-dev) expected");

namespace {

// ODE's user geom keeps its six AABB values (ODE's order: x min, x max, y
// min, ...) as class data; the AABB callback hands them over unchanged.
void geom_aabb(dGeomID geom, dReal aabb[6]) {
    const auto* bounds = static_cast<const dReal*>(dGeomGetClassData(geom));
    std::copy(bounds, bounds + 6, aabb);
}

dColliderFn* no_collider(int /*class*/) { return nullptr; }  // broad phase only

// ODE once per process, its per-thread data once per thread that runs a
// space (ODE frees it when the thread ends: initialised without
// dInitFlagManualThreadCleanup), and the geom class once.
int box_geom_class() {
    static std::once_flag once;
    static int geom_class = -1;
    std::call_once(once, [] {
        dInitODE2(0);
        dGeomClass cls{};
        cls.bytes = 6 * sizeof(dReal);
        cls.collider = no_collider;
        cls.aabb = geom_aabb;
        geom_class = dCreateGeomClass(&cls);
    });
    thread_local const bool thread_data = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
    if (!thread_data) throw std::runtime_error("ODE could not allocate its data for this thread");
    return geom_class;
}

void place(dGeomID geom, const FloatBox& box) {
    auto* bounds = static_cast<dReal*>(dGeomGetClassData(geom));
    for (int axis = 0; axis < 3; ++axis) {
        bounds[2 * axis] = widened_low(box.min[axis]);
        bounds[2 * axis + 1] = widened_high(box.max[axis]);
    }
    dGeomSetPosition(geom, 0, 0, 0);  // marks the geom moved: ODE asks its AABB again
}

uint32_t index_of(dGeomID geom) { return static_cast<uint32_t>(reinterpret_cast<std::uintptr_t>(dGeomGetData(geom))); }

void offer_to_sink(void* sink, dGeomID a, dGeomID b) {
    static_cast<CandidateSink*>(sink)->offer(index_of(a), index_of(b));  // ODE cannot stop early
}

// ODE's hash space indexes its n-by-n tested matrix with an int.
constexpr std::size_t kMostHashBoxes = 131000;

bool finite_box(const FloatBox& box) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(box.min[axis]) || !std::isfinite(box.max[axis])) return false;
    }
    return true;
}

double largest_extent(const FloatBox& box) {
    double extent = 0;
    for (int axis = 0; axis < 3; ++axis) extent = std::max(extent, widened_high(box.max[axis]) - widened_low(box.min[axis]));
    return extent;
}

bool upright(const FloatBox& box) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(box.min[axis] <= box.max[axis])) return false;
    }
    return true;
}

// The finite boxes' largest extents and the span of their bounds.
struct Spread {
    std::vector<double> extents;  // sorted
    double low[3] = {INFINITY, INFINITY, INFINITY}, high[3] = {-INFINITY, -INFINITY, -INFINITY};
    double centre_spread[3] = {0, 0, 0};

    explicit Spread(const std::vector<FloatBox>& boxes) {
        double sum[3] = {0, 0, 0}, squares[3] = {0, 0, 0};
        for (const FloatBox& box : boxes) {
            if (!upright(box) || !finite_box(box)) continue;
            extents.push_back(largest_extent(box));
            for (int axis = 0; axis < 3; ++axis) {
                low[axis] = std::min(low[axis], static_cast<double>(box.min[axis]));
                high[axis] = std::max(high[axis], static_cast<double>(box.max[axis]));
                const double centre = 0.5 * (static_cast<double>(box.min[axis]) + box.max[axis]);
                sum[axis] += centre;
                squares[axis] += centre * centre;
            }
        }
        std::sort(extents.begin(), extents.end());
        const double n = static_cast<double>(std::max<std::size_t>(extents.size(), 1));
        for (int axis = 0; axis < 3; ++axis) centre_spread[axis] = squares[axis] / n - (sum[axis] / n) * (sum[axis] / n);
    }
    bool empty() const { return extents.empty(); }
    double median() const { return extents[extents.size() / 2]; }
};

int level_of(double size) { return static_cast<int>(std::ceil(std::log2(size))); }

class OdeBroadPhase : public LibraryBroadPhase {
public:
    explicit OdeBroadPhase(OdeKind kind) : kind_(kind), geom_class_(box_geom_class()) {}
    ~OdeBroadPhase() override { reset(); }

    std::string name() const override {
        switch (kind_) {
            case OdeKind::hash: return "ode_hash";
            case OdeKind::quadtree: return "ode_quadtree";
            case OdeKind::sap: return "ode_sap";
        }
        return "ode";
    }

protected:
    bool holds(const FloatBox& box) const override {
        if (!LibraryBroadPhase::holds(box)) return false;
        if (kind_ != OdeKind::hash || !finite_box(box)) return true;  // an infinite box is a big one
        for (int axis = 0; axis < 3; ++axis) {
            if (std::fabs(box.min[axis]) >= hash_limit_ || std::fabs(box.max[axis]) >= hash_limit_) return false;
        }
        return true;
    }

    void configure(const std::vector<FloatBox>& boxes) override {
        if (kind_ == OdeKind::hash && boxes.size() > kMostHashBoxes) {
            throw std::invalid_argument("ode_hash: ODE's hash space holds at most " + std::to_string(kMostHashBoxes) +
                                        " boxes (its tested-pair matrix is indexed by an int); got " +
                                        std::to_string(boxes.size()));
        }
        const Spread spread(boxes);
        space_ = make_space(spread);
        dSpaceSetCleanup(space_, 0);  // the geoms are ours
    }

    void build(const std::vector<FloatBox>& boxes, const std::vector<char>& held) override {
        geoms_.reserve(boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            dGeomID geom = dCreateGeom(geom_class_);
            geoms_.push_back(geom);
            dGeomSetData(geom, reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
            if (!held[i]) continue;
            place(geom, boxes[i]);
            dSpaceAdd(space_, geom);
        }
    }

    void update(const std::vector<FloatBox>& boxes, const std::vector<char>& held,
                const std::vector<uint32_t>& left, const std::vector<uint32_t>& entered) override {
        for (const uint32_t i : left) dSpaceRemove(space_, geoms_[i]);
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            if (held[i]) place(geoms_[i], boxes[i]);
        }
        for (const uint32_t i : entered) dSpaceAdd(space_, geoms_[i]);
    }

    void collide(CandidateSink& sink) override {
        box_geom_class();  // this thread's ODE data, if another thread built the space
        if (space_ != nullptr) dSpaceCollide(space_, &sink, offer_to_sink);
    }

    void reset() override {
        if (space_ != nullptr) dSpaceDestroy(space_);
        space_ = nullptr;
        for (dGeomID geom : geoms_) dGeomDestroy(geom);
        geoms_.clear();
    }

private:
    dSpaceID make_space(const Spread& spread) {
        switch (kind_) {
            case OdeKind::hash: {
                int low = -3, high = 10;  // ODE's defaults, for a scene of no finite box
                if (!spread.empty()) {
                    const int median = level_of(spread.median());
                    low = std::max(level_of(spread.extents.front()), median - 3);
                    high = std::max(low, std::min(level_of(spread.extents.back()), median + 10));
                }
                hash_limit_ = std::ldexp(1.0, low + 30);
                dSpaceID space = dHashSpaceCreate(nullptr);
                dHashSpaceSetLevels(space, low, high);
                return space;
            }
            case OdeKind::quadtree: {
                dVector3 centre = {0, 0, 0, 0}, extents = {1, 1, 1, 0};
                int depth = 1;
                if (!spread.empty()) {
                    double widest = 0;
                    for (int axis = 0; axis < 3; ++axis) {
                        const double span = spread.high[axis] - spread.low[axis];
                        centre[axis] = 0.5 * (spread.low[axis] + spread.high[axis]);
                        extents[axis] = std::max(0.625 * span, 0.5 * spread.median());  // half of 1.25 spans
                        widest = std::max(widest, 2 * extents[axis]);
                    }
                    const double blocks = widest / (4 * spread.median());
                    depth = blocks > 1 ? 1 + static_cast<int>(std::floor(std::log2(blocks))) : 1;
                    depth = std::clamp(depth, 1, 8);
                }
                return dQuadTreeSpaceCreate(nullptr, centre, extents, depth);
            }
            case OdeKind::sap: break;
        }
        const double* s = spread.centre_spread;
        const int axis = s[1] > s[0] && s[1] >= s[2] ? 1 : (s[2] > s[0] && s[2] > s[1] ? 2 : 0);
        static const int kOrder[3] = {dSAP_AXES_XYZ, dSAP_AXES_YXZ, dSAP_AXES_ZXY};
        return dSweepAndPruneSpaceCreate(nullptr, kOrder[axis]);
    }

    OdeKind kind_;
    int geom_class_;
    double hash_limit_ = INFINITY;
    dSpaceID space_ = nullptr;
    std::vector<dGeomID> geoms_;
};

}  // namespace

std::unique_ptr<BroadPhase> make_ode_broad_phase(OdeKind kind) { return std::make_unique<OdeBroadPhase>(kind); }

}  // namespace cdvp
