// The seed's address generator for the all-pairs sweep.
#pragma once

#include "models/address_generator/port_window.h"

#include <cstdint>

namespace cdvp {

// Port 0 holds box i; ports 1..2m-1 hold j, j+1, ..., j+2m-2. In the first
// cycle of row i, j = i+1; each following cycle j advances by 2m-1 until a port
// has reached N-1; then i advances by one, until i = N-2. Ports whose address
// is past N-1 are invalid and their lanes are not evaluated.
// Row i takes ceil((N-1-i) / (2m-1)) cycles, so a sweep takes
// S(N,m) = sum_{r=1}^{N-1} ceil(r / (2m-1)) cycles.
class AddressGenerator {
public:
    explicit AddressGenerator(uint32_t m);

    uint32_t lanes() const { return lanes_; }

    // Starts a sweep over boxes 0..objects-1.
    void start(uint32_t objects);
    bool exhausted() const { return objects_ < 2 || row_ > objects_ - 2; }

    // The addresses driven this cycle; only while !exhausted().
    PortWindow current() const {  // valid_lanes >= 1
        const uint32_t remaining = objects_ - first_column_;
        return {row_, first_column_, remaining < lanes_ ? remaining : lanes_};
    }
    // The clock edge: move to the next cycle's addresses.
    void advance() {
        first_column_ += lanes_;
        if (first_column_ > objects_ - 1) {
            ++row_;
            first_column_ = row_ + 1;
        }
    }

    // S(N, m): cycles to sweep N boxes with 2m-1 lanes.
    static uint64_t sweep_cycles(uint64_t objects, uint32_t m);

private:
    uint32_t lanes_;
    uint32_t objects_ = 0;
    uint32_t row_ = 0;
    uint32_t first_column_ = 1;
};

}  // namespace cdvp
