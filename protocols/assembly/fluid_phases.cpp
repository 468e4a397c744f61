#include "protocols/assembly/fluid_phases.h"

#include <numbers>

#include "anatomy/material_library.h"
#include "protocols/scenario/scenario_error.h"
#include "protocols/tissue/add_tissues.h"
#include "sim/core/error.h"

namespace protocols {

FluidPhase phaseFromLibrary(const std::string& name, bool isTamponade) {
  const anatomy::MaterialRecord& r = anatomy::MaterialLibrary::builtin().find(name);
  FluidPhase f;
  f.material = name;
  f.isTamponade = isTamponade;
  f.density = r.density->value;
  f.dynamicViscosity = r.dynamicViscosity->value;
  if (r.interfacialTension) f.interfacialTension = r.interfacialTension->value;
  if (r.contactAngle) f.contactAngleThroughAqueous = r.contactAngle->value;
  return f;
}

FluidPhase tamponadePhase(const TamponadeSpec& t) {
  FluidPhase f;
  if (!t.isCustom()) {
    f = phaseFromLibrary(t.agent.value, true);
  } else {
    f.material = "custom";
    f.isTamponade = true;
  }
  if (t.density) f.density = t.density->value;
  if (t.viscosity) {
    const Viscosity& v = t.viscosity->value;
    f.dynamicViscosity = v.kind == ViscosityKind::kDynamic ? v.value : v.value * f.density;
  }
  if (t.interfacialTension) f.interfacialTension = t.interfacialTension->value;
  if (t.contactAngle)
    f.contactAngleThroughAqueous = t.contactAngle->value * 180.0 / std::numbers::pi;
  return f;
}

void createWorld(const Protocol& p, Scenario& s) {
  s.phases.push_back(phaseFromLibrary("aqueous", false));
  s.phases.push_back(tamponadePhase(p.tamponade));
  const double d = s.accuracy.particleSpacing;  // [m]
  sim::WorldParameters wp;
  wp.particleSpacing = d;
  wp.gravity = s.schedule.front().gravity;
  wp.minTimeStep = s.accuracy.minTimeStep;
  wp.maxTimeStep = s.accuracy.maxTimeStep;
  wp.stopBelowMinTimeStep = true;  // accuracy.min_time_step: "the run stops as unstable"
  Eigen::AlignedBox3d bounds;
  for (const auto& v : s.cavity.vertices) bounds.extend(v);
  const double pad = 4.0 * wp.supportRadiusFactor * d + tissueDomainPadding(p, d);  // [m]
  wp.domain =
      sim::Box(bounds.min() - sim::Vec3::Constant(pad), bounds.max() + sim::Vec3::Constant(pad));
  s.world = std::make_unique<sim::World>(wp);
  s.world->gravity = wp.gravity;
  try {
    for (FluidPhase& phase : s.phases) {
      sim::Material m;
      m.name = phase.material;
      m.restDensity = phase.density;
      m.dynamicViscosity = phase.dynamicViscosity;
      phase.materialIndex = s.world->materials.add(m);
    }
  } catch (const sim::SimError& error) {
    failAt(p.tamponade.agent.where, error.what(), "check the tamponade's properties");
  }
}

}  // namespace protocols
