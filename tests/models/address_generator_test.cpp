#include "models/address_generator/address_generator.h"

#include <gtest/gtest.h>

#include <vector>

namespace cdvp {
namespace {

uint64_t sweep_cycles_by_sum(uint64_t n, uint32_t m) {
    uint64_t s = 0;
    for (uint64_t r = 1; r + 1 <= n; ++r) s += (r + 2 * m - 2) / (2 * m - 1);
    return s;
}

// Every pair i < j exactly once, nothing past N-1, and S(N,m) cycles.
TEST(AddressGenerator, EveryPairExactlyOnceInSweepCycles) {
    for (uint32_t m = 1; m <= 9; ++m) {
        for (uint32_t n = 0; n <= 80; ++n) {
            AddressGenerator ag(m);
            ag.start(n);
            std::vector<int> seen(static_cast<size_t>(n) * n, 0);
            uint64_t cycles = 0;
            while (!ag.exhausted()) {
                const PortWindow is = ag.current();
                ASSERT_GE(is.valid_lanes, 1u);
                ASSERT_LE(is.valid_lanes, ag.lanes());
                ASSERT_LT(is.row, is.first_column);
                ASSERT_LE(is.first_column + is.valid_lanes - 1, n - 1) << "valid lane past N-1";
                // Lanes are invalid exactly when their address is past N-1.
                if (is.valid_lanes < ag.lanes()) {
                    ASSERT_EQ(is.first_column + is.valid_lanes, n);
                }
                for (uint32_t k = 0; k < is.valid_lanes; ++k) ++seen[is.row * n + is.first_column + k];
                ag.advance();
                ++cycles;
                ASSERT_LE(cycles, uint64_t{n} * n) << "runaway sweep";
            }
            for (uint32_t i = 0; i < n; ++i) {
                for (uint32_t j = 0; j < n; ++j) {
                    ASSERT_EQ(seen[i * n + j], i < j ? 1 : 0) << "pair " << i << "," << j << " n=" << n << " m=" << m;
                }
            }
            EXPECT_EQ(cycles, sweep_cycles_by_sum(n, m)) << "n=" << n << " m=" << m;
            EXPECT_EQ(cycles, AddressGenerator::sweep_cycles(n, m)) << "n=" << n << " m=" << m;
        }
    }
}

// The seed's scheme literally: first cycle of a row holds i+1..i+2m-1, then +2m-1.
TEST(AddressGenerator, FollowsTheSeedScheme) {
    AddressGenerator ag(2);  // 3 lanes
    ag.start(6);
    const std::vector<std::pair<uint32_t, uint32_t>> expected = {
        {0, 1}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {3, 4}, {4, 5}};
    for (const auto& [row, first] : expected) {
        ASSERT_FALSE(ag.exhausted());
        EXPECT_EQ(ag.current().row, row);
        EXPECT_EQ(ag.current().first_column, first);
        ag.advance();
    }
    EXPECT_TRUE(ag.exhausted());
}

TEST(AddressGenerator, NoWorkForZeroOrOneObject) {
    for (uint32_t n : {0u, 1u}) {
        AddressGenerator ag(4);
        ag.start(n);
        EXPECT_TRUE(ag.exhausted());
        EXPECT_EQ(AddressGenerator::sweep_cycles(n, 4), 0u);
    }
}

TEST(AddressGenerator, ClosedFormMatchesSumForLargeN) {
    for (uint32_t m : {1u, 4u, 8u, 24u, 32u}) {
        for (uint64_t n : {500ull, 2000ull, 4097ull, 100000ull}) {
            EXPECT_EQ(AddressGenerator::sweep_cycles(n, m), sweep_cycles_by_sum(n, m)) << n << " " << m;
        }
    }
    EXPECT_EQ(AddressGenerator::sweep_cycles(500, 1), 124750u);  // N(N-1)/2 with one lane
}

TEST(AddressGenerator, RejectsZeroParallelism) { EXPECT_THROW(AddressGenerator(0), std::invalid_argument); }

}  // namespace
}  // namespace cdvp
