// The sclera as a shell around the cavity wall: its thickness as a function of the position on
// the wall, for meshing/ to offset and sample (the shell spans the wall from the rim to the
// posterior pole; the lens/IOL cap has no sclera). Material "sclera" (material_library.h).
//
// Thickness profile (Vurgese S, Panda-Jonas S, Jonas JB, PLoS One 2012;7(1):e29692, 238 globes,
// AL <= 26 mm; reference-data.md 4.4) [S]: limbus 0.50, ora serrata 0.43, equator 0.42, midway
// equator-pole 0.65, posterior pole 0.94 mm; piecewise linear in wall distance between these
// landmarks on each meridian. Eyes longer than 26 mm are thinner at and behind the equator
// (same source, no numbers), so for myopic eyes pass a thinner profile; none is invented here.
#pragma once

#include <string>
#include <vector>

#include "anatomy/eye.h"
#include "meshing/triangle_mesh.h"

namespace anatomy {

struct ScleraThicknessProfile {
  double limbus = 0.50e-3;          // [m]
  double oraSerrata = 0.43e-3;      // [m]
  double equator = 0.42e-3;         // [m]
  double midEquatorPole = 0.65e-3;  // [m]
  double posteriorPole = 0.94e-3;   // [m]
};

class ScleraShell {
 public:
  // Keeps a reference to `eye`, which must outlive the shell. Validates the profile (positive,
  // at most 1.5 mm: the cavity generators guarantee no fold for offsets up to that).
  ScleraShell(const Eye& eye, const ScleraThicknessProfile& profile = {});

  const Eye& eye() const { return *eye_; }
  const std::string& materialName() const { return materialName_; }
  const ScleraThicknessProfile& profile() const { return profile_; }

  double thicknessAt(const WallCoordinate& w) const;  // [m]
  // Thickness at the wall point nearest to `point`; 0 on the lens/IOL cap.
  double thicknessAt(const Vec3& point) const;
  // One thickness per vertex of a cavity mesh (0 on the cap) [m]; #V.
  std::vector<double> vertexThickness(const meshing::TriangleMesh& cavityMesh) const;
  // Outer surface point: wall point + thickness x outward normal.
  Vec3 outerPoint(const WallCoordinate& w) const;

 private:
  const Eye* eye_;
  ScleraThicknessProfile profile_;
  std::string materialName_ = "sclera";
};

}  // namespace anatomy
