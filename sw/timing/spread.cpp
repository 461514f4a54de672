#include "sw/timing/spread.h"

#include <algorithm>
#include <cmath>

namespace cdvp {

double quantile(const std::vector<double>& sorted, double p) {
    if (sorted.empty()) return 0.0;
    const double h = static_cast<double>(sorted.size() - 1) * std::clamp(p, 0.0, 1.0);
    const std::size_t below = static_cast<std::size_t>(std::floor(h));
    if (below + 1 >= sorted.size()) return sorted.back();
    return sorted[below] + (h - static_cast<double>(below)) * (sorted[below + 1] - sorted[below]);
}

double mean_of(const std::vector<double>& samples) {
    if (samples.empty()) return 0.0;
    double sum = 0;
    for (const double value : samples) sum += value;
    return sum / static_cast<double>(samples.size());
}

double geometric_mean(const std::vector<double>& values) {
    if (values.empty()) return 0.0;
    double log_sum = 0;
    for (const double value : values) log_sum += std::log(value);
    return std::exp(log_sum / static_cast<double>(values.size()));
}

Spread spread_of(std::vector<double> samples) {
    const double mean = mean_of(samples);
    std::sort(samples.begin(), samples.end());
    return {mean, quantile(samples, 0.5), quantile(samples, 0.99), samples.empty() ? 0.0 : samples.back(),
            samples.size()};
}

double finite_ratio(double numerator, double denominator) {
    const double ratio = numerator / denominator;
    return std::isfinite(numerator) && denominator > 0 && std::isfinite(ratio) ? ratio : 0.0;
}

double speedup(const Spread& software, const Spread& board) { return finite_ratio(software.mean, board.mean); }

}  // namespace cdvp
