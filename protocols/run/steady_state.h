// "until steady": when a posture has settled. A posture is steady when, over the last
// `window` of simulated time, (a) the fluid's kinetic energy per unit mass stayed below
// kineticEnergyPerMass and (b) the whole-retina oil coverage moved by less than coverageChange
// (max - min over the window). Both are needed: a slowly creeping interface can change the
// coverage at speeds below any useful energy threshold, and a sloshing fluid can pass through the
// same coverage twice. The posture's maximum duration (protocol `max_duration`) bounds it anyway.
//
// Defaults, and why (emmetropic eye, 90 % SO 1000, d = 1.5 mm, WCSPH, see
// protocols/run/README.md): after the start-up expansion the kinetic energy per mass falls
// from 0.94 J/kg to 5e-4 at 20 ms and then sits at a floor of 0.3-2e-6 J/kg (r.m.s. speed
// 1-2 mm/s: the solver's jitter next to the wall). The threshold 5e-6 J/kg is just above that
// floor. It cannot separate the slow buoyant creep after a posture change (3 % density
// difference, 1000 cSt: the energy stayed below 2e-6 J/kg while the inferior quadrant's coverage
// crept 0.4 percentage points in 0.3 s), so the coverage condition does that work: 0.5
// percentage points of any region or break within a 0.5 s window (a few wall particles of a
// region changing state). A slower creep than ~1 %/s is declared steady: lower
// steady_coverage_change or lengthen steady_window (protocol [schedule]) to be stricter.
#pragma once

#include <span>
#include <vector>

#include "protocols/format/protocol.h"

namespace protocols {

struct SteadyCriteria {
  double window = 0.5;                 // [s] simulated time the two conditions must hold
  double kineticEnergyPerMass = 5e-6;  // [J/kg] = [m^2/s^2]; (3.2 mm/s)^2 / 2
  double coverageChange = 0.005;       // [1] max - min of any region's coverage in the window
  double sampleInterval = 0.05;        // [s] how often the runner samples (window / 10)
};

// The protocol's schedule.steady_window and schedule.steady_coverage_change, sampled ten times
// per window; the energy threshold is the toolkit's (above).
SteadyCriteria steadyCriteriaOf(const Protocol& protocol);

// One sample the runner takes while a posture is held.
struct SteadySample {
  double time = 0.0;                  // [s] simulated
  double kineticEnergyPerMass = 0.0;  // [J/kg] sum(m v^2 / 2) / sum(m) of the fluid
  // [1] area-weighted oil coverage of each reported region and each break (whole retina,
  // quadrants, macula, ..., then the breaks' covered fractions). Each one separately must
  // settle: at 90 % fill the whole retina's coverage hardly depends on the posture (the aqueous
  // pool covers about the same area wherever it lies), while the macula's goes from 0 to 1.
  std::vector<double> coverage;
};

// True when `samples` (increasing time, all taken during the current posture, which started at
// `postureStart` [s]) show the posture steady at the last sample: the posture has lasted at least
// one window, the samples reach back to the window's start, and every sample inside the window
// meets both thresholds. False for an empty series. Pure: the runner and the tests call it alike.
bool isSteady(std::span<const SteadySample> samples, double postureStart,
              const SteadyCriteria& criteria);

}  // namespace protocols
