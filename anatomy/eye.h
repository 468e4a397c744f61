// One eye made concrete: which eye (OD/OS), its cavity shape, and the clinical landmarks that turn
// clinical coordinates (clock hour, mm posterior to the limbus or the ora serrata) into points on
// the cavity wall and back.
//
// Distances are measured along the cavity wall on the meridian of the clock hour (the plane
// through the optical axis), posterior to the limbus. The limbus itself is anterior to the
// modelled cavity (the cavity ends at the lens/IOL cap), so the wall starts `limbusToRim`
// posterior to it. Clinical distances are taken on the outer sclera, about 0.5 mm further out
// than the inner wall; over the 6-7 mm to the ora that differs by < 5 %, which this model ignores.
//
// Landmarks (reference-data.md 4.4): ora serrata 6.2 mm posterior to the limbus [S] (6-8 mm
// reported); fovea on the posterior pole (the visual axis) [D]; optic disc 4.76 mm nasal to the
// fovea along the wall [S] (Beijing Eye Study 2011; the 1.5 deg vertical offset is ignored);
// macula 4 mm across [S] (Polyak 1941 via BioNumbers 100707). limbusToRim (4.5 mm), the optic
// disc diameter (1.8 mm) and the posterior-pole radius (6 mm chord from the fovea, enough to hold
// disc and macula) are [U] model choices.
#pragma once

#include <vector>

#include "anatomy/cavity_shape.h"
#include "anatomy/laterality.h"

namespace anatomy {

struct ClinicalLandmarks {
  double limbusToRim = 4.5e-3;          // [m] wall distance limbus -> cavity rim [U]
  double oraFromLimbus = 6.2e-3;        // [m] [S]
  double foveaToDisc = 4.76e-3;         // [m] along the wall [S]
  double maculaDiameter = 4.0e-3;       // [m] [S]
  double opticDiscDiameter = 1.8e-3;    // [m] [U]
  double posteriorPoleRadius = 6.0e-3;  // [m] chord from the fovea [U]
};

enum class DistanceReference { kLimbus, kOraSerrata };

struct ClinicalPosition {
  double clockHour = 12.0;  // (0, 12], see clock_hour.h
  double distance = 0.0;    // [m] along the wall, posterior to `from`
  DistanceReference from = DistanceReference::kLimbus;
};

struct WallPoint {
  Vec3 position = Vec3::Zero();  // eye frame [m]
  Vec3 normal = Vec3::UnitZ();   // outward unit normal
};

class Eye {
 public:
  // Validates the landmarks (the ora must lie between the rim and the equator on every
  // meridian); throws AnatomyError naming the landmark.
  Eye(Laterality laterality, const CavityShape& cavity, const ClinicalLandmarks& landmarks = {});

  Laterality laterality() const { return laterality_; }
  const CavityShape& cavity() const { return cavity_; }
  const ClinicalLandmarks& landmarks() const { return landmarks_; }

  // Clinical position -> wall point. Throws AnatomyError when the position is anterior to the
  // modelled wall or farther than the posterior pole.
  WallPoint wallPointAt(const ClinicalPosition& position) const;
  // Point (on or near the wall) -> clinical position of its nearest wall point. Throws for a
  // point on the lens/IOL cap. Points on the optical axis get clock hour 12.
  ClinicalPosition clinicalPositionOf(const Vec3& point,
                                      DistanceReference from = DistanceReference::kLimbus) const;

  // Wall distance posterior to the limbus of a wall coordinate [m] (tabulated, < 1 um error).
  double distanceFromLimbus(const WallCoordinate& w) const;
  // Distance from the limbus to the posterior pole along the meridian of `w` [m].
  double distanceToPosteriorPole(double meridian) const;
  // The wall coordinate at `distance` [m] posterior to the limbus on `meridian`.
  WallCoordinate wallCoordinateAt(double meridian, double distance) const;

  Vec3 fovea() const { return fovea_; }
  Vec3 opticDisc() const { return opticDisc_; }

 private:
  double arcFromRim(double theta, double meridian) const;

  Laterality laterality_;
  CavityShape cavity_;
  ClinicalLandmarks landmarks_;
  // Arc length from each tabulated theta to the rim, per meridian: kMeridians x (kThetas + 1).
  std::vector<double> arcTable_;
  Vec3 fovea_ = Vec3::Zero();
  Vec3 opticDisc_ = Vec3::Zero();
};

}  // namespace anatomy
