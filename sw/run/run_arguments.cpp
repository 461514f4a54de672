#include "sw/run/run_arguments.h"

#include <stdexcept>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ",") + item;
    return text;
}

// A value given typed: its dedicated flag, a switch without a value, else the
// NAME=VALUE override (a setting without a flag, or a switch set to "no").
void given_words(const Assignment& a, std::vector<std::string>& words) {
    const Setting& s = *a.setting;
    const std::string value = to_text(a.value);
    if (!s.flag.empty() && !s.value_name.empty()) {
        words.push_back("--" + s.flag + "=" + value);
    } else if (!s.flag.empty() && value == "yes") {
        words.push_back("--" + s.flag);
    } else {
        words.insert(words.end(), {"-c", s.name + "=" + value});
    }
}

}  // namespace

std::vector<std::string> to_arguments(const RunSpec& spec) {
    std::vector<std::string> words;
    const SettingLayers& layers = spec.settings;
    if (spec.frames) {
        if (const auto* trace = std::get_if<TraceFrames>(&*spec.frames)) words.push_back("--trace=" + trace->path);
        if (const auto* scene = std::get_if<SceneFrames>(&*spec.frames)) words.push_back("--scene=" + scene->name);
        if (const auto* worlds = std::get_if<BulletWorlds>(&*spec.frames)) {
            words.insert(words.end(), {"--scene=" + worlds->name, "--software=" + worlds->software});
        }
    }
    if (layers.board) words.push_back("--board=" + *layers.board);
    if (layers.config) words.push_back("--config=" + *layers.config);
    // NAME=VALUE starts with a letter: never an option.
    for (const std::string& text : layers.overrides) words.insert(words.end(), {"-c", text});
    for (const Assignment& a : layers.given) given_words(a, words);
    if (!spec.baselines.empty()) words.push_back("--baseline=" + joined(spec.baselines));
    if (spec.software_timings) words.push_back("--software-timings=" + *spec.software_timings);
    for (const std::string& fault : spec.faults) words.push_back("--inject=" + fault);
    if (spec.outputs.pairs_csv) words.push_back("--pairs-out=" + *spec.outputs.pairs_csv);
    if (spec.outputs.report) words.push_back("--report=" + *spec.outputs.report);
    if (const std::optional<WaveRequest>& waves = spec.outputs.waves) {
        words.push_back("--vcd=" + waves->path);
        if (waves->frames) words.push_back("--vcd-frames=" + *waves->frames);
        if (waves->format) words.push_back("--vcd-format=" + *waves->format);
    }
    if (!spec.outputs.summary) words.push_back("-q");
    return words;
}

void set_input(RunSpec& spec, const std::string& key, const std::string& value, bool typed) {
    if (const Setting* s = find_setting(key)) {
        if (typed) {
            SettingValue parsed;
            try {
                parsed = s->parse_text(value);
            } catch (const std::invalid_argument& e) {
                throw InputError(spec.settings.names->given(*s) + ": " + e.what());
            }
            spec.settings.given.push_back({s, parsed, {SettingOrigin::Kind::kGiven, "", 0}});
        } else {
            spec.settings.overrides.push_back(key + "=" + value);
        }
        return;
    }
    if (key == "board") {
        spec.settings.board = value;
    } else if (key == "config") {
        spec.settings.config = value;
    } else if (key == "trace") {
        spec.frames = TraceFrames{value};
    } else if (key == "scene") {
        spec.frames = SceneFrames{value};
    } else if (key == "baseline") {
        spec.baselines = comma_list(value);
    } else if (key == "inject") {
        spec.faults.push_back(value);
    } else if (key == "software-timings") {
        spec.software_timings = value;
    } else {
        throw std::invalid_argument("no input of a run is named '" + key + "'");
    }
}

std::vector<std::string> comma_list(const std::string& text) {
    std::vector<std::string> items;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        items.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return items;
}

}  // namespace cdvp
