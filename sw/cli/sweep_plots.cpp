#include "sw/cli/sweep_plots.h"

#include "sw/cli/sweep_samples.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace cdvp {

namespace sweep_figures {

std::string Line::title() const {
    const std::string m_part = "m=" + num(m);
    return variant.empty() ? m_part : m_part + " " + variant;
}

Series series(const std::vector<Sample>& samples, const std::string& board, const std::string& column, double scale) {
    Series lines;
    for (const Sample& s : samples) {
        const double y = number(s.row, column);
        if (s.board != board || std::isnan(y)) continue;
        Line& line = lines[{s.variant_order, s.m}];
        line.m = s.m;
        line.variant = s.variant;
        line.points.push_back({s.n, y * scale});
    }
    for (auto& [key, line] : lines) std::sort(line.points.begin(), line.points.end());
    return lines;
}

double number(const RowView& row, const std::string& column) {
    const std::string value = row.get(column);
    return value.empty() ? std::nan("") : std::strtod(value.c_str(), nullptr);
}

std::string text(const RowView& row, const std::string& column) { return row.get(column); }

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
    return q + "'";
}

std::string file_part(std::string s) {
    for (char& c : s) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+') c = '-';
    }
    return s;
}

std::string num(double v) {
    char t[40];
    std::snprintf(t, sizeof t, "%.10g", v);
    return t;
}

std::string datablock(const std::string& name, const std::vector<std::pair<double, double>>& points) {
    std::string block = "$" + name + " << EOD\n";
    for (const auto& [x, y] : points) block += num(x) + " " + num(y) + "\n";
    return block + "EOD\n";
}

}  // namespace sweep_figures

namespace {

using namespace sweep_figures;

std::string line_plot(const std::string& title, const std::string& ylabel, const Series& lines,
                      const std::string& extra_blocks, const std::string& extra_plots) {
    std::ostringstream gp;
    std::vector<std::string> plots;
    // A colour per m and a dash and point type per variant, so that lines stay
    // apart when there are more of them than colours.
    std::vector<double> ms;
    std::vector<std::string> variants;
    for (const auto& [key, line] : lines) {
        if (std::find(ms.begin(), ms.end(), line.m) == ms.end()) ms.push_back(line.m);
        if (std::find(variants.begin(), variants.end(), line.variant) == variants.end()) variants.push_back(line.variant);
    }
    std::sort(ms.begin(), ms.end());
    static const int kPointTypes[] = {7, 5, 9, 11, 13, 15};
    std::size_t k = 0;
    for (const auto& [key, line] : lines) {
        const auto colour = std::find(ms.begin(), ms.end(), line.m) - ms.begin();
        const auto variant = std::find(variants.begin(), variants.end(), line.variant) - variants.begin();
        gp << datablock("m" + std::to_string(k), line.points);
        plots.push_back("$m" + std::to_string(k++) + " using 1:2 with linespoints lc " + std::to_string(colour + 1) +
                        " dt " + std::to_string(variant % 5 + 1) + " pt " + std::to_string(kPointTypes[variant % 6]) +
                        " title " + quoted(line.title()));
    }
    gp << extra_blocks << "set title " << quoted(title) << "\nset xlabel 'N (objects)'\nset ylabel " << quoted(ylabel)
       << "\nset logscale x\nset logscale y\nset grid\nset key outside right\nplot ";
    for (std::size_t p = 0; p < plots.size(); ++p) gp << (p == 0 ? "" : ", ") << plots[p];
    gp << extra_plots << "\n";
    return gp.str();
}

// The smallest N at which the board wins, and how it was found.
struct Crossover {
    double n = 0;
    const char* how = "none";  // interpolated, measured (the smallest N already wins), none
};
Crossover crossover(const std::vector<std::pair<double, double>>& speedups) {
    for (std::size_t k = 0; k < speedups.size(); ++k) {
        const auto [n1, s1] = speedups[k];
        if (s1 < 1) continue;
        if (k == 0) return {n1, "measured"};
        const auto [n0, s0] = speedups[k - 1];
        const double t = (1 - s0) / (s1 - s0);
        return {std::exp(std::log(n0) + t * (std::log(n1) - std::log(n0))), "interpolated"};
    }
    return {};
}

void add_crossovers(const std::vector<Sample>& samples, const std::vector<std::string>& boards,
                    const std::vector<std::string>& variant_axes, const std::vector<std::string>& baselines,
                    FigurePlan& plan) {
    std::string csv = "board,m,";
    for (const std::string& axis : variant_axes) csv += axis + ",";
    csv += "baseline,crossover_n,how\n";
    for (const std::string& baseline : baselines) {
        std::ostringstream blocks, plots;
        std::size_t drawn = 0;
        for (const std::string& board : boards) {
            // One line per variant: crossover N against m.
            std::map<std::string, Line> by_variant;
            for (const auto& [key, line] : series(samples, board, baseline + "_speedup", 1)) {
                const Crossover c = crossover(line.points);
                std::string values;
                for (const Sample& s : samples) {
                    if (s.board == board && s.variant == line.variant) {
                        for (const std::string& v : s.variant_values) values += v + ",";
                        break;
                    }
                }
                csv += board + "," + num(line.m) + "," + values + baseline + "," + (c.n > 0 ? num(c.n) : "") + "," +
                       c.how + "\n";
                Line& variant_line = by_variant[key.first];
                variant_line.variant = line.variant;
                if (c.n > 0) variant_line.points.push_back({line.m, c.n});
            }
            for (const auto& [order, line] : by_variant) {
                if (line.points.empty()) continue;
                blocks << datablock("c" + std::to_string(drawn), line.points);
                plots << (drawn == 0 ? "" : ", ") << "$c" << drawn << " using 1:2 with linespoints pt 7 title "
                      << quoted(line.variant.empty() ? board : board + " " + line.variant);
                ++drawn;
            }
        }
        if (drawn == 0) {
            plan.notes.push_back("no crossover plot against " + baseline + ": the board beats it at no N of the sweep");
            continue;
        }
        plan.figures.push_back({"crossover-" + file_part(baseline) + ".png",
                                blocks.str() + "set title " + quoted("crossover N against " + baseline +
                                                                     " (interpolated in log N; crossover.csv)") +
                                    "\nset xlabel 'm'\nset ylabel 'N where the board starts to win'\nset logscale y\n"
                                    "set grid\nset key outside right\nset offsets 0.5, 0.5, 0, 0\nplot " + plots.str() + "\n",
                                ""});
    }
    plan.figures.push_back({"crossover.csv", "", csv});
}

Figure phase_bars(const std::vector<Sample>& samples, const std::string& board, const std::vector<std::string>& phases) {
    std::vector<const Sample*> bars;
    for (const Sample& s : samples) {
        if (s.board == board) bars.push_back(&s);
    }
    std::stable_sort(bars.begin(), bars.end(), [](const Sample* a, const Sample* b) {
        return a->m != b->m ? a->m < b->m : a->n < b->n;
    });
    std::ostringstream gp;
    gp << "$p << EOD\npoint";
    for (const std::string& phase : phases) gp << ' ' << phase.substr(7, phase.size() - 10);  // median_X_ns -> X
    gp << '\n';
    for (const Sample* s : bars) {
        gp << "N=" << num(s->n) << ",m=" << num(s->m);
        for (const std::string& phase : phases) gp << ' ' << num(number(s->row, phase) / 1e3);
        gp << '\n';
    }
    gp << "EOD\nset title " << quoted("median frame time by phase on " + board)
       << "\nset ylabel 'us per frame'\nset style data histograms\nset style histogram rowstacked\n"
          "set style fill solid 0.8 border -1\nset boxwidth 0.8\nset xtics rotate by -60 font ',8'\nset grid y\n"
          "set key outside right\nplot for [i=2:"
       << phases.size() + 1 << "] $p using i:xtic(1) title columnheader(i)\n";
    return {"phases-" + file_part(board) + ".png", gp.str(), ""};
}

}  // namespace

FigurePlan plan_figures(const Grid& grid, const SweepTable& table) {
    FigurePlan plan;
    // Each by what it sets, whatever its name (a grid named by hand keys its axes by name).
    const Axis* board_axis = grid.find("board");
    const Axis* n_axis = grid.find("scene.objects") ? grid.find("scene.objects") : grid.find("objects");
    const Axis* m_axis = grid.find("board.m") ? grid.find("board.m") : grid.find("m");
    // Every other axis that varies draws lines of its own.
    std::vector<const Axis*> variant_axes;
    std::vector<std::string> variant_names;
    for (const Axis& axis : grid.axes()) {
        if (&axis != board_axis && &axis != n_axis && &axis != m_axis && axis.values.size() > 1) {
            variant_axes.push_back(&axis);
            variant_names.push_back(axis.name);
        }
    }
    // Each variant value's place in its axis, for lines in grid order.
    std::vector<std::map<std::string, std::size_t>> variant_places;
    for (const Axis* axis : variant_axes) {
        variant_places.emplace_back();
        for (std::size_t k = 0; k < axis->values.size(); ++k) variant_places.back().emplace(axis->values[k], k);
    }
    std::vector<Sample> samples;
    std::vector<std::string> boards;
    table.for_each([&](std::size_t, const RowView& row) {
        if (text(row, "status") != "ok") return;
        Sample s;
        s.board = text(row, board_axis ? board_axis->name : "config.board");
        s.m = number(row, m_axis ? m_axis->name : "config.m");
        s.n = number(row, n_axis ? n_axis->name : "median_objects");
        s.row = row;
        for (std::size_t v = 0; v < variant_axes.size(); ++v) {
            const Axis* axis = variant_axes[v];
            const std::string value = text(row, axis->name);
            const auto at = variant_places[v].find(value);
            const std::size_t place = at == variant_places[v].end() ? axis->values.size() : at->second;
            char order[16];
            std::snprintf(order, sizeof order, "%08zu|", place);
            s.variant += (s.variant.empty() ? "" : " ") + axis->name + "=" + value;
            s.variant_order += order;
            s.variant_values.push_back(value);
        }
        if (std::find(boards.begin(), boards.end(), s.board) == boards.end()) boards.push_back(s.board);
        samples.push_back(s);
    });
    if (samples.empty()) {
        plan.notes.push_back("no plots: no point of the sweep ran");
        return plan;
    }
    std::vector<std::string> phases, baselines;
    for (const std::string& column : table.columns()) {
        const bool phase = column.rfind("median_", 0) == 0 && column.size() > 10 &&
                           column.compare(column.size() - 3, 3, "_ns") == 0 && column != "median_total_ns" &&
                           !is_measured_column(column);
        if (phase) phases.push_back(column);
        if (column.size() > 8 && column.compare(column.size() - 8, 8, "_speedup") == 0) {
            baselines.push_back(column.substr(0, column.size() - 8));
        }
    }
    // The phases stacked in the order a frame goes through them.
    const std::vector<std::string> kFrameOrder{"upload", "start", "compute", "irq", "readback", "driver"};
    auto place = [&](const std::string& phase) {
        return std::find(kFrameOrder.begin(), kFrameOrder.end(), phase.substr(7, phase.size() - 10)) - kFrameOrder.begin();
    };
    std::stable_sort(phases.begin(), phases.end(), [&](const auto& a, const auto& b) { return place(a) < place(b); });
    for (const std::string& board : boards) {
        if (!phases.empty()) plan.figures.push_back(phase_bars(samples, board, phases));
    }
    add_fit_figures(samples, boards, variant_names, plan);
    if (n_axis == nullptr) {
        plan.notes.push_back("no plots against N (time, speedup, crossover): objects (or scene.objects) is not an axis of this sweep");
        return plan;
    }
    if (baselines.empty()) plan.notes.push_back("no speedup or crossover plots: the sweep has no --baseline");
    for (const std::string& board : boards) {
        // Software lines are native time x the host factor: the labels say by how much.
        const auto on_board = std::find_if(samples.begin(), samples.end(), [&](const Sample& s) { return s.board == board; });
        auto on_host = [&](const std::string& baseline) {
            const double factor = number(on_board->row, baseline + "_host_factor");
            char label[128];
            std::snprintf(label, sizeof label, std::isnan(factor) ? "%s on the modelled host" : "%s on the modelled host (native x %.3g)",
                          baseline.c_str(), factor);
            return std::string(label);
        };
        std::ostringstream blocks, plots;
        for (std::size_t b = 0; b < baselines.size(); ++b) {
            Series software = series(samples, board, baselines[b] + "_mean_host_ns", 1e-3);
            if (software.empty()) continue;
            blocks << datablock("b" + std::to_string(b), software.begin()->second.points);
            plots << ", $b" << b << " using 1:2 with lines lc rgb 'gray30' dt 2 lw 3 title " << quoted(on_host(baselines[b]));
        }
        const Series times = series(samples, board, "mean_total_ns", 1e-3);
        if (times.empty()) {
            plan.notes.push_back("no plots of time or speedup on " + board + ": no point timed a frame (--frames 0)");
            continue;
        }
        plan.figures.push_back({"time-" + file_part(board) + ".png",
                                line_plot("mean frame time on " + board + " (board: simulated)", "us per frame",
                                          times, blocks.str(),
                                          plots.str()),
                                ""});
        for (const std::string& baseline : baselines) {
            plan.figures.push_back({"speedup-" + file_part(board) + "-" + file_part(baseline) + ".png",
                                    line_plot("speedup over " + on_host(baseline) + " on " + board + ": ratio of mean frame times",
                                              "speedup (x)",
                                              series(samples, board, baseline + "_speedup", 1), "",
                                              ", 1 with lines lc 'black' dt 3 title 'break-even'"),
                                    ""});
        }
    }
    if (!baselines.empty()) add_crossovers(samples, boards, variant_names, baselines, plan);
    return plan;
}

std::string figure_script(const Figure& figure, const std::string& png_path) {
    return "set terminal pngcairo noenhanced size 900,560 font 'sans,10'\nset output " + quoted(png_path) + "\n" +
           figure.script + "unset output\nreset\n";
}

}  // namespace cdvp
