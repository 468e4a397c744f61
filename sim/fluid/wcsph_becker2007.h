// Weakly compressible SPH (Becker & Teschner 2007, "Weakly compressible SPH for free surface
// flows", SCA): Tait equation of state p = B ((rho/rho0)^7 - 1), B = rho0 c^2 / 7, negative
// pressures clamped to zero (free surface), symmetric pressure force, Akinci 2012 wall pressure,
// and the Monaghan artificial viscosity of Becker & Teschner eq. 11 for stability.
#pragma once

#include "sim/core/reduction.h"
#include "sim/fluid/pressure_solver.h"

namespace sim {

struct WcsphParameters {
  // [m/s] numerical speed of sound; 10x the largest expected flow speed keeps density errors
  // near 1 % (Becker & Teschner 2007, section 4). Required: the caller knows the scene's scale.
  Real speedOfSound = 0.0;
  Real artificialViscosity = 0.05;  // [1] alpha of the Monaghan term (0 disables)
  Real courantNumber = 0.4;         // [1] dt <= courant * d / c
};

class WcsphBecker2007 final : public PressureSolver {
 public:
  explicit WcsphBecker2007(const WcsphParameters& parameters);
  std::string_view name() const override { return "wcsph"; }
  void attach(World& world) override;
  void beginStep(World& world, const StepContext& context) override;
  void correctVelocities(World& world, const StepContext& context) override;
  Real maxTimeStep(const World& world) const override;

 private:
  WcsphParameters params_;
  std::vector<Real>* pressure_ = nullptr;   // [Pa]
  std::vector<Vec3> pressureAcceleration_;  // [m/s^2] scratch
  DeterministicReducer reducer_;
};

}  // namespace sim
