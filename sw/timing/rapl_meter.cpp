#include "sw/timing/rapl_meter.h"

#include <filesystem>
#include <fstream>
#include <optional>

namespace cdvp {

namespace {

// A counter file's one number, or nothing when it cannot be read.
std::optional<double> read_number(const std::string& path) {
    std::ifstream in(path);
    double value = 0;
    if (!(in >> value) || value < 0) return std::nullopt;
    return value;
}

}  // namespace

RaplMeter::RaplMeter(std::string root) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(root, ec)) {
        const std::string name = entry.path().filename().string();
        // A package domain: intel-rapl:N (its sub-domains are intel-rapl:N:M).
        if (name.rfind("intel-rapl:", 0) != 0 || name.find(':', 11) != std::string::npos) continue;
        const std::string dir = entry.path().string();
        const std::optional<double> energy = read_number(dir + "/energy_uj");
        const std::optional<double> range = read_number(dir + "/max_energy_range_uj");
        if (energy && range && *range > 0) packages_.push_back({dir + "/energy_uj", *range * 1e-6});
    }
}

double RaplMeter::joules() const {
    double sum = 0;
    for (const Package& p : packages_) sum += read_number(p.energy_path).value_or(0) * 1e-6;
    return sum;
}

double RaplMeter::joules_since(double start) const {
    double used = joules() - start;
    // One wrap at most between two readings a frame apart: a counter of
    // 2^32 uJ wraps after about an hour at full power.
    if (used < 0 && packages_.size() == 1) used += packages_.front().range_j;
    return used < 0 ? 0 : used;
}

}  // namespace cdvp
