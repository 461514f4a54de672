# Run by GTKWave (gtkwave -S check_view.tcl -a waves.gtkw DUMP) once the save
# file is loaded: checks what a user sees when the waveforms open, prints one
# "check:" line per finding and a last "check: PASS" or "check: FAIL", then quits.
source [file join [file dirname [info script]] view_checks.tcl]

if {[catch {
    # Every signal the save file names is on screen.
    set shown [check_saved_signals_shown 16]

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
finish
