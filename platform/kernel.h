// Kernel settings every cdvp executable applies before elaborating.
#pragma once

namespace cdvp {

// Time resolution 1 fs, so clock periods such as 1/66 MHz are exact to well
// under a part per million (at the default 1 ps the period is 0.003% long);
// informational kernel messages off. Call first thing in sc_main.
void configure_kernel();

}  // namespace cdvp
