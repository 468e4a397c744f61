#include "protocols/assembly/cavity.h"

#include "anatomy/anatomy_error.h"
#include "anatomy/vitreous_cavity.h"
#include "meshing/load_mesh.h"
#include "meshing/mesh_error.h"
#include "meshing/mesh_measures.h"
#include "protocols/report/report_format.h"
#include "protocols/scenario/scenario_error.h"

namespace protocols {

namespace {

std::string gibibytes(double bytes) { return formatNumber(bytes / 1073741824.0, 3) + " GiB"; }

}  // namespace

void buildCavity(const Protocol& p, Scenario& s) {
  const EyeSpec& e = p.eye;
  try {
    if (e.kind.value == EyeKind::kMesh) {
      const MeshSource& m = *e.mesh;
      const meshing::LengthUnit unit = meshing::parseLengthUnit(m.units.value);
      meshing::LoadedMesh loaded = meshing::loadMesh(m.path.value.string(), unit);
      s.cavity = std::move(loaded.mesh);
      s.notes.push_back(
          "imported cavity mesh: it carries no clinical landmarks, so the whole wall counts as "
          "retina (no quadrants, macula or periphery) and breaks cannot be placed");
      if (!e.breaks.empty())
        failAt(e.breaks.front().where,
               "retinal break '" + e.breaks.front().name.value + "' on an imported mesh cavity",
               "breaks are placed by clinical coordinates, which need a parametric eye (kind = "
               "\"emmetropic\", \"myopic\" or \"staphyloma\"); remove the breaks or use one");
    } else {
      auto make = [&]() {
        if (e.kind.value == EyeKind::kEmmetropic) {
          anatomy::EmmetropicCavityParameters q;
          if (e.axialLength) q.axialLength = e.axialLength->value;
          return anatomy::makeEmmetropicCavity(q);
        }
        if (e.kind.value == EyeKind::kMyopic) {
          anatomy::MyopicCavityParameters q;
          if (e.axialLength) q.axialLength = e.axialLength->value;
          return anatomy::makeMyopicCavity(q);
        }
        anatomy::StaphylomaCavityParameters q;
        if (e.axialLength) q.axialLength = e.axialLength->value;
        if (e.staphylomaDepth) q.staphylomaDepth = e.staphylomaDepth->value;
        if (e.staphylomaWidth) q.staphylomaWidth = e.staphylomaWidth->value;
        return anatomy::makeStaphylomaCavity(q);
      };
      anatomy::VitreousCavity cavity = make();
      s.cavity = std::move(cavity.mesh);
      s.eye.emplace(
          e.side.value == EyeSide::kOd ? anatomy::Laterality::kRight : anatomy::Laterality::kLeft,
          cavity.shape);
    }
  } catch (const anatomy::AnatomyError& error) {
    failAt(e.axialLength ? e.axialLength->where : e.kind.where, error.what(),
           "change the eye's parameters to the range named above");
  } catch (const meshing::MeshError& error) {
    failAt(e.mesh->path.where, error.what(), "repair the mesh or give its units");
  }
  const meshing::MeshMeasures measures = meshing::measureMesh(s.cavity);
  s.cavityVolume = measures.signedVolume;
  s.cavityArea = measures.area;
}

void checkMemory(const Protocol& p, const ScenarioOptions& options, Scenario& s, double d) {
  const bool tissue = p.eye.sclera.has_value() || p.eye.orbitalFat.has_value();
  s.memory = estimateMemory(s.cavityVolume, s.cavityArea, d, tissue);
  if (!options.memoryLimit || s.memory.bytes <= *options.memoryLimit) return;
  const double fits =
      smallestSpacingWithin(s.cavityVolume, s.cavityArea, *options.memoryLimit, tissue);
  failAt(spacingSource(p),
         "particle spacing " + formatNumber(d * 1e3, 3) + " mm needs about " +
             gibibytes(s.memory.bytes) + " (" + formatNumber(s.memory.fluidParticles, 3) +
             " fluid particles in " + formatNumber(s.cavityVolume * 1e6, 3) +
             " mL), more than the " + gibibytes(*options.memoryLimit) + " available",
         "use accuracy.particle_spacing = \"" + formatNumber(fits * 1e3, 3) +
             " mm\" or coarser, which fits, or allow more with --max-memory");
}

}  // namespace protocols
