#include "sw/baselines/fcl_broad_phase.h"

#include <fcl/broadphase/broadphase_SaP.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/broadphase_interval_tree.h>
#include <fcl/broadphase/broadphase_spatialhash.h>
#include <fcl/geometry/shape/box.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sw/baselines/library_broad_phase.h"

namespace cdvp {

namespace {

using FclObject = fcl::CollisionObjectd;

// FCL's tree sorts its leaves by their centres when it builds (inf - inf is
// NaN: no order) and weighs volumes: an infinite bound becomes +-1e100, beyond
// every float and finite when cubed. The map is monotone (a <= b gives
// clamp(a) <= clamp(b)), so it keeps every overlap.
constexpr double kFclInfinity = 1e100;

double fcl_bound(double v) { return std::clamp(v, -kFclInfinity, kFclInfinity); }

// The box as FCL sees it: widened by an ulp, infinities clamped.
fcl::AABBd fcl_box(const FloatBox& box) {
    fcl::AABBd out;
    for (int axis = 0; axis < 3; ++axis) {
        out.min_[axis] = fcl_bound(widened_low(box.min[axis]));
        out.max_[axis] = fcl_bound(widened_high(box.max[axis]));
    }
    return out;
}

// A collision object whose world AABB is the box: the managers read
// getAABB() alone, and CollisionObject keeps it in a protected member, which
// computeAABB() (never called here) would take from the shape.
class FclBox : public FclObject {
public:
    FclBox(const std::shared_ptr<fcl::CollisionGeometryd>& shape, uint32_t index) : FclObject(shape) {
        setUserData(reinterpret_cast<void*>(static_cast<std::uintptr_t>(index)));
    }
    void place(const fcl::AABBd& box) { aabb = box; }
};

// FCL's SaP moves a box's end points along an axis in the direction its lower
// end moved, and the upper one only that way: an end that stays while the
// other moves, or ends moving apart or together, corrupt its lists (a hang).
int sign_of_move(double from, double to) { return (from < to) - (to < from); }

bool sap_can_move(const fcl::AABBd& from, const fcl::AABBd& to, int axis) {
    return sign_of_move(from.min_[axis], to.min_[axis]) == sign_of_move(from.max_[axis], to.max_[axis]);
}

// Where a move SaP cannot take stops first: on such an axis a point below
// both boxes (both ends move down to it, then both up), elsewhere the end.
fcl::AABBd sap_waypoint(const fcl::AABBd& from, const fcl::AABBd& to) {
    fcl::AABBd via = to;
    for (int axis = 0; axis < 3; ++axis) {
        if (sap_can_move(from, to, axis)) continue;
        via.min_[axis] = via.max_[axis] = std::nextafter(std::min(from.min_[axis], to.min_[axis]), -INFINITY);
    }
    return via;
}

uint32_t index_of(const FclObject* object) {
    return static_cast<uint32_t>(reinterpret_cast<std::uintptr_t>(object->getUserData()));
}

bool offer_to_sink(FclObject* a, FclObject* b, void* sink) {
    return !static_cast<CandidateSink*>(sink)->offer(index_of(a), index_of(b));  // true stops FCL
}

// fcl_hash: boxes wider than this many cells on an axis are tested here.
constexpr double kMostCells = 8;
constexpr double kMostCellsAnAxis = 1 << 20;

// The hash's settings from the boxes (fcl_broad_phase.h says why each).
struct HashSettings {
    double cell = 1;
    fcl::Vector3d low = fcl::Vector3d::Zero(), high = fcl::Vector3d::Ones();

    bool fits(const FloatBox& box) const {
        for (int axis = 0; axis < 3; ++axis) {
            const double extent = static_cast<double>(box.max[axis]) - box.min[axis];
            if (!std::isfinite(extent) || extent > kMostCells * cell) return false;
        }
        return true;
    }

    static bool ordinary(const FloatBox& box) {
        for (int axis = 0; axis < 3; ++axis) {
            if (!(box.min[axis] <= box.max[axis])) return false;
        }
        return true;
    }

    static HashSettings from(const std::vector<FloatBox>& boxes) {
        HashSettings s;
        std::vector<double> largest;
        for (const FloatBox& box : boxes) {
            if (!ordinary(box)) continue;
            double extent = 0;
            for (int axis = 0; axis < 3; ++axis) extent = std::max(extent, widened_high(box.max[axis]) - widened_low(box.min[axis]));
            if (std::isfinite(extent)) largest.push_back(extent);
        }
        if (!largest.empty()) {
            std::nth_element(largest.begin(), largest.begin() + largest.size() / 2, largest.end());
            s.cell = largest[largest.size() / 2];
        }
        // The limit: per axis, the boxes' bounds within Tukey's fences (a span
        // of the middle half beyond its quartiles); a few boxes far out then
        // lie outside it, in FCL's outside list, instead of stretching the cells.
        for (int axis = 0; axis < 3; ++axis) {
            std::vector<double> lows, highs;
            for (const FloatBox& box : boxes) {
                if (!ordinary(box) || !s.fits(box)) continue;
                lows.push_back(widened_low(box.min[axis]));
                highs.push_back(widened_high(box.max[axis]));
            }
            if (lows.empty()) {
                s.low[axis] = 0;
                s.high[axis] = 1;
                continue;
            }
            std::sort(lows.begin(), lows.end());
            std::sort(highs.begin(), highs.end());
            const double q1 = lows[lows.size() / 4], q3 = highs[highs.size() * 3 / 4];
            s.low[axis] = std::max(lows.front(), q1 - (q3 - q1));
            s.high[axis] = std::min(highs.back(), q3 + (q3 - q1));
        }
        double widest = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double margin = std::max(0.25 * (s.high[axis] - s.low[axis]), s.cell);
            s.low[axis] -= margin;
            s.high[axis] += margin;
            widest = std::max(widest, s.high[axis] - s.low[axis]);
        }
        s.cell = std::max(s.cell, widest / kMostCellsAnAxis);
        return s;
    }
};

class FclBroadPhase : public LibraryBroadPhase {
public:
    explicit FclBroadPhase(FclKind kind) : kind_(kind), shape_(std::make_shared<fcl::Boxd>(1, 1, 1)) {}
    ~FclBroadPhase() override { reset(); }  // the manager before the objects it points to

    std::string name() const override {
        switch (kind_) {
            case FclKind::tree: return "fcl_tree";
            case FclKind::sap: return "fcl_sap";
            case FclKind::interval: return "fcl_interval";
            case FclKind::hash: return "fcl_hash";
        }
        return "fcl";
    }

protected:
    bool holds(const FloatBox& box) const override {
        return LibraryBroadPhase::holds(box) && (kind_ != FclKind::hash || hash_.fits(box));
    }

    void configure(const std::vector<FloatBox>& boxes) override {
        if (kind_ == FclKind::hash) hash_ = HashSettings::from(boxes);
    }

    void build(const std::vector<FloatBox>& boxes, const std::vector<char>& held) override {
        objects_.reserve(boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            objects_.push_back(std::make_unique<FclBox>(shape_, static_cast<uint32_t>(i)));
        }
        register_all(boxes, held);
    }

    void update(const std::vector<FloatBox>& boxes, const std::vector<char>& held,
                const std::vector<uint32_t>& left, const std::vector<uint32_t>& entered) override {
        // A box leaving SaP or the interval manager builds the manager again
        // instead: SaP's unregisterObject reads a list node it has just erased,
        // the interval manager's drops the last two end points of its list
        // instead of the object's.
        const bool sorted = kind_ == FclKind::sap || kind_ == FclKind::interval;
        if (sorted && (!left.empty() || !entered.empty())) {
            count_rebuild();
            register_all(boxes, held);
            return;
        }
        if (kind_ == FclKind::sap) step_to_waypoints(boxes, held);
        for (const uint32_t i : left) manager_->unregisterObject(objects_[i].get());
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            if (held[i]) objects_[i]->place(fcl_box(boxes[i]));
        }
        for (const uint32_t i : entered) manager_->registerObject(objects_[i].get());
        manager_->update();
    }

    void collide(CandidateSink& sink) override { manager_->collide(&sink, offer_to_sink); }

    void reset() override {
        manager_.reset();
        objects_.clear();
    }

private:
    // A new manager with the held boxes, registered in bulk (SaP sorts them
    // once, the tree builds top-down).
    void register_all(const std::vector<FloatBox>& boxes, const std::vector<char>& held) {
        manager_.reset();
        manager_ = make_manager(boxes.size());
        std::vector<FclObject*> registered;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            if (!held[i]) continue;
            objects_[i]->place(fcl_box(boxes[i]));
            registered.push_back(objects_[i].get());
        }
        manager_->registerObjects(registered);
        manager_->setup();
    }

    // The boxes whose move SaP cannot take go to their waypoints first (rounding
    // alone gives a few such moves a frame at 10,000 drifting cubes).
    void step_to_waypoints(const std::vector<FloatBox>& boxes, const std::vector<char>& held) {
        stepped_.clear();
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            if (!held[i]) continue;
            const fcl::AABBd from = objects_[i]->getAABB(), to = fcl_box(boxes[i]);
            if (sap_can_move(from, to, 0) && sap_can_move(from, to, 1) && sap_can_move(from, to, 2)) continue;
            objects_[i]->place(sap_waypoint(from, to));
            stepped_.push_back(objects_[i].get());
        }
        if (!stepped_.empty()) manager_->update(stepped_);
    }

    std::unique_ptr<fcl::BroadPhaseCollisionManagerd> make_manager(std::size_t boxes) const {
        switch (kind_) {
            case FclKind::tree: return std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
            case FclKind::sap: return std::make_unique<fcl::SaPCollisionManagerd>();
            case FclKind::interval: return std::make_unique<fcl::IntervalTreeCollisionManagerd>();
            case FclKind::hash: break;
        }
        const auto buckets = static_cast<unsigned>(std::clamp<std::size_t>(8 * boxes, 1000, 1u << 24));
        return std::make_unique<fcl::SpatialHashingCollisionManagerd<>>(hash_.cell, hash_.low, hash_.high, buckets);
    }

    FclKind kind_;
    std::shared_ptr<fcl::CollisionGeometryd> shape_;  // never used: the AABB is set directly
    HashSettings hash_;
    std::unique_ptr<fcl::BroadPhaseCollisionManagerd> manager_;
    std::vector<std::unique_ptr<FclBox>> objects_;
    std::vector<FclObject*> stepped_;
};

}  // namespace

std::unique_ptr<BroadPhase> make_fcl_broad_phase(FclKind kind) { return std::make_unique<FclBroadPhase>(kind); }

}  // namespace cdvp
