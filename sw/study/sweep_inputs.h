// The files a sweep's points read, named for its manifest (so that a resume
// with a changed file is refused), whichever face built the sweep: the files
// its axes name, the host profile the points read when none is named, and
// what a host profile may differ by on a resume.
#pragma once

#include "sw/study/sweep.h"

namespace cdvp {

// Adds every file the axes name (traces, configs, presets, host profiles) to
// spec.inputs after the files the face named for the points' own options,
// then the default host profile when none is named; sets spec.input_facts.
// Without a scene or trace axis the points run the spheres scene. Throws
// InputError for a scene axis beside a trace axis.
void name_sweep_inputs(SweepSpec& spec);

}  // namespace cdvp
