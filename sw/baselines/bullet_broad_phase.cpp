#include "sw/baselines/bullet_broad_phase.h"

#include <BulletCollision/BroadphaseCollision/btAxisSweep3.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sw/baselines/brute_force.h"
#include "sw/baselines/bullet_factory.h"

namespace cdvp {

namespace {

// Bullet never sees an infinity: a monotone clamp keeps every true overlap
// (a <= b implies clamp(a) <= clamp(b)) and the exact filter removes what it
// adds. Finite stand-ins also keep DBVT's velocity prediction, (max-min)/2 * 0,
// from turning into NaN, and SAP's quantization scale finite.
constexpr float kBig = 1e37f;

float clamp_bound(float v) { return std::min(std::max(v, -kBig), kBig); }

btVector3 to_bullet(const float (&v)[3]) {
    return btVector3(clamp_bound(v[0]), clamp_bound(v[1]), clamp_bound(v[2]));
}

// SAP quantizes inside fixed world bounds and clamps whatever leaves them to the
// edge (only loosening its set). Take them from the finite bounds of the first
// frame, enlarged so that coherent motion stays inside for a while; the margin
// never drops below an absolute 1 or a relative 1e-3 so the world has volume.
std::pair<btVector3, btVector3> world_bounds(const std::vector<FloatBox>& boxes) {
    btVector3 world_min, world_max;
    for (int axis = 0; axis < 3; ++axis) {
        double lo = INFINITY, hi = -INFINITY;
        for (const FloatBox& box : boxes) {
            for (float v : {box.min[axis], box.max[axis]}) {
                if (!std::isfinite(v)) continue;
                lo = std::min(lo, static_cast<double>(clamp_bound(v)));
                hi = std::max(hi, static_cast<double>(clamp_bound(v)));
            }
        }
        if (lo > hi) lo = hi = 0.0;  // no finite bound on this axis
        const double margin =
            std::max({0.25 * (hi - lo), 1.0, 1e-3 * std::max(std::fabs(lo), std::fabs(hi))});
        world_min[axis] = static_cast<btScalar>(lo - margin);
        world_max[axis] = static_cast<btScalar>(hi + margin);
    }
    return {world_min, world_max};
}

std::unique_ptr<btBroadphaseInterface> create_broadphase(BulletKind kind, const std::vector<FloatBox>& boxes) {
    constexpr bool kRayAccelerator = false;  // a DBVT shadow we never query
    if (kind == BulletKind::dbvt) return make_bt_broadphase(kind, {}, {}, boxes.size(), kRayAccelerator);
    const auto [world_min, world_max] = world_bounds(boxes);
    return make_bt_broadphase(kind, world_min, world_max, boxes.size(), kRayAccelerator);
}

// Both broad phases own a btHashedOverlappingPairCache (the default when none is
// passed). No collision algorithms are ever created, so a null dispatcher is
// safe: the cache touches the dispatcher only to free a pair's algorithm.
class BulletBroadPhase : public BroadPhase {
public:
    explicit BulletBroadPhase(BulletKind kind) : kind_(kind) {}
    ~BulletBroadPhase() override { release(); }

    std::string name() const override { return kind_ == BulletKind::sap ? "sap" : "dbvt"; }

    void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) override {
        out.clear();
        if (!broadphase_ || boxes.size() != proxies_.size()) {
            rebuild(boxes);
            if (!broadphase_) return;
        } else {
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                broadphase_->setAabb(proxies_[i], to_bullet(boxes[i].min),
                                     to_bullet(boxes[i].max), nullptr);
            }
        }
        broadphase_->calculateOverlappingPairs(nullptr);
        collect_exact(boxes, out);
    }

private:
    void rebuild(const std::vector<FloatBox>& boxes) {
        release();
        if (boxes.empty()) return;
        broadphase_ = create_broadphase(kind_, boxes);
        proxies_.assign(boxes.size(), nullptr);
        for (const std::size_t i : insertion_order(boxes)) {
            // The box index rides in the proxy's client pointer.
            void* index = reinterpret_cast<void*>(static_cast<std::uintptr_t>(i));
            proxies_[i] = broadphase_->createProxy(to_bullet(boxes[i].min), to_bullet(boxes[i].max),
                                                   BOX_SHAPE_PROXYTYPE, index, 1, -1, nullptr);
        }
    }

    // SAP inserts a handle by moving its new edges down each axis past every
    // greater one, testing overlaps on the last axis (z): O(n) a handle, hours
    // for 10^5 boxes in arbitrary order. In order of their lower z bound the
    // z edges pass only the boxes they overlap in z. The sorted axes, the
    // pairs and every later frame are the same in any order (quantized
    // bounds never tie a lower with an upper edge); what is timed is those
    // frames, not the insertion. DBVT's tree depends on the order: as given.
    std::vector<std::size_t> insertion_order(const std::vector<FloatBox>& boxes) const {
        std::vector<std::size_t> order(boxes.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        if (kind_ == BulletKind::sap) {
            // A NaN bound sorts last (the order must be a strict weak one).
            const auto key = [&](std::size_t i) {
                const float z = boxes[i].min[2];
                return std::isnan(z) ? INFINITY : z;
            };
            std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
        }
        return order;
    }

    // DBVT allocates each proxy separately: destroy them before the broad
    // phase, its pairs first (a proxy's removal searches every pair in the
    // cache: O(pairs) each). SAP's handles live in its own array, and removing
    // one re-sorts every axis (O(n) each), so the destructor alone frees them.
    void release() {
        if (kind_ == BulletKind::dbvt && broadphase_) {
            btOverlappingPairCache* cache = broadphase_->getOverlappingPairCache();
            const btBroadphasePairArray& pairs = cache->getOverlappingPairArray();
            while (pairs.size() > 0) {
                const btBroadphasePair& last = pairs[pairs.size() - 1];
                cache->removeOverlappingPair(last.m_pProxy0, last.m_pProxy1, nullptr);
            }
            for (btBroadphaseProxy* proxy : proxies_) broadphase_->destroyProxy(proxy, nullptr);
        }
        proxies_.clear();
        broadphase_.reset();
    }

    // Bullet's set is a superset (quantized SAP endpoints; enlarged DBVT leaves and
    // stale pairs removed a few per frame): keep only the exact overlaps.
    void collect_exact(const std::vector<FloatBox>& boxes, PairList& out) const {
        const btBroadphasePairArray& pairs =
            broadphase_->getOverlappingPairCache()->getOverlappingPairArray();
        for (int k = 0; k < pairs.size(); ++k) {
            auto a = static_cast<uint32_t>(
                reinterpret_cast<std::uintptr_t>(pairs[k].m_pProxy0->m_clientObject));
            auto b = static_cast<uint32_t>(
                reinterpret_cast<std::uintptr_t>(pairs[k].m_pProxy1->m_clientObject));
            if (a > b) std::swap(a, b);
            if (boxes_overlap(boxes[a], boxes[b])) budget_.push(out, {a, b});
        }
    }

    BulletKind kind_;
    std::unique_ptr<btBroadphaseInterface> broadphase_;
    std::vector<btBroadphaseProxy*> proxies_;
};

}  // namespace

std::unique_ptr<BroadPhase> make_bullet_broad_phase(BulletKind kind) {
    return std::make_unique<BulletBroadPhase>(kind);
}

std::unique_ptr<btBroadphaseInterface> make_bt_broadphase(BulletKind kind, const btVector3& world_min,
                                                              const btVector3& world_max, uint64_t handles,
                                                              bool ray_accelerator) {
    constexpr uint64_t kMax16BitHandles = 16384;  // btAxisSweep3's default
    if (kind == BulletKind::dbvt) return std::make_unique<btDbvtBroadphase>();
    if (handles > INT32_MAX) throw std::invalid_argument("too many proxies for Bullet's broad phases");
    if (handles <= kMax16BitHandles) {
        return std::make_unique<btAxisSweep3>(world_min, world_max, static_cast<unsigned short>(handles), nullptr,
                                              !ray_accelerator);
    }
    return std::make_unique<bt32BitAxisSweep3>(world_min, world_max, static_cast<unsigned int>(handles), nullptr,
                                               !ray_accelerator);
}

}  // namespace cdvp
