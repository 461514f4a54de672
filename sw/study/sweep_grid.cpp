#include "sw/study/sweep_grid.h"

#include <cstring>
#include <map>
#include <string_view>
#include <unordered_map>

#include "models/common/user_text.h"
#include "sw/output/digest.h"

namespace cdvp {

namespace {

[[noreturn]] void refuse(const std::string& label, const std::string& list, const std::string& why) {
    throw InputError(label + ": '" + excerpt(list) + "': " + why);
}

// Text safe in a file name: anything but letters, digits, '.', '+', '-' and
// the characters in 'also' becomes '-'. A value's fragment keeps no '_' (it
// joins the axes) and no '~' (it marks a digest); an axis name keeps '_'.
std::string sanitized(std::string name, const char* also = "") {
    for (char& c : name) {
        const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                          c == '+' || c == '-' || (c != '\0' && std::strchr(also, c) != nullptr);
        if (!kept) c = '-';
    }
    return name.empty() ? "-" : name;
}

// The readable part of a value's fragment: a file (a trace, a preset) is
// named by its file name without the extension.
std::string readable_fragment(const std::string& value) {
    std::string name = value;
    if (const std::size_t slash = name.find_last_of('/'); slash != std::string::npos && slash + 1 < name.size()) {
        name = name.substr(slash + 1);
    }
    for (const char* extension : {".json", ".csv"}) {
        if (ends_with(name, extension) && name.size() > std::string(extension).size()) {
            name.resize(name.size() - std::string(extension).size());
        }
    }
    return sanitized(name);
}

// One fragment per value, unique within the axis (see kMaxFragmentBytes).
std::vector<std::string> axis_fragments(const std::vector<std::string>& values) {
    std::vector<std::string> fragments;
    std::map<std::string, std::size_t> uses;
    for (const std::string& value : values) {
        fragments.push_back(readable_fragment(value));
        ++uses[fragments.back()];
    }
    constexpr std::size_t kDigestHex = 8;
    constexpr std::size_t kKeptBytes = kMaxFragmentBytes - 1 - kDigestHex;
    std::map<std::string, std::size_t> digested;
    for (std::size_t k = 0; k < values.size(); ++k) {
        std::string& fragment = fragments[k];
        if (fragment.size() <= kMaxFragmentBytes && uses[fragment] == 1) continue;
        fragment = fragment.substr(0, kKeptBytes) + "~" + sha256_hex(values[k]).substr(0, kDigestHex);
        ++digested[fragment];
    }
    // Two digests alike: their places in the list tell them apart.
    for (std::size_t k = 0; k < values.size(); ++k) {
        if (digested.count(fragments[k]) != 0 && digested[fragments[k]] > 1) fragments[k] += "~" + std::to_string(k + 1);
    }
    return fragments;
}

}  // namespace

std::vector<std::string> expand_list(const std::string& list, const std::string& label, bool ranges) {
    std::vector<std::string> values;
    if (ranges && list.find(':') != std::string::npos && list.find(',') == std::string::npos) {
        values = expand_range(list, label);
    } else {
        std::size_t start = 0;
        while (true) {
            const std::size_t comma = list.find(',', start);
            const std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            if (item.empty()) refuse(label, list, "an empty value (expected a,b,c)");
            if (values.size() == kMaxAxisValues) refuse(label, list, "more than " + std::to_string(kMaxAxisValues) + " values");
            values.push_back(item);
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    if (const auto repeat = first_repeat(values)) {
        refuse(label, list, "'" + excerpt(values[repeat->first]) + "' is given twice");
    }
    return values;
}

std::optional<std::pair<std::size_t, std::size_t>> first_repeat(const std::vector<std::string>& keys) {
    std::unordered_map<std::string_view, std::size_t> seen;  // a key -> its first place
    seen.reserve(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const auto [earlier, fresh] = seen.emplace(keys[k], k);
        if (!fresh) return std::make_pair(k, earlier->second);
    }
    return std::nullopt;
}

void check_grid_size(const std::vector<Axis>& axes) {
    long double points = 1;
    for (const Axis& axis : axes) points *= static_cast<long double>(axis.values.size());
    if (points > static_cast<long double>(Grid::kMaxPoints)) {
        throw InputError("the grid has " + count_text(points) + " points, more than " + std::to_string(Grid::kMaxPoints));
    }
}

Axis parse_set(const std::string& text) {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) {
        throw InputError("--set: '" + excerpt(text) + "': expected NAME=LIST (for example m=1,2,4 or objects=50:2000:x2)");
    }
    Axis axis{text.substr(0, equals), {}};
    const bool starts_with_letter = !axis.name.empty() && axis.name[0] >= 'a' && axis.name[0] <= 'z';
    if (!starts_with_letter || axis.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_.-") != std::string::npos) {
        throw InputError("--set: '" + excerpt(axis.name) +
                         "': expected a flag of cdvp run (m, objects, ...) or a setting name (bus.interrupt_ns, ...)");
    }
    axis.values = expand_list(text.substr(equals + 1), "--set " + axis.name);
    return axis;
}

Shard parse_shard(const std::string& text) {
    const std::size_t slash = text.find('/');
    auto whole = [](const std::string& digits, uint64_t& value) {
        if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
        value = std::stoull(digits);
        return true;
    };
    Shard shard;
    if (slash == std::string::npos || !whole(text.substr(0, slash), shard.index_1) ||
        !whole(text.substr(slash + 1), shard.count) || shard.index_1 < 1 || shard.index_1 > shard.count) {
        throw InputError("--shard: '" + excerpt(text) + "': expected K/N with 1 <= K <= N (for example 2/8)");
    }
    return shard;
}

Grid::Grid(std::vector<Axis> axes) : axes_(std::move(axes)) {
    if (axes_.empty()) throw InputError("a sweep needs at least one axis (--board LIST, --set NAME=LIST, ...)");
    std::map<std::string, std::string> names;  // key -> the name it was first given as
    for (Axis& axis : axes_) {
        if (axis.key.empty()) {
            axis.key = axis.name;
            if (!is_setting_name(axis.name)) axis.flag = axis.name;
        }
        const auto [first, fresh] = names.emplace(axis.key, axis.name);
        if (!fresh) {
            throw InputError("--set " + excerpt(axis.name) + ": " +
                             (first->second == axis.name ? std::string("the axis is given twice")
                                                         : "the same setting as the axis " + excerpt(first->second)) +
                             "; give it once");
        }
        if (axis.values.empty()) throw InputError(excerpt(axis.name) + ": an axis without values");
    }
    check_grid_size(axes_);
    for (const Axis& axis : axes_) {
        size_ *= axis.values.size();
        fragments_.push_back(axis_fragments(axis.values));
    }
}

const Axis* Grid::find(const std::string& key) const {
    for (const Axis& axis : axes_) {
        if (axis.key == key) return &axis;
    }
    return nullptr;
}

Point Grid::point(std::size_t index) const {
    Point point;
    point.index = index;
    point.values.resize(axes_.size());
    std::vector<std::size_t> places(axes_.size());
    std::size_t rest = index;
    for (std::size_t a = axes_.size(); a-- > 0;) {
        places[a] = rest % axes_[a].values.size();
        point.values[a] = axes_[a].values[places[a]];
        rest /= axes_[a].values.size();
    }
    for (std::size_t a = 0; a < axes_.size(); ++a) {
        point.id += (a == 0 ? "" : "_") + sanitized(axes_[a].name, "_") + "-" + fragments_[a][places[a]];
    }
    if (point.id.size() > kMaxIdBytes) {
        const std::string suffix = "~p" + std::to_string(index);
        point.id = point.id.substr(0, kMaxIdBytes - suffix.size()) + suffix;
    }
    return point;
}

std::vector<std::string> Grid::run_arguments(const Point& point) const {
    std::vector<std::string> args;
    for (std::size_t a = 0; a < axes_.size(); ++a) {
        if (axes_[a].flag.empty()) {
            args.insert(args.end(), {"-c", axes_[a].key + "=" + point.values[a]});
        } else {
            args.push_back("--" + axes_[a].flag + "=" + point.values[a]);
        }
    }
    return args;
}

}  // namespace cdvp
