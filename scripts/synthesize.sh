#!/usr/bin/env bash
# Synthesises the board's RTL pieces with Yosys and prints one CSV row per
# piece, family and parameter set: the data behind cdvp's resource model
# (models/resources/synthesis.csv).
#
#   scripts/synthesize.sh                  every row, in parallel (GNU parallel), CSV on stdout
#   scripts/synthesize.sh --row FAMILY PIECE FORMAT M
#                                          one row (e.g. xc2v compare_lane float32 -,
#                                          xc2v pair_collector distributed 8); the grid
#                                          board's blocks: grid_cell_function FORMAT -,
#                                          home_cell_filter - M (in the table), and
#                                          cell_loader FORMAT -, cell_buffer FORMAT M (not
#                                          in it: docs/grid_board.md compares them with the model),
#                                          grid_sequencer FORMAT M (its logic, without the
#                                          cell-function units and the cell memory)
#   scripts/synthesize.sh --check FAMILY PIECE FORMAT M
#                                          re-synthesises one row and compares it with the stored one
#   scripts/synthesize.sh --board FAMILY M [FORMAT]
#                                          the whole board (models/board/rtl/collision_board_top.v)
#                                          as one design, a row of piece "board" (FORMAT float32 or
#                                          fixedK, default float32); BOARD_ADDRESS_BITS (default 9:
#                                          512 boxes, one block RAM deep), BOARD_BUFFER_DEPTH
#                                          (default 512 pairs, on chip) and BOARD_FIFO_DISTRIBUTED
#                                          (default 0; 1: the pair FIFO in LUTs) set its memories,
#                                          BOARD_COMPARE_LATENCY (default 2) its lanes. Slow at
#                                          large m (minutes); not part of the full table or ctest.
#
# Needs yosys (Debian: yosys 0.23) and, for the full table, GNU parallel.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
stored="$root/models/resources/synthesis.csv"
header="family,piece,format,m,address_bits,fifo_depth,luts,lutram_luts,flip_flops,carry_cells,block_rams_18k,multipliers"
address_bits=16   # up to 65,536 boxes: the board's largest scene
fifo_depth=512    # the pair FIFO's default depth (models/pair_collector)
tile_boxes=512    # the tile walker's tiles (timing only: its paths run through the box indices)
tile_bits=9
families="xc2v xcup"
ms="1 2 3 4 6 8 12 16 24 32"

die() { echo "synthesize.sh: $*" >&2; exit 2; }

# Yosys's cell statistics (text) -> the CSV's resource columns. Distributed
# RAM and shift registers count the LUTs they occupy: on Virtex-II a 4-input
# LUT holds 16 bits and a dual-port RAM twice its single-port LUTs (Xilinx
# UG002); on UltraScale+ a 6-input LUT holds 64 bits (UG574).
count_cells() {
    awk -v family="$1" '
        BEGIN {
            bits = family == "xc2v" ? 16 : 64
            split("RAM16X1S:16:1 RAM32X1S:32:1 RAM64X1S:64:1 RAM128X1S:128:1 RAM256X1S:256:1 " \
                  "RAM16X1D:16:2 RAM32X1D:32:2 RAM64X1D:64:2 RAM128X1D:128:2 RAM32M:64:4 RAM64M:64:4 " \
                  "RAM32M16:64:8 RAM64M8:64:8", kinds, " ")
            for (i in kinds) {
                split(kinds[i], f, ":")
                per_cell[f[1]] = f[3] * (f[2] > bits ? f[2] / bits : 1)
            }
        }
        $1 ~ /^LUT[1-6]$/                     { luts += $2 }
        $1 in per_cell                        { lutram += per_cell[$1] * $2 }
        $1 ~ /^SRL16E?$|^SRLC16E$|^SRLC32E$/  { lutram += $2 }
        $1 ~ /^FD/                            { ffs += $2 }
        $1 ~ /^MUXCY$|^XORCY$|^CARRY4$|^CARRY8$/ { carry += $2 }
        $1 ~ /^RAMB16/ || $1 ~ /^RAMB18/      { bram += $2 }
        $1 ~ /^RAMB36/                        { bram += 2 * $2 }
        $1 ~ /^MULT18X18/ || $1 ~ /^DSP48/    { mult += $2 }
        END { printf "%d,%d,%d,%d,%d,%d\n", luts, lutram, ffs, carry, bram, mult }'
}

# The chparam arguments of a number format: float32 or fixedK.
format_params() {
    case $1 in
        float32) echo "-set FLOAT 1 -set WIDTH 32" ;;
        fixed*) echo "-set FLOAT 0 -set WIDTH ${1#fixed}" ;;
        *) die "unknown format '$1'" ;;
    esac
}

# The design of one piece: sets 'sources' (Verilog files) and 'params'
# (chparam arguments) for FAMILY PIECE FORMAT M ("-" where a parameter does
# not apply), with the compare lane at LATENCY stages (default: the RTL's 2).
# The timing table (scripts/timing.sh) synthesises the same pieces.
piece_design() {
    local piece=$2 format=$3 m=$4 latency=${5:--}
    black_boxes=""  # Verilog files read as black boxes (their ports only)
    case $piece in
        compare_lane)
            sources="$root/models/comparison_unit/rtl/float_le.v $root/models/comparison_unit/rtl/compare_lane.v"
            params=$(format_params "$format")
            [[ $latency == - ]] || params="$params -set LATENCY $latency" ;;
        address_generator)
            sources="$root/models/address_generator/rtl/address_generator.v"
            params="-set M $m -set AW $address_bits" ;;
        pair_collector)
            sources="$root/models/pair_collector/rtl/pair_collector.v"
            case $format in
                block_ram) params="-set DISTRIBUTED 0" ;;
                distributed) params="-set DISTRIBUTED 1" ;;
                *) die "the pair collector's format is its memory: block_ram or distributed, not '$format'" ;;
            esac
            params="$params -set M $m -set AW $address_bits -set DEPTH $fifo_depth"
            # LATENCY given (2): fed by lanes of compare latency 2 or more, it counts
            # their hits a cycle ahead (COUNT_AHEAD); else it counts its cycle's.
            [[ $latency == - ]] || params="$params -set COUNT_AHEAD 1" ;;
        board_control)
            sources="$root/models/control_registers/rtl/board_control.v"
            params="" ;;
        grid_cell_function)
            sources="$root/models/grid_binning/rtl/grid_float_add.v $root/models/grid_binning/rtl/grid_cell_function.v"
            params=$(format_params "$format") ;;
        home_cell_filter)
            sources="$root/models/grid_schedule/rtl/home_cell_filter.v"
            params="-set LANES $((2 * m - 1))" ;;
        cell_loader)
            sources="$root/models/grid_binning/rtl/grid_float_add.v $root/models/grid_binning/rtl/grid_cell_function.v"
            sources="$sources $root/models/cell_memory/rtl/cell_loader.v"
            params="$(format_params "$format") -set AW $address_bits -set EAW 24 -set CAW 9 -set LAT 2" ;;
        cell_buffer)
            # Entries of 512 boxes: first cells (24 bits), index, six coordinates.
            local width=32
            [[ $format == float32 ]] || width=${format#fixed}
            sources="$root/models/cell_memory/rtl/cell_buffer.v"
            params="-set M $m -set EW $((24 + address_bits + 6 * width)) -set CAW 9" ;;
        grid_sequencer)
            # Its logic alone: the cell-function units are costed as grid_cell_function and
            # the cell memory is the board's SSRAM (docs/grid_board.md), so both are black boxes.
            sources="$root/models/grid_binning/rtl/grid_float_add.v $root/models/grid_binning/rtl/grid_code_float.v"
            sources="$sources $root/models/grid_binning/rtl/grid_float_divide.v $root/models/grid_clocked_engine/rtl/grid_sequencer.v"
            black_boxes="$root/models/grid_binning/rtl/grid_cell_function.v $root/models/cell_memory/rtl/grid_cell_memory.v"
            params="$(format_params "$format") -set M $m -set AW $address_bits -set EAW 24 -set CW 15 -set CAW 9 -set SPAN 8 -set LAT 2" ;;
        tile_walker)
            sources="$root/models/board/rtl/tile_walker.v"
            params="-set M $m -set AW $address_bits -set T $tile_boxes -set TAW $tile_bits -set LAT 2" ;;
        *) die "unknown piece '$piece'" ;;
    esac
}

# One row: FAMILY PIECE FORMAT M ("-" where a parameter does not apply).
row() {
    local family=$1 piece=$2 format=$3 m=$4 sources params black_boxes
    piece_design "$family" "$piece" "$format" "$m"
    local log
    log=$(mktemp)
    trap 'rm -f "$log"' RETURN
    local chparam=""
    [[ -n $params ]] && chparam="chparam $params $piece;"
    local read_black_boxes=""
    [[ -n $black_boxes ]] && read_black_boxes="read_verilog -sv -lib $black_boxes;"
    yosys -q -p "read_verilog -sv $sources; $read_black_boxes $chparam synth_xilinx -family $family -top $piece -flatten -noiopad; tee -q -o $log stat" \
        >/dev/null 2>&1 || die "yosys failed on $piece ($family, $format, m=$m)"
    local depth=-
    [[ $piece == pair_collector ]] && depth=$fifo_depth
    local bits=-
    [[ $piece == address_generator || $piece == pair_collector || $piece == cell_loader || $piece == cell_buffer ||
       $piece == grid_sequencer ]] && bits=$address_bits
    echo "$family,$piece,$format,$m,$bits,$depth,$(count_cells "$family" <"$log")"
}

# The whole board's Verilog files (collision_board_top and every piece).
board_sources() {
    echo "$root/models/board/rtl/collision_board_top.v $root/models/board/rtl/board_host.v $root/models/board/rtl/board_ram.v" \
        "$root/models/board/rtl/tile_walker.v $root/models/address_generator/rtl/address_generator.v" \
        "$root/models/comparison_unit/rtl/float_le.v $root/models/comparison_unit/rtl/compare_lane.v" \
        "$root/models/pair_collector/rtl/pair_collector.v $root/models/control_registers/rtl/board_control.v"
}

# The whole board's chparam arguments: M FORMAT, its memories and compare
# latency from BOARD_ADDRESS_BITS, BOARD_BUFFER_DEPTH, BOARD_FIFO_DISTRIBUTED
# and BOARD_COMPARE_LATENCY (default 2).
board_params() {
    local format
    format=$(format_params "$2")
    echo "$format -set M $1 -set AW ${BOARD_ADDRESS_BITS:-9} -set FIFO_DEPTH $fifo_depth" \
        "-set BUFFER_DEPTH ${BOARD_BUFFER_DEPTH:-512} -set COMPARE_LATENCY ${BOARD_COMPARE_LATENCY:-2}" \
        "-set FIFO_DISTRIBUTED ${BOARD_FIFO_DISTRIBUTED:-0}"
}

# The grid board's Verilog files (grid_board_top and every piece): the seed's
# host side and lanes with the grid blocks.
grid_board_sources() {
    echo "$root/models/board/rtl/grid_board_top.v $root/models/board/rtl/board_host.v $root/models/board/rtl/board_ram.v" \
        "$root/models/comparison_unit/rtl/float_le.v $root/models/comparison_unit/rtl/compare_lane.v" \
        "$root/models/pair_collector/rtl/pair_collector.v $root/models/control_registers/rtl/board_control.v" \
        "$root/models/grid_clocked_engine/rtl/grid_sequencer.v $root/models/cell_memory/rtl/grid_cell_memory.v" \
        "$root/models/cell_memory/rtl/cell_loader.v $root/models/cell_memory/rtl/cell_buffer.v" \
        "$root/models/grid_binning/rtl/grid_cell_function.v $root/models/grid_binning/rtl/grid_float_add.v" \
        "$root/models/grid_binning/rtl/grid_code_float.v $root/models/grid_binning/rtl/grid_float_divide.v" \
        "$root/models/grid_schedule/rtl/home_cell_filter.v"
}

# The grid board's chparam arguments: M FORMAT, with board_params' memories
# and compare latency (its pair FIFO is always in block RAM), the SSRAM's read
# latency from BOARD_SSRAM_LATENCY (default 2: the paper's board) and the
# grid as the settings build it by default (automatic dims and cell size, 512
# boxes a cell, 8 cells a box, 4,096 cell entries).
grid_board_params() {
    local format
    format=$(format_params "$2")
    echo "$format -set M $1 -set AW ${BOARD_ADDRESS_BITS:-9} -set FIFO_DEPTH $fifo_depth" \
        "-set BUFFER_DEPTH ${BOARD_BUFFER_DEPTH:-512} -set COMPARE_LATENCY ${BOARD_COMPARE_LATENCY:-2}" \
        "-set LAT ${BOARD_SSRAM_LATENCY:-2}"
}

# The whole board: FAMILY M FORMAT.
board_row() {
    local family=$1 m=$2 format=${3:-float32} params sources
    local bits=${BOARD_ADDRESS_BITS:-9}
    params=$(board_params "$m" "$format")
    sources=$(board_sources)
    local log
    log=$(mktemp)
    trap 'rm -f "$log"' RETURN
    # shellcheck disable=SC2086
    yosys -q -p "read_verilog -sv $sources; chparam $params collision_board_top; synth_xilinx -family $family -top collision_board_top -flatten -noiopad; tee -q -o $log stat" \
        >/dev/null 2>&1 || die "yosys failed on the board ($family, $format, m=$m)"
    echo "$family,board,$format,$m,$bits,$fifo_depth,$(count_cells "$family" <"$log")"
}

all_rows() {
    for family in $families; do
        echo "$family board_control - -"
        echo "$family compare_lane float32 -"
        for k in $(seq 8 32); do echo "$family compare_lane fixed$k -"; done
        for m in $ms; do
            echo "$family address_generator - $m"
            echo "$family pair_collector block_ram $m"
            echo "$family pair_collector distributed $m"
            echo "$family home_cell_filter - $m"
        done
        echo "$family grid_cell_function float32 -"
        for k in 8 16 24 32; do echo "$family grid_cell_function fixed$k -"; done  # fixedK between: interpolated
        echo "$family grid_sequencer float32 8"  # minutes: its two adders, divider and pass logic flattened
    done
}

# Sourced (scripts/timing.sh) for its functions: no command is run.
[[ ${BASH_SOURCE[0]} == "$0" ]] || return 0

case "${1:-}" in
    --row) shift; [[ $# -eq 4 ]] || die "--row needs FAMILY PIECE FORMAT M"; row "$@" ;;
    --board) shift; [[ $# -eq 2 || $# -eq 3 ]] || die "--board needs FAMILY M [FORMAT]"; board_row "$@" ;;
    --check)
        shift; [[ $# -eq 4 ]] || die "--check needs FAMILY PIECE FORMAT M"
        fresh=$(row "$@")
        key=$(cut -d, -f1-4 <<<"$fresh")
        kept=$(grep -F "$key," "$stored" | head -n 1) || die "$stored: no row for $key"
        if [[ $fresh != "$kept" ]]; then
            echo "synthesize.sh: $key differs from $stored" >&2
            echo "  stored:      $kept" >&2
            echo "  synthesised: $fresh" >&2
            exit 1
        fi
        echo "$fresh" ;;
    "")
        export -f row piece_design format_params count_cells die
        export root address_bits fifo_depth tile_boxes tile_bits
        echo "$header"
        all_rows | parallel --keep-order --jobs "${SYNTH_JOBS:-100%}" --colsep ' ' row {1} {2} {3} {4} ;;
    *) die "unknown option '$1' (see the comment at the top)" ;;
esac
