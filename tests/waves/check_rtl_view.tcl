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
        "first view $start to $end ps; first enabled edge at $enabled, first pair at $pair"

    # The controller idles (one-hot 00001) at time 0 and has counted cycles by the view's end
    # (or the dump's, which ends at the RTL's last edge).
    set state [value_at "$top.state\[4:0\]" 0]
    check [expr {[string trimleft $state 0] eq "1"}] "at time 0 the state reads '$state' (idle)"
    set last [expr {min($end, [gtkwave::getMaxTime])}]
    set cycles [value_at "$top.cycles\[63:0\]" $last]
    check [expr {[string is integer -strict $cycles] && $cycles > 0}] "CYCLES reads $cycles at $last ps"
} error]} {
    check 0 "the check script failed: $error"
}
finish
