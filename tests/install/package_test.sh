#!/usr/bin/env bash
# package_test.sh BUILD_DIR CMAKE SOURCE_DIR
# Installs the build into a temporary prefix and uses it as a user would:
# Bullet named in the installed targets only as the imported target the
# package finds again; each of examples/ configured and built from a copy
# outside the tree against the prefix (find_package(cdvp), warnings as
# errors), run and its output checked; the Python module imported from the
# prefix and run; a small program built with `pkg-config --cflags --libs cdvp`; then
# the prefix moved, and the package must still configure from its new place.
set -euo pipefail
build=$1 cmake=$2 source=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "package test: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" || fail "cmake --install failed: $(cat "$work/install.log")"
# Bullet reaches the package's users as an imported target found again at
# their configure time (pkg-config's bullet.pc), not as this machine's include
# path and bare library names.
targets=$(cat "$work"/prefix/lib/cmake/cdvp/cdvpTargets*.cmake)
grep -qF 'PkgConfig::Bullet' <<< "$targets" || fail "cdvp::bullet does not link PkgConfig::Bullet"
if grep -nE 'include/bullet|[";:<]((BulletSoftBody|BulletDynamics|BulletCollision|LinearMath))[";>]' <<< "$targets"; then
  fail "the installed targets name Bullet by path or bare library name (above)"
fi
grep -qF 'pkg_check_modules(Bullet REQUIRED IMPORTED_TARGET bullet)' "$work/prefix/lib/cmake/cdvp/cdvpConfig.cmake" ||
  fail "cdvpConfig.cmake does not find Bullet"
# The same for FCL and ODE, which the static cdvp::baselines links privately.
grep -qF 'LINK_ONLY:fcl>' <<< "$targets" || fail "cdvp::baselines does not link FCL's target fcl"
grep -qF 'LINK_ONLY:PkgConfig::ODE>' <<< "$targets" || fail "cdvp::baselines does not link PkgConfig::ODE"
grep -qF 'find_dependency(fcl 0.7)' "$work/prefix/lib/cmake/cdvp/cdvpConfig.cmake" || fail "cdvpConfig.cmake does not find FCL"
grep -qF 'pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)' "$work/prefix/lib/cmake/cdvp/cdvpConfig.cmake" ||
  fail "cdvpConfig.cmake does not find ODE"
cp -r "$source/examples" "$work/examples"
unset CDVP_BOARDS CDVP_BINARY
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)
launcher=()
if command -v ccache > /dev/null; then  # paths relative to $work: a rerun hits the cache
  export CCACHE_BASEDIR=$work CCACHE_NOHASHDIR=1
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

build_example() {  # build_example NAME PREFIX: configures and builds, one job (ctest runs others beside)
  "$cmake" -S "$work/examples/$1" -B "$work/build-$1" "${generator[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$2" -DCMAKE_COMPILE_WARNING_AS_ERROR=ON > "$work/$1.log" 2>&1 &&
    "$cmake" --build "$work/build-$1" -j1 >> "$work/$1.log" 2>&1 || fail "$1 did not build: $(tail -20 "$work/$1.log")"
}
expect() {  # expect NAME TEXT: NAME's output holds TEXT
  grep -qF -- "$2" "$work/$1.out" || fail "$1's output lacks '$2':"$'\n'"$(cat "$work/$1.out")"
}
mkdir "$work/run"
cd "$work/run"

build_example foreign_platform "$work/prefix"
"$work/build-foreign_platform/foreign_platform" > "$work/foreign_platform.out" 2>/dev/null || fail "foreign_platform failed: $(cat "$work/foreign_platform.out")"
expect foreign_platform "refused m too large: override board.m: expected an integer from 1 to 32, got '40'"
expect foreign_platform "refused a bad preset value: bad-preset.json: board.clock_mhz: expected 1 to 1000 MHz, got -66"
[ "$(grep -c '^frame [0-9]*: 400 boxes, [0-9]* pairs (= all-pairs test)' "$work/foreign_platform.out")" = 4 ] ||
  fail "foreign_platform did not match the all-pairs test on 4 frames: $(cat "$work/foreign_platform.out")"
expect foreign_platform "4 frames, 491 pairs, 0 mismatches"
expect foreign_platform "bus: 38400 bytes of boxes uploaded, 3928 bytes of pairs read back"
# Delta uploads and the encoded pair formats need host memory for their
# records and words: the example sizes it as the platform does.
preset=$(find "$work/prefix" -name adm-xrc-ii.json | head -1)
for format in counted bitmap; do
  "$work/build-foreign_platform/foreign_platform" "$preset" 400 4 \
    driver.upload=delta driver.pair_format=$format > "$work/foreign_platform.out" 2>&1 ||
    fail "foreign_platform with delta uploads and $format pairs failed: $(cat "$work/foreign_platform.out")"
  expect foreign_platform "4 frames, 491 pairs, 0 mismatches"
  expect foreign_platform "bus: 44800 bytes of boxes uploaded"  # 28-byte records
done

build_example bullet_app "$work/prefix"
"$work/build-bullet_app/bullet_app" > "$work/bullet_app.out" 2>/dev/null || fail "bullet_app failed: $(cat "$work/bullet_app.out")"
expect bullet_app "120 steps, 40 bodies"
expect bullet_app "0 failing steps"
expect bullet_app "43 of 43 bodies bit-identical to btSimpleBroadphase; rays the same"
expect bullet_app "240 rays"
expect bullet_app "the same as btSimpleBroadphase's; the CCD projectile stopped by the wall 4 times of 4"

build_example study_api "$work/prefix"
"$work/build-study_api/study_api" > "$work/study_api.out" 2>&1 || fail "study_api failed: $(cat "$work/study_api.out")"
for objects in 100 200 400; do expect study_api "N=$objects  4 frames"; done
expect study_api "refused: status 2: cdvp run: -c board.m: expected an integer from 1 to 32"
expect study_api "analytic, in this process: 3 frames"
expect study_api "status 0, 2 rows (2 ok, 0 refused, 0 faulted)"

# Python: the installed module, imported with the prefix's site-packages on
# PYTHONPATH by Debian's python3, runs several configurations in one process on
# the prefix's own binary and presets, and refuses a bad value naming its keyword.
site=$(find "$work/prefix" -type d -name dist-packages | head -1)
[ -n "$site" ] && [ -f "$site/cdvp/__init__.py" ] || fail "no cdvp Python package under $work/prefix"
PYTHONPATH=$site /usr/bin/python3 - "$work/prefix" > "$work/python.out" 2>&1 <<'PYTHON' || fail "the installed Python module failed: $(cat "$work/python.out")"
import os, sys
import cdvp
prefix = os.path.realpath(sys.argv[1])
assert os.path.realpath(cdvp.find_binary()).startswith(prefix), cdvp.find_binary()
assert "adm-xrc-ii" in cdvp.presets()
for m in (4, 8):
    report = cdvp.run(board="adm-xrc-ii", scene="spheres", objects=60, frames=2, m=m)
    print("m", m, "frames", len(report.frames), "pairs", int(report.frames["pairs"].sum()))
try:
    cdvp.run(board="adm-xrc-ii", scene="spheres", objects=-1)
    raise SystemExit("a bad value was not refused")
except cdvp.InputError as error:
    print("refused", error.status, error)
PYTHON
[ "$(grep -c '^m [48] frames 2 pairs [0-9]' "$work/python.out")" = 2 ] || fail "the installed module's runs: $(cat "$work/python.out")"
grep -qF "refused 2 cdvp.run: objects=: expected 0 to" "$work/python.out" ||
  fail "the installed module's refusal: $(cat "$work/python.out")"

# pkg-config: the board's headers and every library, in link order.
cat > "$work/pc_program.cpp" <<'PROGRAM'
#include <cstdio>
#include "models/board/collision_board.h"
#include "platform/driver/board_driver.h"
#include "platform/kernel.h"
#include "sw/baselines/broad_phase.h"
int sc_main(int, char*[]) {
    // The baselines over FCL and ODE link from the flags alone: two touching boxes, one apart.
    const std::vector<cdvp::FloatBox> boxes{{{0, 0, 0}, {1, 1, 1}}, {{1, 0, 0}, {2, 1, 1}}, {{5, 5, 5}, {6, 6, 6}}};
    for (const char* name : {"fcl_tree", "ode_hash"}) {
        cdvp::PairList pairs;
        cdvp::make_broad_phase(name)->find_pairs(boxes, pairs);
        std::printf("%s: %zu pair\n", name, pairs.size());
    }
    cdvp::configure_kernel();
    cdvp::CollisionBoard board("board", cdvp::BoardConfig{}, 1000);
    std::printf("board of %u boxes, %u lanes; the driver needs %llu bytes of host memory\n", board.core().capacity(),
                cdvp::BoardConfig{}.lanes(), static_cast<unsigned long long>(cdvp::BoardDriver::host_memory_bytes(1000, 4096)));
    return 0;
}
PROGRAM
export PKG_CONFIG_PATH=$work/prefix/lib/pkgconfig
# shellcheck disable=SC2046  # pkg-config's words are meant to split
g++ -Wall -Wextra -Werror -o "$work/pc_program" "$work/pc_program.cpp" $(pkg-config --cflags --libs cdvp) 2> "$work/pc.log" ||
  fail "pkg-config build failed: $(head -20 "$work/pc.log")"
"$work/pc_program" > "$work/pc_program.out" 2>/dev/null || fail "the pkg-config program failed"
expect pc_program "board of 1000 boxes, 15 lanes"
expect pc_program "fcl_tree: 1 pair"
expect pc_program "ode_hash: 1 pair"

# A public header that moved still builds from its old path, through an
# installed forwarding header that says where it went; each names a header
# the prefix has.
forwarding=$(cd "$source/cmake/moved_headers" && find . -name '*.h' | sed 's|^\./||' | sort)
[ -n "$forwarding" ] || fail "no forwarding headers in cmake/moved_headers"
for old in $forwarding; do
  [ -f "$work/prefix/include/cdvp/$old" ] || fail "the forwarding header $old is not installed"
  new=$(sed -n 's/^#include "\(.*\)"$/\1/p' "$work/prefix/include/cdvp/$old")
  [ -f "$work/prefix/include/cdvp/$new" ] || fail "$old forwards to $new, which is not installed"
  printf '#include "%s"\nint main() { return 0; }\n' "$old" > "$work/moved_header.cpp"
  # shellcheck disable=SC2046  # pkg-config's words are meant to split
  g++ -Wall -Wextra -Werror -fsyntax-only $(pkg-config --cflags cdvp) "$work/moved_header.cpp" 2> "$work/moved.log" ||
    fail "a program including $old did not build: $(head -5 "$work/moved.log")"
  grep -qF "$old is deprecated: include \"$new\"" "$work/moved.log" || fail "$old builds without its note: $(cat "$work/moved.log")"
done
grep -qF 'namespace cdvp' "$work/prefix/include/cdvp/platform/settings/board_preset.h" || fail "platform/settings/board_preset.h"
# A forwarding header never stands where the tree has a real one (installed
# after the tree's headers, it would replace it).
for old in $forwarding; do
  [ ! -e "$source/$old" ] || fail "cmake/moved_headers/$old would replace the tree's own $old"
done
# docs/library.md says what is public: every header its tables there name
# (the public ones, and the old paths of those that moved) is in the prefix,
# and its table of moved headers is cmake/moved_headers, pair for pair.
public_tables=$(sed -n '/^## The public headers/,/^## Embedding/p' "$source/docs/library.md" | grep '^|')
named=$(grep -o '`[A-Za-z0-9_/]*\.h`' <<< "$public_tables" | tr -d '`' | sort -u)
[ -n "$named" ] || fail "docs/library.md names no public header"
for header in $named; do
  [ -f "$work/prefix/include/cdvp/$header" ] || fail "docs/library.md names $header as public, and the prefix has no $header"
done
documented=$(sed -n 's/^| `\([^`]*\.h\)` | `\([^`]*\.h\)` |$/\1 -> \2/p' <<< "$public_tables" | sort)
installed=$(for old in $forwarding; do
  echo "$old -> $(sed -n 's/^#include "\(.*\)"$/\1/p' "$work/prefix/include/cdvp/$old")"
done | sort)
[ "$documented" = "$installed" ] ||
  fail "docs/library.md's moved headers ($documented) are not the forwarding headers installed ($installed)"

# Relocatable: the moved prefix's package names its own places.
mv "$work/prefix" "$work/moved"
mkdir "$work/probe"
cat > "$work/probe/CMakeLists.txt" <<'PROBE'
cmake_minimum_required(VERSION 3.16)
project(probe CXX)
find_package(cdvp CONFIG REQUIRED)
get_target_property(include_dirs cdvp::base INTERFACE_INCLUDE_DIRECTORIES)
message(STATUS "boards: ${cdvp_BOARDS_DIR}; binary: ${cdvp_EXECUTABLE}; includes: ${include_dirs}")
PROBE
"$cmake" -S "$work/probe" -B "$work/build-probe" -DCMAKE_PREFIX_PATH="$work/moved" > "$work/probe.out" 2>&1 ||
  fail "the moved package does not configure: $(cat "$work/probe.out")"
expect probe "boards: $work/moved/share/cdvp/boards; binary: $work/moved/bin/cdvp; includes: $work/moved/include/cdvp"
[ "$(PKG_CONFIG_PATH=$work/moved/lib/pkgconfig pkg-config --variable=includedir cdvp)" -ef "$work/moved/include/cdvp" ] ||
  fail "the moved cdvp.pc names $(PKG_CONFIG_PATH=$work/moved/lib/pkgconfig pkg-config --variable=includedir cdvp)"
echo "examples built and checked against $work/prefix; pkg-config program ran; moved headers build from their old paths with their note, as docs/library.md lists them; the moved package configures"
