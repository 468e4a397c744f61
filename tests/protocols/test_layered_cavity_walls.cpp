// The layered cavity wall (protocols/assembly/layered_cavity_walls.h): layers cut from the fluid
// lattice behind the eye's cavity mesh.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <set>
#include <tuple>

#include "anatomy/vitreous_cavity.h"
#include "meshing/mesh_measures.h"
#include "meshing/mesh_query.h"
#include "meshing/sample_volume.h"
#include "protocols/assembly/layered_cavity_walls.h"

using namespace protocols;

TEST_CASE("layered cavity wall: three lattice layers behind the eye, one lattice with the fluid",
          "[unit][scenario]") {
  const double d = 1.2e-3;  // [m] the draft preset's spacing
  const anatomy::VitreousCavity cavity = anatomy::makeEmmetropicCavity({});
  const LayeredCavityWalls w = sampleLayeredCavityWalls(cavity.mesh, d, 3);
  const meshing::MeshMeasures m = meshing::measureMesh(cavity.mesh);
  const meshing::MeshQuery query(cavity.mesh);

  REQUIRE(w.surfaceCount > 0);
  REQUIRE(w.positions.size() == w.normals.size());
  REQUIRE(w.positions.size() == w.layer.size());
  // Each layer is the lattice points in a shell d thick outside the mesh: N d^3 = the shell's
  // volume, A d (1 + O(d / R)) for layer k at depth (k + 1/2) d, R ~ 11 mm; the lattice's count
  // in a thin shell fluctuates by the staircase, measured below 3 % here: bound 8 %.
  std::array<double, 3> count{};
  for (std::size_t b = 0; b < w.positions.size(); ++b) {
    REQUIRE(w.layer[b] == (b < w.surfaceCount ? 0 : w.layer[b]));
    count[static_cast<std::size_t>(w.layer[b])] += 1;
    const double depth = std::sqrt(query.squaredDistance(w.positions[b]));
    CHECK_FALSE(query.isInside(w.positions[b]));
    CHECK(depth <= (w.layer[b] + 1) * d * (1 + 1e-9));
    CHECK(depth >= w.layer[b] * d * (1 - 1e-9));
    CHECK(w.normals[b].norm() == Approx(1.0).epsilon(1e-12));
  }
  for (int k = 0; k < 3; ++k) {
    const double grow = 1 + (k + 0.5) * d / 11e-3;
    INFO("layer " << k << ": " << count[static_cast<std::size_t>(k)] << " particles");
    CHECK(count[static_cast<std::size_t>(k)] * d * d * d ==
          Approx(m.area * d * grow * grow).epsilon(0.08));
  }
  // Fluid (sampleVolume without gap) and walls are one lattice: no wall particle sits on a fluid
  // lattice point, and the fluid count holds the cavity's volume (V / d^3 on average; bound 3 %).
  meshing::VolumeSamplingOptions vo;
  vo.spacing = d;
  vo.wallGap = 0.0;
  const std::vector<meshing::Vec3> fluid = meshing::sampleVolume(cavity.mesh, query, vo);
  CHECK(static_cast<double>(fluid.size()) * d * d * d == Approx(m.signedVolume).epsilon(0.03));
  auto cell = [d](const meshing::Vec3& x) {
    return std::make_tuple(std::lround(x.x() / d), std::lround(x.y() / d), std::lround(x.z() / d));
  };
  std::set<std::tuple<long, long, long>> fluidCells;
  for (const auto& x : fluid) {
    CHECK((x / d - (x / d).array().round().matrix()).norm() < 1e-6);  // on the lattice
    fluidCells.insert(cell(x));
  }
  for (const auto& x : w.positions) {
    CHECK((x / d - (x / d).array().round().matrix()).norm() < 1e-6);
    CHECK(fluidCells.count(cell(x)) == 0);
  }
}
