#!/usr/bin/env bash
# Lints the whole-board RTL (models/board/rtl/collision_board_top.v and the
# pieces it uses) with Verilator 5 (-Wall, waivers in
# models/board/rtl/verilator.vlt) in several configurations: block RAM and
# tiled, float32 and fixed point, combinational and piped compare lanes; then
# the grid board's blocks (cell function, one-cell filter, cell loader and
# buffer, binning sequencer) in float32 and fixed point, SSRAM latencies 0
# and 8, one lane and many; and the grid board's whole top
# (models/board/rtl/grid_board_top.v) in five configurations.
# Exit status 0 when every configuration is clean.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
command -v verilator >/dev/null || { echo "lint-rtl.sh: verilator not found (scripts/setup.sh installs it)" >&2; exit 2; }
sources=(
  "$root/models/board/rtl/verilator.vlt"
  "$root"/models/board/rtl/*.v
  "$root/models/address_generator/rtl/address_generator.v"
  "$root/models/comparison_unit/rtl/float_le.v"
  "$root/models/comparison_unit/rtl/compare_lane.v"
  "$root/models/pair_collector/rtl/pair_collector.v"
  "$root/models/control_registers/rtl/board_control.v"
)
configurations=(
  ""
  "-GM=1 -GFLOAT=0 -GWIDTH=16"
  "-GM=8 -GAW=10 -GCOMPARE_LATENCY=0 -GFIFO_DISTRIBUTED=1"
  "-GM=24 -GCOMPARE_LATENCY=2 -GBUFFER_DEPTH=262144"
  "-GM=2 -GAW=10 -GTILE_BOXES=64"
  "-GM=3 -GTILE_BOXES=32 -GTILE_LATENCY=0 -GCOMPARE_LATENCY=1 -GFLOAT=0 -GWIDTH=12"
  "-GM=8 -GAW=4 -GTILE_BOXES=1 -GTILE_LATENCY=3"  # tiles of one box: every diagonal block empty
)
status=0
for g in "${configurations[@]}"; do
  # shellcheck disable=SC2086
  if ! verilator --lint-only -Wall --top-module collision_board_top $g "${sources[@]}"; then
    echo "lint-rtl.sh: not clean with '${g:-defaults}'" >&2
    status=1
  fi
done
grid_sources=(
  "$root/models/board/rtl/verilator.vlt"
  "$root/models/grid_binning/rtl/grid_float_add.v"
  "$root/models/grid_binning/rtl/grid_code_float.v"
  "$root/models/grid_binning/rtl/grid_float_divide.v"
  "$root/models/grid_binning/rtl/grid_cell_function.v"
  "$root/models/grid_schedule/rtl/home_cell_filter.v"
  "$root/models/cell_memory/rtl/cell_loader.v"
  "$root/models/cell_memory/rtl/cell_buffer.v"
  "$root/models/cell_memory/rtl/grid_cell_memory.v"
  "$root/models/grid_clocked_engine/rtl/grid_sequencer.v"
)
grid_configurations=(
  "grid_cell_function"
  "grid_cell_function -GFLOAT=0 -GWIDTH=16"
  "grid_cell_function -GFLOAT=0 -GWIDTH=32"
  "home_cell_filter -GLANES=1"
  "home_cell_filter -GLANES=63"
  "cell_loader"
  "cell_loader -GLAT=0 -GFLOAT=0 -GWIDTH=12 -GCAW=4"
  "cell_loader -GLAT=8 -GAW=20 -GEAW=24 -GCAW=16"
  "cell_buffer -GM=1"
  "cell_buffer -GM=8 -GEW=120 -GCAW=10"
  "grid_sequencer"
  "grid_sequencer -GFLOAT=0 -GWIDTH=16 -GLAT=0 -GM=1 -GSPAN=1 -GCW=6 -GAW=10 -GEAW=12 -GCAW=4"
  "grid_sequencer -GLAT=8 -GM=32 -GSPAN=64 -GAW=18 -GEAW=22 -GCAW=16 -GCW=15"
)
for g in "${grid_configurations[@]}"; do
  top=${g%% *}
  parameters=${g#"$top"}
  # shellcheck disable=SC2086
  if ! verilator --lint-only -Wall --top-module "$top" $parameters "${grid_sources[@]}"; then
    echo "lint-rtl.sh: not clean: $g" >&2
    status=1
  fi
done
# The grid board's top: the board's host side and lanes with the grid blocks.
grid_top_configurations=(
  ""
  "-GM=8 -GAW=10 -GCOMPARE_LATENCY=0 -GLAT=0 -GFLOAT=0 -GWIDTH=16 -GCELL_CAPACITY=9 -GMAX_SPAN=1 -GENTRY_CAPACITY=100"
  "-GM=3 -GAW=12 -GCOMPARE_LATENCY=1 -GLAT=8 -GDIMS=11 -GCELL_SIZE=32'h3F800000 -GCELL_CAPACITY=64 -GMAX_SPAN=27 -GENTRY_CAPACITY=110592"
  "-GM=1 -GAW=4 -GFIFO_DEPTH=1 -GBUFFER_DEPTH=1 -GCELL_CAPACITY=2 -GMAX_SPAN=64 -GENTRY_CAPACITY=1024"
  "-GM=2 -GAW=5 -GCELL_CAPACITY=512 -GENTRY_CAPACITY=256"
)
for g in "${grid_top_configurations[@]}"; do
  # shellcheck disable=SC2086
  if ! verilator --lint-only -Wall --top-module grid_board_top $g "${sources[@]}" "${grid_sources[@]:1}"; then
    echo "lint-rtl.sh: not clean: grid_board_top ${g:-defaults}" >&2
    status=1
  fi
done
total=$((${#configurations[@]} + ${#grid_configurations[@]} + ${#grid_top_configurations[@]}))
[[ $status -eq 0 ]] && echo "lint-rtl.sh: $total configurations clean"
exit $status
