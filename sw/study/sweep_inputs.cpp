#include "sw/study/sweep_inputs.h"

#include <algorithm>
#include <set>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "platform/settings/board_preset.h"
#include "sw/run/host_profile.h"

namespace cdvp {

namespace {

// Anything there, a file it cannot read included: the sweep refuses that with its reason.
bool fs_exists(const std::string& path) { return !input_presence(path).absent(); }

// Every file an axis names, for the manifest's digests; one source of frames at most.
void name_axis_inputs(SweepSpec& o) {
    std::set<std::string> sources;
    for (const Axis& axis : o.axes) {
        if (axis.key == "scene" || axis.key == "trace") sources.insert(axis.key);
        for (const std::string& value : axis.values) {
            if (axis.key == "trace" || axis.key == "config") o.inputs.push_back({"--" + axis.key, value, value});
            if (axis.key == "board") o.inputs.push_back({"--board", value, board_preset_path(value)});
            if (axis.key == "host.profile") o.inputs.push_back({"--host-profile", value, value});
        }
    }
    if (sources.size() == 2) throw InputError("--scene and --trace: give one of them (the points' frames come from it)");
    if (sources.empty()) o.run.frames = SceneFrames{"spheres"};
}

// A host profile's reference times and, as what each may move by on a
// resume, its recorded spread (the worst of its sizes).
nlohmann::json host_profile_facts(const NamedInput& input, const std::string& text) {
    if (input.option != "--host-profile") return nullptr;
    HostProfile profile;
    try {
        profile = parse_host_profile(input.path, text);
    } catch (const InputError&) {
        return nullptr;  // the points refuse it, naming the field
    }
    nlohmann::json values = nlohmann::json::object(), tolerance = nlohmann::json::object();
    for (const auto& [name, baseline] : profile.reference) {
        values[name + "'s reference time (ns)"] = baseline.reference_native_ns;
        double spread = 0;
        for (const ReferenceTiming& t : baseline.sizes) spread = std::max(spread, t.spread());
        tolerance[name + "'s reference time (ns)"] = spread;
    }
    return {{"values", values}, {"tolerance", tolerance}};
}

}  // namespace

void name_sweep_inputs(SweepSpec& o) {
    name_axis_inputs(o);
    o.input_facts = host_profile_facts;
    // The host profile the points read when none is named: a calibration
    // between two runs of the sweep changes its factors.
    const bool profile_named = std::any_of(o.inputs.begin(), o.inputs.end(),
                                           [](const NamedInput& input) { return input.option == "--host-profile"; });
    if (const std::string path = default_host_profile_path(); !profile_named && !path.empty() && fs_exists(path)) {
        o.inputs.push_back({"--host-profile", "(its default place)", path});
    }
}

}  // namespace cdvp
