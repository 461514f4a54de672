// sc_main for GoogleTest binaries that elaborate SystemC designs. Every SystemC
// warning or error becomes a test failure, so nothing is swallowed. ctest runs
// each test in its own process (a process can elaborate only once).
#include <gtest/gtest.h>

#include <cstdlib>
#include <systemc>

#include "platform/kernel.h"

namespace {
void fail_on_report(const sc_core::sc_report& report, const sc_core::sc_actions& actions) {
    if (report.get_severity() >= sc_core::SC_WARNING) {
        ADD_FAILURE() << "SystemC " << (report.get_severity() == sc_core::SC_WARNING ? "warning" : "error") << ": "
                      << report.get_msg_type() << ": " << report.get_msg();
    }
    sc_core::sc_report_handler::default_handler(report, actions & ~sc_core::SC_DISPLAY);
}
}  // namespace

int sc_main(int argc, char** argv) {
    cdvp::configure_kernel();
    sc_core::sc_report_handler::set_handler(fail_on_report);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

int main(int argc, char** argv) {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
    const int status = sc_core::sc_elab_and_sim(argc, argv);
    cdvp::after_kernel_returns();
    return status;
}
