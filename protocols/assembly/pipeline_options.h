// The pipeline options of a scenario: the pressure solver by name (the format's default, INDSPH,
// or WCSPH with the comparison fill rules), the closed cavity, the surface-stress form, the
// accuracy's tolerance for every implicit solve, the solvers' eye-scene parameters, and the
// effects the protocol forces; then the frames' fields checked against the assembled pipeline.
#pragma once

#include <string>

#include "protocols/scenario/scenario.h"

namespace protocols {

// INDSPH's Jacobi relaxation in eye scenes (the engine's default is 0.5; why:
// pipeline_options.cpp).
inline constexpr double kEyeIndsphRelaxation = 0.8;

// Whether the named pressure solver iterates to accuracy.solver_tolerance (DFSPH, INDSPH, IISPH);
// the explicit solvers (WCSPH, number_density) have no solve to stop.
bool isImplicitSolver(const std::string& solver);

void choosePipelineOptions(const Protocol& protocol, const ScenarioOptions& options, Scenario& s);

// outputs.fields against the particle fields the run will have (with "did you mean" at each
// unknown name's place), and s.outputFields: those plus what coverage, report and resume need.
void resolveOutputFields(const Protocol& protocol, Scenario& s);

}  // namespace protocols
