#include "anatomy/sclera_shell.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "anatomy/anatomy_error.h"

namespace anatomy {

ScleraShell::ScleraShell(const Eye& eye, const ScleraThicknessProfile& profile)
    : eye_(&eye), profile_(profile) {
  const std::array values = {profile.limbus, profile.oraSerrata, profile.equator,
                             profile.midEquatorPole, profile.posteriorPole};
  for (double t : values)
    require(t > 0.0 && t <= 1.5e-3,
            "sclera thickness " + mmText(t) + " is out of range (0 < t <= 1.5 mm)");
}

double ScleraShell::thicknessAt(const WallCoordinate& w) const {
  const Eye& eye = *eye_;
  const double equatorTheta = std::min(0.5 * std::numbers::pi, eye.cavity().rimTheta());
  const double s = eye.distanceFromLimbus(w);
  const double ora = eye.landmarks().oraFromLimbus;
  const double equator = eye.distanceFromLimbus({equatorTheta, w.meridian});
  const double pole = eye.distanceToPosteriorPole(w.meridian);
  const double mid = 0.5 * (equator + pole);
  // Landmark distances increase strictly (the Eye checks ora < equator).
  const std::array<double, 5> at = {0.0, ora, equator, mid, pole};
  const std::array<double, 5> thickness = {profile_.limbus, profile_.oraSerrata, profile_.equator,
                                           profile_.midEquatorPole, profile_.posteriorPole};
  if (s >= pole) return thickness[4];
  for (size_t k = 0; k + 1 < at.size(); ++k)
    if (s < at[k + 1]) {
      const double f = std::clamp((s - at[k]) / (at[k + 1] - at[k]), 0.0, 1.0);
      return thickness[k] + f * (thickness[k + 1] - thickness[k]);
    }
  return thickness[4];
}

double ScleraShell::thicknessAt(const Vec3& point) const {
  const CavityProjection projection = eye_->cavity().project(point);
  return projection.part == CavityPart::kCap ? 0.0 : thicknessAt(projection.wall);
}

std::vector<double> ScleraShell::vertexThickness(const meshing::TriangleMesh& cavityMesh) const {
  std::vector<double> result(cavityMesh.vertices.size());
  for (size_t i = 0; i < result.size(); ++i) result[i] = thicknessAt(cavityMesh.vertices[i]);
  return result;
}

Vec3 ScleraShell::outerPoint(const WallCoordinate& w) const {
  const CavityShape& cavity = eye_->cavity();
  return cavity.wallPoint(w) + thicknessAt(w) * cavity.wallNormal(w);
}

}  // namespace anatomy
