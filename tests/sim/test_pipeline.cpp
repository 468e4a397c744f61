// The World and the effect pipeline: the pair loop's gradients from the cached scales equal the
// kernel's, in list order, Z-order sorting
// keeps every registered field with its particle, the pipeline holds only the stages a scene
// calls for (and allocates only their fields), forcing works, unknown names are errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>

#include "scene_fixtures.h"
#include "sim/scenes/dam_break.h"
#include "sim/world/pair_loop.h"
#include "sim/world/stage_registry.h"

using namespace sim;

namespace {

testing::Tank smallTank() { return testing::hydrostaticTank(0.03, 0.03, 0.005); }

}  // namespace

// Bit for bit (==, not a tolerance): the solvers' results must not depend on whether a gradient
// comes from the cache or from the kernel, which the cache holds in single precision
// (sim/neighbors/pair_precision.h).
TEST_CASE("cached kernel gradients equal the kernel's gradient of each pair", "[unit][world]") {
  auto tank = smallTank();
  World& w = *tank.world;
  const auto& nf = w.fluidNeighbors();
  const auto& nw = w.wallNeighbors();
  REQUIRE(nf.totalPairs() > 0);
  REQUIRE(nw.totalPairs() > 0);
  const PairLoop fluid = fluidPairs(w), wall = wallPairs(w);
  for (Index i = 0; i < w.particles.size(); ++i) {
    Index k = nf.offsets[i];
    fluid.forEach(i, [&](Index j, const Vec3& gradW, Index slot) {
      REQUIRE(slot == k);
      REQUIRE(j == nf.indices[k++]);
      REQUIRE(gradW == cachedPrecision(w.kernel.gradW(w.particles.x[i] - w.particles.x[j])));
      REQUIRE(fluid.gradient(slot, i, j) == gradW);
    });
    REQUIRE(k == nf.offsets[i + 1]);
    wall.forEach(i, [&](Index b, const Vec3& gradW) {
      REQUIRE(gradW == cachedPrecision(w.kernel.gradW(w.particles.x[i] - w.walls.x[b])));
    });
  }
}

TEST_CASE("Z-order sorting keeps every field with its particle", "[unit][world]") {
  auto tank = smallTank();
  World& w = *tank.world;
  auto& tagField = w.particles.fields.add<Real>({"test_tag", "1", true, false});
  std::map<int, std::pair<Vec3, Real>> byId;
  for (Index i = 0; i < w.particles.size(); ++i) {
    tagField[i] = 1000.0 + w.particles.id[i];
    byId[w.particles.id[i]] = {w.particles.x[i], tagField[i]};
  }
  // Scramble the order, then let the periodic sort restore locality.
  std::vector<Index> reverse(w.particles.size());
  for (Index k = 0; k < reverse.size(); ++k)
    reverse[k] = static_cast<Index>(reverse.size() - 1 - k);
  w.particles.fields.permute(reverse);
  for (int k = 0; k < w.parameters().zSortInterval; ++k) w.updateNeighbors();
  for (Index i = 0; i < w.particles.size(); ++i) {
    const auto& expected = byId.at(w.particles.id[i]);
    REQUIRE(w.particles.x[i] == expected.first);
    REQUIRE(tagField[i] == expected.second);
  }
}

// The in-place reorder along the permutation's cycles (FieldRegistry::permute) against a copy
// gathered by hand, for every element kind (1, 3 and 9 scalars, reals and integers), a random
// permutation (long cycles) with fixed points, and the selection of increasing indices.
TEST_CASE("fields are reordered in place and selected exactly", "[unit][world]") {
  FieldRegistry fields;
  auto& r = fields.add<Real>({"r", "1", false, false});
  auto& v = fields.add<Vec3>({"v", "1", false, false});
  auto& m = fields.add<Mat3>({"m", "1", false, false});
  auto& n = fields.add<std::int32_t>({"n", "1", false, false});
  const std::size_t count = 1000;
  fields.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    r[i] = 0.5 * static_cast<Real>(i);
    v[i] = Vec3(1.0, 2.0, 3.0) * static_cast<Real>(i);
    m[i] = Mat3::Constant(static_cast<Real>(i)) + Mat3::Identity();
    n[i] = -static_cast<std::int32_t>(i);
  }
  std::vector<Index> newToOld(count);
  std::iota(newToOld.begin(), newToOld.end(), Index{0});
  std::mt19937 rng(3);
  std::shuffle(newToOld.begin() + 100, newToOld.end(), rng);  // the first 100 stay in place
  const auto r0 = r;
  const auto v0 = v;
  const auto m0 = m;
  const auto n0 = n;
  fields.permute(newToOld);
  for (std::size_t k = 0; k < count; ++k) {
    REQUIRE(r[k] == r0[newToOld[k]]);
    REQUIRE(v[k] == v0[newToOld[k]]);
    REQUIRE(m[k] == m0[newToOld[k]]);
    REQUIRE(n[k] == n0[newToOld[k]]);
  }
  const std::vector<Index> keep{0, 3, 4, 500, 999};
  const auto r1 = r;
  const auto m1 = m;
  fields.select(keep);
  REQUIRE(fields.size() == keep.size());
  REQUIRE(r.size() == keep.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    REQUIRE(r[k] == r1[keep[k]]);
    REQUIRE(m[k] == m1[keep[k]]);
  }
  CHECK_THROWS_AS(fields.select({2, 1}), SimError);
  CHECK_THROWS_AS(fields.permute({0, 1}), SimError);
}

TEST_CASE("the pipeline holds only the stages the scene calls for", "[unit][pipeline]") {
  auto tank = smallTank();
  World& w = *tank.world;
  const std::size_t fieldsBefore = w.particles.fields.fieldCount();

  SECTION("water with gravity: gravity, viscosity and velocity smoothing, nothing else") {
    Pipeline p = assemblePipeline(w, PipelineOptions{});
    CHECK(p.hasStage("gravity"));
    CHECK(p.hasStage("viscosity"));
    CHECK(p.hasStage("velocity_smoothing"));
    CHECK(p.solver().name() == "dfsph");
    CHECK(p.effects().size() == 3);
    p.attach(w);
    // DFSPH's own fields only: factor, pressure, two warm-start stiffnesses.
    CHECK(w.particles.fields.fieldCount() == fieldsBefore + 4);
    CHECK(p.describe().find("gravity is non-zero") != std::string::npos);
  }
  SECTION("an inviscid fluid without gravity has no viscosity or gravity stage") {
    w.gravity = Vec3::Zero();
    MaterialTable inviscid;
    Material m = testing::water();
    m.dynamicViscosity = 0;
    inviscid.add(m);
    w.materials = inviscid;
    PipelineOptions o;
    o.velocitySmoothing = 0;
    Pipeline p = assemblePipeline(w, o);
    CHECK(p.effects().empty());
    CHECK_FALSE(p.hasStage("viscosity"));
  }
  SECTION("a protocol can force an effect off or on, and the decision says so") {
    PipelineOptions o;
    o.forced["viscosity"] = StageOverride::kOff;
    Pipeline p = assemblePipeline(w, o);
    CHECK_FALSE(p.hasStage("viscosity"));
    const auto it = std::find_if(p.decisions().begin(), p.decisions().end(),
                                 [](const StageDecision& d) { return d.name == "viscosity"; });
    REQUIRE(it != p.decisions().end());
    CHECK(it->forced);
    CHECK(it->reason.find("forced off") != std::string::npos);
  }
  SECTION("unknown solver and effect names are errors that list the known ones") {
    PipelineOptions o;
    o.solver = "sph-magic";
    CHECK_THROWS_WITH(assemblePipeline(w, o), Catch::Contains("known: dfsph, wcsph"));
    PipelineOptions f;
    f.forced["surface_tensionn"] = StageOverride::kOn;
    CHECK_THROWS_WITH(assemblePipeline(w, f), Catch::Contains("unknown effect"));
  }
}

// Every pressure solver without the pair cache (WorldParameters::cachePairKernels = false): the
// stages evaluate the kernel where they read the cache, whose values are the kernel's own bit for
// bit, so the state after some steps of the dam break must be equal (==, not a tolerance).
TEST_CASE("every solver gives the same state bit for bit without the pair cache",
          "[unit][pipeline]") {
  for (const auto& entry : solverRegistry()) {
    std::vector<DamBreakScene> scenes;
    std::vector<Pipeline> pipelines;
    for (const bool cache : {true, false}) {
      DamBreakSpec spec;
      spec.solver = entry.name;
      spec.spacing = spec.columnWidth / 8;
      spec.cachePairKernels = cache;
      scenes.push_back(buildDamBreak(spec));
    }
    for (auto& scene : scenes) {
      pipelines.push_back(assemblePipeline(*scene.world, scene.options));
      pipelines.back().attach(*scene.world);
    }
    for (int step = 0; step < 15; ++step)
      for (std::size_t k = 0; k < 2; ++k) pipelines[k].step(*scenes[k].world);
    const auto& a = scenes[0].world->particles;
    const auto& b = scenes[1].world->particles;
    INFO("solver " << entry.name);
    REQUIRE(scenes[0].world->stepCount == scenes[1].world->stepCount);
    for (Index i = 0; i < a.size(); ++i) {
      REQUIRE(a.x[i] == b.x[i]);
      REQUIRE(a.v[i] == b.v[i]);
    }
  }
}
