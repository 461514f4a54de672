# Run by GTKWave (gtkwave -S check_view.tcl -a waves.gtkw DUMP) once the save
# file is loaded: checks what a user sees when the waveforms open, prints one
# "check:" line per finding and a last "check: PASS" or "check: FAIL", then quits.
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

if {[catch {
    # Every signal the save file names is on screen.
    set saved {}
    set f [open [gtkwave::getSaveFileName] r]
    while {[gets $f line] >= 0} {
        if {$line ne "" && [string first [string index $line 0] "@-\[*^"] < 0} { lappend saved $line }
    }
    close $f
    set shown [gtkwave::getDisplayedSignals]
    set missing {}
    foreach s $saved { if {[lsearch -exact $shown $s] < 0} { lappend missing $s } }
    check [expr {[llength $saved] > 15 && [llength $missing] == 0}] \
        "[llength $shown] signals displayed, [llength $saved] named in the save file, missing: {$missing}"

    # The first view spans the first frame: its upload DMA, START, DONE and
    # read-back DMA, and stops before the next frame's upload.
    set busy SystemC.platform.bridge.dma.busy
    set control SystemC.platform.board.control
    set start [gtkwave::getWindowStartTime]
    set end [gtkwave::getWindowEndTime]
    set upload [lindex [times_of $busy 1] 0]
    set done [lindex [times_of $control.done 1] 0]
    set readback_end [first_after [times_of $busy 0] $done]
    set next_upload [first_after [times_of $busy 1] $readback_end]
    check [expr {$start <= $upload && $end >= $readback_end && ($next_upload < 0 || $end < $next_upload)}] \
        "first view $start to $end fs; frame 0: upload DMA at $upload, DONE at $done, read-back over at $readback_end, next upload at $next_upload"
    set moving 0
    foreach s $shown {
        foreach {t v} [gtkwave::signalChangeList $s -start_time $start -end_time $end -max 3] {
            if {$t > $start && $t <= $end} { incr moving; break }
        }
    }
    check [expr {$moving > 0}] "$moving of [llength $shown] signals change inside the first view"

    # The controller from time 0, its states and the DMA engine's by name.
    set idle [value_at $control.idle 0]
    set state [value_at "$control.state\[1:0\]" 0]
    check [expr {$idle eq "1" && $state eq "idle"}] "at time 0: idle = $idle, state = $state"
    set state [value_at "$control.state\[1:0\]" $done]
    set dma [value_at "SystemC.platform.bridge.dma.state\[1:0\]" $upload]
    check [expr {$state eq "done" && $dma eq "to_board"}] "at DONE the controller reads '$state'; at the upload the DMA engine reads '$dma'"
} error]} {
    check 0 "the check script failed: $error"
}
puts [expr {$failures == 0 ? "check: PASS" : "check: FAIL ($failures)"}]
gtkwave::/File/Quit
