// The kinematic scene families (sw/scene: pile, heavy, planar, brownian):
// deterministic by seed, their sizes and motion as documented, every size
// from an empty scene up, bad configs refused on one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>

#include "sw/scene/brownian.h"
#include "sw/scene/heavy.h"
#include "sw/scene/pile.h"
#include "sw/scene/planar.h"
#include "sw/scene/spheres.h"

namespace cdvp {
namespace {

bool same_family_frame(const Frame& a, const Frame& b) {
    return a.number == b.number && a.ids == b.ids && a.boxes.size() == b.boxes.size() &&
           std::memcmp(a.boxes.data(), b.boxes.data(), a.boxes.size() * sizeof(Box)) == 0;
}

// Each family made from an object count and a seed, its other settings at their defaults.
using Make = std::function<std::unique_ptr<KinematicScene>(std::size_t objects, uint64_t seed)>;

template <class Scene, class Config>
Make make() {
    return [](std::size_t objects, uint64_t seed) {
        Config config;
        config.objects = objects;
        config.seed = seed;
        return std::unique_ptr<KinematicScene>(std::make_unique<Scene>(config));
    };
}

struct Family {
    const char* name;
    Make make;
};

const Family kFamilies[] = {{"pile", make<PileScene, PileConfig>()},
                            {"heavy", make<HeavyScene, HeavyConfig>()},
                            {"planar", make<PlanarScene, PlanarConfig>()},
                            {"brownian", make<BrownianScene, BrownianConfig>()}};

double box_extent(const Box& b, int axis) { return b.max[axis] - b.min[axis]; }

TEST(SceneFamilies, SameSeedSameFramesOtherSeedOtherFrames) {
    for (const Family& family : kFamilies) {
        auto a = family.make(300, 7), b = family.make(300, 7), c = family.make(300, 8);
        for (int k = 0; k < 30; ++k) {
            const Frame fa = a->next(), fb = b->next(), fc = c->next();
            ASSERT_TRUE(same_family_frame(fa, fb)) << family.name << " frame " << k;
            EXPECT_EQ(fa.number, static_cast<uint64_t>(k)) << family.name;
            for (std::size_t i = 0; i < fa.ids.size(); ++i) ASSERT_EQ(fa.ids[i], i) << family.name;
            if (k == 0) {
                EXPECT_FALSE(same_family_frame(fa, fc)) << family.name << ": another seed, another scene";
            }
        }
    }
}

TEST(SceneFamilies, NoObjectsAndOneObject) {
    for (const Family& family : kFamilies) {
        auto empty = family.make(0, 1);
        EXPECT_EQ(empty->max_boxes(5), 0u) << family.name;
        for (int k = 0; k < 3; ++k) {
            const Frame frame = empty->next();
            EXPECT_TRUE(frame.boxes.empty() && frame.ids.empty()) << family.name;
            EXPECT_EQ(frame.number, static_cast<uint64_t>(k)) << family.name;
        }
        auto one = family.make(1, 1);
        EXPECT_EQ(one->max_boxes(5), 1u) << family.name;
        for (int k = 0; k < 5; ++k) {
            const Frame frame = one->next();
            ASSERT_EQ(frame.boxes.size(), 1u) << family.name << " frame " << k;
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_LE(0.0, frame.boxes[0].min[axis]) << family.name;
                EXPECT_LT(frame.boxes[0].min[axis], frame.boxes[0].max[axis]) << family.name;
            }
        }
    }
}

TEST(SceneFamilies, EveryBoxValidAndFramesAsManyAsSaid) {
    for (const Family& family : kFamilies) {
        auto scene = family.make(500, 3);
        std::size_t most = 0;
        for (int k = 0; k < 40; ++k) {
            const Frame frame = scene->next();
            most = std::max(most, frame.boxes.size());
            for (const Box& b : frame.boxes) {
                for (int axis = 0; axis < 3; ++axis) {
                    ASSERT_TRUE(std::isfinite(b.min[axis]) && std::isfinite(b.max[axis])) << family.name;
                    ASSERT_LE(0.0, b.min[axis]) << family.name << ": nothing below the floor or past a wall";
                    ASSERT_LT(b.min[axis], b.max[axis]) << family.name;
                }
            }
        }
        EXPECT_EQ(most, scene->max_boxes(40)) << family.name;
    }
}

// Heavy: the large boxes' longest extent is 0.75 to 1 x size_ratio x the
// small boxes' mean extent; they stand still, the debris drifts slowly.
TEST(SceneFamilies, HeavyHasLargeStaticBoxesAmongSlowDebris) {
    for (const double ratio : {100.0, 20.0}) {
        HeavyConfig config;
        config.objects = 3000;
        config.size_ratio = ratio;
        HeavyScene scene(config);
        const Frame first = scene.next();
        const Frame second = scene.next();
        double small_sum = 0;
        std::size_t small = 0, large = 0;
        for (std::size_t k = 0; k < first.boxes.size(); ++k) {
            if (scene.is_large(k)) continue;
            for (int axis = 0; axis < 3; ++axis) small_sum += box_extent(first.boxes[k], axis);
            ++small;
        }
        const double small_mean = small_sum / (3.0 * static_cast<double>(small));
        EXPECT_NEAR(small_mean, 1.5, 0.05);
        for (std::size_t k = 0; k < first.boxes.size(); ++k) {
            const Box& a = first.boxes[k];
            const Box& b = second.boxes[k];
            if (!scene.is_large(k)) {
                double moved2 = 0;
                for (int axis = 0; axis < 3; ++axis) moved2 += (b.min[axis] - a.min[axis]) * (b.min[axis] - a.min[axis]);
                ASSERT_LE(std::sqrt(moved2), config.max_speed * config.dt * (1 + 1e-9)) << "debris drifts slowly";
                continue;
            }
            ++large;
            const double longest = std::max({box_extent(a, 0), box_extent(a, 1), box_extent(a, 2)});
            EXPECT_GE(longest / small_mean, 0.7 * ratio) << "box " << k;
            EXPECT_LE(longest / small_mean, 1.05 * ratio) << "box " << k;
            EXPECT_EQ(0, std::memcmp(&a, &b, sizeof a)) << "level geometry stands still";
            for (int axis = 0; axis < 3; ++axis) EXPECT_LE(a.max[axis], scene.edge());
        }
        EXPECT_EQ(large, 30u) << "floor(N x large_fraction), spread over the ids";
    }
}

// Planar: the boxes stand in a thin band on a wide floor and move in the plane only.
TEST(SceneFamilies, PlanarIsThinAgainstItsWidthAndMovesInThePlane) {
    for (const double aspect : {1.0, 8.0}) {
        PlanarConfig config;
        config.objects = 2000;
        config.aspect = aspect;
        PlanarScene scene(config);
        EXPECT_NEAR(scene.length() / scene.width(), aspect, 1e-9 * aspect);
        const Frame first = scene.next();
        Frame last;
        for (int k = 0; k < 20; ++k) last = scene.next();
        double low = INFINITY, high = -INFINITY, moved = 0;
        for (std::size_t k = 0; k < first.boxes.size(); ++k) {
            low = std::min(low, first.boxes[k].min[2]);
            high = std::max(high, first.boxes[k].max[2]);
            EXPECT_EQ(first.boxes[k].min[2], last.boxes[k].min[2]) << "no vertical motion";
            EXPECT_EQ(first.boxes[k].max[2], last.boxes[k].max[2]) << "no vertical motion";
            moved += std::fabs(last.boxes[k].min[0] - first.boxes[k].min[0]);
            EXPECT_LE(last.boxes[k].max[0], scene.length());
            EXPECT_LE(last.boxes[k].max[1], scene.width());
        }
        EXPECT_GE(low, 0.0);
        EXPECT_LE(high - low, config.height_band + kMaxExtent);
        EXPECT_LT(20 * (high - low), std::min(scene.length(), scene.width()) * std::sqrt(aspect))
            << "the height spread is small against the floor";
        EXPECT_GT(moved, 0.0);
    }
}

bool overlap_in_plan(const Box& a, const Box& b) {
    return a.min[0] < b.max[0] && b.min[0] < a.max[0] && a.min[1] < b.max[1] && b.min[1] < a.max[1];
}

// Pile: nothing sinks into the floor or into another box; every box at
// rest stands on the floor or exactly on a box under it; many touch.
TEST(SceneFamilies, PileBoxesRestTouchingAndNeverSink) {
    PileConfig config;
    config.objects = 400;
    PileScene scene(config);
    std::size_t first_count = 0, touching = 0;
    for (int k = 0; k < 400; ++k) {
        const Frame frame = scene.next();
        if (k == 0) first_count = frame.boxes.size();
        for (std::size_t i = 0; i < frame.boxes.size(); ++i) {
            const Box& a = frame.boxes[i];
            ASSERT_GE(a.min[2], 0.0) << "frame " << k << " box " << i;
            if (!scene.resting(i)) continue;
            bool supported = a.min[2] == 0.0;
            for (std::size_t j = 0; j < frame.boxes.size(); ++j) {
                const Box& b = frame.boxes[j];
                if (j == i || !scene.resting(j) || !overlap_in_plan(a, b)) continue;
                ASSERT_FALSE(a.min[2] < b.max[2] && b.min[2] < a.max[2])
                    << "frame " << k << ": resting boxes " << i << " and " << j << " sink into each other";
                if (b.max[2] == a.min[2]) supported = true;
                if (k == 399 && j > i && (b.max[2] == a.min[2] || a.max[2] == b.min[2])) ++touching;
            }
            ASSERT_TRUE(supported) << "frame " << k << ": box " << i << " rests on nothing";
        }
        if (k == 399) {
            EXPECT_EQ(frame.boxes.size(), config.objects) << "every box released";
            for (std::size_t i = 0; i < frame.boxes.size(); ++i) EXPECT_TRUE(scene.resting(i)) << i << " landed";
        }
    }
    EXPECT_EQ(first_count, 200u + 2u) << "half landed before frame 0, and the first batch";
    EXPECT_GT(touching, config.objects / 2) << "a pile's boxes touch";
}

TEST(SceneFamilies, PileBoxesFallUnderGravityFromAboveTheirCluster) {
    PileConfig config;
    config.objects = 100;
    config.settled_fraction = 0;
    PileScene scene(config);
    const Frame first = scene.next();
    ASSERT_EQ(first.boxes.size(), 1u);
    EXPECT_FALSE(scene.resting(0));
    const Frame second = scene.next();
    const Frame third = scene.next();
    const double fall1 = first.boxes[0].min[2] - second.boxes[0].min[2];
    const double fall2 = second.boxes[0].min[2] - third.boxes[0].min[2];
    EXPECT_GT(fall1, 0.0);
    EXPECT_NEAR(fall2 - fall1, config.gravity * config.dt * config.dt, 1e-12) << "accelerating";
}

double mean_displacement(const Frame& a, const Frame& b) {
    double sum = 0;
    for (std::size_t k = 0; k < a.boxes.size(); ++k) {
        double d2 = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double d = b.boxes[k].min[axis] - a.boxes[k].min[axis];
            d2 += d * d;
        }
        sum += std::sqrt(d2);
    }
    return sum / static_cast<double>(a.boxes.size());
}

// Brownian: a box jumps far further between two frames than its own size;
// the spheres move a fraction of theirs.
TEST(SceneFamilies, BrownianJumpsFarUnlikeSpheres) {
    BrownianConfig config;
    config.objects = 1000;
    BrownianScene brownian(config);
    Frame previous = brownian.next();
    for (int k = 0; k < 5; ++k) {
        const Frame frame = brownian.next();
        EXPECT_GT(mean_displacement(previous, frame), 5 * kMeanExtent) << "frame " << frame.number;
        previous = frame;
    }
    SpheresConfig spheres_config;
    spheres_config.objects = 1000;
    SpheresScene spheres(spheres_config);
    const Frame a = spheres.next();
    EXPECT_LT(mean_displacement(a, spheres.next()), 0.1 * kMeanExtent);
    // A small jump keeps the frames coherent.
    config.jump = 0.001;
    BrownianScene calm(config);
    const Frame c = calm.next();
    EXPECT_LT(mean_displacement(c, calm.next()), 0.1 * kMeanExtent);
}

template <class Scene, class Config>
void expect_refused(const Config& config, const std::string& message) {
    try {
        Scene scene(config);
        ADD_FAILURE() << "accepted; expected: " << message;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), message);
    }
}

TEST(SceneFamilies, BadConfigsRefusedNamingTheSetting) {
    PileConfig pile;
    pile.clusters = 0;
    expect_refused<PileScene>(pile, "pile scene: expected clusters from 1 to 1048576");
    HeavyConfig heavy;
    heavy.size_ratio = 0.5;
    expect_refused<HeavyScene>(heavy, "heavy scene: expected size_ratio >= 1");
    heavy = HeavyConfig{};
    heavy.large_fraction = 1.5;
    expect_refused<HeavyScene>(heavy, "heavy scene: expected large_fraction in [0, 1]");
    PlanarConfig planar;
    planar.aspect = 0.5;
    expect_refused<PlanarScene>(planar, "planar scene: expected aspect >= 1");
    BrownianConfig brownian;
    brownian.jump = -1;
    expect_refused<BrownianScene>(brownian, "brownian scene: expected jump in [0, 1]");
}

}  // namespace
}  // namespace cdvp
