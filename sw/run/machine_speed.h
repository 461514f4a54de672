// The machine's fast speed as cdvp has seen it on this CPU model, kept
// between runs, so that a run whose every probe is slow (a neighbour or a
// lowered clock for the whole run) is not held to its own slow speed and
// called clean (docs/timing.md, "Slowed machines").
#pragma once

#include <string>
#include <vector>

namespace cdvp {

// Where it is kept: $XDG_CACHE_HOME/cdvp/speed-probe.json (when absolute),
// else ~/.cache/cdvp/speed-probe.json; empty when neither is: nothing kept.
std::string machine_speed_path();

// The fastest a run's probes have shown (the 10th percentile of its probes,
// fast_probe_ns) on a CPU of this model; 0 when none is kept. The file is
// cdvp's own cache: one that is not a small regular file of that shape is
// taken as none and written anew.
double remembered_fast_probe_ns(const std::string& cpu_model);
// Keeps `ns` when it is lower than the one kept (or none is, or it was kept
// for another CPU model). Best effort: a cache that cannot be written is left.
void remember_fast_probe_ns(const std::string& cpu_model, double ns);

// The speed a run's frames are held to: the host profile's calibrated one
// when there is one (calibrated_ns > 0); else the faster of the run's own
// (fast_probe_ns of its probes) and the one kept for this machine, which the
// run's own then updates.
double probe_reference_ns(double calibrated_ns, const std::vector<double>& probes);

}  // namespace cdvp
