#include "tests/fast_engine/word_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <sstream>
#include <string>

#include "models/address_generator/address_generator.h"
#include "models/board/board_core.h"
#include "models/clocked_engine/clocked_engine.h"
#include "models/fast_engine/fast_engine.h"
#include "tests/support/core_driver.h"

namespace cdvp::testing {

CoordinateWords WordScene::view() const {
    CoordinateWords view{};
    for (uint32_t c = 0; c < kCoordinates; ++c) view[c] = words[c].data();
    return view;
}

WordScene WordScene::from_boxes(const std::vector<FloatBox>& boxes) {
    WordScene scene;
    for (const FloatBox& box : boxes) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            scene.words[c].push_back(ComparisonUnit::as_bits(c < 3 ? box.min[c] : box.max[c - 3]));
        }
    }
    return scene;
}

WordScene random_scene(uint32_t n, float extent, float size, std::mt19937& rng) {
    return WordScene::from_boxes(random_boxes(n, extent, size, rng));
}

WordScene clustered_scene(uint32_t n, uint32_t clusters, std::mt19937& rng) {
    std::uniform_real_distribution<float> centre(0.0f, 1000.0f), offset(-1.0f, 1.0f), side(0.0f, 0.5f);
    std::vector<std::array<float, 3>> centres(clusters);
    for (auto& c : centres) c = {centre(rng), centre(rng), centre(rng)};
    std::vector<FloatBox> boxes(n);
    for (uint32_t i = 0; i < n; ++i) {
        const auto& c = centres[rng() % clusters];
        for (int a = 0; a < 3; ++a) {
            boxes[i].min[a] = c[a] + offset(rng);
            boxes[i].max[a] = boxes[i].min[a] + side(rng);
        }
    }
    return WordScene::from_boxes(boxes);
}

WordScene overlapping_scene(uint32_t n, std::mt19937& rng) {
    std::uniform_real_distribution<float> reach(0.0f, 2.0f);
    std::vector<FloatBox> boxes(n);
    for (FloatBox& b : boxes) {
        for (int a = 0; a < 3; ++a) {
            b.min[a] = -reach(rng);
            b.max[a] = reach(rng);
        }
    }
    return WordScene::from_boxes(boxes);
}

WordScene denormal_scene(uint32_t n, std::mt19937& rng) {
    WordScene scene;
    std::uniform_int_distribution<int32_t> low(-40, 40), side(0, 12);
    // The float whose value is k times the smallest denormal (|k| < 2^23).
    auto denormal = [](int32_t k) { return k < 0 ? 0x8000'0000u | static_cast<uint32_t>(-k) : static_cast<uint32_t>(k); };
    for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t a = 0; a < 3; ++a) {
            const int32_t lo = low(rng);
            scene.words[a].push_back(denormal(lo));
            scene.words[a + 3].push_back(denormal(lo + side(rng)));
        }
    }
    return scene;
}

void sprinkle_special_values(WordScene& scene, double fraction, std::mt19937& rng) {
    static const uint32_t kSpecial[] = {
        0x7FC0'0000u,  // quiet NaN
        0x7F80'0001u,  // signalling NaN
        0xFFC0'0001u,  // negative NaN with payload
        0x0000'0000u,  // +0
        0x8000'0000u,  // -0
        0x7F80'0000u,  // +inf
        0xFF80'0000u,  // -inf
        0x0000'0001u,  // smallest denormal
        0x807F'FFFFu,  // largest negative denormal
        0x7F7F'FFFFu,  // FLT_MAX
    };
    std::bernoulli_distribution pick(fraction);
    for (uint32_t i = 0; i < scene.size(); ++i) {
        for (auto& column : scene.words) {
            if (pick(rng)) column[i] = kSpecial[rng() % std::size(kSpecial)];
        }
        if (pick(rng)) std::swap(scene.words[kMinY][i], scene.words[kMaxY][i]);  // inverted in y
    }
}

WordScene fixed_scene(uint32_t n, NumberFormat format, double size_share, std::mt19937& rng) {
    const double top = format.max_code();
    std::uniform_real_distribution<double> corner(0.0, top), side(0.0, size_share * top);
    WordScene scene;
    for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t axis = 0; axis < 3; ++axis) {
            const double lo = corner(rng), hi = std::min(top, lo + side(rng));
            // Bits above K are junk the memories drop.
            const uint32_t junk = format.bits() == 32 ? 0u : static_cast<uint32_t>(rng()) & ~format.word_mask();
            scene.words[axis].push_back(static_cast<uint32_t>(lo) | junk);
            scene.words[axis + 3].push_back(static_cast<uint32_t>(hi) | junk);
        }
    }
    return scene;
}

PairList lane_hit_pairs(const WordScene& scene, NumberFormat format) {
    PairList pairs;
    auto box = [&](uint32_t i, uint32_t (&bounds)[kCoordinates]) {
        for (uint32_t c = 0; c < kCoordinates; ++c) bounds[c] = scene.words[c][i];
    };
    for (uint32_t i = 0; i < scene.size(); ++i) {
        uint32_t a[kCoordinates];
        box(i, a);
        for (uint32_t j = i + 1; j < scene.size(); ++j) {
            uint32_t b[kCoordinates];
            box(j, b);
            if (ComparisonUnit::lane_hit(format, a, b)) pairs.push_back({i, j});
        }
    }
    return pairs;
}

BoardConfig collector_config(uint32_t m, uint32_t fifo, uint32_t drain, uint32_t buffer) {
    BoardConfig config;
    config.m = m;
    config.collector.fifo_depth = fifo;
    config.collector.drain_per_cycle = drain;
    config.collector.buffer_depth = buffer;
    return config;
}

namespace {

BoardObservation observe_core(BoardCore& core) {
    const SweepCounters counters = core.counters();
    BoardObservation seen;
    seen.cycles = counters.cycles;
    seen.stalls = counters.stalls;
    seen.buffer_count = counters.buffered;
    seen.total_pairs = counters.total_pairs;
    seen.fifo_level = static_cast<ClockedEngine&>(core.engine()).fifo_level();
    seen.phase = core.phase();
    return seen;
}

std::string describe(const BoardObservation& o) {
    std::ostringstream text;
    text << "{cycles " << o.cycles << ", stalls " << o.stalls << ", buffer " << o.buffer_count << ", total "
         << o.total_pairs << ", fifo " << o.fifo_level << ", phase " << static_cast<int>(o.phase) << "}";
    return text.str();
}

bool same(const BoardObservation& a, const BoardObservation& b) {
    return a.cycles == b.cycles && a.stalls == b.stalls && a.buffer_count == b.buffer_count &&
           a.total_pairs == b.total_pairs && a.fifo_level == b.fifo_level && a.phase == b.phase;
}

// Edges to compare in a segment of `edges` edges: both ends and the probes.
std::vector<uint64_t> probe_edges(uint64_t edges, uint32_t probes, std::mt19937_64& rng) {
    std::vector<uint64_t> at{0, edges};
    if (probes == 0) {
        for (uint64_t e = 1; e < edges; ++e) at.push_back(e);
    } else {
        std::uniform_int_distribution<uint64_t> pick(0, edges);
        for (uint32_t k = 0; k < probes; ++k) at.push_back(pick(rng));
    }
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    return at;
}

}  // namespace

uint32_t expect_lockstep(const BoardConfig& config, const WordScene& scene, uint32_t probes_per_segment,
                         std::mt19937& rng) {
    const uint32_t n = scene.size();
    const std::string context = "n=" + std::to_string(n) + " m=" + std::to_string(config.m) + " fifo=" +
                                std::to_string(config.collector.fifo_depth) + " drain=" +
                                std::to_string(config.collector.drain_per_cycle) + " buffer=" +
                                std::to_string(config.collector.buffer_depth) + " compare latency=" +
                                std::to_string(config.compare.latency_cycles) + " tile=" +
                                std::to_string(config.tiles.boxes) + " format=" + config.format.name();
    BoardCore core(config, n);
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        for (uint32_t i = 0; i < n; ++i) core.write_coordinate(static_cast<Coordinate>(c), i, scene.words[c][i]);
    }
    core.write_register(ControlRegisters::kObjectCount, n);
    core.write_register(ControlRegisters::kControl, ControlRegisters::kStart);
    FastEngine engine(config);
    engine.start(n, scene.view());
    std::mt19937_64 edge_rng(rng());
    PairList from_core;
    for (uint32_t segment = 1;; ++segment) {
        const uint64_t edges = engine.segment_cycles();
        uint64_t stepped = 0;
        for (uint64_t at : probe_edges(edges, probes_per_segment, edge_rng)) {
            for (; stepped < at; ++stepped) {
                if (!core.running()) {
                    ADD_FAILURE() << context << ": the board stopped after " << stepped << " edges of segment "
                                  << segment << ", the engine says " << edges;
                    return segment;
                }
                core.step();
            }
            const BoardObservation board = observe_core(core), fast = engine.observe(at);
            if (!same(board, fast)) {
                ADD_FAILURE() << context << ": segment " << segment << " edge " << at << " of " << edges
                              << ": board " << describe(board) << ", engine " << describe(fast);
                return segment;
            }
        }
        if (core.running()) {
            ADD_FAILURE() << context << ": the board runs on past edge " << edges << " of segment " << segment;
            return segment;
        }
        EXPECT_EQ(engine.phase(), core.phase()) << context;
        const uint32_t buffered = core.buffered_pairs();
        for (uint32_t k = 0; k < buffered; ++k) {
            if (!(engine.buffer_entry(k) == core.buffered_pair(k))) {
                ADD_FAILURE() << context << ": segment " << segment << " buffer entry " << k << " differs";
                return segment;
            }
            from_core.push_back(core.buffered_pair(k));
        }
        if (core.phase() == SweepState::kDone) {
            EXPECT_EQ(engine.pairs(), from_core) << context;
            EXPECT_EQ(core.counters().cycles,
                      config.sweep_cycles(n) + config.pipeline_latency() + core.counters().stalls)
                << context << " tiles of " << config.tiles.boxes;
            return segment;
        }
        core.write_register(ControlRegisters::kControl, ControlRegisters::kResume);
        engine.resume();
    }
}

CoordinateStore store_of(const WordScene& scene) {
    CoordinateStore store;
    for (uint32_t c = 0; c < kCoordinates; ++c) store[c] = scene.words[c];
    return store;
}

PairList buffer_of(BoardEngine& engine, uint64_t edges) {
    PairList pairs;
    const uint32_t count = engine.counters_after(edges).buffered;
    for (uint32_t k = 0; k < count; ++k) pairs.push_back(engine.buffer_entry(k));
    return pairs;
}

void expect_same_engines(BoardEngine& reference, BoardEngine& other, const WordScene& scene, std::mt19937& rng,
                         int probes) {
    const CoordinateStore store = store_of(scene);
    reference.start(store, scene.size());
    other.start(store, scene.size());
    for (int segment = 1;; ++segment) {
        const uint64_t edges = other.segment_edges();
        std::uniform_int_distribution<uint64_t> pick(0, edges);
        for (int probe = 0; probe < probes; ++probe) {
            const uint64_t at = pick(rng);
            ASSERT_EQ(reference.ended_by(at), other.ended_by(at)) << "segment " << segment << " edge " << at;
            ASSERT_EQ(reference.counters_after(at), other.counters_after(at)) << "segment " << segment << " edge " << at;
        }
        ASSERT_EQ(reference.segment_edges(), edges) << "segment " << segment;
        ASSERT_EQ(reference.segment_finishes(), other.segment_finishes()) << "segment " << segment;
        ASSERT_EQ(reference.counters_after(edges + 5), other.counters_after(edges + 5)) << "past the end";
        ASSERT_EQ(buffer_of(reference, edges), buffer_of(other, edges)) << "segment " << segment;
        if (other.segment_finishes()) return;
        reference.resume();
        other.resume();
    }
}

void expect_same_aborts(const MakeEngine& make_reference, const MakeEngine& make_other, const WordScene& scene,
                        std::mt19937& rng, int trials) {
    const CoordinateStore store = store_of(scene);
    for (int trial = 0; trial < trials; ++trial) {
        const std::unique_ptr<BoardEngine> reference = make_reference(), other = make_other();
        reference->start(store, scene.size());
        other->start(store, scene.size());
        if (trial % 2 == 1) {  // abort in the second segment
            reference->segment_edges();
            reference->resume();
            other->resume();
        }
        const uint64_t at = std::uniform_int_distribution<uint64_t>(0, other->segment_edges() + 3)(rng);
        reference->abort(at);
        other->abort(at);
        EXPECT_EQ(buffer_of(*reference, at), buffer_of(*other, at)) << "abort at edge " << at;
        EXPECT_EQ(reference->counters_after(at), other->counters_after(at)) << "abort at edge " << at;
        EXPECT_FALSE(other->segment_finishes());
        EXPECT_TRUE(other->ended_by(at));
    }
}

}  // namespace cdvp::testing
