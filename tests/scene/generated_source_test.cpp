// The generated scenes as a run opens them (sw/run/generated_source.h): the
// settings' defaults are the families' own, a source rewinds to the same
// frames, a memo replays them, and a family's setting goes with its scene only.
#include "sw/run/generated_source.h"

#include <gtest/gtest.h>

#include <cstring>

#include "sw/run/scene_memo.h"

namespace cdvp {
namespace {

std::vector<Frame> all_frames(FrameSource& source) {
    std::vector<Frame> frames;
    while (std::optional<Frame> frame = source.next()) frames.push_back(std::move(*frame));
    return frames;
}

bool same_frames(const std::vector<Frame>& a, const std::vector<Frame>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (a[k].number != b[k].number || a[k].ids != b[k].ids || a[k].boxes.size() != b[k].boxes.size() ||
            std::memcmp(a[k].boxes.data(), b[k].boxes.data(), a[k].boxes.size() * sizeof(Box)) != 0) {
            return false;
        }
    }
    return true;
}

SettingValues values_with(const std::vector<std::pair<const char*, SettingValue>>& given) {
    SettingValues values;
    std::vector<Assignment> layer;
    for (const auto& [name, value] : given) layer.push_back({&declared_setting(name), value, {SettingOrigin::Kind::kOverride, "", 0}});
    values.apply(layer);
    return values;
}

TEST(GeneratedSource, SettingsDefaultsAreTheFamiliesOwn) {
    const SceneSettings defaults;
    EXPECT_EQ(defaults.pile_clusters, PileConfig{}.clusters);
    EXPECT_EQ(defaults.heavy_size_ratio, HeavyConfig{}.size_ratio);
    EXPECT_EQ(defaults.heavy_large_fraction, HeavyConfig{}.large_fraction);
    EXPECT_EQ(defaults.planar_aspect, PlanarConfig{}.aspect);
    EXPECT_EQ(defaults.brownian_jump, BrownianConfig{}.jump);
    EXPECT_EQ(defaults.objects, KinematicConfig{}.objects);
    EXPECT_EQ(defaults.seed, KinematicConfig{}.seed);
    const PileConfig pile = pile_config(values_with({{"scene.pile.clusters", uint64_t{5}}}).settings().scene);
    EXPECT_EQ(pile.clusters, 5u);
}

TEST(GeneratedSource, EachFamilyRewindsAndReplaysTheSameFrames) {
    SceneMemo memo;
    for (const std::string& scene : generated_scene_names()) {
        const SettingValues values = values_with({{"scene.objects", uint64_t{120}}, {"scene.frames", uint64_t{6}}});
        const std::unique_ptr<FrameSource> source = generated_source(scene, values);
        EXPECT_EQ(source->frame_count(), 6u) << scene;
        EXPECT_EQ(source->last_frame(), std::optional<uint64_t>(5)) << scene;
        const std::vector<Frame> first = all_frames(*source);
        ASSERT_EQ(first.size(), 6u) << scene;
        source->rewind();
        EXPECT_TRUE(same_frames(first, all_frames(*source))) << scene;
        const std::unique_ptr<FrameSource> generated = generated_source(scene, values, &memo);
        EXPECT_TRUE(same_frames(first, all_frames(*generated))) << scene;
        const std::unique_ptr<FrameSource> replayed = generated_source(scene, values, &memo);
        EXPECT_TRUE(same_frames(first, all_frames(*replayed))) << scene;
        EXPECT_EQ(replayed->describe(), source->describe());
    }
    EXPECT_EQ(memo.hits(), 5u);
    const SettingValues values = values_with({{"scene.objects", uint64_t{120}}, {"scene.pile.clusters", uint64_t{2}}});
    EXPECT_EQ(generated_source("pile", values)->describe(), "pile objects=120 seed=1 clusters=2");
    EXPECT_EQ(generated_source("pile", values, &memo)->describe(), "pile objects=120 seed=1 clusters=2")
        << "another setting, another scene: not the memo's";
}

TEST(GeneratedSource, AFamilysSettingGoesWithItsSceneOnly) {
    const SettingValues values = values_with({{"scene.heavy.size_ratio", 10.0}});
    EXPECT_NO_THROW(check_family_settings(values, "heavy"));
    EXPECT_NO_THROW(check_family_settings(values, ""));  // a trace: check_scene_settings says it
    try {
        check_family_settings(values, "pile");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "scene.heavy.size_ratio: goes with scene heavy, not scene pile");
    }
    EXPECT_EQ(scene_of_setting(declared_setting("scene.pile.clusters")), "pile");
    EXPECT_EQ(scene_of_setting(declared_setting("scene.moving_fraction")), "spheres");
    EXPECT_EQ(scene_of_setting(declared_setting("scene.objects")), "");
    EXPECT_EQ(scene_of_setting(declared_setting("board.m")), "");
}

}  // namespace
}  // namespace cdvp
