// The answer as text: answer.csv, answer.md and the short form a sweep prints.
#include <algorithm>
#include <cstdio>

#include "sw/study/sweep_answer.h"
#include "sw/study/sweep_csv.h"

namespace cdvp::sweep_figures {

namespace {

// A number for a CSV field: empty when there is none.
std::string field(double v) { return std::isnan(v) ? "" : num(v); }

std::string percent(double share) {
    char t[16];
    std::snprintf(t, sizeof t, "%.0f%%", 100 * share);
    return t;
}

std::string ratio_words(double ratio) { return std::isnan(ratio) ? "-" : short_number(ratio) + "x"; }

std::string scene_name(const SceneAnswer& answer) { return answer.scene.empty() ? "the scene" : answer.scene; }

bool timed_software(const SceneAnswer& answer) {
    return std::any_of(answer.points.begin(), answer.points.end(), [](const AnswerPoint& a) { return !a.software.empty(); });
}

// A markdown table cell: a '|' would end it.
std::string cell(std::string text) {
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.replace(at, 1, "\\|");
    return text.empty() ? "-" : text;
}

// "software timing clean, the board's clock met"
std::string trust_words(const AnswerCrossover& c) {
    std::string words = "software timing " + c.software_timing;
    if (c.clock_met == "yes") return words + ", the board's clock met";
    if (c.clock_met == "no") return words + ", a board clock beyond what its design reaches";
    return words + ", the board's clock not stated";
}

// "N ~ 120", "N <= 50"
std::string n_words(const Crossover& c) {
    return (std::string(c.how) == "measured" ? "N <= " : "N ~ ") + short_number(c.n);
}

// "faster from N ~ 142 (interpolated) on", "faster from no N of the sweep on"
std::string from_words(const std::string& winning, const Crossover& c) {
    return c.n == 0 ? winning + " from no N of the sweep on" : winning + " from " + crossover_words(c) + " on";
}

std::string time_sentence(const SceneAnswer& answer) {
    const AnswerCrossover& c = answer.time;
    return "The board is " + from_words("faster than the fastest software", c.at) +
           (c.at.n > 0 ? " (" + trust_words(c) + ")." : ".");
}

std::string energy_sentence(const SceneAnswer& answer) {
    return "It takes " + from_words("less energy a frame", answer.energy.at) + " (" + energy_band_words(answer) +
           ": the board's own power x" + short_number(kBoardPowerBand.low) + " to x" + short_number(kBoardPowerBand.high) +
           ", the host's x" + short_number(kHostPowerBand.low) + " to x" + short_number(kHostPowerBand.high) +
           ", docs/energy.md).";
}

// What the largest N says, and what bounds the board there.
std::string largest_sentence(const AnswerPoint& a) {
    std::string words = "At N = " + num(a.n) + ", " + a.configuration + " takes " + frame_time_words(a.frame_ns) +
                        (std::isnan(a.energy_j) ? "" : " and " + energy_words(a.energy_j)) + " a frame";
    if (!a.software.empty()) {
        words += " against " + a.software + "'s " + frame_time_words(a.software_ns) +
                 (std::isnan(a.software_energy_j) ? "" : " and " + energy_words(a.software_energy_j)) + ": " +
                 ratio_words(a.speedup) + " the speed" +
                 (std::isnan(a.energy_ratio)  ? ""
                  : a.energy_ratio >= 1       ? ", " + ratio_words(a.energy_ratio) + " less energy"
                                              : ", " + ratio_words(1 / a.energy_ratio) + " more energy");
    }
    if (!a.bound_by.empty()) {
        const double share = a.bound_by == "bus"      ? a.bus_share
                             : a.bound_by == "memory" ? a.memory_share
                             : a.bound_by == "host"   ? a.host_share
                                                      : a.compute_share;
        words += "; its frame is bound by " + a.bound_by + " (" + percent(share) + " of it)";
    }
    return words + ".";
}

// The N of the scene's answers that `has`: "500, 2000"; empty for none.
template <class Has>
std::string ns_where(const SceneAnswer& answer, Has has) {
    std::string ns;
    for (const AnswerPoint& a : answer.points) {
        if (has(a)) ns += (ns.empty() ? "" : ", ") + num(a.n);
    }
    return ns;
}

// The N whose software timing was disturbed, and what would help.
std::string disturbed_sentence(const SceneAnswer& answer) {
    const std::string ns = ns_where(answer, [](const AnswerPoint& a) { return a.software_timing == "disturbed"; });
    return ns.empty() ? "" : " The software's timing was disturbed at N = " + ns +
                                 " (docs/timing.md): a quieter machine, --pin-cpu or more --repeat would firm it up.";
}

std::string clock_sentence(const SceneAnswer& answer) {
    const std::string ns = ns_where(answer, [](const AnswerPoint& a) { return a.clock_met == "no"; });
    return ns.empty() ? "" : " At N = " + ns + " the fastest configuration's clock is beyond what its design " +
                                 "reaches (its times are optimistic).";
}

}  // namespace

std::string crossover_words(const Crossover& c) {
    if (c.n == 0) return "no N of the sweep";
    return n_words(c) + (std::string(c.how) == "measured" ? " (the sweep's smallest)" : " (interpolated)");
}

std::string energy_band_words(const SceneAnswer& answer) {
    const Crossover &early = answer.energy_early.at, &late = answer.energy_late.at;
    if (early.n == 0) return "from no N of the sweep on anywhere in the power band";
    return "from " + n_words(early) + (late.n > 0 ? " to " + n_words(late) : " to beyond the sweep's largest N") +
           " across the power band";
}

std::string energy_words(double joules) {
    if (std::isnan(joules)) return "-";
    if (joules >= 1) return short_number(joules) + " J";
    if (joules >= 1e-3) return short_number(joules * 1e3) + " mJ";
    return short_number(joules * 1e6) + " uJ";
}

std::string answer_csv(const std::vector<SceneAnswer>& answers) {
    std::string csv =
        "scene,objects,configuration,board,algorithm,m,format,point,board_frame_ns,board_energy_j,software,"
        "software_frame_ns,software_energy_j,speedup,energy_ratio,energy_ratio_low,energy_ratio_high,software_timing,"
        "bound_by,bus_share,memory_share,compute_share,host_share,clock_mhz,fmax_mhz,clock_met,time_crossover_n,"
        "time_crossover_how,time_crossover_timing,time_crossover_clock,energy_crossover_n,energy_crossover_how,"
        "energy_crossover_early_n,energy_crossover_late_n\n";
    auto crossover_fields = [](const AnswerCrossover& c) {
        return (c.at.n > 0 ? num(c.at.n) : "") + "," + c.at.how;
    };
    for (const SceneAnswer& answer : answers) {
        for (const AnswerPoint& a : answer.points) {
            const std::vector<std::string> fields{
                answer.scene, num(a.n), a.configuration, a.board->board, a.algorithm, num(a.board->m), a.format,
                text(a.board->row, "point"), field(a.frame_ns), field(a.energy_j), a.software, field(a.software_ns),
                field(a.software_energy_j), field(a.speedup), field(a.energy_ratio), field(a.energy_ratio_low),
                field(a.energy_ratio_high), a.software_timing, a.bound_by, field(a.bus_share), field(a.memory_share),
                field(a.compute_share), field(a.host_share), field(a.clock_mhz), field(a.fmax_mhz), a.clock_met};
            for (const std::string& f : fields) csv += csv_field(f) + ",";
            csv += crossover_fields(answer.time) + "," + answer.time.software_timing + "," + answer.time.clock_met + "," +
                   crossover_fields(answer.energy) + "," +
                   (answer.energy_early.at.n > 0 ? num(answer.energy_early.at.n) : "") + "," +
                   (answer.energy_late.at.n > 0 ? num(answer.energy_late.at.n) : "") + "\n";
        }
    }
    return csv;
}

std::string answer_markdown(const std::vector<SceneAnswer>& answers, const std::string& context) {
    std::string md = "# The sweep's answer\n\nAt each scene and N, the fastest board configuration (by mean frame "
                     "time) against the fastest software timed there on the same modelled host. " + context + "\n";
    for (const SceneAnswer& answer : answers) {
        md += "\n## " + scene_name(answer) + "\n\n";
        md += "| N | fastest board configuration | frame | energy a frame | fastest software | its frame | speedup | "
              "energy ratio (band) | bound by | software timing | clock met |\n"
              "|---:|---|---:|---:|---|---:|---:|---:|---|---|---|\n";
        for (const AnswerPoint& a : answer.points) {
            const std::string band = std::isnan(a.energy_ratio_low)
                                         ? ""
                                         : " (" + short_number(a.energy_ratio_low) + "-" + short_number(a.energy_ratio_high) + ")";
            md += "| " + num(a.n) + " | " + cell(a.configuration) + " | " + frame_time_words(a.frame_ns) + " | " +
                  energy_words(a.energy_j) + " | " + cell(a.software) + " | " +
                  (a.software.empty() ? "-" : frame_time_words(a.software_ns)) + " | " + ratio_words(a.speedup) + " | " +
                  ratio_words(a.energy_ratio) + band + " | " + cell(a.bound_by) + " | " + cell(a.software_timing) + " | " +
                  cell(a.clock_met) + " |\n";
        }
        md += "\n";
        if (!timed_software(answer)) {
            md += "No software was timed (no --baseline): nothing to hold the board to.";
        } else {
            md += time_sentence(answer) + " " + energy_sentence(answer);
        }
        md += " " + largest_sentence(answer.points.back()) + disturbed_sentence(answer) + clock_sentence(answer) + "\n";
    }
    return md;
}

std::string answer_summary(const std::vector<SceneAnswer>& answers) {
    std::vector<std::vector<std::string>> table{
        {"scene", "N", "fastest board", "frame", "energy", "software", "speedup", "energy ratio", "bound by"}};
    for (const SceneAnswer& answer : answers) {
        for (const AnswerPoint& a : answer.points) {
            table.push_back({scene_name(answer), num(a.n), a.configuration, frame_time_words(a.frame_ns),
                             energy_words(a.energy_j), a.software.empty() ? "-" : a.software, ratio_words(a.speedup),
                             ratio_words(a.energy_ratio), a.bound_by.empty() ? "-" : a.bound_by});
        }
    }
    std::vector<std::size_t> width(table.front().size(), 0);
    for (const auto& row : table) {
        for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
    }
    std::string out;
    for (const auto& row : table) {
        std::string line;
        for (std::size_t c = 0; c < row.size(); ++c) line += "  " + row[c] + std::string(width[c] - row[c].size(), ' ');
        out += line.substr(0, line.find_last_not_of(' ') + 1) + "\n";
    }
    for (const SceneAnswer& answer : answers) {
        if (!timed_software(answer)) continue;
        out += "  " + scene_name(answer) + ": " + from_words("faster", answer.time.at) +
               (answer.time.at.n > 0 ? " (" + trust_words(answer.time) + ")" : "") + "; " +
               from_words("less energy", answer.energy.at) + " (" + energy_band_words(answer) + ")\n";
    }
    return out;
}

}  // namespace cdvp::sweep_figures
