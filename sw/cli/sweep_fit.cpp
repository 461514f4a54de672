#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "sw/cli/sweep_samples.h"

namespace cdvp::sweep_figures {

namespace {

// The extra pairs a number format adds, as a share of the float32
// reference's pairs; NaN when the report has no such figures.
double extra_share(const RowView& row) {
    const double extra = number(row, "median_extra_pairs");
    const double reference = number(row, "median_reference_pairs");
    if (std::isnan(extra) || std::isnan(reference)) return std::nan("");
    return reference > 0 ? extra / reference : 0.0;
}

// What fits at one (board, variant, N).
struct Fit {
    const Sample* any = nullptr;      // a point that ran there
    const Sample* at_best = nullptr;  // the point at the largest m, when the sweep ran it
    double largest_m = std::nan("");
};

}  // namespace

void add_fit_figures(const std::vector<Sample>& samples, const std::vector<std::string>& boards,
                     const std::vector<std::string>& variant_axes, FigurePlan& plan) {
    // board -> (variant order, N) -> fit
    std::map<std::string, std::map<std::pair<std::string, double>, Fit>> fits;
    for (const Sample& s : samples) {
        const double largest = number(s.row, "config.resources.largest_m");
        if (std::isnan(largest)) continue;
        Fit& fit = fits[s.board][{s.variant_order, s.n}];
        fit.any = &s;
        fit.largest_m = largest;
        if (s.m == largest) fit.at_best = &s;
    }
    if (fits.empty()) {
        plan.notes.push_back("no fit.csv: the points' reports have no config.resources.largest_m (no device family)");
        return;
    }
    std::string csv = "board,";
    for (const std::string& axis : variant_axes) csv += axis + ",";
    csv += "objects,largest_m,lanes,extra_pair_share,board_median_total_ns\n";
    for (const std::string& board : boards) {
        std::map<std::string, Line> largest_by_variant;
        // Lanes against extra pairs: one line per N, one point per variant.
        std::map<double, std::vector<std::pair<const Sample*, double>>> frontier;
        for (const auto& [key, fit] : fits[board]) {
            const Sample& s = *fit.any;
            const double lanes = fit.largest_m > 0 ? 2 * fit.largest_m - 1 : 0;
            const double share = extra_share(s.row);
            csv += board + ",";
            for (const std::string& v : s.variant_values) csv += v + ",";
            csv += num(s.n) + "," + num(fit.largest_m) + "," + num(lanes) + "," + (std::isnan(share) ? "" : num(share)) +
                   "," + (fit.at_best ? text(fit.at_best->row, "median_total_ns") : "") + "\n";
            Line& line = largest_by_variant[key.first];
            line.variant = s.variant;
            line.points.push_back({s.n, fit.largest_m});
            if (!std::isnan(share) && !s.variant.empty()) frontier[s.n].push_back({&s, lanes});
        }
        std::ostringstream gp, plots;
        std::size_t k = 0;
        for (const auto& [order, line] : largest_by_variant) {
            gp << datablock("f" + std::to_string(k), line.points);
            // Variants often share a line: dashes and point types keep each visible.
            plots << (k == 0 ? "" : ", ") << "$f" << k << " using 1:2 with linespoints lw 2 dt " << k % 5 + 1
                  << " pt " << k % 14 + 1 << " ps 1.5 title "
                  << quoted(line.variant.empty() ? board : line.variant);
            ++k;
        }
        gp << "set title " << quoted("largest m that fits " + board + " (fit.csv)")
           << "\nset xlabel 'N (objects)'\nset ylabel 'largest m (2m-1 lanes)'\nset logscale x\nset grid\n"
              "set key outside right\nplot "
           << plots.str() << "\n";
        plan.figures.push_back({"largest-m-" + file_part(board) + ".png", gp.str(), ""});
        if (frontier.empty()) continue;
        // The variants along x in grid order: lanes that fit (left axis, solid) and
        // extra pairs (right axis, dashed), one pair of lines per N; at most
        // kMostN values of N, spread from the smallest to the largest.
        constexpr std::size_t kMostN = 4;
        std::vector<double> drawn_n;
        for (const auto& [n, points] : frontier) drawn_n.push_back(n);
        if (drawn_n.size() > kMostN) {
            std::vector<double> spread;
            for (std::size_t i = 0; i < kMostN; ++i) spread.push_back(drawn_n[i * (drawn_n.size() - 1) / (kMostN - 1)]);
            plan.notes.push_back("lanes-extra-" + file_part(board) + ".png shows " + std::to_string(kMostN) + " of the " +
                                 std::to_string(drawn_n.size()) + " values of N (fit.csv has them all)");
            drawn_n = spread;
        }
        std::ostringstream fp, fplots;
        k = 0;
        for (const double n : drawn_n) {
            const auto& points = frontier[n];
            fp << "$x" << k << " << EOD\n";
            std::size_t place = 0;
            for (const auto& [s, lanes] : points) {
                std::string label;
                for (const std::string& v : s->variant_values) label += (label.empty() ? "" : "/") + v;
                fp << place++ << ' ' << num(lanes) << ' ' << num(100 * extra_share(s->row)) << " \"" << label << "\"\n";
            }
            fp << "EOD\n";
            fplots << (k == 0 ? "" : ", ") << "$x" << k << " using 1:2:xtic(4) with linespoints pt 7 lc " << k + 1
                   << " title " << quoted("lanes, N=" + num(n)) << ", $x" << k << " using 1:3 axes x1y2 with linespoints"
                   << " pt 6 dt 2 lc " << k + 1 << " title " << quoted("extra pairs, N=" + num(n));
            ++k;
        }
        fp << "set title " << quoted("lanes that fit " + board + " and the extra pairs of each variant (fit.csv)")
           << "\nset ylabel 'lanes (2m-1) that fit'\nset y2label 'extra pairs (% of the float32 reference)'\n"
              "set ytics nomirror\nset y2tics\nset yrange [0:*]\nset y2range [0:*]\nset offsets 0.3, 0.3, 0, 0\n"
              "set grid\nset key outside right\nplot "
           << fplots.str() << "\n";
        plan.figures.push_back({"lanes-extra-" + file_part(board) + ".png", fp.str(), ""});
    }
    plan.figures.push_back({"fit.csv", "", csv});
}

}  // namespace cdvp::sweep_figures
