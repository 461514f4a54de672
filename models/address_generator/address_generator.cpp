#include "models/address_generator/address_generator.h"

#include <stdexcept>

namespace cdvp {

AddressGenerator::AddressGenerator(uint32_t m) : lanes_(2 * m - 1) {
    if (m == 0) throw std::invalid_argument("the address generator needs m >= 1");
}

void AddressGenerator::start(uint32_t objects) {
    objects_ = objects;
    row_ = 0;
    first_column_ = 1;
}

uint64_t AddressGenerator::sweep_cycles(uint64_t objects, uint32_t m) {
    // Closed form of sum_{r=1}^{N-1} ceil(r / w): full groups of w rows
    // contribute w*q each for q = 1..Q, and the last partial group R rows of Q+1.
    const uint64_t w = 2ull * m - 1;
    if (objects < 2) return 0;
    const uint64_t n = objects - 1;
    const uint64_t q = n / w;
    const uint64_t r = n % w;
    return w * q * (q + 1) / 2 + r * (q + 1);
}

}  // namespace cdvp
