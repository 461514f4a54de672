#!/usr/bin/env bash
# Builds cdvp with AddressSanitizer and UndefinedBehaviorSanitizer into
# build-asan/ and runs the test suite under them: every test but those
# labelled `tool`, which check the sources or run outside tools only (the
# layer check, Yosys, the Verilator lint, the Slurm job array) and which the
# Release stage runs. Any sanitizer report fails its test (UBSan is built
# non-recovering). See docs/testing.md for the SystemC coroutine settings below.
#
#   scripts/sanitize.sh [ctest arguments...]     e.g. -R TraceCsv; -L tool runs those too
# Environment: SANITIZERS (default address,undefined,float-cast-overflow), BUILD_DIR (build-asan),
# SANITIZE_OPT (-O1 -g1: optimisation and debug info), JOBS (nproc),
# RTL_VARIANTS (the board RTL's Verilator builds: by default the few the
# command-line and waveform tests name and the grid board's lockstep test's,
# not the whole default list).
set -euo pipefail
cd "$(dirname "$0")/.."

# GCC's 'undefined' leaves out float-cast-overflow (clang's has it): a NaN or
# an out-of-range float converted to an integer, which x86 turns into
# 0x80000000 silently. Named here so that GCC's build checks it too.
sanitizers="${SANITIZERS:-address,undefined,float-cast-overflow}"
build_dir="${BUILD_DIR:-build-asan}"
jobs="${JOBS:-$(nproc)}"
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

run() { echo "+ $*"; "$@"; }

# Debian's SystemC switches QuickThreads coroutine stacks and tells ASan
# (it calls __sanitizer_start_switch_fiber without saving the fake stack), so
# fake stacks for use-after-return detection must stay off. SystemC's memory
# pool is bypassed so ASan sees every allocation. Leak checking stays on.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=0:detect_leaks=1:abort_on_error=1:strict_string_checks=1:check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export SYSTEMC_MEMPOOL_DONT_USE=1
# A library's own leaks, named one by one (tests/sanitize/lsan.supp).
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitize/lsan.supp:print_suppressions=0}"

paper="format=float32,latency=2,fifo=512,buffer=262144,capacity=512"
grid="m=3,fifo=5,buffer=24,tile_latency=2,capacity=512,algorithm=grid,cell_capacity=9,entries=400"
rtl_variants="${RTL_VARIANTS-m=8,$paper;m=8,fifo=15,buffer=128,capacity=1024;m=2,buffer=40,capacity=512;m=2,format=fixed16,latency=1,fifo=3,buffer=64,capacity=1024;m=2,fifo=8,buffer=64,tile=64,tile_latency=2,capacity=1024;$grid}"

# -O1 -g1: what ASan's and UBSan's checks need (every check is compiled in
# at any level; -O1 keeps the tests fast) and line tables for the reports'
# stacks, inlined frames included. Full -g and -O2 made this build take over
# twice as long (docs/testing.md, CI).
opt="${SANITIZE_OPT:--O1 -g1}"

start=$SECONDS
run cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$opt -DNDEBUG" \
  "-DCDVP_SANITIZE=$sanitizers" "-DCDVP_RTL_VARIANTS=$rtl_variants" "${launcher[@]}"
run cmake --build "$build_dir" -j "$jobs"
built=$SECONDS
status=0
labels=(-LE tool)
for arg in "$@"; do [ "$arg" = "-L" ] && labels=(); done
run ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" "${labels[@]}" "$@" || status=$?
if [ "$status" -eq 0 ]; then
  echo "sanitize: PASS: the test suite under -fsanitize=$sanitizers (build $((built - start)) s, tests $((SECONDS - built)) s)"
else
  echo "sanitize: FAIL: tests failed under -fsanitize=$sanitizers (ctest exit $status; reports above)"
fi
exit "$status"
