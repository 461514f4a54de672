// A frame's pairs against the float32 reference, and what the extra ones cost:
// their share of the simulated readback phase, and the driver's unpacking of
// them (the host preset's ns per pair each), both already inside the frame's
// simulated time. Counted by FormatReference, reported in every frame and
// in the report's summary.
#pragma once

#include <cstdint>

namespace cdvp {

struct ExtraPairs {
    uint64_t reference_pairs = 0;
    uint64_t extra_pairs = 0;
    double extra_readback_ns = 0;
    double extra_driver_ns = 0;

    // Extra pairs as a share of the board's pairs (0 without pairs).
    double share() const {
        const uint64_t board = reference_pairs + extra_pairs;
        return board > 0 ? static_cast<double>(extra_pairs) / static_cast<double>(board) : 0.0;
    }
    ExtraPairs& operator+=(const ExtraPairs& other) {
        reference_pairs += other.reference_pairs;
        extra_pairs += other.extra_pairs;
        extra_readback_ns += other.extra_readback_ns;
        extra_driver_ns += other.extra_driver_ns;
        return *this;
    }
};

}  // namespace cdvp
