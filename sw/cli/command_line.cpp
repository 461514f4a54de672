// What `cdvp bullet` and `cdvp record` share: Bullet's scene names and help,
// record's scene options, parsing, exit statuses.
#include <algorithm>
#include <cstring>
#include <sstream>
#include <iostream>

#include "models/common/user_text.h"
#include "sw/bullet/board_link.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/number_option.h"
#include "sw/cli/run_command.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/run_options.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {
constexpr uint64_t kMaxFrames = 1'000'000;
}  // namespace

std::string bullet_scene_help() { return bullet_scene_list() + " (docs/bullet.md)"; }

std::string bullet_objects_help() { return "(default: the scene's own: " + bullet_scene_defaults() + ")"; }

void check_bullet_scene_name(const std::string& name) {
    if (const std::optional<std::string> refused = bullet_scene_refusal(name)) throw InputError("--scene: " + *refused);
}

po::options_description scene_options(SceneOptions& o) {
    po::options_description scene("Scene");
    const std::string objects = "bodies in the scene " + bullet_objects_help();
    scene.add_options()
        ("scene", po::value(&o.scene)->value_name("NAME"), bullet_scene_help().c_str())
        ("objects", number<uint32_t>(&o.objects, 1, kMaxSceneObjects, "N", false), objects.c_str())
        ("frames", number<uint64_t>(&o.frames, 1, kMaxFrames, "F"), "steps of 1/60 s")
        ("seed", number<uint64_t>(&o.seed, 0, UINT64_MAX, "S"), "random seed (same seed, same scene)");
    return scene;
}

SceneSpec scene_spec(const SceneOptions& o, const po::variables_map& vm) {
    if (vm.count("scene") == 0) throw InputError("--scene: expected one of " + bullet_scene_list());
    check_bullet_scene_name(o.scene);
    SceneSpec spec{o.scene, o.objects, o.seed};
    try {
        scene_layout(spec);
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("--scene: ") + e.what());
    }
    return spec;
}

int run_command_line(const char* program, int argc, char** argv, const std::string& usage,
                     const po::options_description& options,
                     const std::function<int(const po::variables_map&)>& body) {
    for (int k = 1; k < argc && std::strcmp(argv[k], "--") != 0; ++k) {
        if (std::strcmp(argv[k], "--help") == 0 || std::strcmp(argv[k], "-h") == 0) {
            std::ostringstream help;
            help << usage << "\n\n" << options << '\n';
            return print_to_stdout(program, help.str());
        }
    }
    return exit_status_of(program, [&] {
        try {
            return body(parse_strictly(argc, argv, options));
        } catch (const po::error& e) {
            std::cerr << program << ": " << printable(e.what()) << " (see " << program << " --help)\n";
            return kExitBadInput;
        } catch (const BoardFrameFault& e) {
            std::cerr << program << ": the simulated system faulted: " << printable(e.what()) << '\n';
            return kExitDeviceFault;
        }
    });
}

}  // namespace cdvp
