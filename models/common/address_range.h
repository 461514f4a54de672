// Overflow-safe address decoding, shared by every TLM target of the platform:
// an access [address, address + length) lies inside [base, base + size) only
// if no part of it wraps around 2^64.
#pragma once

#include <cstdint>

namespace cdvp {

// True when the whole access lies inside the window. Never computes
// address + length, which can wrap for hostile addresses near 2^64.
constexpr bool range_within(uint64_t address, uint64_t length, uint64_t base, uint64_t size) {
    return address >= base && address - base <= size && length <= size - (address - base);
}

// True when the access starts inside the window (it may still run past its end).
constexpr bool starts_within(uint64_t address, uint64_t base, uint64_t size) {
    return address >= base && address - base < size;
}

static_assert(range_within(0, 16, 0, 16), "a full window fits");
static_assert(!range_within(0xFFFF'FFFF'FFFF'FFF0ull, 16, 0, 1u << 24), "a wrapping access does not");
static_assert(!range_within(8, 16, 0, 16), "an access running past the end does not");
static_assert(range_within(16, 0, 0, 16), "an empty access at the end does");

}  // namespace cdvp
