# Run by GTKWave on the RTL's waveforms (cdvp run --fidelity rtl --vcd):
# checks what a user sees when they open, as check_view.tcl does for the
# clocked engine's; one "check:" line per finding, then PASS or FAIL.
set failures 0
proc check {ok what} {
    global failures
    if {$ok} { puts "check: ok: $what" } else { puts "check: FAIL: $what"; incr failures }
}
proc times_of {signal value} {
    set times {}
    foreach {t v} [gtkwave::signalChangeList $signal -start_time 0 -max 100000] {
        if {$t <= [gtkwave::getMaxTime] && $v eq $value} { lappend times $t }
    }
    return $times
}
proc value_at {signal t} {
    gtkwave::setMarker $t
    return [gtkwave::getTraceValueAtMarkerFromName $signal]
}

if {[catch {
    set saved {}
    set f [open [gtkwave::getSaveFileName] r]
    while {[gets $f line] >= 0} {
        if {$line ne "" && [string first [string index $line 0] "@-\[*^"] < 0} { lappend saved $line }
    }
    close $f
    set shown [gtkwave::getDisplayedSignals]
    set missing {}
    foreach s $saved { if {[lsearch -exact $shown $s] < 0} { lappend missing $s } }
    check [expr {[llength $saved] >= 15 && [llength $missing] == 0}] \
        "[llength $shown] signals displayed, [llength $saved] named in the save file, missing: {$missing}"

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
puts [expr {$failures == 0 ? "check: PASS" : "check: FAIL ($failures)"}]
gtkwave::/File/Quit
