# Shared by check_view.tcl and check_rtl_view.tcl (sourced once the save
# file is loaded): one "check:" line per finding, and what GTKWave shows.
set failures 0
proc check {ok what} {
    global failures
    if {$ok} { puts "check: ok: $what" } else { puts "check: FAIL: $what"; incr failures }
}
# The times at which a signal takes a value, from the dump (GTKWave lists
# time value pairs, ending with markers past the last time).
proc times_of {signal value} {
    set times {}
    foreach {t v} [gtkwave::signalChangeList $signal -start_time 0 -max 100000] {
        if {$t <= [gtkwave::getMaxTime] && $v eq $value} { lappend times $t }
    }
    return $times
}
proc first_after {times after} {
    foreach t $times { if {$t > $after} { return $t } }
    return -1
}
proc value_at {signal t} {
    gtkwave::setMarker $t
    return [gtkwave::getTraceValueAtMarkerFromName $signal]
}
# Every signal the save file names is on screen, and there are at least `least`.
proc check_saved_signals_shown {least} {
    set saved {}
    set f [open [gtkwave::getSaveFileName] r]
    while {[gets $f line] >= 0} {
        if {$line ne "" && [string first [string index $line 0] "@-\[*^"] < 0} { lappend saved $line }
    }
    close $f
    set shown [gtkwave::getDisplayedSignals]
    set missing {}
    foreach s $saved { if {[lsearch -exact $shown $s] < 0} { lappend missing $s } }
    check [expr {[llength $saved] >= $least && [llength $missing] == 0}] \
        "[llength $shown] signals displayed, [llength $saved] named in the save file, missing: {$missing}"
    return $shown
}
proc finish {} {
    global failures
    puts [expr {$failures == 0 ? "check: PASS" : "check: FAIL ($failures)"}]
    gtkwave::/File/Quit
}
