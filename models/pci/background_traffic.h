// Background masters on the host bus (plain C++): the traffic of other
// devices (a NIC, a disk controller) that shares the bus with the board and
// delays its transfers. Deterministic: the same load gives the same arrivals.
#pragma once

#include <cstdint>

#include "models/pci/bus_timing.h"

namespace cdvp {

// How a background master's bursts arrive: evenly spaced, or with seeded
// pseudo-random exponential gaps (a Poisson process of the same mean rate).
enum class LoadArrivals : uint8_t { kPeriodic, kRandom };

struct BusLoad {
    double bytes_per_s = 0.0;          // 0: an idle bus, no background master
    uint32_t burst_bytes = 512;        // bytes a background request moves
    Direction direction = Direction::kToHost;  // kToHost: it writes host memory (a NIC receiving)
    LoadArrivals arrivals = LoadArrivals::kPeriodic;
    uint64_t seed = 1;                 // of the random arrivals
    bool active() const { return bytes_per_s > 0.0; }
    double period_ns() const { return burst_bytes * 1e9 / bytes_per_s; }  // mean gap between bursts
    void validate() const;  // std::invalid_argument "bus.load_...: expected ..., got ..."
};

// The arrival times of a background master's bursts, in ns from time 0.
class ArrivalProcess {
public:
    explicit ArrivalProcess(const BusLoad& load);
    double next();  // the next burst's arrival time; +infinity when there is no load

private:
    double uniform();  // in (0, 1]
    BusLoad load_;
    double time_ = 0.0;
    uint64_t state_;
};

}  // namespace cdvp
