#include "platform/settings/board_preset.h"

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "platform/settings/preset_json.h"
#include "platform/settings/setting_values.h"
#include "models/common/input_path.h"
#include "models/common/user_text.h"

namespace cdvp {

namespace {

using nlohmann::json;

// Reads a preset's sections, each declared with its keys: a key that is
// not declared is refused with the nearest declared one; every number is
// a {"value": number, "source": "..."} field within its setting's range.
// Every error names the file and the key.
class PresetReader {
public:
    PresetReader(std::string path, json root) : path_(std::move(path)), root_(std::move(root)) {}

    std::vector<std::string> keys(const std::string& section) const {
        std::vector<std::string> names;
        for (const auto& [key, value] : this->section(section).items()) names.push_back(key);
        return names;
    }
    // Refuses keys of 'section' ("" for the top level) outside 'keys'.
    void only(const std::string& section, const std::vector<std::string>& keys) const {
        const json& object = section.empty() ? root_ : this->section(section);
        for (const auto& [key, value] : object.items()) {
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
                const std::optional<std::string> nearest = nearest_name(key, keys);
                fail(qualified(section, excerpt(key)) + ": unknown key" +
                     (nearest ? "; did you mean '" + *nearest + "'?" : ""));
            }
        }
    }
    // A {"value": number, "source": "..."} field, checked against its setting.
    SettingValue number(const Setting& setting) const {
        const std::string section = setting.section();
        const std::string& name = setting.name;
        const json* field = find(section, setting.key().c_str());
        const char* kForm = ": expected {\"value\": <number>, \"source\": \"<source or assumption>\"}";
        if (field == nullptr) fail(name + ": missing;" + std::string(kForm).substr(1));
        if (!field->is_object()) fail(name + kForm);
        for (const auto& [key, value] : field->items()) {
            if (key != "value" && key != "source") fail(name + kForm + ", found '" + excerpt(key) + "'");
        }
        const auto value = field->find("value");
        const auto source = field->find("source");
        if (value == field->end() || !value->is_number() || source == field->end() || !source->is_string() ||
            source->get<std::string>().empty()) {
            fail(name + kForm);
        }
        try {
            if (value->is_number_unsigned()) return setting.from_count(value->get<uint64_t>());
            return setting.from_number(value->get<double>(), value->dump());
        } catch (const std::invalid_argument& e) {
            fail(name + ": " + e.what());
        }
    }
    std::string text(const std::string& section, const char* key) const {
        const json* field = find(section, key);
        if (field == nullptr || !field->is_string() || field->get<std::string>().empty()) {
            fail(qualified(section, key) + ": expected a non-empty string");
        }
        return field->get<std::string>();
    }
    [[noreturn]] void fail(const std::string& what) const { throw InputError(path_ + ": " + what); }

private:
    static std::string qualified(const std::string& section, const std::string& key) {
        return section.empty() ? key : section + "." + key;
    }
    const json& section(const std::string& name) const {
        const auto it = root_.find(name);
        if (it == root_.end() || !it->is_object()) fail(name + ": expected an object of fields");
        return *it;
    }
    const json* find(const std::string& section, const char* key) const {
        const json& object = section.empty() ? root_ : this->section(section);
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }
    std::string path_;
    json root_;
};

// The keys of 'section' a preset of bus type 'bus' must give, in table order.
std::vector<const Setting*> preset_settings(const std::string& section, BusType bus) {
    std::vector<const Setting*> keys;
    for (const Setting& s : settings_table()) {
        if (s.in_preset && s.section() == section && s.applies_to_bus(bus)) keys.push_back(&s);
    }
    return keys;
}

// A key the section does not declare: a setting of the other bus type, one
// that is the user's and never a preset's, or a misspelling.
void refuse_undeclared_keys(const PresetReader& r, const std::string& section, BusType bus) {
    std::vector<std::string> keys;
    for (const Setting* s : preset_settings(section, bus)) keys.push_back(s->key());
    for (const std::string& key : r.keys(section)) {
        if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
        const Setting* known = find_setting(section + "." + key);
        if (known != nullptr && known->in_preset) {
            r.fail(known->name + ": a key of a " + known->bus_types() + " bus; this preset's bus is " + name_of(bus));
        }
        if (known != nullptr) {
            r.fail(known->name + ": not a preset key: the user's choice" +
                   (known->flag.empty() ? "" : " (--" + known->flag + " or -c " + known->name + ")"));
        }
        const std::optional<std::string> nearest = nearest_name(key, keys);
        r.fail(section + "." + excerpt(key) + ": unknown key" + (nearest ? "; did you mean '" + *nearest + "'?" : ""));
    }
}

constexpr const char* kWhat = "a board preset";  // in refusals of the file as a whole

std::string read_preset_text(const std::string& path, bool is_path, const std::string& name, const std::string& label) {
    if (const std::string* pinned = PinnedFiles::find(path)) return *pinned;
    // Only a name with nothing behind it is unknown: a loop, a directory or a
    // file it may not read is said as such, by read_small_file.
    if (!is_path && input_presence(path).absent()) {
        std::string known;
        for (const std::string& n : board_preset_names()) known += (known.empty() ? "" : ", ") + n;
        const char* env = std::getenv("CDVP_BOARDS");
        const std::string where = env != nullptr && env[0] != '\0'
                                      ? "$CDVP_BOARDS (" + excerpt(env) + ")"
                                      : "the presets directory " + excerpt(boards_directory());
        if (known.empty()) {
            throw InputError(label + ": unknown board '" + excerpt(name) + "': " + where +
                             " holds no preset (NAME.json); give a .json path, or unset CDVP_BOARDS");
        }
        throw InputError(label + ": unknown board '" + excerpt(name) + "'; expected one of: " + known);
    }
    return read_small_file(path, kWhat);
}

bool names_a_path(const std::string& name) {
    return name.find('/') != std::string::npos || (name.size() > 5 && name.rfind(".json") == name.size() - 5);
}

}  // namespace

// $CDVP_BOARDS; else the presets installed beside the running binary
// (PREFIX/bin/cdvp -> PREFIX/share/cdvp/boards), found through /proc/self/exe
// so that a moved prefix still works; else the source tree's, for a build
// run where it was built.
std::string boards_directory() {
    const char* env = std::getenv("CDVP_BOARDS");
    if (env != nullptr && env[0] != '\0') return env;
    // Beside the executable once installed, else the source tree's: the
    // executable does not move while it runs, so this is looked up once.
    static const std::string beside_executable = [] {
        std::error_code ec;
        const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec) {
            const std::filesystem::path installed = executable.parent_path() / CDVP_INSTALLED_BOARDS_DIR;
            if (std::filesystem::is_directory(installed, ec)) return installed.lexically_normal().string();
        }
        return std::string(CDVP_BOARDS_DIR);
    }();
    return beside_executable;
}

std::vector<std::string> board_preset_names() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(boards_directory(), ec)) {
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string board_preset_path(const std::string& name) {
    return names_a_path(name) ? name : boards_directory() + "/" + name + ".json";
}

namespace {

BoardPreset parse_board_preset(const std::string& path, const std::string& text);

std::shared_ptr<const BoardPreset> read_board_preset(const std::string& name, const std::string& label) {
    const std::string path = board_preset_path(name);
    std::string text = read_preset_text(path, names_a_path(name), name, label);
    // Presets read before, by path and their whole text: a sweep reads its
    // preset once a point, and only parsing and checking cost anything.
    static constexpr std::size_t kKept = 16;
    static std::vector<std::pair<std::pair<std::string, std::string>, std::shared_ptr<const BoardPreset>>> kept;
    for (const auto& [key, preset] : kept) {
        if (key.first == path && key.second == text) return preset;
    }
    auto p = std::make_shared<const BoardPreset>(parse_board_preset(path, text));
    if (kept.size() == kKept) kept.erase(kept.begin());
    kept.push_back({{path, std::move(text)}, p});
    return p;
}

BoardPreset parse_board_preset(const std::string& path, const std::string& text) {
    const PresetReader r(path, parse_preset(path, text, kWhat));
    r.only("", {"name", "description", "board", "device", "bus", "host"});
    BoardPreset p;
    p.path = path;
    p.name = r.text("", "name");
    p.description = r.text("", "description");
    const std::string bus_text = r.text("bus", "type");
    // A preset's board sits on a bus: the ideal one is no preset's.
    const BusType bus = parse_choice<BusType>(bus_text).value_or(BusType::kIdeal);
    if (bus == BusType::kIdeal) {
        r.fail("bus.type: expected \"pci\" or \"pcie\", got \"" + excerpt(bus_text) + "\"");
    }
    for (const char* section : {"board", "device", "bus", "host"}) {
        refuse_undeclared_keys(r, section, bus);
        for (const Setting* s : preset_settings(section, bus)) {
            const bool is_text = s->type == SettingType::kText || s->type == SettingType::kChoice;
            p.values.push_back({s, is_text ? SettingValue(r.text(section, s->key().c_str())) : r.number(*s),
                                {SettingOrigin::Kind::kPreset, path, 0}});
        }
    }
    // The bus model's own rules, refused as any layer's would be.
    p.applied().bus();
    return p;
}

}  // namespace

SettingValues BoardPreset::applied() const {
    SettingValues settings;
    settings.apply(values);
    return settings;
}

std::shared_ptr<const BoardPreset> load_shared_board_preset(const std::string& name, const std::string& label) {
    try {
        return read_board_preset(name, label);
    } catch (const InputError& e) {
        // One line whatever the file holds: keys, strings and paths may hold control characters.
        throw InputError(printable(e.what()));
    }
}

BoardPreset load_board_preset(const std::string& name, const std::string& label) {
    return *load_shared_board_preset(name, label);
}

}  // namespace cdvp
