#include "sw/run/run_footprint.h"

#include <algorithm>
#include <limits>

#include "models/address_generator/sweep_schedule.h"
#include "models/common/aabb.h"
#include "models/fast_engine/pair_finder.h"
#include "models/fast_engine/sweep_timeline.h"
#include "models/grid_fast_engine/grid_search.h"
#include "sw/scene/pairs_csv.h"
#include "sw/scene/scene.h"
#include "sw/scene/spheres.h"

namespace cdvp {

namespace {

// A list grown by push_back may hold up to twice what it needs.
constexpr uint64_t kGrowth = 2;
constexpr uint64_t kPair = sizeof(IndexPair);
constexpr uint64_t kFloatBox = sizeof(FloatBox);
// The fast engine's timeline keeps a cursor (under 96 bytes) every
// SweepTimeline::kCheckpointEvery events of a segment.
constexpr uint64_t kCheckpointBytes = 96;

// The program before any scene: code, the C++ and SystemC runtimes, Bullet,
// the kernel's coroutine stacks as far as they are touched, output buffers.
// Measured: a run of one small frame peaks at 14-16 MiB of RSS (fast or
// clocked engine, any baseline, with a report and pairs); twice that leaves
// room for what a run's size does not show (allocator slack, stdio).
constexpr uint64_t kProgram = uint64_t{32} << 20;

// Bullet's structures, which this code does not size, measured as the peak
// RSS a baseline adds per box (at 100,000 spread boxes) and per pair (at
// 2,000 boxes that all overlap), rounded up: btAxisSweep3's handles and
// edges, btDbvtBroadphase's proxies and tree nodes; each one's hashed pair
// cache (btBroadphasePair and its hash links, grown by doubling).
constexpr uint64_t kSapBox = 240, kDbvtBox = 400;
constexpr uint64_t kBulletPair = 96;

// FCL's managers and ODE's spaces, measured the same way (peak RSS over the
// scene alone, one frame built and one moved, 100,000 spread cubes; 2,000
// that all overlap), rounded up: per box the wrapper's object or geom and the
// library's nodes (fcl_tree 499, fcl_sap 690, fcl_interval 1,207, fcl_hash
// 850, ode_quadtree 413, ode_sap 446 bytes; the interval manager keeps three
// interval trees and three maps); per pair beside the pair list, fcl_sap's
// list of overlapping pairs (47 bytes), the set fcl_interval's collide fills
// (63) and ode_sap's array of pairs (8); the others keep none.
constexpr uint64_t kFclTreeBox = 512, kFclSapBox = 704, kFclIntervalBox = 1216, kFclHashBox = 864;
constexpr uint64_t kOdeQuadtreeBox = 416, kOdeSapBox = 448;
constexpr uint64_t kFclSapPair = 48, kFclIntervalPair = 64, kOdeSapPair = 8;
// ODE's hash space: 810 bytes a box beside an n-by-n bit matrix of tested
// pairs (n^2/8 bytes) it allocates every frame.
constexpr uint64_t kOdeHashBox = 832;

// A Bullet world of a scene (cdvp bullet's, or the one a run's Bullet scene
// is recorded from), measured as the peak RSS its scenes add and rounded up
// to cover the heaviest: a body (its rigid body, shape, proxy and solver
// body) under 3.7 KiB at 30,000 elastic spheres, each with a shape of its
// own; a pair of touching bodies (its cache entry, collision algorithm,
// contact manifold and solver constraints) under 1.8 KiB in piles of 3,000
// to 20,000 boxes; and the pools a world allocates up front (Bullet's
// default collision configuration keeps 4,096 manifolds and algorithms).
constexpr uint64_t kBulletBody = 4096, kBulletContact = 2048;
constexpr uint64_t kBulletWorld = uint64_t{8} << 20;

// A frame of boxes as a trace reader builds it (by push_back) and checks its
// ids (an index a box), or as the application holds its spheres and frame.
uint64_t scene_bytes_per_box(bool trace) {
    const uint64_t frame = sizeof(Box) + sizeof(uint64_t);
    if (trace) return kGrowth * frame + sizeof(std::size_t);
    return sizeof(SphereState) + sizeof(double) + frame;
}

uint64_t baseline_bytes_per_box(const std::string& name) {
    if (name == "sap") return kSapBox;
    if (name == "dbvt") return kDbvtBox;
    if (name == "soa") return kFloatBox;  // its structure of arrays
    if (name == "sap_mt") return kFloatBox + sizeof(uint32_t);  // its sorted bounds and their indices
    // Its valid list, keys and order twice over (the radix sort's two
    // buffers), and the sorted key and bounds: 4 + 16 + 28 bytes.
    if (name == "prune" || name == "prune_mt") return 48;
    // Its valid list, level and cell a box, the 32-byte entry, and the cells
    // (at most two a box in level 0, a quarter of that above): 4 + 1 + 4 + 32 + 11.
    if (name == "hgrid" || name == "hgrid_mt") return 52;
    if (name == "fcl_tree") return kFclTreeBox;
    if (name == "fcl_sap") return kFclSapBox;
    if (name == "fcl_interval") return kFclIntervalBox;
    if (name == "fcl_hash") return kFclHashBox;
    if (name == "ode_hash") return kOdeHashBox;
    if (name == "ode_quadtree") return kOdeQuadtreeBox;
    if (name == "ode_sap") return kOdeSapBox;
    return 0;                             // brute: nothing of its own
}

// Everything a pair costs on its way: the engine's search (fast) or nothing
// beyond the pair buffer (clocked); the driver's list; the float32 reference
// of a fixed-point board (its search, its list, the board's sorted and the
// kept); the application's sorted candidates and contacts; the pairs by id;
// the baselines' lists (the kept pairs, a baseline's pairs), Bullet's caches
// and the pairs FCL's SaP and interval manager and ODE's sweep keep.
uint64_t bytes_per_pair(const BudgetShape& shape) {
    uint64_t bytes = kGrowth * kPair;  // the driver's list
    const uint64_t search = PairFinder::scratch_bytes_per_pair();
    if (!shape.clocked) {
        bytes += search + (shape.board.tiles.tiled() ? kPair : 0);  // a tiled board's order by block
        if (shape.board.grid_board()) bytes += GridSearch::scratch_bytes_per_pair();  // the large sweep's search
        bytes += kCheckpointBytes / SweepTimeline::kCheckpointEvery;  // the timeline's checkpoints
    }
    if (!shape.board.format.is_float()) bytes += search + 3 * kPair;
    if (!shape.trace) bytes += kPair + kGrowth * (2 * sizeof(uint32_t) + 4 * sizeof(double));  // candidates, contacts
    if (shape.pairs_out) bytes += sizeof(IdPair);
    if (!shape.baselines.empty()) bytes += kPair + kGrowth * kPair;
    for (const std::string& name : shape.baselines) {
        if (name == "sap" || name == "dbvt") bytes += kBulletPair;
        if (name == "fcl_sap") bytes += kFclSapPair;
        if (name == "fcl_interval") bytes += kFclIntervalPair;
        if (name == "ode_sap") bytes += kOdeSapPair;
    }
    return bytes + shape.bullet_worlds * kBulletContact;
}

uint64_t saturating_add(uint64_t a, uint64_t b) {
    return a > std::numeric_limits<uint64_t>::max() - b ? std::numeric_limits<uint64_t>::max() : a + b;
}

}  // namespace

uint64_t Footprint::with_pairs(uint64_t pairs) const {
    if (per_pair != 0 && pairs > std::numeric_limits<uint64_t>::max() / per_pair) {
        return std::numeric_limits<uint64_t>::max();
    }
    return saturating_add(before_pairs(), pairs * per_pair);
}

// The scene; its float32 boxes (again for each later baseline run); the
// board's store and the host memory's arrays; the engine's search (fast) and,
// for a fixed-point board, the float32 reference's words and search; the
// tiled clocked board's SSRAM; each baseline's own structures.
uint64_t bytes_per_box(const BudgetShape& shape) {
    uint64_t bytes = scene_bytes_per_box(shape.trace) + kFloatBox * (shape.repeat > 1 ? 2 : 1) + 2 * kFloatBox;
    const uint64_t search = PairFinder::scratch_bytes_per_box();
    if (!shape.clocked) bytes += search;
    if (shape.clocked && shape.board.tiles.tiled()) bytes += kFloatBox;
    if (!shape.board.format.is_float()) bytes += kFloatBox + search;
    for (const std::string& name : shape.baselines) bytes += baseline_bytes_per_box(name);
    return bytes + shape.bullet_worlds * kBulletBody;
}

// The board's and each baseline's timing samples (grown by push_back), and a
// trace's number and digest of each frame from its first reading.
uint64_t bytes_per_frame(const BudgetShape& shape) {
    const uint64_t samples = 2 + uint64_t{shape.baselines.size()} * shape.repeat;
    return kGrowth * sizeof(double) * samples + (shape.trace ? kGrowth * 2 * sizeof(uint64_t) : 0);
}

// The program and its Bullet worlds, and what the pair buffer sizes: the host memory's pair area,
// the pair collector's buffer and the clocked engine's per-pair records of a
// segment, the fast engine's checkpoints of one.
uint64_t program_bytes(const BudgetShape& shape) {
    const uint64_t depth = shape.board.collector.buffer_depth + shape.board.collector.fifo_depth;
    return kProgram + shape.bullet_worlds * kBulletWorld +
           depth * (kPair + (shape.clocked ? kPair + 2 * kGrowth * sizeof(uint64_t) : 0));
}

namespace {

// A tiled board's schedule: its blocks, kept by the timeline or the clocked
// engine, built again by the fast engine and the driver, and a count of
// pairs each.
uint64_t schedule_bytes(const BoardConfig& board, uint64_t objects) {
    if (!board.tiles.tiled() || objects == 0) return 0;
    const uint64_t tiles = (objects + board.tiles.boxes - 1) / board.tiles.boxes;
    return tiles * (tiles + 1) / 2 * (3 * sizeof(SweepSchedule::Block) + sizeof(uint64_t));
}

}  // namespace

Footprint estimate_footprint(const BudgetShape& shape, uint64_t objects, uint64_t frames) {
    Footprint f;
    f.program = program_bytes(shape);
    f.boxes = objects * bytes_per_box(shape);
    for (const std::string& name : shape.baselines) {
        if (name == "ode_hash") f.boxes = saturating_add(f.boxes, objects * ((objects + 7) / 8));  // its tested matrix
    }
    f.model = (shape.clocked ? shape.board.block_ram_bytes(objects) : 0) + schedule_bytes(shape.board, objects) +
              (shape.board.grid_board() ? GridSearch::scratch_bytes(shape.board.grid, objects) : 0);
    f.frames = frames * bytes_per_frame(shape);
    f.per_pair = bytes_per_pair(shape);
    return f;
}

}  // namespace cdvp
