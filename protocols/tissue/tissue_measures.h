// What the tissues did during a run: displacements, the cavity volume change, the retina's
// movement, fluid that got into or through the sclera (a leak), the frames' displacement field and
// the report's tissue lines.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "protocols/scenario/scenario.h"

namespace protocols {

struct TissueMeasures {
  std::vector<double> maxDisplacement;  // [m] per Scenario::tissues entry (0 when rigid)
  double retinaMaxDisplacement = 0.0;   // [m] largest movement of a retina sample
  // [m^3] cavity volume change, sum_w A_w n_w . u_w over the retina samples (first order in u;
  // the divergence theorem on the wall, A_w the samples' areas).
  double cavityVolumeChange = 0.0;
  // [m] area-weighted mean outward displacement per reported region (kReportedRegions order).
  std::vector<double> regionMeanOutward;
  // Fluid in the tissue (a leak through the tissue's lattice; counted only when the sclera is
  // sampled). A fluid particle outside the cavity surface at depth r (distance to the rest surface)
  // is
  // - `fluidInTissue` when some sclera particle within 1.5 d of it lies more than d shallower
  //   (r_j < r - d), or none lies within 1.5 d and r > d: it sits behind a tissue particle, inside
  //   the layer. Fluid in the openings of the lattice-sampled face (the staircase's hollows, up to
  //   ~1 d deep) is not counted: it is no deeper than the innermost tissue particle of its own
  //   column (<= 1.37 d: the first lattice point past d/2 along a tilted column), and the
  //   shallowest one nearby is >= d/2 deep, so it is < 0.87 d + (relative tissue motion) deeper.
  // - `fluidThroughTissue` (a subset) when r > max(t_layer, d), t_layer the sampled layer at its
  //   nearest retina sample (0 on the cap): it has passed the whole layer (or the cap's wall).
  std::size_t fluidInTissue = 0;
  std::size_t fluidThroughTissue = 0;
  double deepestFluid = 0.0;  // [m] largest r of a fluid particle outside the cavity surface
};

// Current retina sample positions from the dynamic particles' positions and ids (#F each; any
// order). With no moving sample it returns the rest positions.
std::vector<sim::Vec3> retinaPositions(const Scenario& scenario, const std::vector<sim::Vec3>& x,
                                       const std::vector<std::int32_t>& ids);

TissueMeasures measureTissues(const Scenario& scenario, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids);

// Per dynamic particle displacement from its rest position [m] (zero for fluid), #F, in the
// arrays' order; written to the frames as the "tissue_displacement" field.
inline constexpr const char* kTissueDisplacementField = "tissue_displacement";
void updateTissueDisplacement(const Scenario& scenario, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids, std::vector<sim::Vec3>& out);

// The report's tissue lines: one ("tissue rigid (estimate ... < 0.1 d)") when no tissue is
// elastic, else per tissue its maximum displacement, the retina's, and the cavity volume change;
// with the run's mean time step [s] (0 = unknown), a warning for each elastic tissue whose
// thickness mode the step does not resolve ((omega_1 dt)^2 > 1, docs/methods/elasticity.md).
std::vector<std::string> tissueReportLines(const Scenario& scenario, const TissueMeasures& last,
                                           double lastTime, double meanTimeStep = 0.0);

}  // namespace protocols
