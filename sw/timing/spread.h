// Order statistics of measured samples: the median and the 10th and 90th
// percentiles that the run reports for every timed quantity.
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

struct Spread {
    double median = 0;
    double p10 = 0;
    double p90 = 0;
    std::size_t count = 0;  // samples it rests on

    Spread scaled(double factor) const { return {median * factor, p10 * factor, p90 * factor, count}; }
};

// The median, p10 and p90 of samples in any order.
Spread spread_of(std::vector<double> samples);

}  // namespace cdvp
