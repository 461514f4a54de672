#include "platform/board_preset.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/scene/scene.h"

namespace cdvp {

namespace {

using nlohmann::json;

// Reads {"value": number, "source": "..."} fields, naming the file on error.
class PresetReader {
public:
    PresetReader(std::string path, json root) : path_(std::move(path)), root_(std::move(root)) {}

    double number(const char* section, const char* key) const {
        const json* field = find(section, key);
        if (field == nullptr || !field->is_object() || !field->contains("value") || !(*field)["value"].is_number() ||
            !field->contains("source") || !(*field)["source"].is_string() ||
            (*field)["source"].get<std::string>().empty()) {
            fail(std::string(section) + "." + key + ": expected {\"value\": <number>, \"source\": \"<source or assumption>\"}");
        }
        return (*field)["value"].get<double>();
    }
    uint32_t count(const char* section, const char* key) const {
        const double v = number(section, key);
        if (v < 0 || v > 4294967295.0 || v != static_cast<uint32_t>(v)) {
            fail(std::string(section) + "." + key + ": expected a non-negative integer");
        }
        return static_cast<uint32_t>(v);
    }
    std::string text(const char* section, const char* key) const {
        const json* field = find(section, key);
        if (field == nullptr || !field->is_string()) fail(std::string(section) + "." + key + ": expected a string");
        return field->get<std::string>();
    }
    [[noreturn]] void fail(const std::string& what) const { throw InputError(path_ + ": " + what); }

private:
    const json* find(const char* section, const char* key) const {
        const json* s = section[0] ? (root_.contains(section) ? &root_[section] : nullptr) : &root_;
        return s != nullptr && s->is_object() && s->contains(key) ? &(*s)[key] : nullptr;
    }
    std::string path_;
    json root_;
};

// A bus config's fields by their names in the preset's "bus" section.
template <class Config>
struct BusFields {
    std::vector<std::pair<const char*, uint32_t Config::*>> counts;
    std::vector<std::pair<const char*, double Config::*>> numbers;
};

template <class Timing, class Config>
std::shared_ptr<const BusTiming> read_bus_fields(const PresetReader& r, const BusFields<Config>& fields) {
    Config c;
    for (const auto& [key, member] : fields.counts) c.*member = r.count("bus", key);
    for (const auto& [key, member] : fields.numbers) c.*member = r.number("bus", key);
    c.local_bus = {r.count("bus", "local_bus_width_bits"), r.number("bus", "local_bus_clock_mhz")};
    try {
        return std::make_shared<Timing>(c);
    } catch (const std::invalid_argument& e) {
        r.fail(e.what());
    }
}

std::shared_ptr<const BusTiming> read_bus(const PresetReader& r) {
    const std::string type = r.text("bus", "type");
    if (type == "pci") {
        using C = PciConfig;
        static const BusFields<C> kFields{
            {{"width_bits", &C::width_bits},
             {"arbitration_clocks", &C::arbitration_clocks},
             {"address_phase_clocks", &C::address_phase_clocks},
             {"board_read_latency_clocks", &C::board_read_latency_clocks},
             {"board_write_latency_clocks", &C::board_write_latency_clocks},
             {"host_read_latency_clocks", &C::host_read_latency_clocks},
             {"host_write_latency_clocks", &C::host_write_latency_clocks},
             {"wait_states", &C::wait_states},
             {"turnaround_clocks", &C::turnaround_clocks},
             {"latency_timer_clocks", &C::latency_timer_clocks},
             {"dma_read_burst_bytes", &C::dma_read_burst_bytes},
             {"dma_write_burst_bytes", &C::dma_write_burst_bytes}},
            {{"clock_mhz", &C::clock_mhz}, {"host_pio_overhead_ns", &C::host_pio_overhead_ns},
             {"interrupt_ns", &C::interrupt_ns}}};
        return read_bus_fields<PciTiming>(r, kFields);
    }
    if (type == "pcie") {
        using C = PcieConfig;
        static const BusFields<C> kFields{
            {{"lanes", &C::lanes},
             {"max_payload_bytes", &C::max_payload_bytes},
             {"max_read_request_bytes", &C::max_read_request_bytes},
             {"tlp_overhead_bytes", &C::tlp_overhead_bytes}},
            {{"gigatransfers_per_s", &C::gigatransfers_per_s}, {"encoding_efficiency", &C::encoding_efficiency},
             {"read_round_trip_ns", &C::read_round_trip_ns}, {"posted_write_ns", &C::posted_write_ns},
             {"interrupt_ns", &C::interrupt_ns}}};
        return read_bus_fields<PcieTiming>(r, kFields);
    }
    r.fail("bus.type: expected \"pci\" or \"pcie\", found \"" + type + "\"");
}

}  // namespace

std::string boards_directory() {
    const char* env = std::getenv("CDVP_BOARDS");
    return env != nullptr && env[0] != '\0' ? env : CDVP_BOARDS_DIR;
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

namespace {

bool names_a_path(const std::string& name) {
    return name.find('/') != std::string::npos || (name.size() > 5 && name.rfind(".json") == name.size() - 5);
}

}  // namespace

std::string board_preset_path(const std::string& name) {
    return names_a_path(name) ? name : boards_directory() + "/" + name + ".json";
}

BoardPreset load_board_preset(const std::string& name) {
    const bool is_path = names_a_path(name);
    const std::string path = board_preset_path(name);
    std::ifstream in(path);
    if (!in) {
        std::string known;
        for (const std::string& n : board_preset_names()) known += (known.empty() ? "" : ", ") + n;
        throw InputError(is_path ? path + ": cannot open" : "--board: unknown board '" + name + "'; expected one of: " + known);
    }
    json root;
    try {
        root = json::parse(in);
    } catch (const json::parse_error& e) {
        throw InputError(path + ": invalid JSON (" + e.what() + ")");
    }
    const PresetReader r(path, root);
    BoardPreset p;
    p.path = path;
    p.name = r.text("", "name");
    p.description = r.text("", "description");
    p.board.clock_mhz = r.number("board", "clock_mhz");
    p.board.compare.latency_cycles = r.count("board", "compare_latency_cycles");
    p.board.collector.fifo_depth = r.count("board", "fifo_depth");
    p.board.collector.drain_per_cycle = r.count("board", "drain_per_cycle");
    p.board.collector.buffer_depth = r.count("board", "pair_buffer_depth");
    p.block_rams = r.count("board", "block_rams");
    p.bus = read_bus(r);
    p.host.name = r.text("host", "name");
    p.host.speed_factor = r.number("host", "speed_factor");
    if (!(p.host.speed_factor > 0)) r.fail("host.speed_factor: expected a positive number");
    p.driver.ns_per_box = r.number("host", "ns_per_box");
    p.driver.ns_per_pair = r.number("host", "ns_per_pair");
    p.driver.call_ns = r.number("host", "call_ns");
    return p;
}

}  // namespace cdvp
