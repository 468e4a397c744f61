// How much memory a scene will take, estimated from the cavity alone, before any particle is
// allocated, so that `plan` and `run` can refuse a spacing the machine cannot hold instead of
// growing until std::bad_alloc (or the kernel's OOM killer).
//
// Model: peak resident bytes = kBaseBytes + kBytesPerFluidParticle V / d^3 +
// kBytesPerWallArea A / d^2, for a cavity of volume V and wall area A at particle spacing d. The
// volume term is the fluid (its fields, neighbour lists, the solver's and the fill's work arrays);
// the area term the retina samples (Poisson-disk points at d/2 with their regions and coverage
// maps) and the wall particles. Coefficients fitted to the peak resident size (/usr/bin/time -v)
// of `tamponade plan` on the emmetropic eye at 0.2-1.2 mm (memory_estimate.cpp has the
// measurements: within 1 %).
#pragma once

#include <cstdint>
#include <optional>

namespace protocols {

struct MemoryEstimate {
  double fluidParticles = 0.0;  // V / d^3
  double wallSamples = 0.0;     // A / d^2 (the walls and retina samples scale with it)
  double bytes = 0.0;           // [B] estimated peak resident size of a run
};

// The estimate for a cavity of `volume` [m^3] and wall `area` [m^2] at spacing `d` [m].
// `withTissue`: the protocol has a sclera or orbital fat table, whose particles, shells and bony
// orbit the cavity does not show (kTissueVolumeFactor in memory_estimate.cpp).
MemoryEstimate estimateMemory(double volume, double area, double d, bool withTissue = false);

// The smallest spacing [m] (to 1 %) whose estimate stays within `limitBytes`; a finer one does
// not fit. Rounded up to 0.01 mm so that it can be written into a protocol as printed.
double smallestSpacingWithin(double volume, double area, double limitBytes,
                             bool withTissue = false);

// This process's peak resident size so far [B] (/proc/self/status VmHWM); nothing where that
// cannot be read. `plan` reports it after assembling and stepping the scene: a run of the same
// scene peaked 3-10 % above it (tiny.toml at 0.5 and 0.8 mm, paper_sclera_10kpa.toml at 1.2 mm).
std::optional<double> peakResidentBytes();

// What this process may use [B]: the smaller of the memory the kernel reports available
// (/proc/meminfo MemAvailable) and the address-space and data limits (ulimit -v, -d); nothing
// when neither can be read.
std::optional<double> machineMemoryLimit();

}  // namespace protocols
