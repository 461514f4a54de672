#include "models/pci/background_traffic.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace cdvp {

void BusLoad::validate() const {
    auto fail = [](const char* what, double got) {
        std::ostringstream s;
        s << what << ", got " << got;
        throw std::invalid_argument(s.str());
    };
    if (!(bytes_per_s >= 0 && bytes_per_s <= 1e12)) fail("bus.load_bytes_per_s: expected 0 to 1e12", bytes_per_s);
    if (burst_bytes < 4 || burst_bytes > 65536) fail("bus.load_burst_bytes: expected 4 to 65536", burst_bytes);
}

ArrivalProcess::ArrivalProcess(const BusLoad& load) : load_(load), state_(load.seed * 0x9E3779B97F4A7C15ull + 1) {}

// splitmix64: small, fast and the same on every platform.
double ArrivalProcess::uniform() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (static_cast<double>(z >> 11) + 1.0) / 9007199254740992.0;
}

double ArrivalProcess::next() {
    if (!load_.active()) return std::numeric_limits<double>::infinity();
    const double period = load_.period_ns();
    const double gap = load_.arrivals == LoadArrivals::kPeriodic ? period : -std::log(uniform()) * period;
    const double at = time_;
    time_ += gap;
    return at;
}

}  // namespace cdvp
