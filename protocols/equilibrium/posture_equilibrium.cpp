#include "protocols/equilibrium/posture_equilibrium.h"

#include <algorithm>
#include <chrono>
#include <numbers>

#include "meshing/mesh_measures.h"
#include "meshing/mesh_query.h"
#include "meshing/voxel_fractions.h"
#include "sim/equilibrium/interface_surface.h"
#include "sim/equilibrium/wall_oil.h"

namespace protocols {

bool isEquilibriumSchedule(const Scenario& s) {
  return !s.schedule.empty() &&
         std::all_of(s.schedule.begin(), s.schedule.end(),
                     [](const ScheduledPosture& p) { return p.equilibrium; });
}

std::size_t leadingEquilibria(const Scenario& s) {
  const auto simulated = std::find_if(s.schedule.begin(), s.schedule.end(),
                                      [](const ScheduledPosture& p) { return !p.equilibrium; });
  return static_cast<std::size_t>(simulated - s.schedule.begin());
}

std::size_t equilibriaBeforeSimulation(const Scenario& s) {
  const std::size_t leading = leadingEquilibria(s);
  return leading < s.schedule.size() ? leading : 0;
}

double equilibriumVoxelSpacing(const std::string& preset) {
  if (preset == "fine") return 0.2e-3;
  if (preset == "standard") return 0.25e-3;
  return 0.3e-3;  // draft
}

CavityVoxels voxelizeCavity(const Scenario& s, double voxelSpacing) {
  sim::Vec3 lo = s.cavity.vertices.front(), hi = lo;
  for (const sim::Vec3& v : s.cavity.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  CavityVoxels out;
  out.grid = sim::equilibrium::gridAround(lo, hi, voxelSpacing, 2);
  const meshing::MeshQuery query(s.cavity);
  out.fluidFraction = meshing::voxelInsideFractions(
      query, {out.grid.origin, out.grid.spacing, out.grid.nx, out.grid.ny, out.grid.nz});
  out.wallArea = meshing::measureMesh(s.cavity).area;
  return out;
}

namespace {

meshing::TriangleMesh toMesh(const sim::equilibrium::InterfaceSurface& surface) {
  meshing::TriangleMesh mesh;
  mesh.vertices = surface.vertices;
  mesh.faces.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles) mesh.faces.push_back({t[0], t[1], t[2]});
  return mesh;
}

}  // namespace

PostureEquilibrium solvePostureEquilibrium(const Scenario& s, const CavityVoxels& cavity,
                                           double fill, const sim::Vec3& gravity) {
  const auto start = std::chrono::steady_clock::now();
  const FluidPhase& aqueous = s.phases[0];
  const FluidPhase& oil = s.phases[1];
  const std::size_t samples = s.retinaSamples.restPositions.size();
  PostureEquilibrium out;
  out.wall.oilFraction.assign(samples, 1.0);
  out.wall.wetting.assign(samples, WallWetting::kOil);
  if (fill < 1.0) {
    sim::equilibrium::EquilibriumProblem problem;
    problem.grid = cavity.grid;
    problem.fluidFraction = cavity.fluidFraction;
    problem.oilDensity = oil.density;
    problem.aqueousDensity = aqueous.density;
    problem.tension = oil.interfacialTension.value_or(0.0);
    problem.contactAngle = oil.contactAngleThroughAqueous.value_or(90.0) * std::numbers::pi / 180;
    problem.gravity = gravity;
    problem.oilFraction = fill;
    problem.wallArea = cavity.wallArea;
    out.solution = sim::equilibrium::solveEquilibrium(problem);
    const sim::equilibrium::WallOilReader reader(out.solution, problem.contactAngle);
#pragma omp parallel for schedule(static)
    for (std::size_t w = 0; w < samples; ++w) {
      const bool covered =
          reader.oilCovered(s.retinaSamples.restPositions[w], s.retinaSamples.normals[w]);
      out.wall.oilFraction[w] = covered ? 1.0 : 0.0;
      out.wall.wetting[w] = covered ? WallWetting::kOil : WallWetting::kAqueous;
    }
    out.interface = toMesh(sim::equilibrium::interfaceSurface(out.solution));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace protocols
