#!/usr/bin/env bash
# Estimates how fast each board piece can be clocked: synthesises it with
# Yosys (the pieces of scripts/synthesize.sh), puts every port behind the
# register or block RAM that feeds or takes it on the board, and runs
# Yosys's static timing analysis (sta) with the family's cell delays
# (models/resources/timing_arcs.txt, delays.csv). One CSV row a piece,
# parameter set and speed grade: the longest register-to-register path in
# ns and what it runs through; cdvp compiles the table in
# (models/resources/timing.csv).
#
#   scripts/timing.sh                  every row, in parallel (GNU parallel), CSV on stdout
#   scripts/timing.sh --row FAMILY PIECE FORMAT M LATENCY
#                                      the rows of one synthesis, one a speed grade (e.g.
#                                      xc2v compare_lane float32 - 2, xcup pair_collector block_ram 8 -;
#                                      the pair FIFO's LATENCY 2: its hits counted a cycle ahead;
#                                      the grid board's: grid_cell_function FORMAT - -, cell_loader
#                                      FORMAT - -, home_cell_filter - M -, grid_sequencer float32 8 -)
#   scripts/timing.sh --check FAMILY PIECE FORMAT M LATENCY
#                                      re-derives those rows and compares them with the stored ones
#   scripts/timing.sh --path FAMILY PIECE FORMAT M LATENCY GRADE
#                                      sta's report of the critical path, to read
#   scripts/timing.sh --board [BOARD] FAMILY GRADE M [FORMAT]
#                                      the whole board as one design, sta's report of its longest
#                                      path, across the pieces' boundaries (minutes at large m).
#                                      BOARD all_pairs (default: collision_board_top, with
#                                      scripts/synthesize.sh --board's parameters and BOARD_* knobs)
#                                      or grid (grid_board_top: synthesize.sh's grid_board_params,
#                                      BOARD_SSRAM_LATENCY its SSRAM's read latency, default 2)
#   scripts/timing.sh --board-row BOARD FAMILY M [FORMAT]
#                                      the whole board's rows of the whole-board table, one a speed
#                                      grade (models/resources/whole_board_timing.csv: the clock's
#                                      check beside the pieces'); keyed by its compare latency
#                                      (BOARD_COMPARE_LATENCY), pair FIFO memory
#                                      (BOARD_FIFO_DISTRIBUTED) and address bits (BOARD_ADDRESS_BITS)
#   scripts/timing.sh --board-check BOARD FAMILY M [FORMAT]
#                                      re-derives those rows and compares them with the stored ones
#   scripts/timing.sh --board-table    the whole-board table's rows (all_board_rows), in parallel (GNU
#                                      parallel, SYNTH_JOBS at a time); CSV on stdout (minutes a row at
#                                      m = 8, more at large m)
#
# Needs yosys (Debian: yosys 0.23) and, for the full table, GNU parallel.
set -euo pipefail
shopt -s inherit_errexit

here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=scripts/synthesize.sh
source "$here/synthesize.sh"
die() { echo "timing.sh: $*" >&2; exit 2; }

timing_stored="$root/models/resources/timing.csv"
arcs="$root/models/resources/timing_arcs.txt"
delays="$root/models/resources/delays.csv"
timing_header="family,piece,format,m,latency,speed_grade,path_ns,luts,carry_cells,wide_muxes,from,to"
whole_board_stored="$root/models/resources/whole_board_timing.csv"
latencies="0 1 2"   # compare stages; more only delay the AND (compare_lane.v)

# Ports that meet a block RAM on the board (their other ports meet registers).
# The grid sequencer's cell memory is the board's SSRAM, as its resource row
# takes it (its ports, everted from the black box, named memory__PORT; a
# name ending in * is a prefix); the SSRAM's read stages and the
# cell-function units' stages are registers.
from_ram_ports() {
    case $1 in
        compare_lane) echo "box_i box_j" ;;
        grid_sequencer) echo 'memory__*' ;;
        *) echo "" ;;
    esac
}
to_ram_ports() {
    case $1 in
        address_generator) echo "row columns" ;;
        tile_walker) echo "row_local columns_local land_addr" ;;
        pair_collector) echo "out_pair out_valid" ;;
        cell_loader) echo "write write_half write_addr write_data" ;;
        grid_sequencer) echo 'memory__*' ;;
        *) echo "" ;;
    esac
}

# The speed grades of a family (delays.csv), slowest first.
speed_grades() {
    awk -F, -v family="$1" 'NR > 1 && $1 == family { print $2 }' "$delays" | sort -n -u | tr '\n' ' '
}

# Yosys -D flags for FAMILY GRADE: every delay parameter in picoseconds. A
# grade given as SCALE takes the slowest grade's delays times the factor.
delay_flags() {
    awk -F, -v family="$1" -v grade="$2" '
        NR == 1 || $1 != family { next }
        { if (base == "" || $2 + 0 < base + 0) base = $2 }
        $2 == grade && $3 == "SCALE" { scale = $4 }
        { value[$2 "," $3] = $4 }
        END {
            if (base == "") { print "no delays for the family " family > "/dev/stderr"; exit 2 }
            from = scale != "" ? base : grade
            if (scale == "") scale = 1
            for (key in value) {
                split(key, k, ",")
                if (k[1] != from || k[2] == "SCALE") continue
                printf "-D%s=%d ", k[2], value[key] * scale * 1000 + 0.5; found = 1
            }
            if (!found) { print "no delays for " family " speed grade " grade > "/dev/stderr"; exit 2 }
        }' "$delays"
}

# Blackbox timing models of CELLS for FAMILY: the ports of Yosys's own cell
# library, specify entries from the arcs file. Boundary cells (TIMING_*) are
# the harness's own.
timing_cells() {
    local family=$1; shift
    local select="" cell ports
    for cell in "$@"; do [[ $cell == TIMING_* ]] || select+=" =$cell"; done
    ports=$(mktemp)
    # shellcheck disable=SC2064
    trap "rm -f '$ports'" RETURN
    yosys -q -p "read_verilog -lib +/xilinx/cells_sim.v; read_verilog -lib +/xilinx/cells_xtra.v; select$select; write_verilog -blackboxes -selected $ports" \
        >/dev/null 2>&1 || die "yosys could not list the ports of$select"
    for cell in "$@"; do
        [[ $cell == TIMING_* ]] && printf 'module %s(O, I);\n  input I;\n  output O;\nendmodule\n' "$cell" >>"$ports"
    done
    awk -v family="$family" -v wanted=" $* " '
        FNR == NR {
            if ($0 ~ /^[ \t]*#/ || NF < 6) next
            n = split($1, families, ","); mine = 0
            for (i = 1; i <= n; i++) if (families[i] == family) mine = 1
            if (!mine) next
            n = split($2, cells, ",")
            for (i = 1; i <= n; i++) arcs[cells[i]] = arcs[cells[i]] $3 " " $4 " " $5 " " $6 "\n"
            next
        }
        /^module / {
            name = $2; sub(/\(.*/, "", name)
            keep = index(wanted, " " name " ") > 0
            if (keep) { print "(* blackbox *)"; print }
            header = $0 !~ /\);$/
            split("", dir); ports = 0
            next
        }
        !keep { next }
        header { print; header = $0 !~ /\);$/; next }
        /^  (input|output) / { port = $NF; sub(/;$/, "", port); dir[port] = $1; order[++ports] = port; print; next }
        /^endmodule/ {
            if (!(name in arcs)) { print "timing.sh: no timing arcs for the cell " name " (" family ")" > "/dev/stderr"; exit 2 }
            print "  specify"
            n = split(arcs[name], lines, "\n")
            for (l = 1; l <= n; l++) {
                if (lines[l] == "") continue
                split(lines[l], f, " ")
                terms = split(f[4], term, "+"); delay = ""
                for (t = 1; t <= terms; t++) delay = delay (t > 1 ? " + " : "") "`" term[t]
                nf = split(f[2], from, ","); nt = split(f[3], to, ",")
                if (f[2] == "*") { nf = 0; for (p = 1; p <= ports; p++) if (dir[order[p]] == "input") from[++nf] = order[p] }
                for (a = 1; a <= nf; a++) for (b = 1; b <= nt; b++) {
                    if (!(from[a] in dir) || !(to[b] in dir)) continue
                    if (f[1] == "comb") print "    (" from[a] " *> " to[b] ") = " delay ";"
                    else if (f[1] == "clock") print "    (posedge " from[a] " *> (" to[b] " : " to[b] ")) = " delay ";"
                    else if (f[1] == "setup") print "    $setup(" from[a] ", posedge " to[b] ", " delay ");"
                }
            }
            print "  endspecify"; print
        }' "$arcs" "$ports"
}

# A netlist without its cells' parameters (timing needs none, and a
# blackbox would have to declare them all).
strip_parameters() {
    awk '/^  [A-Za-z][A-Za-z0-9_]* #\($/ { type = $1; skip = 1; next }
         skip && /^  \) .* \($/ { sub(/^  \) /, ""); print "  " type " " $0; skip = 0; next }
         skip { next }
         { print }' "$1"
}

# The harness around module 'piece': every port but clk behind a boundary
# cell, as the board drives and takes it (FROM_RAM, TO_RAM: block RAM ports).
harness() {
    awk -v from_ram="$2" -v to_ram="$3" '
        function listed(list, name,    n, k, item) {
            n = split(list, item, " ")
            for (k = 1; k <= n; k++) {
                if (item[k] == name) return 1
                if (item[k] ~ /\*$/ && index(name, substr(item[k], 1, length(item[k]) - 1)) == 1) return 1
            }
            return 0
        }
        /^module piece[ (]/ { inside = 1; next }
        inside && /^endmodule/ { exit }
        inside && /^  (input|output) / {
            width = $0 ~ /\[/ ? $2 " " : ""
            name = $NF; sub(/;$/, "", name)
            if (name ~ /__clk$/) next  # an everted black box clock: the clock itself
            high = 0
            if (width != "") { w = width; gsub(/[\[\] ]/, "", w); split(w, r, ":"); high = r[1] }
            ports = ports ", " name
            decl = decl "  " $1 " " width name ";\n"
            if (name == "clk") { conn = conn ", .clk(clk)"; next }
            decl = decl "  wire " width name "_q;\n"
            conn = conn ", ." name "(" name "_q)"
            if ($1 == "input") {
                cell = listed(from_ram, name) ? "TIMING_FROM_RAM" : "TIMING_FROM_FF"
                body = body "  " cell " " name "_boundary [" high ":0] (.I(" name "), .O(" name "_q));\n"
            } else {
                cell = listed(to_ram, name) ? "TIMING_TO_RAM" : "TIMING_TO_FF"
                body = body "  " cell " " name "_boundary [" high ":0] (.I(" name "_q), .O(" name "));\n"
            }
        }
        END {
            print "module timing_harness(" substr(ports, 3) ");"
            printf "%s%s", decl, body
            print "  piece dut(" substr(conn, 3) ");"
            print "endmodule"
        }' "$1"
}

# sta's report -> path_ns,luts,carry_cells,wide_muxes,from,to
path_fields() {
    awk '
        /^Latest arrival time in / { on = 1; ps = $NF; sub(/:$/, "", ps); next }
        on && /^Arrival histogram/ { on = 0 }
        on && /\([A-Za-z0-9_]+\.[^)]*\)$/ {
            cell = $NF; gsub(/[()]/, "", cell); split(cell, c, "."); type = c[1]
            if (first == "") first = type
            last = type
            if (type ~ /^(LUT[1-6]|INV)$/) luts++
            else if (type ~ /^(MUXCY|XORCY|CARRY4|CARRY8)$/) carry++
            else if (type ~ /^MUXF[5-9]$/) muxes++
        }
        function kind(type) {
            if (type ~ /RAM$|^RAMB/) return "block_ram"
            if (type ~ /^RAM(16|32|64|128)/) return "lut_ram"
            return "flip_flop"
        }
        END {
            if (ps == "") { print "timing.sh: sta found no path" > "/dev/stderr"; exit 2 }
            printf "%.3f,%d,%d,%d,%s,%s\n", ps / 1000, luts, carry, muxes, kind(last), kind(first)
        }'
}

# The timing models of every cell the arcs file names for FAMILY, into FILE.
family_cells() {
    # shellcheck disable=SC2046
    timing_cells "$1" $(awk -v family="$1" '!/^[ \t]*#/ && NF >= 6 && index("," $1 ",", "," family ",") {
        n = split($2, cells, ","); for (i = 1; i <= n; i++) print cells[i] }' "$arcs" | sort -u) >"$2"
}

# Synthesises one design into DIR: netlist.v (parameters stripped) and
# harness.v, with cells.v the family's cell models (TIMING_CELLS_DIR keeps one
# a family for a whole table). Arguments: FAMILY TOP "SOURCES" "PARAMS"
# "FROM_RAM" "TO_RAM" ["BLACK_BOXES"]. Black boxes (piece_design's) are
# everted: their connections become the piece's ports, INSTANCE__PORT, and
# meet the harness's boundary cells like the others.
prepare() {
    local dir=$1 family=$2 top=$3 sources=$4 params=$5 from_ram=$6 to_ram=$7 black_boxes=${8:-}
    local chparam="" cells read_black_boxes="" evert=""
    [[ -n $params ]] && chparam="chparam $params $top;"
    if [[ -n $black_boxes ]]; then
        read_black_boxes="read_verilog -sv -lib $black_boxes;"
        evert="expose -evert$(for file in $black_boxes; do printf ' t:%s' "$(basename "$file" .v)"; done);"
    fi
    yosys -q -p "read_verilog -sv $sources; $read_black_boxes $chparam synth_xilinx -family $family -top $top -flatten -noiopad; rename -top piece; $evert write_verilog -noattr $dir/raw.v" \
        >/dev/null 2>&1 || die "yosys failed on $top ($family: $params)"
    # An everted port's escaped name (\memory.box_full) as a plain one (memory__box_full).
    perl -pe 's/\\(\S*\.\S*) /my $n = $1; $n =~ s{\.}{__}g; $n =~ s{\W}{_}g; $n/ge' "$dir/raw.v" >"$dir/plain.v"
    strip_parameters "$dir/plain.v" >"$dir/netlist.v"
    harness "$dir/netlist.v" "$from_ram" "$to_ram" >"$dir/harness.v"
    cells=${TIMING_CELLS_DIR:-}/$family.v
    if [[ -n ${TIMING_CELLS_DIR:-} && -s $cells ]]; then
        cp "$cells" "$dir/cells.v"
    else
        family_cells "$family" "$dir/cells.v"
    fi
    # Every cell of the netlist has its arcs (a missing one would be a shorter path).
    local cell
    for cell in $(grep -oE '^  [A-Z][A-Za-z0-9_]* ' "$dir/netlist.v" | sort -u); do
        grep -q "^module $cell(" "$dir/cells.v" || die "no timing arcs for the cell $cell ($family, $top)"
    done
}

# sta on a prepared DIR at FAMILY GRADE; the report on stdout. A cell without
# arcs, a path that ends nowhere or an output no path reaches is an error,
# not a shorter path; with a fourth argument an output no path reaches is
# taken for a constant (the whole board's tied-off ports).
analyse() {
    local dir=$1 family=$2 grade=$3 constants=${4:-} flags report problems
    flags=$(delay_flags "$family" "$grade")
    report=$(yosys -p "read_verilog -lib -specify $flags $dir/cells.v; read_verilog $dir/netlist.v $dir/harness.v; hierarchy -top timing_harness; flatten; sta" 2>&1) ||
        die "yosys sta failed ($family -$grade): $(grep -m1 ERROR <<<"$report")"
    problems="not recognised|no timing arcs|does not terminate"
    [[ -n $constants ]] || problems+="|no \(\* sta_arrival"
    if grep -qE "$problems" <<<"$report"; then
        die "sta ($family -$grade): $(grep -m1 -E "$problems" <<<"$report")"
    fi
    echo "$report"
}

# A piece's design as timed: piece_design's (sources, params, black_boxes),
# with the controller's 64-bit counters and the model's phase rules, and the
# cell loader's cell-function units as black boxes (their stages are
# registers; they have rows of their own), so its row is its own logic.
# Sets 'constants' where an endpoint no path reaches is a constant, not an
# error, as on the whole board: the grid pieces' fixed-point words narrower
# than a unit's register or a black box's port are tied off above their width.
timing_design() {
    piece_design "$@"
    case $2 in
        board_control) params="-set CW 64 -set MODEL_TIMING 1" ;;
        cell_loader)
            local unit="$root/models/grid_binning/rtl/grid_cell_function.v"
            sources=${sources/" $unit"/}
            black_boxes=$unit ;;
    esac
    constants=""
    case $2 in grid_cell_function | cell_loader | grid_sequencer) constants=constants ;; esac
}

# The rows of one piece: FAMILY PIECE FORMAT M LATENCY, one a speed grade.
timing_rows() {
    local family=$1 piece=$2 format=$3 m=$4 latency=$5 sources params black_boxes constants dir grade
    timing_design "$family" "$piece" "$format" "$m" "$latency"
    dir=$(mktemp -d)
    # shellcheck disable=SC2064
    trap "rm -rf '$dir'" RETURN
    prepare "$dir" "$family" "$piece" "$sources" "$params" "$(from_ram_ports "$piece")" "$(to_ram_ports "$piece")" \
        "$black_boxes"
    local fields
    for grade in $(speed_grades "$family"); do
        fields=$(analyse "$dir" "$family" "$grade" "$constants" | path_fields)
        echo "$family,$piece,$format,$m,$latency,$grade,$fields"
    done
}

# Every row's synthesis: FAMILY PIECE FORMAT M LATENCY.
all_timing_rows() {
    local family k m latency format
    for family in $families; do
        echo "$family board_control - - -"
        for latency in $latencies; do
            echo "$family compare_lane float32 - $latency"
            for k in $(seq 8 32); do echo "$family compare_lane fixed$k - $latency"; done
        done
        for m in $ms; do
            echo "$family address_generator - $m -"
            echo "$family tile_walker - $m -"
            for latency in - 2; do  # 2: the hits counted a cycle ahead (lanes of latency 2 or more)
                echo "$family pair_collector block_ram $m $latency"
                echo "$family pair_collector distributed $m $latency"
            done
            echo "$family home_cell_filter - $m -"
        done
        for format in float32 fixed8 fixed16 fixed24 fixed32; do  # the synthesis table's; fixedK between: the slower
            echo "$family grid_cell_function $format - -"
            echo "$family cell_loader $format - -"
        done
        echo "$family grid_sequencer float32 8 -"  # minutes: its adders, divider and pass logic flattened
    done
}

# The whole board's design: BOARD M FORMAT sets 'top', 'sources' and 'params'.
board_design() {
    case $1 in
        all_pairs) top=collision_board_top; sources=$(board_sources); params=$(board_params "$2" "$3") ;;
        grid) top=grid_board_top; sources=$(grid_board_sources); params=$(grid_board_params "$2" "$3") ;;
        *) die "the board is all_pairs or grid, not '$1'" ;;
    esac
}

# The whole board as one design, synthesised into DIR: BOARD FAMILY M FORMAT,
# its ports behind registers (the host bus and SSRAM interfaces).
prepare_board() {
    local dir=$1 board=$2 family=$3 m=$4 format=$5 top sources params
    board_design "$board" "$m" "$format"
    prepare "$dir" "$family" "$top" "$sources" "$params" "" ""
}

# sta's report of the whole board's longest path: [BOARD] FAMILY GRADE M [FORMAT].
board_timing() {
    local board=all_pairs dir
    [[ $1 == all_pairs || $1 == grid ]] && { board=$1; shift; }
    [[ $# -eq 3 || $# -eq 4 ]] || die "--board needs [BOARD] FAMILY GRADE M [FORMAT]"
    dir=$(mktemp -d)
    # shellcheck disable=SC2064
    trap "rm -rf '$dir'" RETURN
    prepare_board "$dir" "$board" "$1" "$3" "${4:-float32}"
    analyse "$dir" "$1" "$2" constants | sed -n '/^Latest arrival/,/^Arrival histogram/p' | sed '$d'
}

# The whole board's rows: BOARD FAMILY M [FORMAT], one a speed grade, in the
# whole-board table's columns. The pair buffer is the table's (512 pairs on
# chip: its rows say nothing of another).
board_rows() {
    local board=$1 family=$2 m=$3 format=${4:-float32} dir grade fields fifo=block_ram
    [[ ${BOARD_BUFFER_DEPTH:-512} == 512 ]] || die "the whole-board table's rows have a pair buffer of 512 pairs, not BOARD_BUFFER_DEPTH=$BOARD_BUFFER_DEPTH"
    if [[ ${BOARD_FIFO_DISTRIBUTED:-0} != 0 ]]; then
        [[ $board == all_pairs ]] || die "the grid board's pair FIFO is in block RAM (BOARD_FIFO_DISTRIBUTED=$BOARD_FIFO_DISTRIBUTED)"
        fifo=distributed
    fi
    dir=$(mktemp -d)
    # shellcheck disable=SC2064
    trap "rm -rf '$dir'" RETURN
    prepare_board "$dir" "$board" "$family" "$m" "$format"
    for grade in $(speed_grades "$family"); do
        fields=$(analyse "$dir" "$family" "$grade" constants | path_fields)
        echo "$family,$board,$format,$m,${BOARD_COMPARE_LATENCY:-2},$fifo,${BOARD_ADDRESS_BITS:-9},$grade,$fields"
    done
}

# The whole-board table's syntheses: BOARD FAMILY M FORMAT FIFO_DISTRIBUTED.
# (The stored table holds the float32 rows at m = 1 and 8 on xc2v and m = 8
# on xcup so far; this list is the table to come.)
# float32 and fixed16 at m = 1 and the presets' default m = 8, and at the
# largest m that fits 500 boxes (cdvp run's fit line): on the paper's
# XC2V6000 24 in float32, its pair FIFO in LUTs (the boxes take every block
# RAM), and 32 in fixed16; 32 on the UltraScale+ presets.
all_board_rows() {
    local format family
    for format in float32 fixed16; do
        for family in $families; do
            echo "all_pairs $family 1 $format 0"
            echo "all_pairs $family 8 $format 0"
        done
    done
    echo "all_pairs xc2v 24 float32 1"
    echo "all_pairs xc2v 32 fixed16 0"
    echo "all_pairs xcup 32 float32 0"
    echo "all_pairs xcup 32 fixed16 0"
}

# One whole-board synthesis's rows: BOARD FAMILY M FORMAT FIFO_DISTRIBUTED.
board_rows_with_fifo() {
    BOARD_FIFO_DISTRIBUTED=$5 board_rows "$1" "$2" "$3" "$4"
}

# Re-derived rows FRESH against the rows of STORED starting with KEY: printed
# when the same, else both shown and exit 1.
same_as_stored() {
    local key=$1 stored=$2 fresh=$3 kept
    kept=$(grep -F "$key," "$stored") || die "$stored: no rows for $key"
    if [[ $fresh != "$kept" ]]; then
        echo "timing.sh: $key differs from $stored" >&2
        echo "  stored:" >&2; sed 's/^/    /' <<<"$kept" >&2
        echo "  derived:" >&2; sed 's/^/    /' <<<"$fresh" >&2
        exit 1
    fi
    echo "$fresh"
}

[[ ${BASH_SOURCE[0]} == "$0" ]] || return 0

case "${1:-}" in
    --row) shift; [[ $# -eq 5 ]] || die "--row needs FAMILY PIECE FORMAT M LATENCY"; timing_rows "$@" ;;
    --path)
        shift; [[ $# -eq 6 ]] || die "--path needs FAMILY PIECE FORMAT M LATENCY GRADE"
        timing_design "$1" "$2" "$3" "$4" "$5"
        dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
        prepare "$dir" "$1" "$2" "$sources" "$params" "$(from_ram_ports "$2")" "$(to_ram_ports "$2")" "$black_boxes"
        analyse "$dir" "$1" "$6" "$constants" | sed -n '/^Latest arrival/,/^Arrival histogram/p' | sed '$d' ;;
    --board) shift; board_timing "$@" ;;
    --board-row) shift; [[ $# -eq 3 || $# -eq 4 ]] || die "--board-row needs BOARD FAMILY M [FORMAT]"; board_rows "$@" ;;
    --board-check)
        shift; [[ $# -eq 3 || $# -eq 4 ]] || die "--board-check needs BOARD FAMILY M [FORMAT]"
        fresh=$(board_rows "$@")
        same_as_stored "$(cut -d, -f1-7 <<<"$fresh" | head -n 1)" "$whole_board_stored" "$fresh" ;;
    --check)
        shift; [[ $# -eq 5 ]] || die "--check needs FAMILY PIECE FORMAT M LATENCY"
        fresh=$(timing_rows "$@")
        same_as_stored "$1,$2,$3,$4,$5" "$timing_stored" "$fresh" ;;
    --board-table)
        TIMING_CELLS_DIR=$(mktemp -d)
        trap 'rm -rf "$TIMING_CELLS_DIR"' EXIT
        for family in $families; do family_cells "$family" "$TIMING_CELLS_DIR/$family.v"; done
        export -f board_rows_with_fifo board_rows prepare_board board_design board_sources board_params grid_board_sources \
            grid_board_params format_params prepare analyse path_fields harness strip_parameters timing_cells \
            family_cells delay_flags speed_grades die
        export root fifo_depth arcs delays TIMING_CELLS_DIR
        head -n 1 "$whole_board_stored"
        all_board_rows | parallel --keep-order --jobs "${SYNTH_JOBS:-100%}" --colsep ' ' board_rows_with_fifo {1} {2} {3} {4} {5} ;;
    "")
        TIMING_CELLS_DIR=$(mktemp -d)
        trap 'rm -rf "$TIMING_CELLS_DIR"' EXIT
        for family in $families; do family_cells "$family" "$TIMING_CELLS_DIR/$family.v"; done
        export -f timing_rows timing_design piece_design format_params prepare analyse path_fields harness strip_parameters timing_cells \
            family_cells delay_flags speed_grades from_ram_ports to_ram_ports die
        export root address_bits fifo_depth tile_boxes tile_bits arcs delays TIMING_CELLS_DIR
        echo "$timing_header"
        all_timing_rows | parallel --keep-order --jobs "${SYNTH_JOBS:-100%}" --colsep ' ' timing_rows {1} {2} {3} {4} {5} ;;
    *) die "unknown option '$1' (see the comment at the top)" ;;
esac
