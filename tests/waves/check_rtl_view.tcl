# Run by GTKWave on the RTL's waveforms (cdvp run --fidelity rtl --vcd):
# checks what a user sees when they open, as check_view.tcl does for the
# clocked engine's; one "check:" line per finding, then PASS or FAIL.
source [file join [file dirname [info script]] view_checks.tcl]

if {[catch {
    check_saved_signals_shown 15

    # The first view spans the first sweep: the pipeline's first enabled
    # edge and the first pair entering the pair buffer lie inside it.
    set top board.collision_board_top
    set start [gtkwave::getWindowStartTime]
    set end [gtkwave::getWindowEndTime]
    set enabled [lindex [times_of $top.enable 1] 0]
    set pair [lindex [times_of $top.out_valid 1] 0]
    check [expr {$enabled ne "" && $pair ne "" && $start <= $enabled && $enabled <= $pair && $pair <= $end}] \
        "first view $start to $end fs; first enabled edge at $enabled, first pair at $pair"

    # The controller's one-hot state by name (its translate filter): idle at
    # time 0, sweeping at the first enabled edge, done at the view's end; and
    # it has counted cycles by then (or by the dump's end, the RTL's last edge).
    set state "$top.state\[4:0\]"
    set last [expr {min($end, [gtkwave::getMaxTime])}]
    set names [list [value_at $state 0] [value_at $state $enabled] [value_at $state $last]]
    check [expr {$names eq {idle sweep done}}] "the state reads '[join $names {', '}]' at 0, $enabled and $last fs"
    set cycles [value_at "$top.cycles\[63:0\]" $last]
    check [expr {[string is integer -strict $cycles] && $cycles > 0}] "CYCLES reads $cycles at $last fs"

    # The same unit as the platform's waveforms: one board clock (66 MHz) is 15,151,515 fs.
    set rises [times_of $top.clk 1]
    if {[llength $rises] < 2} { set rises [times_of board.clk 1] }
    set period [expr {[lindex $rises 1] - [lindex $rises 0]}]
    check [expr {$period == 15151515}] "the clock's period is $period fs"
} error]} {
    check 0 "the check script failed: $error"
}
finish
