// The simulator's true rig (rig/rig.h): what a perfect calibration would
// give, for tests, benchmarks and comparisons (no quality figures). The
// truth file it wrote holds it too (SimTruth::rig).
#pragma once

#include "rig/rig.h"
#include "sim/sim_config.h"

namespace ws {

// The cameras, R and T of a simulator config.
Rig TrueStereoRig(const SimConfig& sim);

}  // namespace ws
