// Kernel settings every cdvp executable applies before elaborating.
#pragma once

namespace cdvp {

// Time resolution 1 fs, so clock periods such as 1/66 MHz are exact to well
// under a part per million (at the default 1 ps the period is 0.003% long);
// informational kernel messages off. Call first thing in sc_main.
void configure_kernel();

// Call on the main stack whenever the kernel has handed control back (after
// sc_start, after sc_elab_and_sim). SystemC tells AddressSanitizer of each
// coroutine switch but describes the main stack as empty when it switches
// back, so ASan's idea of the current stack stays wrong: an exception thrown
// afterwards warns of false positives, and LeakSanitizer at exit scans a
// coroutine stack SystemC has unmapped and crashes. This tells ASan the
// truth: the thread's own stack. Without ASan it does nothing.
void after_kernel_returns();

}  // namespace cdvp
