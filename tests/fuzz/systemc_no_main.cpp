// Debian's libsystemc.so defines main(), which calls sc_main(), so every
// executable linking it must define sc_main. A fuzzer's main() is libFuzzer's:
// this sc_main is only there to link, and is weak so that a fuzzer may define
// its own.
#include <cstdio>

// Declared extern "C" by SystemC (sc_externs.h).
extern "C" __attribute__((weak)) int sc_main(int, char**) {
    std::fputs("sc_main: a fuzzer runs from libFuzzer's main, not SystemC's\n", stderr);
    return 1;
}
