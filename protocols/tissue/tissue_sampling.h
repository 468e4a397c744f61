// The tissue assembly's building blocks: a tissue's material values (library, then the
// protocol's overrides), the load the scene can put on the wall, the elastic material, adding a
// tissue's particles (with anchors) to the World, and tagging the sclera's fluid-facing layer as
// retina.
#pragma once

#include <string>
#include <vector>

#include "meshing/sample_shell.h"
#include "protocols/format/protocol.h"
#include "protocols/scenario/scenario.h"

namespace protocols {

std::string mm(double metres);  // "1.2 mm"
TissueBody tissueFromSpec(const TissueSpec& spec, const std::string& name);
sim::TissueChoice choiceOf(TissueMode mode);
// The largest pressure the scene can put on its wall [Pa]: hydrostatic over the cavity's largest
// extent with the heavier phase, plus the interface's capillary pressure 2 sigma / R.
double sceneLoadPressure(const Protocol& protocol, const Scenario& s, double radius);
sim::Material elasticMaterial(const TissueBody& t);
void addParticles(Scenario& s, TissueBody& t, const std::vector<sim::Vec3>& points,
                  const std::vector<char>& anchored, double d);
// The sclera's particles within 1.5 d of the cavity carry the tag of the wall they replace
// (tissue_sampling.cpp says why); returns how many.
std::size_t tagWettedRetina(Scenario& s, const TissueBody& t, const meshing::ShellSamples& samples,
                            double d);

}  // namespace protocols
