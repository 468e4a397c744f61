// Pipeline::step allocates nothing once the scene's lists have grown to their size (the engine
// rule "allocate in attach()"; docs/developer-guide.md code rule 9): the whole step, neighbour
// update, time-step choice, effects, pressure solve and integration, for an explicit and the
// iterative solvers. A separate executable, because counting allocations replaces the global
// operator new for the whole program.
#include <catch2/catch.hpp>

#include <cmath>

#include "allocation_counter.h"
#include "scene_fixtures.h"
#include "sim/world/stage_registry.h"

using namespace sim;

TEST_CASE("Pipeline::step allocates nothing after warm-up", "[unit][solvers]") {
  for (const char* solver : {"wcsph", "dfsph", "indsph", "iisph", "vslsph"}) {
    INFO(solver);
    // A 3 cm column falling onto the floor of a 3 cm tank at d = 5 mm (a few hundred particles).
    auto tank = testing::hydrostaticTank(0.03, 0.03, 0.005);
    World& w = *tank.world;
    PipelineOptions options;
    options.solver = solver;
    options.wcsph.speedOfSound = 10 * std::sqrt(2 * 9.81 * 0.03);  // [m/s] 10x the impact speed
    Pipeline pipeline = assemblePipeline(w, options);
    pipeline.attach(w);
    for (int s = 0; s < 40; ++s) pipeline.step(w);  // warm-up: lists at size, one Z-order sort
    allocations = 0;
    counting = true;
    for (int s = 0; s < 20; ++s) pipeline.step(w);  // includes a Z-order sort (every 16 updates)
    counting = false;
    CHECK(allocations.load() == 0);
  }
}
