#include "platform/kernel.h"

#include <systemc>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CDVP_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define CDVP_ASAN 1
#endif

#ifdef CDVP_ASAN
#include <pthread.h>
#include <sanitizer/common_interface_defs.h>
#endif

namespace cdvp {

void configure_kernel() {
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
}

void after_kernel_returns() {
#ifdef CDVP_ASAN
    pthread_attr_t attributes;
    if (pthread_getattr_np(pthread_self(), &attributes) != 0) return;
    void* bottom = nullptr;
    size_t size = 0;
    pthread_attr_getstack(&attributes, &bottom, &size);
    pthread_attr_destroy(&attributes);
    // A switch from "wherever ASan thinks we are" to the stack we are on.
    __sanitizer_start_switch_fiber(nullptr, bottom, size);
    __sanitizer_finish_switch_fiber(nullptr, nullptr, nullptr);
#endif
}

}  // namespace cdvp
