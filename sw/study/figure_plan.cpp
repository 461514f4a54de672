#include "sw/study/figure_plan.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <tuple>

#include "sw/study/figure_templates.h"

namespace cdvp {

bool SeriesStyle::operator<(const SeriesStyle& o) const {
    return std::tie(family, colour, shape, dash, filled) < std::tie(o.family, o.colour, o.shape, o.dash, o.filled);
}

SeriesStyle series_style(std::size_t first, std::size_t first_count, std::size_t second, std::size_t second_count) {
    const bool first_leads = first_count >= second_count;
    const std::size_t major = first_leads ? first : second;
    const std::size_t minor = first_leads ? second : first;
    SeriesStyle style;
    style.colour = major % kColours;
    // The shape moves on by one each time the colours come round again, so
    // the (colour, shape) pairs repeat only after kColours x kShapes places.
    style.shape = (major + major / kColours) % kShapes;
    style.dash = minor % kDashes;
    // Alternate places open and filled, and the next round of dashes the other way about.
    style.filled = ((minor % kDashes) % 2 == 0) != ((minor / kDashes) % 2 == 1);
    return style;
}

SeriesStyle baseline_style(std::size_t k) {
    SeriesStyle style;
    style.family = SeriesStyle::Family::kBaseline;
    style.colour = style.shape = style.dash = k % kBaselineStyles;
    style.filled = false;
    return style;
}

SeriesStyle mark_style() {
    SeriesStyle style;
    style.family = SeriesStyle::Family::kMark;
    style.filled = false;
    return style;
}

std::string number_text(double v) {
    char t[40];
    std::snprintf(t, sizeof t, "%.10g", v);
    return t;
}

std::string short_number(double v) {
    char t[40];
    // Whole numbers from 100 up, so no reader meets "1.23e+03".
    std::snprintf(t, sizeof t, std::fabs(v) >= 100 ? "%.0f" : "%.3g", v);
    return t;
}

Figure data_file(const std::string& file, const std::string& text) {
    Figure figure;
    figure.file = file;
    figure.data = text;
    return figure;
}

void mark_beneath(std::vector<PlotSeries>& all) {
    for (std::size_t k = 0; k < all.size(); ++k) {
        all[k].beneath = 0;
        for (std::size_t later = k + 1; later < all.size(); ++later) {
            bool shared = false;
            for (const SeriesPoint& p : all[k].points) {
                for (const SeriesPoint& q : all[later].points) shared |= p.x == q.x && p.y == q.y;
            }
            all[k].beneath += shared && all[k].second_axis == all[later].second_axis ? 1 : 0;
        }
    }
}

namespace {

std::vector<std::pair<double, std::string>> ticks_of(double low, double high, const std::vector<int>& mantissas) {
    std::vector<std::pair<double, std::string>> ticks;
    for (double decade = std::pow(10.0, std::floor(std::log10(low))); decade <= high; decade *= 10) {
        for (const int m : mantissas) {
            const double v = m * decade;
            if (v >= low * (1 - 1e-9) && v <= high * (1 + 1e-9)) ticks.push_back({v, short_number(v)});
        }
    }
    return ticks;
}

}  // namespace

std::vector<std::pair<double, std::string>> log_ticks(double low, double high) {
    if (!(low > 0) || !(high >= low)) return {};
    std::vector<std::pair<double, std::string>> ticks = ticks_of(low, high, {1, 2, 5});
    if (ticks.size() > 9) return ticks_of(low, high, {1});
    if (ticks.size() < 3) return ticks_of(low, high, {1, 2, 3, 4, 5, 6, 7, 8, 9});
    return ticks;
}

std::vector<std::pair<double, std::string>> integer_ticks(double low, double high) {
    std::vector<std::pair<double, std::string>> ticks;
    const double span = std::max(1.0, high - low);
    double step = 1;
    for (const double candidate : {1.0, 2.0, 4.0, 5.0, 8.0, 10.0, 20.0, 25.0, 50.0, 100.0}) {
        step = candidate;
        if (span / candidate <= 8) break;
    }
    while (span / step > 8) step *= 10;
    for (double v = std::ceil(low / step) * step; v <= high + 1e-9; v += step) ticks.push_back({v, number_text(v)});
    return ticks;
}

std::vector<std::pair<double, std::string>> value_ticks(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    std::vector<std::pair<double, std::string>> ticks;
    for (const double v : values) ticks.push_back({v, number_text(v)});
    return ticks;
}

std::pair<double, double> padded_log_range(double low, double high, double pad) { return {low / pad, high * pad}; }

namespace {

// A gnuplot double-quoted string.
std::string text(const std::string& s) {
    std::string q = "\"";
    for (const char c : s) {
        if (c == '\\' || c == '"') q += '\\';
        q += c == '\n' ? std::string("\\n") : std::string(1, c);
    }
    return q + "\"";
}

// A label in a data block: quoted, and without the quotes a data file cannot escape.
std::string data_text(std::string s) {
    std::replace(s.begin(), s.end(), '"', '\'');
    std::replace(s.begin(), s.end(), '\n', ' ');
    return "\"" + s + "\"";
}

void axis_variables(std::ostringstream& gp, const std::string& name, const PlotAxis& axis) {
    gp << name << "_label = " << text(axis.label) << '\n' << name << "_log = " << (axis.log ? 1 : 0) << '\n';
    if (!std::isnan(axis.min)) gp << name << "_min = " << number_text(axis.min) << '\n';
    if (!std::isnan(axis.max)) gp << name << "_max = " << number_text(axis.max) << '\n';
    if (!axis.ticks.empty()) {
        std::string list;
        for (const auto& [value, label] : axis.ticks) list += (list.empty() ? "" : ", ") + text(label) + " " + number_text(value);
        gp << name << "_ticks = " << text("(" + list + ")") << '\n';
    }
}

template <class Field>
void series_array(std::ostringstream& gp, const std::string& name, const std::vector<PlotSeries>& series, Field field) {
    gp << "array " << name << "[" << series.size() << "] = [";
    for (std::size_t k = 0; k < series.size(); ++k) gp << (k == 0 ? "" : ", ") << field(series[k]);
    gp << "]\n";
}

}  // namespace

std::string figure_script(const Figure& figure, const std::string& png_path) {
    std::ostringstream gp;
    // A key of many series stands beside the plot (common.gp), a line each:
    // room for them, and for the plot beside them.
    const bool key_beside = figure.series.size() > 8;
    const int height = std::max<int>(figure.height, 240 + 18 * static_cast<int>(figure.series.size()));
    const int width = key_beside ? std::max(figure.width, 1180) : figure.width;
    gp << "reset session\n# " << figure.file << ": figures/common.gp and figures/" << figure.template_name
       << ".gp over these values\noutput_path = " << text(png_path) << "\nkey_beside = " << (key_beside ? 1 : 0) << "\nwidth = " << width
       << "\nheight = " << height << "\ntitle_text = " << text(figure.title)
       << "\ntitle_lines = " << std::count(figure.title.begin(), figure.title.end(), '\n') + 1 << '\n';
    axis_variables(gp, "x", figure.x);
    axis_variables(gp, "y", figure.y);
    axis_variables(gp, "y2", figure.y2);
    for (const auto& [name, value] : figure.numbers) gp << name << " = " << number_text(value) << '\n';
    // gnuplot's arrays count from 1, so do the palettes' places.
    gp << "n_series = " << figure.series.size() << '\n';
    // The marks come after every line (speedup.gp draws them as points alone).
    gp << "n_marks = "
       << std::count_if(figure.series.begin(), figure.series.end(),
                        [](const PlotSeries& s) { return s.style.family == SeriesStyle::Family::kMark; })
       << '\n';
    series_array(gp, "series_title", figure.series, [](const PlotSeries& s) { return text(s.title); });
    series_array(gp, "series_family", figure.series, [](const PlotSeries& s) { return static_cast<int>(s.style.family); });
    series_array(gp, "series_colour", figure.series, [](const PlotSeries& s) { return s.style.colour + 1; });
    series_array(gp, "series_shape", figure.series, [](const PlotSeries& s) { return s.style.shape + 1; });
    series_array(gp, "series_dash", figure.series, [](const PlotSeries& s) { return s.style.dash + 1; });
    series_array(gp, "series_filled", figure.series, [](const PlotSeries& s) { return s.style.filled ? 1 : 0; });
    series_array(gp, "series_axis", figure.series, [](const PlotSeries& s) { return s.second_axis ? 2 : 1; });
    series_array(gp, "series_beneath", figure.series, [](const PlotSeries& s) { return s.beneath; });
    gp << "$series << EOD\n";
    for (std::size_t k = 0; k < figure.series.size(); ++k) {
        if (k > 0) gp << "\n\n";  // two blank lines: the next series is the next index
        for (const SeriesPoint& p : figure.series[k].points) {
            gp << number_text(p.x) << ' ' << number_text(p.y) << ' ' << data_text(p.label) << ' '
               << number_text(std::isnan(p.label_x) ? p.x : p.label_x) << ' '
               << number_text(std::isnan(p.label_y) ? p.y : p.label_y) << ' ' << number_text(p.base) << '\n';
        }
    }
    gp << "EOD\n" << figure_template("common") << figure_template(figure.template_name) << "unset output\n";
    return gp.str();
}

}  // namespace cdvp
