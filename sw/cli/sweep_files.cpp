#include "sw/cli/sweep_files.h"

#include <sys/stat.h>

#include <iostream>

#include "models/common/user_text.h"
#include "sw/cli/child_runs.h"
#include "sw/cli/sweep_plots.h"
#include "sw/scene/output_set.h"

namespace cdvp {

std::string manifest_path(const std::string& dir) { return dir + "/sweep.json"; }
std::string table_path(const std::string& dir) { return dir + "/sweep.csv"; }
std::string points_dir(const std::string& dir) { return dir + "/points"; }
std::string report_path(const std::string& dir, const Point& point) {
    return points_dir(dir) + "/" + point.id + ".json";
}

namespace {

bool is_file(const std::string& path) {
    struct stat status {};
    return stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
}

}  // namespace

std::optional<nlohmann::json> read_manifest(const std::string& dir) {
    const std::string path = manifest_path(dir);
    if (!is_file(path)) return std::nullopt;
    try {
        nlohmann::json manifest = nlohmann::json::parse(slurp(path));
        if (manifest.value("format", "") != "cdvp sweep 1") throw InputError("not a cdvp sweep manifest");
        manifest_grid(manifest);  // checks the axes
        return manifest;
    } catch (const nlohmann::json::exception& e) {
        throw InputError(excerpt(path) + ": not a sweep manifest: " + e.what());
    } catch (const InputError& e) {
        throw InputError(excerpt(path) + ": " + e.what());
    }
}

bool same_sweep(const nlohmann::json& a, const nlohmann::json& b) {
    return a.at("axes") == b.at("axes") && a.at("run_options") == b.at("run_options");
}

Grid manifest_grid(const nlohmann::json& manifest) {
    std::vector<Axis> axes;
    for (const auto& axis : manifest.at("axes")) {
        axes.push_back({axis.at("name").get<std::string>(), axis.at("values").get<std::vector<std::string>>()});
    }
    return Grid(std::move(axes));
}

std::vector<std::string> manifest_run_options(const nlohmann::json& manifest) {
    return manifest.at("run_options").get<std::vector<std::string>>();
}

void read_table(const std::string& dir, SweepTable& table) {
    const std::string path = table_path(dir);
    if (is_file(path)) table.read_csv(slurp(path), excerpt(path));
}

int write_figures(const std::string& dir, const Grid& grid, const SweepTable& table, const std::string& program,
                  bool quiet) {
    const FigurePlan plan = plan_figures(grid, table);
    if (!quiet) {
        for (const std::string& note : plan.notes) std::cerr << program << ": " << printable(note) << '\n';
    }
    if (plan.figures.empty()) return 0;
    OutputSet files;
    std::vector<std::size_t> slots;
    for (const Figure& figure : plan.figures) {
        slots.push_back(files.add_output("--out", dir + "/" + figure.file, "", figure.script.empty()));
    }
    files.open();
    std::string script;
    for (std::size_t k = 0; k < plan.figures.size(); ++k) {
        const Figure& figure = plan.figures[k];
        if (figure.script.empty()) {
            files.file(slots[k]).stream() << figure.data;
        } else {
            script += figure_script(figure, files.file(slots[k]).temp_path());
        }
    }
    if (const std::optional<std::string> error = run_gnuplot(script)) {
        std::cerr << program << ": gnuplot failed to draw the figures in " << printable(dir) << ": " << printable(*error)
                  << '\n';
        return 1;
    }
    if (const std::optional<std::string> error = files.try_commit()) {
        std::cerr << program << ": " << printable(*error) << '\n';
        return 2;
    }
    return 0;
}

}  // namespace cdvp
