#include "platform/settings/config_file.h"

#include <stdexcept>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "models/common/user_text.h"
#include "models/common/number_text.h"
#include "models/common/nesting_limit.h"
#include "platform/settings/preset_json.h"

namespace cdvp {

namespace {

using nlohmann::json;

// The setting called 'name', or a refusal naming the nearest one.
const Setting& setting_named(const std::string& where, const std::string& name) {
    if (const Setting* s = find_setting(name)) return *s;
    const std::optional<std::string> nearest = nearest_name(name, setting_names());
    throw InputError(where + excerpt(name) + ": unknown setting" + (nearest ? "; did you mean '" + *nearest + "'?" : ""));
}

// Collects a file's settings, each with its origin; 'where' prefixes refusals.
class ConfigReader {
public:
    explicit ConfigReader(std::string path) : path_(std::move(path)) {}

    void add_json(const json& node, const std::string& prefix) {
        for (const auto& [key, value] : node.items()) {
            const std::string name = prefix.empty() ? key : prefix + "." + key;
            if (value.is_object() && !value.contains("value")) {
                add_json(value, name);
                continue;
            }
            const json& leaf = value.is_object() ? value.at("value") : value;
            const Setting& s = setting_named(path_ + ": ", name);
            add(s, 0, [&]() -> SettingValue {
                if (leaf.is_number_unsigned()) return s.from_count(leaf.get<uint64_t>());
                if (leaf.is_number()) return s.from_number(leaf.get<double>(), leaf.dump());
                if (leaf.is_string()) return s.from_string(leaf.get<std::string>());
                throw std::invalid_argument("expected " + expected(s) + ", got " + excerpt(leaf.dump()));
            });
        }
    }

    void add_toml(const toml::table& table, const std::string& prefix) {
        for (const auto& [key, node] : table) {
            const std::string name = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
            const toml::node* leaf = &node;
            if (const toml::table* inner = node.as_table()) {
                if (!inner->contains("value")) {
                    add_toml(*inner, name);
                    continue;
                }
                leaf = inner->get("value");
            }
            const int line = static_cast<int>(leaf->source().begin.line);
            const Setting& s = setting_named(path_ + ":" + std::to_string(line) + ": ", name);
            add(s, line, [&]() -> SettingValue {
                if (const auto* i = leaf->as_integer()) {
                    const int64_t v = i->get();
                    return v >= 0 ? s.from_count(static_cast<uint64_t>(v)) : s.from_number(double(v), std::to_string(v));
                }
                if (const auto* f = leaf->as_floating_point()) return s.from_number(f->get(), show_number(f->get()));
                if (const auto* t = leaf->as_string()) return s.from_string(t->get());
                throw std::invalid_argument("expected " + expected(s));
            });
        }
    }

    std::vector<Assignment> values;

private:
    static std::string expected(const Setting& s) {
        if (s.type == SettingType::kText) return "a string";
        if (s.type == SettingType::kChoice) return s.range_text();
        return "a number";
    }
    template <class Read>
    void add(const Setting& s, int line, Read read) {
        const std::string where = path_ + (line > 0 ? ":" + std::to_string(line) : "") + ": " + s.name + ": ";
        for (const Assignment& a : values) {
            if (a.setting == &s) throw InputError(where + "given twice");
        }
        try {
            values.push_back({&s, read(), {SettingOrigin::Kind::kConfig, path_, line}});
        } catch (const std::invalid_argument& e) {
            throw InputError(where + e.what());
        }
    }
    std::string path_;
};

}  // namespace

std::vector<Assignment> read_config_file(const std::string& path) {
    const std::string what = "a config file";
    const std::string text = read_small_file(path, what);
    ConfigReader reader(path);
    if (ends_with(path, ".toml")) {
        check_toml_nesting(path, text, what);  // toml::parse and add_toml recurse
        try {
            reader.add_toml(toml::parse(text, path), "");
        } catch (const toml::parse_error& e) {
            // toml++ quotes what it saw as it is, a newline included ("saw 't\n'").
            throw InputError(path + ":" + std::to_string(e.source().begin.line) + ":" +
                             std::to_string(e.source().begin.column) + ": invalid TOML: " +
                             printable(std::string(e.description())));
        }
    } else {
        reader.add_json(parse_preset(path, text, what), "");
    }
    return std::move(reader.values);
}

Assignment parse_override(const std::string& text, const std::string& label) {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0) {
        throw InputError(label + ": expected NAME=VALUE (see cdvp settings), got '" + excerpt(text) + "'");
    }
    const std::string name = text.substr(0, equals);
    const Setting& s = setting_named(label + " ", name);
    try {
        return {&s, s.parse_text(text.substr(equals + 1)), {SettingOrigin::Kind::kOverride, "", 0}};
    } catch (const std::invalid_argument& e) {
        throw InputError(label + " " + s.name + ": " + e.what());
    }
}

}  // namespace cdvp
