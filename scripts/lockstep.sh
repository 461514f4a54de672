#!/usr/bin/env bash
# The full lockstep set: builds the board RTL for every m from 1 to 32 (with
# FIFOs of 2m-1 pairs and 96-pair buffers) beside the default variants into
# build-lockstep/, and holds each to the clocked engine edge by edge
# (tests/rtl/rtl_lockstep_test.cpp). CI runs the default variants only.
# Building the 45 Verilator models takes long: 62 minutes with JOBS=1 beside
# other builds; the test itself about 25 s.
#
#   scripts/lockstep.sh [gtest filter]        e.g. 'BuiltVariants/*m_17*'
# Environment: BUILD_DIR (build-lockstep), JOBS (nproc).
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir="${BUILD_DIR:-build-lockstep}"
jobs="${JOBS:-$(nproc)}"
run() { echo "+ $*"; "$@"; }

run cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCDVP_RTL_LOCKSTEP_ALL=ON
run cmake --build "$build_dir" -j "$jobs" --target rtl_lockstep_tests
filter=()
[ $# -gt 0 ] && filter=("--gtest_filter=$1")
run "$build_dir/tests/rtl/rtl_lockstep_tests" "${filter[@]}"
