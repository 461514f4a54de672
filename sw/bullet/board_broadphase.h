// A Bullet broad phase whose overlap test runs on the virtual board.
//
// Proxies live in slots (a fixed array of the link's capacity, reused last
// freed first, as btSimpleBroadphase reuses handles); a proxy's unique id is
// its slot + 2, as in btSimpleBroadphase. Each calculateOverlappingPairs()
// sends the live proxies' AABBs to the board in slot order, so board index k
// is the k-th live slot: the mapping is dense (0..live-1) and monotone, and
// is recomputed only after a proxy was created or destroyed.
//
// The pair cache is brought to the board's set the way btSimpleBroadphase
// does it, in the same order: for every pair of slots (i < j) in ascending
// order, an overlapping pair not yet cached is added (the cache's filter,
// needsBroadphaseCollision with groups and masks or the user's callback,
// decides), and a cached pair that no longer overlaps is removed. Only the
// pairs that change are touched: O(N) to gather the boxes, the board's frame,
// then O(P log P) over the board's pairs and the cache's. destroyProxy()
// removes every cached pair of that proxy at once, as Bullet's broad phases
// do, so a destroyed proxy's pairs never reach the next frame.
#pragma once

#include <btBulletCollisionCommon.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "sw/bullet/board_link.h"

namespace cdvp {

struct BoardFrameStats {
    uint32_t proxies = 0;        // boxes sent to the board
    std::size_t board_pairs = 0; // overlapping pairs the board found
    std::size_t added = 0;       // pairs handed to the cache's addOverlappingPair
    std::size_t removed = 0;     // cached pairs removed as no longer overlapping
    FramePhases phases;          // the board's simulated time, by phase
    double simulate_ns = 0;      // host wall time spent simulating the board
    double bookkeeping_ns = 0;   // host wall time gathering boxes and updating the cache
};

class BoardBroadphase : public btBroadphaseInterface {
public:
    // link: the board, shared and outliving this; its capacity bounds the
    // live proxies. pair_cache: null for a btHashedOverlappingPairCache owned
    // here, else the caller's (it must remove pairs at once, i.e. have no
    // deferred removal, and outlive this).
    explicit BoardBroadphase(BoardLink& link, btOverlappingPairCache* pair_cache = nullptr);
    ~BoardBroadphase() override;
    BoardBroadphase(const BoardBroadphase&) = delete;
    BoardBroadphase& operator=(const BoardBroadphase&) = delete;

    // Throws std::length_error when every slot is taken (capacity proxies).
    btBroadphaseProxy* createProxy(const btVector3& aabbMin, const btVector3& aabbMax, int shapeType,
                                   void* userPtr, int collisionFilterGroup, int collisionFilterMask,
                                   btDispatcher* dispatcher) override;
    void destroyProxy(btBroadphaseProxy* proxy, btDispatcher* dispatcher) override;
    void setAabb(btBroadphaseProxy* proxy, const btVector3& aabbMin, const btVector3& aabbMax,
                 btDispatcher* dispatcher) override;
    void getAabb(btBroadphaseProxy* proxy, btVector3& aabbMin, btVector3& aabbMax) const override;
    // Host-side queries over the live proxies in slot order, btSimpleBroadphase's
    // handle order (the board answers only all-pairs questions; docs/bullet.md,
    // "The query contract"). rayTest calls process() for every proxy whose AABB,
    // grown by the swept box [aabbMin, aabbMax], the callback's ray meets: from
    // rayFrom along 1 / m_rayDirectionInverse for a parameter up to m_lambda_max,
    // in btRayAabb2's test, as btDbvtBroadphase tests its nodes (rayTo is not
    // read, there either). m_lambda_max is read again before each proxy, so a
    // callback that shortens it clips the rest of the query. aabbTest calls it
    // for every proxy whose closed AABB overlaps the query (btSimpleBroadphase's
    // test). process()'s result is ignored, as Bullet's broad phases ignore it.
    void rayTest(const btVector3& rayFrom, const btVector3& rayTo, btBroadphaseRayCallback& rayCallback,
                 const btVector3& aabbMin = btVector3(0, 0, 0),
                 const btVector3& aabbMax = btVector3(0, 0, 0)) override;
    void aabbTest(const btVector3& aabbMin, const btVector3& aabbMax, btBroadphaseAabbCallback& callback) override;
    // Throws BoardFrameFault when the simulated system faulted (the cache is
    // then left as it was) and std::length_error beyond the board's capacity.
    void calculateOverlappingPairs(btDispatcher* dispatcher) override;
    btOverlappingPairCache* getOverlappingPairCache() override { return cache_; }
    const btOverlappingPairCache* getOverlappingPairCache() const override { return cache_; }
    // The union of the live proxies' AABBs (zero vectors when there are none).
    void getBroadphaseAabb(btVector3& aabbMin, btVector3& aabbMax) const override;
    // With no live proxy, slots are handed out from 0 again; otherwise nothing.
    void resetPool(btDispatcher* dispatcher) override;
    void printStats() override;

    uint32_t capacity() const { return capacity_; }
    uint32_t proxy_count() const { return live_; }
    // The board index a live proxy gets in the next frame.
    uint32_t board_index(const btBroadphaseProxy* proxy);
    // The boxes of the last frame, in board order.
    const std::vector<FloatBox>& last_boxes() const { return boxes_; }
    const BoardFrameStats& last_frame() const { return last_; }
    uint64_t frames() const { return frames_; }

private:
    struct Slot : btBroadphaseProxy {
        bool live = false;
    };

    int slot_of(const btBroadphaseProxy* proxy) const;
    void refresh_board_order();
    void reset_slots();
    // Sorted (lower slot << 32 | higher slot) keys of the board's pairs and of the cache's.
    void collect_board_pairs(const PairList& pairs);
    void collect_cached_pairs();
    void update_cache(btDispatcher* dispatcher);

    BoardLink& link_;
    uint32_t capacity_;
    std::unique_ptr<Slot[]> slots_;
    std::vector<int> free_slots_;  // a stack: the last freed slot is reused first
    uint32_t live_ = 0;
    std::unique_ptr<btOverlappingPairCache> owned_cache_;
    btOverlappingPairCache* cache_;

    bool order_dirty_ = true;
    std::vector<int> board_to_slot_;
    std::vector<uint32_t> slot_to_board_;
    std::vector<FloatBox> boxes_;
    std::vector<uint64_t> board_keys_;
    std::vector<uint64_t> cached_keys_;
    BoardFrameStats last_;
    uint64_t frames_ = 0;
    uint64_t total_added_ = 0;
    uint64_t total_removed_ = 0;
    double total_board_ns_ = 0;
};

}  // namespace cdvp
