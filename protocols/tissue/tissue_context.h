// What the steps of the tissue assembly share (add_tissues.cpp, sclera_walls.cpp): the spacing,
// the scene's load, the sclera's anatomy, and what the sclera step decided.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "anatomy/sclera_shell.h"
#include "protocols/scenario/tissue_body.h"

namespace protocols {

struct TissueContext {
  double d = 0.0;                             // [m] particle spacing
  double radius = 0.0;                        // [m] the cavity's equivalent-sphere radius
  double load = 0.0;                          // [Pa] sceneLoadPressure
  std::optional<anatomy::ScleraShell> shell;  // the sclera's anatomy (also the fat's inner face)
  double thinnest = 0.0;                      // [m] thinnest scleral thickness of the profile
  std::optional<std::size_t> scleraIndex;     // in Scenario::tissues
  bool scleraBackstop = false;  // an elastic sclera held at its outer surface: a backstop behind
  std::vector<double> scleraLayer;  // [m] sampled thickness per retina sample (0 on the cap)

  // Sampled sclera layer at the wall point nearest q: anatomical, at least
  // kMinTissueLayerSpacings d (tissue_body.h); 0 on the lens/IOL cap.
  double layerAt(const sim::Vec3& q) const {
    const double anatomical = shell->thicknessAt(q);
    return anatomical > 0.0 ? std::max(anatomical, kMinTissueLayerSpacings * d) : 0.0;
  }
};

}  // namespace protocols
