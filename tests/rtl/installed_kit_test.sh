#!/usr/bin/env bash
# installed_kit_test.sh BUILD_DIR CMAKE CACHE KIT_FILE...
# `cmake --install` puts the RTL kit (models/rtl_engine/rtl_kit.h) beside the
# binary: every kit file, byte for byte; the installed binary, run from
# elsewhere, finds it and loads the variant the RtlCompile tests compiled
# into CACHE without compiling (the same key: the same files, the same
# build); and the kit alone compiles a model's entry: Verilator on its
# Verilog, then the C++ compiler with only the kit and Verilator's headers on
# the include path.
set -euo pipefail
build=$1 cmake=$2 cache=$3
shift 3
source_dir=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "installed kit test: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" || fail "cmake --install failed: $(cat "$work/install.log")"
kit="$work/prefix/share/cdvp/rtl"
for file in "$@"; do
  cmp -s "$source_dir/$file" "$kit/$file" || fail "$kit/$file is not the source tree's $file"
done
[ "$(cd "$kit" && find . -type f | sort | sed 's|^\./||')" = "$(printf '%s\n' "$@" | sort)" ] ||
  fail "the installed kit holds other files: $(cd "$kit" && find . -type f | sort | tr '\n' ' ')"

mkdir "$work/elsewhere"
cd "$work/elsewhere"
CDVP_RTL_CACHE="$cache" "$work/prefix/bin/cdvp" run --board adm-xrc-ii --m 3 --fifo-depth 5 --pair-buffer 48 \
  --scene spheres --objects 100 --frames 1 -q --fidelity rtl 2> err.txt || fail "the installed binary failed: $(cat err.txt)"
[ ! -s err.txt ] || fail "the installed binary did not load the cached model: $(cat err.txt)"

# The kit alone: Verilator generates the model, the entry compiles against the kit's headers only.
entry="$kit/models/rtl_engine/rtl_model_entry.cpp.in"
verilog=()
for file in "$@"; do case "$file" in *.v|*.vlt) verilog+=("$kit/$file") ;; esac; done
root=$(verilator --getenv VERILATOR_ROOT)
# Both tops, each with the reader of its probes.
for top in collision_board_top:AllPairsTopProbes grid_board_top:GridTopProbes; do
  module=${top%%:*}
  probes=${top##*:}
  rm -rf "$work/obj"
  verilator --cc --Mdir "$work/obj" --prefix Vkit --top-module "$module" --trace -GM=2 -GAW=5 \
    "${verilog[@]}" > "$work/verilator.log" 2>&1 || fail "verilator on the installed kit ($module): $(tail -5 "$work/verilator.log")"
  sed -e 's/@prefix@/Vkit/g' -e 's/@entry@/cdvp_rtl_make_board/g' -e "s/@probes@/$probes/g" "$entry" > "$work/entry.cpp"
  "$compiler" -std=c++17 -fsyntax-only -I "$kit" -I "$work/obj" -I "$root/include" -I "$root/include/vltstd" "$work/entry.cpp" 2> "$work/cxx.log" ||
    fail "the entry of $module does not compile from the kit alone: $(head -5 "$work/cxx.log")"
done
echo "installed kit: $# files, loaded from the cache, the entry of either top compiles from the kit alone"
