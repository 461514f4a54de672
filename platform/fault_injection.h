// The --inject specs: KIND@WHERE, several separated by ';' or spaces.
//   KIND   target-abort | master-abort | retry | disconnect | lost-irq | dma-hang | board-error
//   WHERE  frame=N[,n=K]   the frame numbered N (as in the trace, the report and the pairs CSV);
//                          K faults of that kind (default 1)
// e.g. "retry@frame=3,n=2; lost-irq@frame=1". docs/faults.md describes each kind.
#pragma once

#include <string>
#include <vector>

#include "models/common/fault_plan.h"

namespace cdvp {

// Throws InputError naming the spec and what was expected (the valid kinds
// or keys); the caller prefixes the input it came from ("--inject: ").
std::vector<FaultSpec> parse_fault_specs(const std::string& text);

// The spec back as text, e.g. "retry@frame=3,n=2".
std::string to_string(const FaultSpec& spec);

}  // namespace cdvp
