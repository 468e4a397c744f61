#include "protocols/assembly/interface_physics.h"

#include <algorithm>

#include "protocols/assembly/wall_wetting_notes.h"
#include "sim/boundary/wetted_surface.h"

namespace protocols {

void setInterfacePhysics(Scenario& s) {
  const FluidPhase& aqueous = s.phases[0];
  const FluidPhase& oil = s.phases[1];
  if (!oil.interfacialTension || *oil.interfacialTension <= 0.0) return;
  s.world->materials.setInterfacialTension(aqueous.materialIndex, oil.materialIndex,
                                           *oil.interfacialTension);
  if (!oil.contactAngleThroughAqueous) return;
  std::vector<int> tags(s.world->walls.tag.begin(), s.world->walls.tag.end());
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  for (const int tag : tags)
    s.world->materials.setContactAngle(aqueous.materialIndex, tag, *oil.contactAngleThroughAqueous);
  if (const std::string note = contactAngleRangeNote(180.0 - *oil.contactAngleThroughAqueous);
      !note.empty())
    s.notes.push_back(note);
  // Tagged tissue (tissue_particles.cpp) is the retina over an elastic sclera.
  s.notes.push_back(contactAngleWallModelNote(
      sim::findWettedSurfaceField(s.world->particles) != nullptr ? RetinaWall::kElasticSclera
      : s.layeredWalls                                           ? RetinaWall::kLayered
                                                                 : RetinaWall::kSingleLayer));
}

}  // namespace protocols
