// What `cdvp bullet` and `cdvp record` share: Bullet's scene names and help,
// parsing, exit statuses.
#include <algorithm>
#include <cstring>
#include <sstream>
#include <iostream>

#include "models/common/user_text.h"
#include "sw/bullet/board_link.h"
#include "sw/cli/help_text.h"
#include "sw/cli/bullet_command.h"
#include "sw/cli/number_option.h"
#include "sw/cli/run_command.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/run_options.h"

namespace po = boost::program_options;

namespace cdvp {

std::string bullet_scene_help() { return bullet_scene_list() + " (docs/bullet.md)"; }

int run_command_line(const char* program, int argc, char** argv, const std::string& usage,
                     const po::options_description& options,
                     const std::function<int(const po::variables_map&)>& body) {
    for (int k = 1; k < argc && std::strcmp(argv[k], "--") != 0; ++k) {
        if (std::strcmp(argv[k], "--help") == 0 || std::strcmp(argv[k], "-h") == 0) {
            std::ostringstream help;
            help << usage << "\n\n" << options << '\n';
            return print_help(program, help.str());
        }
    }
    return exit_status_of(program, [&] {
        try {
            return body(parse_strictly(argc, argv, options));
        } catch (po::error& e) {  // option_error_text shortens a huge name in place
            std::cerr << program << ": " << option_error_text(e, program, &options) << '\n';
            return kExitBadInput;
        } catch (const BoardFrameFault& e) {
            std::cerr << program << ": the simulated system faulted: " << printable(e.what()) << '\n';
            return kExitDeviceFault;
        }
    });
}

}  // namespace cdvp
