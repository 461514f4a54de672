#include "sw/scene/scene_random.h"

#include <cmath>

namespace cdvp {

double exact_cube_root(double x) {
    int e = 0;
    double m = std::frexp(x, &e);  // x = m * 2^e, m in [0.5, 1), exact
    int r = ((e % 3) + 3) % 3;
    m = std::ldexp(m, r);          // m in [0.5, 4), e - r divisible by 3
    double y = 1.0;
    for (int i = 0; i < 8; ++i) {
        y = (2.0 * y + m / (y * y)) / 3.0;
    }
    return std::ldexp(y, (e - r) / 3);
}

bool in_even_share(std::size_t k, double f) {
    return std::floor(static_cast<double>(k + 1) * f) != std::floor(static_cast<double>(k) * f);
}

double centre_limit(double edge, double half) {
    double hi = edge - half;
    while (hi + half > edge) {
        hi = std::nextafter(hi, 0.0);
    }
    return hi;
}

void bounce(double& x, double& v, double lo, double hi, double dt) {
    x += v * dt;
    if (x < lo) {
        x = 2.0 * lo - x;
        v = -v;
    } else if (x > hi) {
        x = 2.0 * hi - x;
        v = -v;
    }
    x = x < lo ? lo : (hi < x ? hi : x);
}

}  // namespace cdvp
