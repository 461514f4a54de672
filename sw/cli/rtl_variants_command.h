// `cdvp rtl-variants [--json]`: the parameter sets of the board RTL this
// binary holds as Verilator models (models/rtl_engine/rtl_variant.h), which
// are the boards --fidelity rtl can run.
#pragma once

#include <nlohmann/json.hpp>

namespace cdvp {

int rtl_variants_command(int argc, char** argv);
// What --json prints: one object a variant.
nlohmann::json rtl_variants_json();

}  // namespace cdvp
