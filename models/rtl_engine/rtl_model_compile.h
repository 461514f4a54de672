// Compiling one variant of the board RTL into a shared object: Verilator
// (--build, which runs make and the compiler) on the kit's RTL with the
// variant's parameters and the arguments the built-in variants take, the
// entry point filled in from the kit's template, linked with Verilator's run
// time into DIR/model.so, everything the tools print in one log.
#pragma once

#include <string>

#include "models/rtl_engine/rtl_kit.h"
#include "models/rtl_engine/rtl_variant.h"

namespace cdvp {

struct RtlToolchain {
    std::string verilator;  // absolute paths
    std::string make;
    std::string compiler;
};

// The tools, found on PATH (the compiler: the one cdvp was built with);
// throws InputError naming the first one missing and what it is for.
RtlToolchain find_rtl_toolchain(const RtlBuild& build, const std::string& what);

// Compiles `variant` into `directory` (which exists): model.so beside the
// Verilator output. Returns Verilator's version line. Throws InputError
// naming the tool and `log` when a step fails, SystemError when the system
// failed it (a tool killed by a signal, a full disk).
std::string compile_rtl_model(const RtlVariant& variant, const RtlToolchain& tools, const RtlBuild& build,
                              const RtlKit& kit, const std::string& directory, const std::string& log);

// The options the model's C++ is compiled with, beside Verilator's own
// (part of the cache key).
const std::vector<std::string>& rtl_model_make_options();

}  // namespace cdvp
