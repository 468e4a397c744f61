// `tamponade bench accuracy PROTOCOL [--tolerances ...] [--spacings ...] [--out DIR]`: what each
// accuracy choice costs and what it changes, side by side. Runs the protocol once per (particle
// spacing, solver tolerance) pair and writes DIR/accuracy.csv and DIR/accuracy.md: wall time,
// steps, the pressure solve's iterations and achieved density error, and every run's coverage
// against the most accurate run (finest spacing, then tightest tolerance) and against each
// posture's static equilibrium. Each run's own output
// (frames, report) stays in DIR/runs/. Not a test: times depend on the machine and its load.
// Exit codes: 0 ok, 2 bad usage or protocol, 1 a run failed or the output is not writable.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "protocols/assembly/assemble_scenario.h"
#include "protocols/assembly/pipeline_options.h"
#include "protocols/equilibrium/posture_equilibrium_coverage.h"
#include "protocols/equilibrium/start_from_equilibrium.h"
#include "protocols/format/parse_protocol.h"
#include "protocols/io/io_error.h"
#include "protocols/report/report_format.h"
#include "protocols/run/run_scenario.h"
#include "sim/core/error.h"
#include "tools/cli.h"
#include "tools/cli_values.h"
#include "tools/progress_printer.h"
#include "tools/protocol_error_print.h"

namespace tools {
namespace {

constexpr const char* kUsage =
    "usage: tamponade bench accuracy PROTOCOL.toml [--tolerances 0.005,0.001,...]\n"
    "                                [--spacings 1.2,0.8,...] [--out DIR] [--threads N]\n";

constexpr const char* kDescription =
    "Runs the protocol once per pair of particle spacing and solver tolerance and writes\n"
    "DIR/accuracy.csv and DIR/accuracy.md: wall time, steps, pressure-solve iterations per step,\n"
    "the mean density error the solve reached, the share of steps that stopped at its iteration\n"
    "cap, and the mean retinal coverage with its difference from the most accurate run (finest\n"
    "spacing, then tightest tolerance) for the whole retina and the worst region, and each\n"
    "run's distance from the answer: the retina's coverage at the end of each posture minus the\n"
    "posture's static equilibrium (solved once; the posture farthest from it named). The runs'\n"
    "frames and reports go to DIR/runs/ (replaced when the bench is run again).\n";

constexpr const char* kFooter =
    "Each run shows its progress (a bar on a terminal, plain lines otherwise). Measured on\n"
    "tiny.toml (docs/accuracy.md): the spacing moves the coverage more than the tolerance does\n"
    "(1.2 mm read 3 points above 0.5 mm; 0.5 % against 0.01 % moved it by 1), and a run costs\n"
    "about (1/d)^4: 7 s at 1.2 mm, 3 min at 0.6 mm, 7 min at 0.5 mm on one thread.\n"
    "Exit codes: 0 done, 2 bad usage or protocol (nothing run), 1 a run failed.\n";

struct AccuracyOptions {
  std::string file, out = "bench_accuracy";
  std::vector<double> tolerances{5e-3, 1e-3, 1e-4}, spacings;  // [1], [mm]
  int threads = 0;
};

void defineAccuracyOptions(CLI::App& app, AccuracyOptions& o) {
  app.add_option("PROTOCOL.toml", o.file, "the protocol to run")->required();
  app.add_option("--tolerances", o.tolerances,
                 "accuracy.solver_tolerance values as fractions, each in (0, 0.05]\n"
                 "(default 0.005,0.001,0.0001: the draft and standard presets and\n"
                 "the papers' eta)")
      ->type_name("X,...")
      ->delimiter(',')
      ->check(positiveNumber(0.05));
  app.add_option("--spacings", o.spacings,
                 "accuracy.particle_spacing values in mm, each at most 5 (default: the\n"
                 "protocol's own)")
      ->type_name("MM,...")
      ->delimiter(',')
      ->check(positiveNumber(5));
  app.add_option("--out", o.out, "output folder")->type_name("DIR")->capture_default_str();
  app.add_option("--threads", o.threads,
                 "OpenMP threads (default OMP_NUM_THREADS); one thread times most steadily")
      ->type_name("N")
      ->check(positiveInteger(std::numeric_limits<int>::max()));
}

struct AccuracyRun {
  double spacing = 0;    // [m]
  double tolerance = 0;  // [1]
  long particles = 0;    // fluid
  protocols::RunSummary summary;
  std::string folder;
};

std::string label(double spacing, double tolerance) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "d%gmm_tol%g", spacing * 1e3, tolerance);
  return buffer;
}

// Per posture, its static equilibrium's retina coverage and its label: the answer every run is
// also held against (none where the scene has no contact angle or tension).
struct Equilibria {
  std::vector<std::optional<double>> retina;  // [1]
  std::vector<std::string> labels;
};

// The largest |run's retina coverage at a posture's end - that posture's equilibrium| and the
// posture (NaN when no posture has an equilibrium).
double worstEquilibriumDifference(const AccuracyRun& run, const Equilibria& e,
                                  std::string& posture) {
  double worst = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < e.retina.size() && k < run.summary.retinaAtPostureEnd.size(); ++k) {
    if (!e.retina[k]) continue;
    const double diff = run.summary.retinaAtPostureEnd[k] - *e.retina[k];
    if (std::isnan(worst) || std::abs(diff) > std::abs(worst)) {
      worst = diff;
      posture = e.labels[k];
    }
  }
  return worst;
}

// Largest |difference| over the reported regions' mean coverage (whole retina, quadrants, zones).
double worstRegionDifference(const protocols::ScheduleCoverage& a,
                             const protocols::ScheduleCoverage& b, std::string& region) {
  double worst = -1;
  for (std::size_t k = 0; k < a.regions.size(); ++k) {
    const double diff = std::abs(a.regions[k] - b.regions[k]);
    if (diff > worst) {
      worst = diff;
      region = std::string(protocols::kReportedRegions[k].name);
    }
  }
  return worst;
}

std::string equilibriumCell(double difference, const std::string& posture) {
  if (std::isnan(difference)) return "n/a";
  char cell[96];
  std::snprintf(cell, sizeof cell, "%+.1f (%s)", 100 * difference, posture.c_str());
  return cell;
}

void writeTables(const std::vector<AccuracyRun>& runs, const Equilibria& equilibria,
                 const std::filesystem::path& dir, const std::string& protocolFile,
                 const std::string& solver, int threads) {
  const AccuracyRun& ref = runs.back();  // sorted coarse -> fine, loose -> tight
  const std::filesystem::path csvPath = dir / "accuracy.csv", mdPath = dir / "accuracy.md";
  std::ofstream csv(csvPath);
  if (!csv)
    throw protocols::IoError(csvPath.string(), "", "cannot be written", "choose another --out");
  csv << "spacing_mm,solver_tolerance,fluid_particles,steps,wall_s,mean_iterations,"
         "steps_at_iteration_cap,mean_density_error,worst_step_density_error,whole_retina_mean,"
         "whole_retina_diff,worst_region_diff,worst_region,equilibrium_diff,equilibrium_posture,"
         "threads\n";
  std::ofstream md(mdPath);
  if (!md)
    throw protocols::IoError(mdPath.string(), "", "cannot be written", "choose another --out");
  md << "Protocol `" << protocolFile << "`, solver " << solver << ", " << threads
     << " thread(s). Differences are in coverage points against the last row (finest spacing, "
        "tightest tolerance). \"vs equilibrium\" is the retina's coverage at the end of a "
        "posture minus the posture's static equilibrium (docs/methods/equilibrium.md), the "
        "posture farthest from it named.\n\n"
        "| spacing [mm] | tolerance | fluid particles | steps | wall [s] | iterations/step | at "
        "cap | "
        "density error reached (worst step) | whole retina | diff | worst region diff | vs "
        "equilibrium |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char line[640];
  for (const AccuracyRun& r : runs) {
    const protocols::PressureSolveTotals& ps = r.summary.pressureSolve;
    std::string region;
    const double worst = worstRegionDifference(r.summary.coverage, ref.summary.coverage, region);
    const double whole = r.summary.coverage.regions[0] - ref.summary.coverage.regions[0];
    std::string posture;
    const double fromEquilibrium = worstEquilibriumDifference(r, equilibria, posture);
    csv << r.spacing * 1e3 << ',' << r.tolerance << ',' << r.particles << ',' << r.summary.steps
        << ',' << r.summary.wallSeconds << ',' << ps.meanIterations() << ','
        << ps.stepsAtIterationCap << ',' << ps.meanDensityError() << ',' << ps.maxStepDensityError
        << ',' << r.summary.coverage.regions[0] << ',' << whole << ',' << worst << ",\"" << region
        << "\"," << fromEquilibrium << ",\"" << posture << "\"," << threads << '\n';
    std::snprintf(line, sizeof line,
                  "| %g | %.3g %% | %ld | %ld | %.1f | %.1f | %.0f %% | %.3g %% (%.3g %%) | %.1f "
                  "%% | %+.1f | "
                  "%.1f (%s) | %s |\n",
                  r.spacing * 1e3, 100 * r.tolerance, r.particles, r.summary.steps,
                  r.summary.wallSeconds, ps.meanIterations(), 100 * ps.capFraction(),
                  100 * ps.meanDensityError(), 100 * ps.maxStepDensityError,
                  100 * r.summary.coverage.regions[0], 100 * whole, 100 * worst, region.c_str(),
                  equilibriumCell(fromEquilibrium, posture).c_str());
    md << line;
  }
  std::printf("wrote %s and %s\n", csvPath.string().c_str(), mdPath.string().c_str());
}

// The postures' equilibria, solved once (they do not depend on the particle spacing).
Equilibria solveEquilibria(const protocols::Protocol& protocol,
                           const protocols::Scenario& scenario) {
  std::fprintf(stderr, "bench accuracy: solving each posture's static equilibrium ...\n");
  Equilibria e;
  e.retina = protocols::equilibriumRetinaCoverage(scenario, protocol.tamponade.fill.value);
  for (const auto& posture : scenario.schedule) e.labels.push_back(posture.label);
  for (std::size_t k = 0; k < e.retina.size(); ++k)
    if (e.retina[k])
      std::fprintf(stderr, "  %s: %s of the retina covered\n", e.labels[k].c_str(),
                   protocols::formatPercent(*e.retina[k]).c_str());
  return e;
}

// One run of `protocol` at this spacing and tolerance, into dir/runs/<label>; `solver` is set to
// the scenario's pressure solver.
AccuracyRun runOnce(const protocols::Protocol& protocol, double spacing, double tolerance,
                    const std::filesystem::path& dir, std::string& solver, std::size_t number,
                    std::size_t total) {
  protocols::Protocol p = protocol;
  p.accuracy.particleSpacing.value = spacing;
  p.accuracy.solverTolerance.value = tolerance;
  protocols::Scenario scenario = protocols::assembleStartingScenario(p);
  solver = scenario.pipelineOptions.solver;
  AccuracyRun r;
  r.spacing = spacing;
  r.tolerance = tolerance;
  for (const auto& phase : scenario.phases) r.particles += static_cast<long>(phase.count);
  r.folder = (dir / "runs" / label(spacing, tolerance)).string();
  std::filesystem::remove_all(r.folder);
  std::filesystem::create_directories(r.folder);
  std::fprintf(stderr, "bench accuracy %zu/%zu: d = %g mm, tolerance %g, %ld fluid particles ...\n",
               number, total, spacing * 1e3, tolerance, r.particles);
  protocols::RunOptions options;
  options.outputFolder = r.folder;
  ProgressPrinter printer;
  options.progress = [&](const protocols::RunProgress& progress) { printer(progress); };
  r.summary = protocols::runScenario(p, scenario, options);
  printer.finish();
  std::fprintf(stderr,
               "  %ld steps in %.1f s, %.1f iterations per step, density error %.3g %%, "
               "coverage %s\n",
               r.summary.steps, r.summary.wallSeconds, r.summary.pressureSolve.meanIterations(),
               100 * r.summary.pressureSolve.meanDensityError(),
               protocols::formatPercent(r.summary.retinaCoverage).c_str());
  return r;
}

int runAccuracy(const AccuracyOptions& o) {
  std::vector<double> tolerances = o.tolerances, spacings;
  for (const double mm : o.spacings) spacings.push_back(mm * 1e-3);  // [m]
  int threads = o.threads;
#ifdef _OPENMP
  if (threads > 0) omp_set_num_threads(threads);
  threads = omp_get_max_threads();
#else
  threads = 1;
#endif
  try {
    const protocols::Protocol protocol = protocols::parseProtocol(o.file);
    if (spacings.empty()) spacings.push_back(protocol.accuracy.particleSpacing.value);
    // Coarse to fine, loose to tight: the last run is the reference.
    std::sort(spacings.begin(), spacings.end(), std::greater<>());
    std::sort(tolerances.begin(), tolerances.end(), std::greater<>());
    const std::filesystem::path dir(o.out);
    std::filesystem::create_directories(dir / "runs");
    std::vector<AccuracyRun> runs;
    std::string solver;
    const std::size_t total = spacings.size() * tolerances.size();
    // The postures' equilibria, on the coarsest scenario (they do not depend on the spacing), as
    // assembled: where the fluid starts does not enter them, so the start is not solved again.
    protocols::Protocol coarsest = protocol;
    coarsest.accuracy.particleSpacing.value = spacings.front();
    const Equilibria equilibria = solveEquilibria(coarsest, protocols::assembleScenario(coarsest));
    for (const double spacing : spacings)
      for (const double tolerance : tolerances)
        runs.push_back(runOnce(protocol, spacing, tolerance, dir, solver, runs.size() + 1, total));
    if (!protocols::isImplicitSolver(solver))
      std::fprintf(stderr, "note: solver %s is explicit: the tolerance changes nothing\n",
                   solver.c_str());
    writeTables(runs, equilibria, dir, o.file, solver, threads);
    std::ifstream md(dir / "accuracy.md");
    std::printf("%s", std::string(std::istreambuf_iterator<char>(md), {}).c_str());
    return 0;
  } catch (const protocols::ProtocolError& e) {
    return printProtocolError(e);
  }
}

}  // namespace

Subcommand addBenchAccuracyCommand(CLI::App& bench) {
  auto o = std::make_shared<AccuracyOptions>();
  CLI::App* accuracy =
      addSubcommand(bench, "accuracy", "what each accuracy choice costs and changes", kUsage,
                    kDescription, kFooter);
  defineAccuracyOptions(*accuracy, *o);
  return {accuracy, [o] { return runAccuracy(*o); }};
}

}  // namespace tools
