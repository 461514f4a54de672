#include "sw/cli/help_text.h"
#include "sw/cli/rtl_variants_command.h"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "models/common/user_text.h"
#include "models/rtl_engine/rtl_variant.h"
#include "sw/cli/exit_status.h"
#include "sw/run/exit_codes.h"

namespace cdvp {

namespace {

constexpr const char* kRtlVariantsHelp =
    "Usage: cdvp rtl-variants [--json]\n"
    "\n"
    "Lists the parameter sets of the whole-board RTL (models/board/rtl/collision_board_top.v;\n"
    "grid_board_top.v for board.algorithm grid, whose spec adds its grid) compiled into this\n"
    "binary by Verilator (the CMake list CDVP_RTL_VARIANTS). A board runs on the variant with\n"
    "its m, number format, comparator latency, FIFO and pair-buffer depths, tiles (or grid),\n"
    "and a capacity (a power of two) of at least its largest frame; for any other\n"
    "board --fidelity rtl compiles its own on first use (verilator and the C++ compiler cdvp was\n"
    "built with, about half a minute) into $CDVP_RTL_CACHE, else $XDG_CACHE_HOME/cdvp/rtl, else\n"
    "~/.cache/cdvp/rtl, and later runs load it from there (docs/rtl.md).\n"
    "\n"
    "  --json   one JSON object a variant, with the fields of the text table\n";

std::string variants_text() {
    std::ostringstream out;
    out << std::left << std::setw(4) << "m" << std::setw(9) << "format" << std::setw(9) << "latency" << std::setw(6)
        << "fifo" << std::setw(8) << "buffer" << std::setw(6) << "tile" << std::setw(14) << "tile_latency"
        << std::setw(10) << "capacity" << "CDVP_RTL_VARIANTS entry\n";
    for (const BuiltRtlVariant& built : built_rtl_variants()) {
        const RtlVariant& v = built.variant;
        out << std::setw(4) << v.m << std::setw(9)
            << v.format().name() << std::setw(9)
            << v.compare_latency << std::setw(6) << v.fifo_depth << std::setw(8) << v.buffer_depth << std::setw(6)
            << v.tile_boxes << std::setw(14) << (v.tile_boxes == 0 ? std::string("-") : std::to_string(v.tile_latency))
            << std::setw(10) << v.capacity() << v.spec() << '\n';
    }
    out << built_rtl_variants().size() << " variants\n";
    return out.str();
}

}  // namespace

nlohmann::json rtl_variants_json() {
    nlohmann::json all = nlohmann::json::array();
    for (const BuiltRtlVariant& built : built_rtl_variants()) {
        const RtlVariant& v = built.variant;
        all.push_back({{"m", v.m},
                       {"format", v.format().name()},
                       {"compare_latency", v.compare_latency},
                       {"fifo_depth", v.fifo_depth},
                       {"buffer_depth", v.buffer_depth},
                       {"tile_boxes", v.tile_boxes},
                       {"tile_latency", v.tile_latency},
                       {"capacity", v.capacity()},
                       {"spec", v.spec()}});
    }
    return all;
}

int rtl_variants_command(int argc, char** argv) {
    if (argc > 2) {
        std::cerr << "cdvp rtl-variants: unexpected argument '" << excerpt(argv[2]) << "' (see cdvp rtl-variants --help)\n";
        return kExitBadInput;
    }
    const std::string mode = argc == 2 ? argv[1] : "";
    if (mode == "--help" || mode == "-h") return print_help("cdvp rtl-variants", kRtlVariantsHelp);
    if (mode == "--json") return print_to_stdout("cdvp rtl-variants", rtl_variants_json().dump(2) + "\n");
    if (!mode.empty()) {
        std::cerr << "cdvp rtl-variants: unknown option '" << excerpt(mode) << "'; expected --json\n";
        return kExitBadInput;
    }
    return print_to_stdout("cdvp rtl-variants", variants_text());
}

}  // namespace cdvp
