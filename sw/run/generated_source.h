// The generated scenes a run takes by name besides Bullet's: spheres (the
// paper's application, stepped on each frame's pairs) and the kinematic
// families (pile, heavy, planar, brownian: sw/scene/kinematic_scene.h),
// each built from the scene.* settings, its family's own among them
// (scene.pile.*, scene.heavy.*, ...).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "platform/settings/setting_values.h"
#include "sw/apps/bouncing_spheres.h"
#include "sw/run/frame_source.h"
#include "sw/scene/brownian.h"
#include "sw/scene/heavy.h"
#include "sw/scene/pile.h"
#include "sw/scene/planar.h"

namespace cdvp {

class SceneMemo;

// "spheres", then the kinematic families: "pile", "heavy", "planar", "brownian".
const std::vector<std::string>& generated_scene_names();
bool is_generated_scene(const std::string& name);
// A generated scene whose frames do not depend on the pairs found: pile, heavy, planar, brownian.
bool is_kinematic_scene(const std::string& name);
// "spheres, pile, heavy, planar, brownian".
std::string generated_scene_list();

// The scene a scene.* setting belongs to: "pile" for scene.pile.clusters,
// "spheres" for scene.moving_fraction; empty for one every scene has
// (objects, frames, seed) and for a setting of another section.
std::string scene_of_setting(const Setting& setting);
// A family's setting set off its default for another scene is refused in
// one line: "-c scene.pile.clusters: goes with --scene pile, not --scene
// heavy". `scene` empty (a trace): nothing here (check_scene_settings says it).
void check_family_settings(const SettingValues& values, const std::string& scene);

// Each family's config from the settings.
BouncingSpheresConfig spheres_config(const SceneSettings& s);
PileConfig pile_config(const SceneSettings& s);
HeavyConfig heavy_config(const SceneSettings& s);
PlanarConfig planar_config(const SceneSettings& s);
BrownianConfig brownian_config(const SceneSettings& s);

// The frames of generated scene `scene` (is_generated_scene) as the
// settings give it: scene.frames frames of scene.objects objects from
// scene.seed. With `memo`, kept and replayed across the runs of a process.
// A kinematic scene's rewind builds it again from its seed.
std::unique_ptr<FrameSource> generated_source(const std::string& scene, const SettingValues& values,
                                              SceneMemo* memo = nullptr);

// Every frame of generated scene `scene`, as `cdvp run --scene` gives it on
// a float32 board: the spheres step on each frame's float32 pairs, found
// on the host (the board's, pair for pair), as the run steps them on the
// board's. `cdvp record` writes them as a trace.
void play_generated(const std::string& scene, const SettingValues& values,
                    const std::function<void(const Frame&)>& take);

}  // namespace cdvp
