// Kernel invariants: normalisation on a lattice, symmetry, compact support, and a gradient
// consistent with the finite difference of W. Every kernel is tested the same way.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/kernels/kernel.h"

using sim::Kernel;
using sim::KernelKind;
using sim::Real;
using sim::Vec3;

namespace {

// Sum of W over a cubic lattice of spacing d times d^3: the SPH estimate of the integral of W,
// which must be 1. The lattice quadrature error shrinks as h/d grows: at h/d = 2 (the default
// resolution) Wendland C2 sums to 1.034, a discretisation error, not a normalisation one; from
// h/d = 3 on both kernels sum to 1 within 1 %, so a wrong constant (>= 5 % off) cannot pass.
Real latticeIntegral(const Kernel& k, Real d, const Vec3& offset) {
  const int n = static_cast<int>(std::ceil(k.supportRadius() / d)) + 1;
  Real sum = 0;
  for (int x = -n; x <= n; ++x)
    for (int y = -n; y <= n; ++y)
      for (int z = -n; z <= n; ++z) sum += k.W(Vec3(x * d, y * d, z * d) + offset);
  return sum * d * d * d;
}

}  // namespace

TEST_CASE("kernels integrate to one on a lattice", "[unit][kernel]") {
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    const Real d = 1e-3;
    for (Real ratio : {3.0, 4.0}) {
      const Kernel k(kind, ratio * d);
      INFO(sim::kernelName(kind) << " h/d=" << ratio);
      CHECK(latticeIntegral(k, d, Vec3::Zero()) == Approx(1.0).epsilon(0.01));
      CHECK(latticeIntegral(k, d, Vec3(0.31, 0.17, 0.43) * d) == Approx(1.0).epsilon(0.01));
    }
  }
}

TEST_CASE("kernels are symmetric, non-negative and compactly supported", "[unit][kernel]") {
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    const Kernel k(kind, 0.01);
    const Vec3 xij(0.003, -0.002, 0.001);
    CHECK(k.W(xij) == k.W(Vec3(-xij)));
    CHECK((k.gradW(xij) + k.gradW(Vec3(-xij))).norm() == 0.0);  // antisymmetric gradient
    CHECK(k.W(0.0100001) == 0.0);
    CHECK(k.gradW(Vec3(0.0100001, 0, 0)).norm() == 0.0);
    for (Real r = 0; r < 0.01; r += 1e-4) CHECK(k.W(r) >= 0.0);
    CHECK(k.gradW(Vec3::Zero()).norm() == 0.0);
    CHECK(k.W(0.0) == k.W0());
  }
}

TEST_CASE("kernel gradients match finite differences of W", "[unit][kernel]") {
  for (auto kind : {KernelKind::kCubicSpline, KernelKind::kWendlandC2}) {
    const Real h = 0.01;
    const Kernel k(kind, h);
    const Real eps = 1e-8;
    for (const Vec3& x :
         {Vec3(0.001, 0.002, -0.0015), Vec3(0.004, 0.003, 0.002), Vec3(-0.006, 0.001, 0.0045)}) {
      Vec3 fd;
      for (int d = 0; d < 3; ++d) {
        Vec3 e = Vec3::Zero();
        e[d] = eps;
        fd[d] = (k.W(Vec3(x + e)) - k.W(Vec3(x - e))) / (2 * eps);
      }
      // Central differences are O(eps^2 W''') accurate: relative 1e-6 is generous.
      CHECK((k.gradW(x) - fd).norm() <= 1e-6 * fd.norm());
    }
  }
}
