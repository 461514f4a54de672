#include "sw/bullet/board_broadphase.h"

#include <LinearMath/btAabbUtil2.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "sw/timing/thread_timer.h"

namespace cdvp {

namespace {

using Clock = std::chrono::steady_clock;

double ns_since(Clock::time_point start) {
    return std::chrono::duration<double, std::nano>(Clock::now() - start).count();
}

// btSimpleBroadphase gives handle h the unique id h + 2; the pair cache orders
// a pair's proxies by it, so the same ids keep the same pair orientation.
constexpr int kUniqueIdOffset = 2;

uint64_t pair_key(int slot_a, int slot_b) {
    const auto lo = static_cast<uint64_t>(std::min(slot_a, slot_b));
    const auto hi = static_cast<uint64_t>(std::max(slot_a, slot_b));
    return lo << 32 | hi;
}

}  // namespace

BoardBroadphase::BoardBroadphase(BoardLink& link, btOverlappingPairCache* pair_cache)
    : link_(link), capacity_(link.capacity()), slots_(new Slot[link.capacity()]) {
    if (pair_cache == nullptr) {
        owned_cache_ = std::make_unique<btHashedOverlappingPairCache>();
        pair_cache = owned_cache_.get();
    }
    if (pair_cache->hasDeferredRemoval()) {
        throw std::invalid_argument("BoardBroadphase needs a pair cache that removes pairs at once (no deferred removal)");
    }
    cache_ = pair_cache;
    reset_slots();
}

BoardBroadphase::~BoardBroadphase() = default;

void BoardBroadphase::reset_slots() {
    free_slots_.clear();
    for (uint32_t slot = capacity_; slot-- > 0;) {
        slots_[slot].m_uniqueId = static_cast<int>(slot) + kUniqueIdOffset;
        free_slots_.push_back(static_cast<int>(slot));
    }
    order_dirty_ = true;
}

int BoardBroadphase::slot_of(const btBroadphaseProxy* proxy) const {
    const auto* slot = static_cast<const Slot*>(proxy);
    const std::ptrdiff_t index = slot - slots_.get();
    if (index < 0 || index >= static_cast<std::ptrdiff_t>(capacity_) || !slots_[index].live) {
        throw std::invalid_argument("not a live proxy of this BoardBroadphase");
    }
    return static_cast<int>(index);
}

btBroadphaseProxy* BoardBroadphase::createProxy(const btVector3& aabbMin, const btVector3& aabbMax, int /*shapeType*/,
                                                void* userPtr, int collisionFilterGroup, int collisionFilterMask,
                                                btDispatcher* /*dispatcher*/) {
    if (free_slots_.empty()) {
        throw std::length_error("BoardBroadphase: all " + std::to_string(capacity_) +
                                " proxy slots (the board's capacity) are taken");
    }
    const int index = free_slots_.back();
    free_slots_.pop_back();
    Slot& slot = slots_[index];
    slot.m_clientObject = userPtr;
    slot.m_collisionFilterGroup = collisionFilterGroup;
    slot.m_collisionFilterMask = collisionFilterMask;
    slot.m_aabbMin = aabbMin;
    slot.m_aabbMax = aabbMax;
    slot.live = true;
    ++live_;
    order_dirty_ = true;
    return &slot;
}

void BoardBroadphase::destroyProxy(btBroadphaseProxy* proxy, btDispatcher* dispatcher) {
    const int index = slot_of(proxy);
    cache_->removeOverlappingPairsContainingProxy(proxy, dispatcher);
    slots_[index].live = false;
    slots_[index].m_clientObject = nullptr;
    free_slots_.push_back(index);
    --live_;
    order_dirty_ = true;
}

void BoardBroadphase::setAabb(btBroadphaseProxy* proxy, const btVector3& aabbMin, const btVector3& aabbMax,
                              btDispatcher* /*dispatcher*/) {
    proxy->m_aabbMin = aabbMin;
    proxy->m_aabbMax = aabbMax;
}

void BoardBroadphase::getAabb(btBroadphaseProxy* proxy, btVector3& aabbMin, btVector3& aabbMax) const {
    aabbMin = proxy->m_aabbMin;
    aabbMax = proxy->m_aabbMax;
}

void BoardBroadphase::rayTest(const btVector3& rayFrom, const btVector3& /*rayTo*/,
                              btBroadphaseRayCallback& rayCallback, const btVector3& aabbMin,
                              const btVector3& aabbMax) {
    // The ray is the callback's, as btDbvtBroadphase reads it: from rayFrom along
    // the direction whose inverse is m_rayDirectionInverse (Bullet's callbacks
    // normalize it, so m_lambda_max is the length), up to m_lambda_max. It is read
    // again before each proxy: a callback that shortens it clips the rest.
    btVector3 bounds[2];
    for (uint32_t index = 0; index < capacity_; ++index) {
        const Slot& slot = slots_[index];
        if (!slot.live) continue;
        // The swept box's Minkowski sum with the proxy, as btDbvt grows its nodes.
        bounds[0] = slot.m_aabbMin - aabbMax;
        bounds[1] = slot.m_aabbMax - aabbMin;
        btScalar entry = 0;
        if (btRayAabb2(rayFrom, rayCallback.m_rayDirectionInverse, rayCallback.m_signs, bounds, entry, 0,
                       rayCallback.m_lambda_max)) {
            rayCallback.process(&slot);  // its result is ignored, as Bullet's broad phases ignore it
        }
    }
}

void BoardBroadphase::aabbTest(const btVector3& aabbMin, const btVector3& aabbMax,
                               btBroadphaseAabbCallback& callback) {
    for (uint32_t index = 0; index < capacity_; ++index) {
        const Slot& slot = slots_[index];
        // btSimpleBroadphase's test: closed boxes, touching counts.
        if (slot.live && TestAabbAgainstAabb2(aabbMin, aabbMax, slot.m_aabbMin, slot.m_aabbMax)) {
            callback.process(&slot);
        }
    }
}

void BoardBroadphase::getBroadphaseAabb(btVector3& aabbMin, btVector3& aabbMax) const {
    bool any = false;
    aabbMin.setZero();
    aabbMax.setZero();
    for (uint32_t index = 0; index < capacity_; ++index) {
        const Slot& slot = slots_[index];
        if (!slot.live) continue;
        if (!any) {
            aabbMin = slot.m_aabbMin;
            aabbMax = slot.m_aabbMax;
            any = true;
        } else {
            aabbMin.setMin(slot.m_aabbMin);
            aabbMax.setMax(slot.m_aabbMax);
        }
    }
}

void BoardBroadphase::resetPool(btDispatcher* /*dispatcher*/) {
    if (live_ == 0) reset_slots();
}

void BoardBroadphase::printStats() {
    std::printf("BoardBroadphase: %u of %u proxies, %llu frames, %llu pairs added, %llu removed, %.3f ms on the board\n",
                live_, capacity_, static_cast<unsigned long long>(frames_),
                static_cast<unsigned long long>(total_added_), static_cast<unsigned long long>(total_removed_),
                total_board_ns_ * 1e-6);
}

uint32_t BoardBroadphase::board_index(const btBroadphaseProxy* proxy) {
    const int slot = slot_of(proxy);
    refresh_board_order();
    return slot_to_board_[slot];
}

void BoardBroadphase::refresh_board_order() {
    if (!order_dirty_) return;
    board_to_slot_.clear();
    slot_to_board_.assign(capacity_, UINT32_MAX);
    for (uint32_t index = 0; index < capacity_; ++index) {
        if (!slots_[index].live) continue;
        slot_to_board_[index] = static_cast<uint32_t>(board_to_slot_.size());
        board_to_slot_.push_back(static_cast<int>(index));
    }
    order_dirty_ = false;
}

void BoardBroadphase::calculateOverlappingPairs(btDispatcher* dispatcher) {
    // The host's bookkeeping is software, timed in the thread's CPU time as
    // Bullet's own broad phases are; the simulation on the wall clock.
    const int64_t gather_start = thread_cpu_ns();
    refresh_board_order();
    boxes_.resize(board_to_slot_.size());
    for (std::size_t k = 0; k < board_to_slot_.size(); ++k) {
        const Slot& slot = slots_[board_to_slot_[k]];
        FloatBox& box = boxes_[k];
        for (int axis = 0; axis < 3; ++axis) {
            box.min[axis] = slot.m_aabbMin[axis];
            box.max[axis] = slot.m_aabbMax[axis];
        }
    }
    double bookkeeping_ns = static_cast<double>(thread_cpu_ns() - gather_start);

    const Clock::time_point board_start = Clock::now();
    const FrameResult& result = link_.run(boxes_);
    const double simulate_ns = ns_since(board_start);

    const int64_t update_start = thread_cpu_ns();
    collect_board_pairs(result.pairs);
    collect_cached_pairs();
    last_ = BoardFrameStats{};
    update_cache(dispatcher);
    bookkeeping_ns += static_cast<double>(thread_cpu_ns() - update_start);

    last_.proxies = static_cast<uint32_t>(boxes_.size());
    last_.board_pairs = result.pairs.size();
    last_.phases = result.phases;
    last_.simulate_ns = simulate_ns;
    last_.bookkeeping_ns = bookkeeping_ns;
    ++frames_;
    total_added_ += last_.added;
    total_removed_ += last_.removed;
    total_board_ns_ += result.phases.total_ns;
}

void BoardBroadphase::collect_board_pairs(const PairList& pairs) {
    board_keys_.resize(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        board_keys_[k] = pair_key(board_to_slot_[pairs[k].first], board_to_slot_[pairs[k].second]);
    }
    std::sort(board_keys_.begin(), board_keys_.end());
}

void BoardBroadphase::collect_cached_pairs() {
    cached_keys_.clear();
    const btBroadphasePairArray& pairs = cache_->getOverlappingPairArray();
    cached_keys_.reserve(static_cast<std::size_t>(pairs.size()));
    const Slot* first = slots_.get();
    const Slot* end = first + capacity_;
    // std::less orders any two pointers, even ones into other broad phases' storage.
    const auto ours = [&](const btBroadphaseProxy* proxy) {
        const auto* slot = static_cast<const Slot*>(proxy);
        return !std::less<const Slot*>()(slot, first) && std::less<const Slot*>()(slot, end);
    };
    for (int k = 0; k < pairs.size(); ++k) {
        // A shared cache may hold other broad phases' pairs: leave them alone.
        if (!ours(pairs[k].m_pProxy0) || !ours(pairs[k].m_pProxy1)) continue;
        cached_keys_.push_back(pair_key(static_cast<int>(static_cast<const Slot*>(pairs[k].m_pProxy0) - first),
                                        static_cast<int>(static_cast<const Slot*>(pairs[k].m_pProxy1) - first)));
    }
    std::sort(cached_keys_.begin(), cached_keys_.end());
}

// One merge of two sorted key lists, in btSimpleBroadphase's (i, j) order.
void BoardBroadphase::update_cache(btDispatcher* dispatcher) {
    auto board = board_keys_.begin();
    auto cached = cached_keys_.begin();
    while (board != board_keys_.end() || cached != cached_keys_.end()) {
        const bool take_board = cached == cached_keys_.end() || (board != board_keys_.end() && *board <= *cached);
        const uint64_t key = take_board ? *board : *cached;
        Slot& lower = slots_[key >> 32];
        Slot& higher = slots_[key & 0xffffffffu];
        const bool overlapping = take_board;
        const bool in_cache = cached != cached_keys_.end() && *cached == key;
        if (overlapping && !in_cache) {
            cache_->addOverlappingPair(&lower, &higher);
            ++last_.added;
        } else if (!overlapping && in_cache) {
            cache_->removeOverlappingPair(&lower, &higher, dispatcher);
            ++last_.removed;
        }
        if (take_board) ++board;
        if (in_cache) ++cached;
    }
}

}  // namespace cdvp
