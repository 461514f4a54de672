# cmake -DCDVP=binary -DHELP2MAN=help2man -DOUT=cdvp.1 -DBOARDS=platform/boards -P man_page.cmake
# Writes cdvp.1 with help2man from `cdvp --help` and `--version`, adding a
# section with `cdvp CMD --help` for every command that `cdvp --help` lists,
# and the environment and files the binary uses.

function(run_help out)
  execute_process(COMMAND ${CDVP} ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${CDVP} ${ARGN} --help exited with ${status}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# A command's --help as it prints, line for line: unfilled, at the left margin
# (an 80-column help indented by the page's 7 would wrap in an 80-column
# terminal). roff: a backslash is \e, a minus is \- (a bare - may print as a
# hyphen, which a copied option would not be), and a line may not start with
# a control character. tests/install/man_section_test.sh compares the two.
function(as_roff_block out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} ".in 0\n.nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

run_help(usage)
# The commands: the indented lines between "Commands:" and the next blank line.
string(REGEX MATCH "Commands:\n(([ ]+[^\n]+\n)+)" block "${usage}")
string(REGEX MATCHALL "\n  ([a-z][a-z-]*) " rows "\n${CMAKE_MATCH_1}")
if(NOT rows)
  message(FATAL_ERROR "no commands found in `${CDVP} --help`")
endif()

set(include_text "")
foreach(row IN LISTS rows)
  string(STRIP "${row}" command)
  run_help(help ${command})
  as_roff_block(block "${help}")
  string(TOUPPER "${command}" title)
  string(APPEND include_text "[OPTIONS OF ${title}]\n${block}\n")
endforeach()

# The presets, from the boards directory itself.
file(GLOB preset_files "${BOARDS}/*.json")
if(NOT preset_files)
  message(FATAL_ERROR "no board presets in '${BOARDS}'")
endif()
set(presets "")
foreach(file IN LISTS preset_files)
  get_filename_component(name "${file}" NAME_WE)
  list(APPEND presets "${name}")
endforeach()
list(SORT presets)
list(JOIN presets ", " preset_list)
string(REPLACE "-" "\\-" preset_list "${preset_list}")

string(APPEND include_text [=[
[EXAMPLES]
.TP
.B cdvp run \-\-board adm\-xrc\-ii \-\-scene spheres \-\-objects 500 \-\-frames 30 \-\-m 24 \-\-baseline sap,dbvt,brute,soa
The paper's board and scene against four software broad phases: frame times, pairs and cycles.
.TP
.B cdvp run \-\-trace scene.csv \-\-m 8 \-\-vcd waves.vcd \-\-vcd\-frames 0:0
Waveforms of the first frame, with a GTKWave save file beside them (\fBgtkwave \-a waves.gtkw waves.vcd\fR).
.TP
.B cdvp sweep \-\-board adm\-xrc\-ii,pcie\-gen3\-x8 \-\-set m=1,2,4,8,16,24 \-\-set objects=50:2000:x2 \-\-frames 30 \-\-baseline sap,soa \-\-out results/ \-\-jobs 2
A grid of boards, parallelisms and scene sizes: results/sweep.csv, each point's report, crossovers and figures. The same command again resumes it.
.TP
.B cdvp sweep ... \-\-shard 2/4 \-\-out results/shard\-2 && cdvp merge \-\-out results/all results/shard\-*
A sweep spread over machines, then merged (all or nothing).
.TP
.B cdvp bullet \-\-scene boxes \-\-frames 60 \-\-board adm\-xrc\-ii \-\-m 4
A Bullet world stepped with the virtual board as its broad phase, beside Bullet's own.
.TP
.B cdvp settings
Every setting with its unit, default, range and source.
[ENVIRONMENT]
.TP
.B CDVP_BOARDS
The directory of the board presets that \fB\-\-board\fR \fINAME\fR reads
(\fINAME\fR.json). Unset, cdvp reads \fIshare/cdvp/boards\fR of the prefix it is
installed in (found from the running binary, so a moved prefix still works), and
a binary run from its build tree reads the source tree's \fIplatform/boards\fR.
A \fB\-\-board\fR value that contains a slash or ends in .json is a file path.
.TP
.B CDVP_RTL_CACHE
Where \fB\-\-fidelity rtl\fR keeps the board RTL's variants it compiles on first
use (those not built into the binary: \fBcdvp rtl\-variants\fR); an absolute path. Unset, it is
\fI$XDG_CACHE_HOME/cdvp/rtl\fR (when absolute), else \fI~/.cache/cdvp/rtl\fR (when HOME is set);
with neither, such a run is refused. Only entries the user owns and alone may write are loaded. Compiling needs
\fBverilator\fR, \fBmake\fR and the C++ compiler cdvp was built with.
.TP
.B CDVP_MEMORY_SHARE
Set by \fBcdvp sweep \-\-jobs\fR \fIJ\fR for its points: J runs share the machine, so each run's
default memory budget (\fB\-\-max\-memory\fR 0) is 1/J of half the memory.
[FILES]
.TP
.I PREFIX/share/cdvp/boards/*.json
The board presets: @PRESET_LIST@.
.TP
.I $XDG_CACHE_HOME/cdvp/speed\-probe.json
(else \fI~/.cache/cdvp/speed\-probe.json\fR) The fastest this CPU model has run the speed probe in
earlier runs: without a host profile, software timings are held to it (docs/timing.md).
.TP
.I PREFIX/share/cdvp/rtl
The board's Verilog and what \fB\-\-fidelity rtl\fR compiles a variant from.
.TP
.I PREFIX/share/doc/cdvp
The README (the worked example, a map of the docs) and docs/: the tutorial (docs/tutorial.md),
every command's help and the rules behind it (docs/cli.md), file formats (docs/formats.md), timing
assumptions (docs/assumptions.md).
[SEE ALSO]
.BR gtkwave (1),
.BR gnuplot (1),
.BR parallel (1),
.BR yosys (1);
the README and docs/ in \fIPREFIX/share/doc/cdvp\fR (docs/tutorial.md, docs/cli.md, docs/formats.md,
docs/sweep.md, docs/settings.md, docs/timing.md).
]=])

string(REPLACE "@PRESET_LIST@" "${preset_list}" include_text "${include_text}")
get_filename_component(include_file "${OUT}.include" ABSOLUTE)
file(WRITE "${include_file}" "${include_text}")
execute_process(
  COMMAND ${HELP2MAN} --no-info --section=1
          "--name=virtual platform of an FPGA broad-phase collision coprocessor"
          --include=${include_file} --output=${OUT}.tmp ${CDVP}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man exited with ${status}")
endif()
file(RENAME "${OUT}.tmp" "${OUT}")
