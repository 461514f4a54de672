// What every generated scene draws its numbers with. Results must be
// bit-identical on every platform: only IEEE basic operations are used (no
// libm transcendental functions, whose last bit varies between C libraries)
// and the scene library is built without FMA contraction (CMakeLists.txt),
// which is why the arithmetic below lives in scene_random.cpp, not inline.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cdvp {

// xoshiro256** seeded through splitmix64, as its authors recommend.
class SceneRng {
public:
    explicit SceneRng(uint64_t seed) {
        for (uint64_t& word : s_) {
            seed += 0x9e3779b97f4a7c15ULL;
            uint64_t z = seed;
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            word = z ^ (z >> 31);
        }
    }

    uint64_t next() {
        uint64_t result = rotl(s_[1] * 5, 7) * 9;
        uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }

    // Uniform in [0, 1) with 53 random bits.
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    // Uniform in [lo, hi) (lo when lo == hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    // Uniform over 0 .. n-1 (n > 0), without modulo bias worth the name for n << 2^64.
    uint64_t below(uint64_t n) { return static_cast<uint64_t>(unit() * static_cast<double>(n)) % n; }

private:
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    uint64_t s_[4];
};

// Cube root of x > 0 by Newton's method from an exact exponent split, since
// std::cbrt is not correctly rounded everywhere.
double exact_cube_root(double x);

// Whether item k of a list is among the share f spread evenly over it:
// floor((k + 1) f) > floor(k f), so floor(N f) of N items are.
bool in_even_share(std::size_t k, double f);

// The largest centre coordinate keeping centre + half <= edge exactly,
// despite rounding (requires 2 * half <= edge).
double centre_limit(double edge, double half);

// One coordinate moved by v * dt and mirrored at the walls lo and hi (the
// velocity turned with it); the clamp covers a step longer than the free
// space (a tiny room, a huge step).
void bounce(double& x, double& v, double lo, double hi, double dt);

}  // namespace cdvp
