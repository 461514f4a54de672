#include "sw/run/generated_source.h"

#include <cstdio>
#include <functional>

#include "models/common/user_text.h"
#include "models/fast_engine/pair_finder.h"
#include "sw/scene/conversion.h"
#include "sw/run/scene_memo.h"

namespace cdvp {

namespace {

// A kinematic scene's frames: the scene built afresh from its config at
// every rewind, so the frames come again as they were.
class KinematicSource : public FrameSource {
public:
    using Make = std::function<std::unique_ptr<KinematicScene>()>;
    KinematicSource(Make make, std::size_t frames, std::string description)
        : make_(std::move(make)), frames_(frames), description_(std::move(description)) {
        rewind();
        max_objects_ = scene_->max_boxes(frames_);
    }
    void rewind() override {
        scene_ = make_();
        produced_ = 0;
    }
    std::optional<Frame> next() override {
        if (produced_ == frames_) return std::nullopt;
        ++produced_;
        return scene_->next();
    }
    std::size_t frame_count() const override { return frames_; }
    std::optional<uint64_t> last_frame() const override {
        return frames_ == 0 ? std::nullopt : std::optional<uint64_t>(frames_ - 1);
    }
    bool has_frame(uint64_t number) const override { return number < frames_; }
    std::size_t max_objects() const override { return max_objects_; }
    std::string describe() const override { return description_; }

private:
    Make make_;
    std::unique_ptr<KinematicScene> scene_;
    std::size_t frames_;
    std::size_t produced_ = 0;
    std::size_t max_objects_ = 0;
    std::string description_;
};

template <class Scene, class Config>
KinematicSource::Make maker(const Config& config) {
    return [config] { return std::make_unique<Scene>(config); };
}

// "pile objects=300 seed=1 clusters=3": the scene and every setting it takes
// but the frame count, each by its key.
std::string description(const std::string& scene, const SettingValues& values) {
    std::string text = scene;
    for (const Setting* s : values.effective()) {
        if (s->section() != "scene" || s->name == "scene.frames") continue;
        const std::string owner = scene_of_setting(*s);
        if (!owner.empty() && owner != scene) continue;
        const std::string key = s->key();
        text += " " + key.substr(key.find('.') + 1) + "=" + to_text(s->get(values.settings()));
    }
    return text;
}

// The memo's key: the description with reals exact (hexadecimal), and the frame count.
std::string memo_key(const std::string& scene, const SettingValues& values) {
    std::string key = scene;
    for (const Setting* s : values.effective()) {
        if (s->section() != "scene") continue;
        const std::string owner = scene_of_setting(*s);
        if (!owner.empty() && owner != scene) continue;
        const SettingValue value = s->get(values.settings());
        char text[64];
        if (const auto* real = std::get_if<double>(&value)) {
            std::snprintf(text, sizeof text, "%a", *real);
        } else {
            std::snprintf(text, sizeof text, "%s", to_text(value).c_str());
        }
        key += " " + s->name + "=" + text;
    }
    return key;
}

}  // namespace

const std::vector<std::string>& generated_scene_names() {
    static const std::vector<std::string> names{"spheres", "pile", "heavy", "planar", "brownian"};
    return names;
}

bool is_generated_scene(const std::string& name) {
    for (const std::string& n : generated_scene_names()) {
        if (n == name) return true;
    }
    return false;
}

bool is_kinematic_scene(const std::string& name) { return name != "spheres" && is_generated_scene(name); }

std::string generated_scene_list() {
    std::string list;
    for (const std::string& n : generated_scene_names()) list += (list.empty() ? "" : ", ") + n;
    return list;
}

std::string scene_of_setting(const Setting& setting) {
    if (setting.section() != "scene") return {};
    if (setting.name == "scene.moving_fraction") return "spheres";
    const std::string key = setting.key();
    const std::size_t dot = key.find('.');
    return dot == std::string::npos ? std::string() : key.substr(0, dot);
}

void check_family_settings(const SettingValues& values, const std::string& scene) {
    if (scene.empty()) return;
    const SettingNames& names = values.names();
    for (const Setting* s : values.effective()) {
        const std::string owner = scene_of_setting(*s);
        // Given at its default, it changes nothing (as --moving 1 with a Bullet scene).
        if (owner.empty() || owner == scene || s->get(values.settings()) == s->default_value()) continue;
        throw InputError(values.where(*s) + ": goes with " + names.input("scene") + " " + owner + ", not " +
                         names.input("scene") + " " + scene);
    }
}

BouncingSpheresConfig spheres_config(const SceneSettings& s) {
    BouncingSpheresConfig c;
    c.objects = static_cast<std::size_t>(s.objects);
    c.seed = s.seed;
    c.moving_fraction = s.moving_fraction;
    return c;
}

namespace {
template <class Config>
Config kinematic_config(const SceneSettings& s) {
    Config c;
    c.objects = static_cast<std::size_t>(s.objects);
    c.seed = s.seed;
    return c;
}
}  // namespace

PileConfig pile_config(const SceneSettings& s) {
    PileConfig c = kinematic_config<PileConfig>(s);
    c.clusters = s.pile_clusters;
    return c;
}

HeavyConfig heavy_config(const SceneSettings& s) {
    HeavyConfig c = kinematic_config<HeavyConfig>(s);
    c.size_ratio = s.heavy_size_ratio;
    c.large_fraction = s.heavy_large_fraction;
    return c;
}

PlanarConfig planar_config(const SceneSettings& s) {
    PlanarConfig c = kinematic_config<PlanarConfig>(s);
    c.aspect = s.planar_aspect;
    return c;
}

BrownianConfig brownian_config(const SceneSettings& s) {
    BrownianConfig c = kinematic_config<BrownianConfig>(s);
    c.jump = s.brownian_jump;
    return c;
}

std::unique_ptr<FrameSource> generated_source(const std::string& scene, const SettingValues& values, SceneMemo* memo) {
    const SceneSettings& s = values.settings().scene;
    const auto frames = static_cast<std::size_t>(s.frames);
    if (scene == "spheres") {
        const BouncingSpheresConfig config = spheres_config(s);
        return memo != nullptr ? memo->spheres(config, frames) : spheres_source(config, frames);
    }
    KinematicSource::Make make;
    if (scene == "pile") make = maker<PileScene>(pile_config(s));
    else if (scene == "heavy") make = maker<HeavyScene>(heavy_config(s));
    else if (scene == "planar") make = maker<PlanarScene>(planar_config(s));
    else if (scene == "brownian") make = maker<BrownianScene>(brownian_config(s));
    else throw std::logic_error("generated_source: no generated scene '" + scene + "'");
    auto open = [make, frames, text = description(scene, values)] {
        return std::unique_ptr<FrameSource>(std::make_unique<KinematicSource>(make, frames, text));
    };
    return memo != nullptr ? memo->generated(memo_key(scene, values), frames, open) : open();
}

void play_generated(const std::string& scene, const SettingValues& values,
                    const std::function<void(const Frame&)>& take) {
    const std::unique_ptr<FrameSource> source = generated_source(scene, values);
    const bool steps_on_pairs = !is_kinematic_scene(scene);
    PairFinder finder(NumberFormat::float32());
    std::vector<uint32_t> words[kCoordinates];
    PairList pairs;
    while (std::optional<Frame> frame = source->next()) {
        take(*frame);
        if (!steps_on_pairs) continue;
        const std::vector<FloatBox> boxes = to_float_boxes(frame->boxes);
        pairs.clear();
        finder.find(static_cast<uint32_t>(boxes.size()), float32_words(boxes, words), pairs);
        source->feed(pairs);
    }
}

}  // namespace cdvp
