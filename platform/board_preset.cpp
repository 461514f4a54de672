#include "platform/board_preset.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/control_registers/control_registers.h"
#include "platform/preset_json.h"
#include "models/common/user_text.h"

namespace cdvp {

namespace {

using nlohmann::json;

// A preset is a small hand-written file; anything bigger is not one.
constexpr std::size_t kMaxPresetBytes = 1 << 20;

// One numeric key of a section: its unit and the range it must lie in.
// Ranges are what the modelled hardware can be, with margin, and keep a
// frame's simulated time far from SystemC's 64-bit femtosecond limit.
struct NumberSpec {
    const char* key;
    const char* unit;
    double min;
    double max;
    bool integer;
};

constexpr NumberSpec kBoardNumbers[] = {
    {"clock_mhz", "MHz", 1, 1000, false},
    {"compare_latency_cycles", "cycles", 0, 64, true},
    {"fifo_depth", "pairs", 1, 1 << 20, true},
    {"drain_per_cycle", "pairs a cycle", 1, 64, true},
    {"pair_buffer_depth", "pairs", 1, address_map::kMaxBufferedPairs, true},
    {"block_rams", "block RAMs", 1, 100000, true},
};
constexpr NumberSpec kHostNumbers[] = {
    {"speed_factor", "x", 0.001, 1000, false},
    {"ns_per_box", "ns", 0, 1e6, false},
    {"ns_per_pair", "ns", 0, 1e6, false},
    {"call_ns", "ns", 0, 1e6, false},
};
constexpr NumberSpec kLocalBusNumbers[] = {
    {"local_bus_width_bits", "bits", 8, 1024, true},
    {"local_bus_clock_mhz", "MHz", 1, 1000, false},
};

template <std::size_t N>
const NumberSpec& spec_of(const NumberSpec (&table)[N], const char* key) {
    for (const NumberSpec& spec : table) {
        if (std::strcmp(spec.key, key) == 0) return spec;
    }
    throw std::logic_error(std::string("no preset key ") + key);
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string nearest(const std::string& key, const std::vector<std::string>& valid) {
    return *std::min_element(valid.begin(), valid.end(), [&](const std::string& x, const std::string& y) {
        return edit_distance(key, x) < edit_distance(key, y);
    });
}

// Whole numbers in full (1048576, not 1.04858e+06); others as %g.
std::string show(double value) {
    if (value == static_cast<double>(static_cast<int64_t>(value)) && std::abs(value) < 1e15) {
        return std::to_string(static_cast<int64_t>(value));
    }
    std::ostringstream text;
    text << value;
    return text.str();
}

// Reads a preset's sections, each declared with its keys: a key that is
// not declared is refused with the nearest declared one; every number is
// a {"value": number, "source": "..."} field within its spec's range.
// Every error names the file and the key.
class PresetReader {
public:
    PresetReader(std::string path, json root) : path_(std::move(path)), root_(std::move(root)) {}

    // Refuses keys of 'section' ("" for the top level) outside 'keys'.
    void only(const std::string& section, const std::vector<std::string>& keys) const {
        const json& object = section.empty() ? root_ : this->section(section);
        for (const auto& [key, value] : object.items()) {
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
                fail(qualified(section, excerpt(key)) + ": unknown key; did you mean '" + nearest(key, keys) + "'?");
            }
        }
    }
    double number(const std::string& section, const NumberSpec& spec) const {
        const std::string name = qualified(section, spec.key);
        const json* field = find(section, spec.key);
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
        const double v = value->get<double>();
        const std::string unit = std::string(" ") + spec.unit;
        if (!(v >= spec.min && v <= spec.max)) {
            fail(name + ": expected " + show(spec.min) + " to " + show(spec.max) + unit + ", got " + value->dump());
        }
        if (spec.integer && v != static_cast<double>(static_cast<uint64_t>(v))) {
            fail(name + ": expected a whole number of" + unit + ", got " + value->dump());
        }
        return v;
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

std::vector<std::string> keys_of(const NumberSpec* begin, const NumberSpec* end, std::vector<std::string> more = {}) {
    for (const NumberSpec* s = begin; s != end; ++s) more.emplace_back(s->key);
    return more;
}

// A bus config's fields by their keys in the preset's "bus" section.
template <class Config>
struct BusField {
    NumberSpec spec;
    uint32_t Config::*count;  // one of the two is set
    double Config::*number;
};

template <class Config>
BusField<Config> count_field(NumberSpec spec, uint32_t Config::*member) {
    return {spec, member, nullptr};
}
template <class Config>
BusField<Config> number_field(NumberSpec spec, double Config::*member) {
    return {spec, nullptr, member};
}

template <class Timing, class Config>
std::shared_ptr<const BusTiming> read_bus_fields(const PresetReader& r, const std::vector<BusField<Config>>& fields) {
    std::vector<std::string> keys = keys_of(std::begin(kLocalBusNumbers), std::end(kLocalBusNumbers), {"type"});
    for (const auto& field : fields) keys.emplace_back(field.spec.key);
    r.only("bus", keys);
    Config c;
    for (const auto& field : fields) {
        const double value = r.number("bus", field.spec);
        if (field.count != nullptr) c.*field.count = static_cast<uint32_t>(value);
        if (field.number != nullptr) c.*field.number = value;
    }
    c.local_bus = {static_cast<uint32_t>(r.number("bus", spec_of(kLocalBusNumbers, "local_bus_width_bits"))),
                   r.number("bus", spec_of(kLocalBusNumbers, "local_bus_clock_mhz"))};
    try {
        return std::make_shared<Timing>(c);
    } catch (const std::invalid_argument& e) {
        // The model names its settings "pci.KEY" or "pcie.KEY"; here they are "bus.KEY".
        std::string message = e.what();
        for (const char* prefix : {"pci.", "pcie.", "local_bus:"}) {
            if (message.rfind(prefix, 0) == 0) {
                message = (std::strcmp(prefix, "local_bus:") == 0 ? "bus.local_bus_*:" : "bus.") +
                          message.substr(std::strlen(prefix));
                break;
            }
        }
        r.fail(message);
    }
}

std::shared_ptr<const BusTiming> read_bus(const PresetReader& r) {
    const std::string type = r.text("bus", "type");
    if (type == "pci") {
        using C = PciConfig;
        static const std::vector<BusField<C>> kFields = {
            count_field<C>({"width_bits", "bits", 32, 64, true}, &C::width_bits),
            number_field<C>({"clock_mhz", "MHz", 1, 133, false}, &C::clock_mhz),
            count_field<C>({"arbitration_clocks", "clocks", 0, 255, true}, &C::arbitration_clocks),
            count_field<C>({"address_phase_clocks", "clocks", 1, 2, true}, &C::address_phase_clocks),
            count_field<C>({"board_read_latency_clocks", "clocks", 0, 16, true}, &C::board_read_latency_clocks),
            count_field<C>({"board_write_latency_clocks", "clocks", 0, 16, true}, &C::board_write_latency_clocks),
            count_field<C>({"host_read_latency_clocks", "clocks", 0, 16, true}, &C::host_read_latency_clocks),
            count_field<C>({"host_write_latency_clocks", "clocks", 0, 16, true}, &C::host_write_latency_clocks),
            count_field<C>({"wait_states", "clocks", 0, 8, true}, &C::wait_states),
            count_field<C>({"turnaround_clocks", "clocks", 0, 8, true}, &C::turnaround_clocks),
            count_field<C>({"latency_timer_clocks", "clocks", 0, 255, true}, &C::latency_timer_clocks),
            count_field<C>({"dma_read_burst_bytes", "bytes", 4, 4096, true}, &C::dma_read_burst_bytes),
            count_field<C>({"dma_write_burst_bytes", "bytes", 4, 4096, true}, &C::dma_write_burst_bytes),
            number_field<C>({"host_pio_overhead_ns", "ns", 0, 1e6, false}, &C::host_pio_overhead_ns),
            number_field<C>({"interrupt_ns", "ns", 0, 1e6, false}, &C::interrupt_ns),
        };
        return read_bus_fields<PciTiming>(r, kFields);
    }
    if (type == "pcie") {
        using C = PcieConfig;
        static const std::vector<BusField<C>> kFields = {
            number_field<C>({"gigatransfers_per_s", "GT/s", 1, 64, false}, &C::gigatransfers_per_s),
            count_field<C>({"lanes", "lanes", 1, 32, true}, &C::lanes),
            number_field<C>({"encoding_efficiency", "(fraction)", 0.5, 1, false}, &C::encoding_efficiency),
            count_field<C>({"max_payload_bytes", "bytes", 128, 4096, true}, &C::max_payload_bytes),
            count_field<C>({"max_read_request_bytes", "bytes", 128, 4096, true}, &C::max_read_request_bytes),
            count_field<C>({"tlp_overhead_bytes", "bytes", 0, 256, true}, &C::tlp_overhead_bytes),
            number_field<C>({"read_round_trip_ns", "ns", 0, 1e6, false}, &C::read_round_trip_ns),
            number_field<C>({"posted_write_ns", "ns", 0, 1e6, false}, &C::posted_write_ns),
            number_field<C>({"interrupt_ns", "ns", 0, 1e6, false}, &C::interrupt_ns),
        };
        return read_bus_fields<PcieTiming>(r, kFields);
    }
    r.fail("bus.type: expected \"pci\" or \"pcie\", got \"" + excerpt(type) + "\"");
}

std::string read_preset_text(const std::string& path, bool is_path, const std::string& name) {
    struct stat status {};
    if (stat(path.c_str(), &status) != 0) {
        if (is_path) throw InputError(path + ": cannot open: " + std::strerror(errno));
        std::string known;
        for (const std::string& n : board_preset_names()) known += (known.empty() ? "" : ", ") + n;
        throw InputError("--board: unknown board '" + excerpt(name) + "'; expected one of: " + known);
    }
    if (!S_ISREG(status.st_mode)) throw InputError(path + ": cannot open: not a regular file");
    if (static_cast<std::size_t>(status.st_size) > kMaxPresetBytes) {
        throw InputError(path + ": larger than " + std::to_string(kMaxPresetBytes) + " bytes; not a board preset");
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw InputError(path + ": cannot read: " + std::strerror(errno));
    return text.str();
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
    std::error_code ec;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::filesystem::path installed = executable.parent_path() / CDVP_INSTALLED_BOARDS_DIR;
        if (std::filesystem::is_directory(installed, ec)) return installed.lexically_normal().string();
    }
    return CDVP_BOARDS_DIR;
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

BoardPreset read_board_preset(const std::string& name) {
    const std::string path = board_preset_path(name);
    const PresetReader r(path, parse_preset(path, read_preset_text(path, names_a_path(name), name)));
    r.only("", {"name", "description", "board", "bus", "host"});
    r.only("board", keys_of(std::begin(kBoardNumbers), std::end(kBoardNumbers)));
    r.only("host", keys_of(std::begin(kHostNumbers), std::end(kHostNumbers), {"name"}));
    BoardPreset p;
    p.path = path;
    p.name = r.text("", "name");
    p.description = r.text("", "description");
    const auto board = [&](const char* key) { return r.number("board", spec_of(kBoardNumbers, key)); };
    const auto board_count = [&](const char* key) { return static_cast<uint32_t>(board(key)); };
    p.board.clock_mhz = board("clock_mhz");
    p.board.compare.latency_cycles = board_count("compare_latency_cycles");
    p.board.collector.fifo_depth = board_count("fifo_depth");
    p.board.collector.drain_per_cycle = board_count("drain_per_cycle");
    p.board.collector.buffer_depth = board_count("pair_buffer_depth");
    p.block_rams = board_count("block_rams");
    p.bus = read_bus(r);
    p.host.name = r.text("host", "name");
    const auto host = [&](const char* key) { return r.number("host", spec_of(kHostNumbers, key)); };
    p.host.speed_factor = host("speed_factor");
    p.driver.ns_per_box = host("ns_per_box");
    p.driver.ns_per_pair = host("ns_per_pair");
    p.driver.call_ns = host("call_ns");
    return p;
}

}  // namespace

BoardPreset load_board_preset(const std::string& name) {
    try {
        return read_board_preset(name);
    } catch (const InputError& e) {
        // One line whatever the file holds: keys, strings and paths may hold control characters.
        throw InputError(printable(e.what()));
    }
}

}  // namespace cdvp
