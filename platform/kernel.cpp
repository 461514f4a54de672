#include "platform/kernel.h"

#include <systemc>

namespace cdvp {

void configure_kernel() {
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
}

}  // namespace cdvp
