// SceneMemo replays a generated scene frame for frame, keys it by every
// setting, keeps nothing of a run that stopped early and stays in its bound.
#include "sw/run/scene_memo.h"

#include "sw/scene/conversion.h"

#include <gtest/gtest.h>

#include <vector>

namespace cdvp {
namespace {

// The frames a source gives, each stepped on its every overlapping pair (as a broad phase gives them).
std::vector<Frame> run(FrameSource& source, std::size_t stop_after = SIZE_MAX) {
    std::vector<Frame> frames;
    while (frames.size() < stop_after) {
        std::optional<Frame> frame = source.next();
        if (!frame) break;
        PairList pairs;
        for (uint32_t i = 0; i < frame->boxes.size(); ++i)
            for (uint32_t j = i + 1; j < frame->boxes.size(); ++j) {
                bool overlap = true;
                for (int a = 0; a < 3; ++a) {
                    overlap = overlap && frame->boxes[i].min[a] <= frame->boxes[j].max[a] &&
                              frame->boxes[j].min[a] <= frame->boxes[i].max[a];
                }
                if (overlap) pairs.push_back({i, j});
            }
        source.feed(pairs);
        frames.push_back(*frame);
    }
    return frames;
}

void expect_same(const std::vector<Frame>& a, const std::vector<Frame>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].number, b[k].number);
        EXPECT_EQ(a[k].ids, b[k].ids);
        ASSERT_EQ(a[k].boxes.size(), b[k].boxes.size());
        for (std::size_t i = 0; i < a[k].boxes.size(); ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_EQ(a[k].boxes[i].min[axis], b[k].boxes[i].min[axis]);
                EXPECT_EQ(a[k].boxes[i].max[axis], b[k].boxes[i].max[axis]);
            }
        }
    }
}

// Steps `source` through `fresh`'s frames: its float32 boxes are each frame's, converted.
void expect_float_boxes(FrameSource& source, const std::vector<Frame>& fresh) {
    EXPECT_EQ(source.float_boxes(), nullptr) << "no frame given yet";
    for (std::size_t k = 0; k < fresh.size(); ++k) {
        ASSERT_TRUE(source.next());
        const std::vector<FloatBox>* boxes = source.float_boxes();
        ASSERT_NE(boxes, nullptr);
        const std::vector<FloatBox> expected = to_float_boxes(fresh[k].boxes);
        ASSERT_EQ(boxes->size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_EQ((*boxes)[i].min[axis], expected[i].min[axis]);
                EXPECT_EQ((*boxes)[i].max[axis], expected[i].max[axis]);
            }
        }
        source.feed({});
    }
}

BouncingSpheresConfig crowded(uint64_t seed) {
    BouncingSpheresConfig config;
    config.objects = 120;
    config.seed = seed;
    config.volume_fraction = 0.3;  // spheres collide, so a frame depends on the pairs fed back
    return config;
}

TEST(SceneMemo, ReplaysTheGeneratedFramesAndTellsSettingsApart) {
    SceneMemo memo;
    const std::vector<Frame> fresh = run(*spheres_source(crowded(1), 6));
    const std::vector<Frame> first = run(*memo.spheres(crowded(1), 6));
    const auto replay = memo.spheres(crowded(1), 6);
    EXPECT_EQ(replay->describe(), spheres_source(crowded(1), 6)->describe());
    EXPECT_EQ(replay->max_objects(), 120u);
    EXPECT_EQ(replay->last_frame(), std::optional<uint64_t>(5));
    EXPECT_TRUE(replay->has_frame(5));
    EXPECT_FALSE(replay->has_frame(6));
    const std::vector<Frame> again = run(*replay);
    EXPECT_EQ(memo.hits(), 1u);
    expect_same(first, fresh);
    expect_same(again, fresh);
    replay->rewind();
    expect_same(run(*replay), fresh);
    // A replay keeps each frame's float32 boxes converted; a generator converts none.
    replay->rewind();
    expect_float_boxes(*replay, fresh);
    EXPECT_EQ(spheres_source(crowded(1), 6)->float_boxes(), nullptr);
    // Any other setting is another scene.
    BouncingSpheresConfig other = crowded(1);
    other.restitution = 0.5;
    expect_same(run(*memo.spheres(other, 6)), run(*spheres_source(other, 6)));
    run(*memo.spheres(crowded(2), 6));
    run(*memo.spheres(crowded(1), 5));
    EXPECT_EQ(memo.hits(), 1u);
    EXPECT_EQ(memo.misses(), 4u);
}

// The recording converts each frame's boxes into the scene it keeps, so that
// a replay finds them converted; after a rewind it gives them again.
TEST(SceneMemo, ARecordingGivesItsFramesFloat32BoxesAndKeepsThem) {
    SceneMemo memo;
    const BouncingSpheresConfig still = crowded(3);
    std::vector<Frame> fresh;  // as expect_float_boxes steps them: no pair fed back
    for (auto source = spheres_source(still, 4); std::optional<Frame> frame = source->next(); source->feed({})) {
        fresh.push_back(*frame);
    }
    const auto recording = memo.spheres(still, 4);
    expect_float_boxes(*recording, fresh);
    const std::vector<FloatBox>* last = recording->float_boxes();
    recording->rewind();
    expect_float_boxes(*recording, fresh);
    const auto replay = memo.spheres(still, 4);
    EXPECT_EQ(memo.hits(), 1u);
    for (int k = 0; k < 4; ++k) replay->next();
    EXPECT_EQ(replay->float_boxes(), last) << "converted once, by the recording";
}

TEST(SceneMemo, KeepsNothingOfARunThatStoppedEarlyAndStaysInItsBound) {
    SceneMemo memo;
    run(*memo.spheres(crowded(3), 6), 3);
    run(*memo.spheres(crowded(3), 6));
    EXPECT_EQ(memo.hits(), 0u) << "three frames were not the scene";
    run(*memo.spheres(crowded(3), 6));
    EXPECT_EQ(memo.hits(), 1u);
    SceneMemo small(1000);  // less than one scene
    expect_same(run(*small.spheres(crowded(4), 2)), run(*spheres_source(crowded(4), 2)));
    expect_same(run(*small.spheres(crowded(4), 2)), run(*spheres_source(crowded(4), 2)));
    EXPECT_EQ(small.hits(), 0u);
}

}  // namespace
}  // namespace cdvp
