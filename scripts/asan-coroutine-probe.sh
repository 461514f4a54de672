#!/usr/bin/env bash
# Evidence for the sanitizer settings of scripts/sanitize.sh (docs/testing.md):
# builds a small SystemC design whose threads throw and catch exceptions on
# their coroutine stacks, lets one exception escape a thread, or commits a
# real stack or heap overflow, with and without ASan's use-after-scope
# instrumentation, and runs it with and without fake stacks. Prints one line a
# case; fails if the chosen settings (no scope poisoning, no fake stacks)
# report a false positive or miss a real bug.
#
#   scripts/asan-coroutine-probe.sh          CXX=clang++-14 to try clang
set -euo pipefail
cxx="${CXX:-g++}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cat > "$work/probe.cpp" <<'CPP'
#include <systemc>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
struct Probe : sc_core::sc_module {
    int caught = 0;
    SC_HAS_PROCESS(Probe);
    explicit Probe(sc_core::sc_module_name n) : sc_module(n) {
        SC_THREAD(a);
        SC_THREAD(b);
        if (std::getenv("PROBE_BUG")) { SC_THREAD(c); }
    }
    void deep(int d) { char buf[256]; std::memset(buf, d, sizeof buf); if (d == 0) throw std::runtime_error("x"); deep(d - 1); }
    void a() { for (int i = 0; i < 1000; ++i) { try { deep(20); } catch (const std::exception&) { ++caught; } wait(1, sc_core::SC_NS); } }
    void b() { for (int i = 0; i < 1000; ++i) { try { deep(10); } catch (const std::exception&) { ++caught; } wait(1, sc_core::SC_NS); }
               if (std::getenv("PROBE_ESCAPE")) throw std::runtime_error("escapes the thread"); }
    void c() {
        wait(500, sc_core::SC_NS);
        const char* bug = std::getenv("PROBE_BUG");
        volatile int index = 8;
        if (bug[0] == 's') { char local[8]; std::memset(local, 0, 8); char* p = local; p[index] = 1; std::printf("%d\n", local[0]); }
        else { char* volatile heap = new char[8]; heap[index] = 1; std::printf("%d\n", heap[0]); delete[] heap; }
    }
};
int sc_main(int, char**) {
    Probe probe("probe");
    try { sc_core::sc_start(); } catch (const std::exception& e) { std::printf("sc_start: %s\n", e.what()); }
    return probe.caught == 2000 ? 0 : 1;
}
CPP

export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 SYSTEMC_MEMPOOL_DONT_USE=1
unexpected=0
for scope in on off; do
  flags=(-std=c++17 -O2 -g -fsanitize=address -fno-omit-frame-pointer)
  [ "$scope" = off ] && flags+=(-fno-sanitize-address-use-after-scope)
  "$cxx" "${flags[@]}" "$work/probe.cpp" -o "$work/probe-$scope" $(pkg-config --cflags --libs systemc)
  for fake_stacks in 0 1; do
    for case in caught escape stack-overflow heap-overflow; do
      env=()
      case "$case" in
        escape) env=(PROBE_ESCAPE=1) ;;
        stack-overflow) env=(PROBE_BUG=stack) ;;
        heap-overflow) env=(PROBE_BUG=heap) ;;
      esac
      env "${env[@]}" ASAN_OPTIONS="detect_stack_use_after_return=$fake_stacks" "$work/probe-$scope" \
        > "$work/out" 2>&1 || true
      report=$(sed -n 's/^SUMMARY: AddressSanitizer: \([^ ]*\).*/\1/p' "$work/out" | head -1)
      echo "use-after-scope $scope, fake stacks $fake_stacks, $case: ${report:-no report}"
      if [ "$scope" = off ] && [ "$fake_stacks" = 0 ]; then
        case "$case" in
          caught | escape) [ -z "$report" ] || unexpected=1 ;;
          stack-overflow) [ "$report" = stack-buffer-overflow ] || unexpected=1 ;;
          heap-overflow) [ "$report" = heap-buffer-overflow ] || unexpected=1 ;;
        esac
      fi
    done
  done
done
if [ "$unexpected" -eq 0 ]; then
  echo "probe: PASS: with scope poisoning off and no fake stacks, no false report and both real overflows reported"
else
  echo "probe: FAIL: the chosen settings gave a false report or missed a real overflow"
fi
exit "$unexpected"
