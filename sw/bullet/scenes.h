// Game-like scenes built from Bullet's own shapes, each run in a BulletWorld
// on any broad phase; deterministic by seed.
//   pyramid  a pyramid of boxes that a heavy ball knocks down
//   boxes    boxes falling in a column onto a ground plane (3,000 by default)
//   mixed    spheres, boxes, capsules and convex hulls falling into a pile
//   stack    towers of boxes that settle and go to sleep
//   bullet-spheres  the paper's bouncing spheres: no gravity, elastic, in a
//            closed box of six walls. Named apart from `cdvp run`'s own
//            spheres scene, whose 500 boxes the paper's application steps:
//            Bullet steps these, and their walls make 506 boxes.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sw/bullet/bullet_world.h"

namespace cdvp {

struct SceneSpec {
    std::string name;
    uint32_t objects = 0;  // bodies the scene is built around; 0 for the scene's default
    uint64_t seed = 1;
};

// "boxes objects=3000 seed=1": how reports and summaries name the scene.
std::string describe(const SceneSpec& spec);

const std::vector<std::string>& bullet_scene_names();
bool is_bullet_scene(const std::string& name);
// Why `name` is none of Bullet's scenes, in one line without the input's
// name ("expected one of ..., got 'x'"), or nothing for one of them.
std::optional<std::string> bullet_scene_refusal(const std::string& name);
// "pyramid, boxes, mixed, stack, bullet-spheres": for messages and help.
std::string bullet_scene_list();
// "pyramid 120, boxes 3000, ...": each scene's default object count.
std::string bullet_scene_defaults();
// The most bodies a scene is built around.
constexpr uint32_t kMaxSceneObjects = 1000000;
// The default object count; std::invalid_argument for an unknown name.
uint32_t default_objects(const std::string& name);

struct SceneLayout {
    uint32_t proxies = 0;  // collision objects (and so broad-phase proxies) the scene creates
    btVector3 world_min;   // a box around everything that moves (btAxisSweep3's range)
    btVector3 world_max;
};
// std::invalid_argument for an unknown name or an object count of 1 to 1,000,000 exceeded.
SceneLayout scene_layout(const SceneSpec& spec);

// The scene in a new world on the given broad phase (link: for the board).
std::unique_ptr<BulletWorld> make_scene_world(const SceneSpec& spec, BroadphaseKind kind, BoardLink* link = nullptr);

}  // namespace cdvp
