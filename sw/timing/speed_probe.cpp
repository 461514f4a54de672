#include "sw/timing/speed_probe.h"

#include <algorithm>
#include <numeric>

#include "sw/timing/spread.h"
#include "sw/timing/thread_timer.h"

namespace cdvp {

namespace {

// Within a core's L1 data cache, and run through once before it is timed:
// the probe must not depend on what the call before it left in the caches.
constexpr std::size_t kChaseBytes = 16 * 1024;
constexpr int kChainSteps = 600;  // about 1.2 us at 3 GHz
constexpr int kChaseSteps = 400;  // about 0.6 us of L1 hits

}  // namespace

SpeedProbe::SpeedProbe() : next_(kChaseBytes / sizeof(uint32_t)) {
    // One cycle through every slot in a fixed pseudo-random order (Sattolo's
    // shuffle), so that each step waits on the last and no prefetcher helps.
    std::vector<uint32_t> order(next_.size());
    std::iota(order.begin(), order.end(), 0u);
    uint64_t x = 88172645463325252ull;
    for (std::size_t k = order.size() - 1; k > 0; --k) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        std::swap(order[k], order[x % k]);
    }
    for (std::size_t k = 0; k < order.size(); ++k) next_[order[k]] = order[(k + 1) % order.size()];
}

// The work once untimed, to warm the caches, branch predictors and clock
// reads the call before it cooled, then once timed. Both passes chase the
// same slots: a timed pass that went on along the cycle would meet lines the
// warm pass never touched, cold after a call that evicted L1 (a Bullet step
// of 3,000 bodies does), and every probe after such a call would read slow.
double SpeedProbe::time_ns() {
    double ns = 0;
    const uint32_t first = at_;
    for (int pass = 0; pass < 2; ++pass) {
        const int64_t start = thread_cpu_ns();
        uint64_t x = state_;
        for (int k = 0; k < kChainSteps; ++k) x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        uint32_t at = first;
        for (int k = 0; k < kChaseSteps; ++k) at = next_[at];
        const int64_t end = thread_cpu_ns();
        // Kept, so that neither loop is optimised away.
        state_ = x | 1;
        at_ = at;
        ns = static_cast<double>(end - start);
    }
    return ns;
}

double fast_probe_ns(std::vector<double> probes) {
    std::sort(probes.begin(), probes.end());
    return quantile(probes, 0.1);
}

}  // namespace cdvp
