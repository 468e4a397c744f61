// `tamponade demo`: a built-in dam-break scene (a water column collapsing in a tank), written as
// HDF5 frames + XDMF so that a new user sees the engine run and ParaView open its output before
// any eye or protocol is involved. The README's first command runs the
// default eye protocol.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "protocols/io/frame_writer.h"
#include "sim/measure/diagnostics.h"
#include "sim/scenes/box_scene.h"
#include "sim/world/stage_registry.h"
#include "tools/cli.h"
#include "tools/cli_values.h"

namespace tools {
namespace {

constexpr const char* kUsage =
    "usage: tamponade demo [--out DIR] [--solver dfsph|wcsph] [--time SECONDS] [--force]\n";

constexpr const char* kDescription =
    "Runs a dam break: a 0.2 m x 0.4 m x 0.1 m water column (spacing 12.5 mm, 4096 particles)\n"
    "collapses in a 0.8 m long tank. Writes DIR/frames.h5 and DIR/frames.xmf (open the .xmf in\n"
    "ParaView) with a frame every 20 ms.\n";

struct DemoOptions {
  std::string out = "runs/dam-break";
  std::string solver = "wcsph";
  double time = 0.5;  // [s]
  bool force = false;
};

void defineDemoOptions(CLI::App& app, DemoOptions& o) {
  app.add_option("--out", o.out, "output folder")->type_name("DIR")->capture_default_str();
  std::vector<std::string> solvers;
  for (const auto& entry : sim::solverRegistry()) solvers.push_back(entry.name);
  app.add_option("--solver", o.solver, "pressure solver")
      ->type_name("NAME")
      ->check(oneOf(solvers))
      ->capture_default_str();
  app.add_option("--time", o.time, "simulated time, at most 60")
      ->type_name("SECONDS")
      ->check(positiveNumber(60))
      ->capture_default_str();
  app.add_flag("--force", o.force, "replace an existing output folder's frames");
}

}  // namespace

int runDemo(Args args) {
  CLI::App app("", "tamponade demo");
  describeCommand(app, kUsage, kDescription);
  DemoOptions o;
  defineDemoOptions(app, o);
  if (const std::optional<int> exit = parseCommandLine(app, args)) return *exit;

  const double d = 0.0125;  // [m]
  sim::TankSpec tank;
  tank.innerMax = sim::Vec3(0.8, 0.6, 0.1 + 2.4 * d);
  sim::WorldParameters params;
  params.particleSpacing = d;
  params.domain = sim::tankDomain(tank, d);
  sim::World world(params);
  sim::Material water;
  water.name = "water";
  water.restDensity = 1000.0;
  water.dynamicViscosity = 1e-3;
  world.materials.add(water);
  sim::addTankWalls(world, tank, d);
  const double gap = 0.7 * d;  // first particle 1.2 d from the walls (see sim/scenes/box_scene.h)
  sim::addFluidBlock(world, sim::Vec3(gap, gap, gap), sim::Vec3(gap + 0.2, gap + 0.4, gap + 0.1), d,
                     0);
  world.initialize();

  sim::PipelineOptions options;
  options.solver = o.solver;
  options.wcsph.speedOfSound = 10.0 * std::sqrt(2.0 * 9.81 * 0.4);  // 10x the largest flow speed
  sim::Pipeline pipeline = sim::assemblePipeline(world, options);
  pipeline.attach(world);

  std::filesystem::create_directories(o.out);
  protocols::RunMetadata metadata;
  metadata.strings["scene"] = "dam break demo";
  metadata.strings["solver"] = o.solver;
  metadata.numbers["particle_spacing [m]"] = d;
  protocols::FrameWriterOptions writerOptions;
  writerOptions.overwrite = o.force;
  protocols::FrameWriter writer(std::filesystem::path(o.out) / "frames.h5", metadata,
                                writerOptions);
  writer.writeStatic("wall", world.walls.fields);

  std::printf("tamponade demo: %zu water particles, %zu wall particles, solver %s\n%s",
              world.particles.size(), world.walls.size(), o.solver.c_str(),
              pipeline.describe().c_str());
  const double frameInterval = 0.02;  // [s]
  double nextFrame = 0.0;
  const auto start = std::chrono::steady_clock::now();
  while (world.time < o.time) {
    if (world.time >= nextFrame) {
      writer.writeFrame(world.time, world.stepCount, {{"fluid", &world.particles.fields}});
      nextFrame += frameInterval;
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf(
          "  t = %5.3f s of %.3f s, step %6ld, dt %.2e s, max speed %.2f m/s, %.0f s elapsed\n",
          world.time, o.time, world.stepCount, world.lastTimeStep, sim::maxSpeed(world), elapsed);
      std::fflush(stdout);
    }
    pipeline.step(world);
  }
  writer.writeFrame(world.time, world.stepCount, {{"fluid", &world.particles.fields}});
  writer.close();
  std::printf("\nstage times:\n");
  for (const auto& e : pipeline.timers().entries())
    std::printf("  %-26s %8.2f s  (%ld calls)\n", e.name.c_str(), e.seconds, e.calls);
  std::printf("\nwrote %s\n  and %s (open this one in ParaView)\n", writer.h5Path().c_str(),
              writer.xdmfPath().c_str());
  return 0;
}

}  // namespace tools
