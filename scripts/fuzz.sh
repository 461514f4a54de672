#!/usr/bin/env bash
# Builds the libFuzzer targets with clang into build-fuzz/ and runs each for a
# bounded time, starting from its checked-in seed corpus. Fails if any fuzzer
# finds a crash, a sanitizer report, a timeout or an out-of-memory input.
#
#   scripts/fuzz.sh [NAME...]        default: every *_fuzzer built
# Environment (defaults): FUZZ_SECONDS (60) per fuzzer, FUZZ_RSS_MB (2048), FUZZ_MALLOC_MB (128),
# FUZZ_TIMEOUT (10 s per input), FUZZ_JOBS (nproc) fuzzers at once,
# BUILD_DIR (build-fuzz), CXX_FUZZ (clang++-14, else clang++).
# New inputs go to BUILD_DIR/corpus/NAME (kept between local runs), crashing
# inputs to BUILD_DIR/artifacts/NAME/, logs to BUILD_DIR/logs/NAME.log.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${FUZZ_SECONDS:-60}"
rss_mb="${FUZZ_RSS_MB:-2048}"
malloc_mb="${FUZZ_MALLOC_MB:-128}"  # one allocation larger than this is a finding: no input may make a model allocate without bound
timeout="${FUZZ_TIMEOUT:-10}"
jobs="${FUZZ_JOBS:-$(nproc)}"
build_dir="${BUILD_DIR:-build-fuzz}"
cxx="${CXX_FUZZ:-$(command -v clang++-14 || command -v clang++ || true)}"
if [ -z "$cxx" ]; then
  echo "fuzz: no clang++ found; run scripts/setup.sh (installs clang-14 and libclang-rt-14-dev)" >&2
  exit 2
fi
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

run() { echo "+ $*"; "$@"; }

# As in scripts/sanitize.sh: SystemC's coroutine switches leave ASan no fake
# stacks to keep, and its memory pool would hide allocations from ASan.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=0}"
# libFuzzer's own driver allocation, reported as a leak at exit (tests/fuzz/lsan.supp).
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0}"
export SYSTEMC_MEMPOOL_DONT_USE=1

start=$SECONDS
# No board RTL variants: no fuzzer runs the rtl level, and Verilator's models
# would take most of the build.
run cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_COMPILER=$cxx" -DCDVP_FUZZ=ON \
  "-DCDVP_RTL_VARIANTS=" "${launcher[@]}"
run cmake --build "$build_dir" -j "$(nproc)" --target fuzzers
echo "fuzz: built in $((SECONDS - start)) s"

if [ $# -gt 0 ]; then
  fuzzers=("$@")
else
  mapfile -t fuzzers < <(find "$build_dir/tests/fuzz" -maxdepth 1 -type f -executable -name '*_fuzzer' -printf '%f\n' | sort)
fi
if [ ${#fuzzers[@]} -eq 0 ]; then
  echo "fuzz: FAIL: no fuzzers found in $build_dir/tests/fuzz" >&2
  exit 1
fi

# Runs one fuzzer; its output goes to its log, its verdict to stdout.
fuzz_one() {
  local name="$1" binary="$build_dir/tests/fuzz/$1"
  local corpus="$build_dir/corpus/$name" artifacts="$build_dir/artifacts/$name/" log="$build_dir/logs/$name.log"
  local seeds="tests/fuzz/corpus/$name" dict="tests/fuzz/$name.dict"
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  if [ ! -x "$binary" ]; then
    echo "fuzz: $name: FAIL: no such fuzzer $binary"
    return 1
  fi
  local args=(-max_total_time="$seconds" -rss_limit_mb="$rss_mb" -malloc_limit_mb="$malloc_mb" -timeout="$timeout"
              -artifact_prefix="$artifacts" -print_final_stats=1)
  [ -f "$dict" ] && args+=(-dict="$dict")
  local dirs=("$corpus")
  [ -d "$seeds" ] && dirs+=("$seeds")
  echo "+ $binary ${args[*]} ${dirs[*]} > $log"
  local status=0 started
  started=$(date +%s.%N)
  "$binary" "${args[@]}" "${dirs[@]}" > "$log" 2>&1 || status=$?
  local runs
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ "$status" -eq 0 ]; then
    echo "fuzz: $name: PASS: ${runs:-?} executions in ${seconds} s, corpus $(find "$corpus" -type f | wc -l) inputs"
  else
    echo "fuzz: $name: FAIL (exit $status) after ${runs:-?} executions; the end of $log:"
    grep -E "ERROR|SUMMARY|invariant|runtime error|terminate called|what\(\)|#[0-9]+ 0x" "$log" | head -40 | sed 's/^/    /' || true
    find "$artifacts" -type f -newermt "@$started" -printf "    reproduce: $binary %p\n"
  fi
  return "$status"
}

failed=0
pids=()
names=()
for name in "${fuzzers[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  fuzz_one "$name" &
  pids+=($!)
  names+=("$name")
done
failures=()
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || failures+=("${names[$i]}")
done

if [ ${#failures[@]} -eq 0 ]; then
  echo "fuzz: PASS: ${#fuzzers[@]} fuzzers, ${seconds} s each, no crash ($((SECONDS - start)) s in all)"
else
  echo "fuzz: FAIL: ${failures[*]} (of ${#fuzzers[@]} fuzzers; $((SECONDS - start)) s in all)"
  failed=1
fi
exit "$failed"
