// What a cdvp run's exit status means: returned by every command, and read
// back by the study when it runs `cdvp run` as a child (README: exit status).
#pragma once

namespace cdvp {

constexpr int kExitDone = 0;
constexpr int kExitInternal = 1;     // a cdvp bug
constexpr int kExitBadInput = 2;     // a bad trace, flag, preset or output path
constexpr int kExitDeviceFault = 3;  // the simulated system faulted (bus, DMA, driver timeout, board error)
constexpr int kExitSystem = 4;       // the operating system failed a write or a resource (disk full, I/O error)

}  // namespace cdvp
