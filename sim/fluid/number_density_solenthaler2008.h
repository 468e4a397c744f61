// Explicit number-density SPH (Solenthaler & Pajarola 2008, "Density contrast SPH interfaces",
// SCA): the adapted density rho~_i = m_i delta_i with delta_i = sum_j W_ij (Wang et al. 2023
// eqs. 6-7), the Tait equation of state of WCSPH (Becker & Teschner 2007) on rho~, and the
// symmetric number-density pressure force
//   F_i = -sum_j (p_i/delta_i^2 + p_j/delta_j^2) gradW_ij - p_i/delta_i^2 sum_b (V_b/V0_i)
//   gradW_ib,
// plus the Monaghan artificial viscosity of the WCSPH solver. The baseline Wang et al. compare
// with.
#pragma once

#include <vector>

#include "sim/core/reduction.h"
#include "sim/fluid/pressure_solver.h"
#include "sim/fluid/wcsph_becker2007.h"

namespace sim {

class NumberDensitySolenthaler2008 final : public PressureSolver {
 public:
  // Uses the WCSPH parameters (speed of sound, artificial viscosity, Courant number).
  explicit NumberDensitySolenthaler2008(const WcsphParameters& parameters);
  std::string_view name() const override { return "number_density"; }
  void attach(World& world) override;
  void beginStep(World& world, const StepContext& context) override;
  void correctVelocities(World& world, const StepContext& context) override;
  Real maxTimeStep(const World& world) const override;

 private:
  WcsphParameters params_;
  std::vector<Real>* numberDensity_ = nullptr;  // [1/m^3]
  std::vector<Real>* pressure_ = nullptr;       // [Pa]
  std::vector<Vec3> acceleration_;              // [m/s^2] scratch
  DeterministicReducer reducer_;
};

}  // namespace sim
