// What the run reports for every timed quantity over its frames: the mean,
// which a speedup compares because a simulation pays every frame's cost, and
// the 50th and 99th percentiles and the maximum, which real-time budgets ask
// about.
#pragma once

#include <cstddef>
#include <vector>

namespace cdvp {

// The p-quantile (0 <= p <= 1) of ascending 'sorted' samples, by linear
// interpolation between order statistics (Hyndman and Fan's type 7, the
// default of R and NumPy): with h = (n - 1) p, the value at index floor(h)
// plus (h - floor(h)) times the step to the next. The 0.5-quantile is the
// usual median (the mean of the middle two for an even count). 0 for no samples.
double quantile(const std::vector<double>& sorted, double p);

// The arithmetic mean, summed in the samples' order; 0 for none.
double mean_of(const std::vector<double>& samples);

// The geometric mean of positive values (0 for none): how times of different
// sizes, or factors of different baselines, combine so that each weighs the
// same whatever its magnitude.
double geometric_mean(const std::vector<double>& values);

struct Spread {
    double mean = 0;
    double p50 = 0;
    double p99 = 0;
    double max = 0;
    std::size_t count = 0;  // samples it rests on

    Spread scaled(double factor) const { return {mean * factor, p50 * factor, p99 * factor, max * factor, count}; }
};

// The mean, p50, p99 and maximum of samples in any order.
Spread spread_of(std::vector<double> samples);

// numerator / denominator when both are finite and the denominator is above
// 0, else 0: a ratio a summary or report shows, which may say "no figure"
// but never inf or nan.
double finite_ratio(double numerator, double denominator);

// The board's speedup over software whose frames cost 'software' (on the
// modelled host): the ratio of their mean frame times (finite_ratio).
double speedup(const Spread& software, const Spread& board);

}  // namespace cdvp
