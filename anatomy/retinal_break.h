// A retinal break (tear or hole) placed on the wall from its clinical description: clock hour,
// distance posterior to the limbus or to the ora serrata, and diameter. Modelled as the disc of
// wall points within diameter / 2 (straight-line distance) of its centre.
#pragma once

#include <string>

#include "anatomy/eye.h"

namespace anatomy {

struct RetinalBreakSpec {
  std::string name;           // e.g. "horseshoe tear 1", used in every message
  ClinicalPosition position;  // centre of the break
  double diameter = 0.0;      // [m] > 0, at most 20 mm
};

class RetinalBreak {
 public:
  // Throws AnatomyError naming the break when it lies anterior to the ora serrata (the retina
  // starts there), beyond the posterior pole, or has a bad diameter or clock hour.
  RetinalBreak(const Eye& eye, RetinalBreakSpec spec);

  bool isInBreak(const Vec3& point) const;

  const std::string& name() const { return spec_.name; }
  const RetinalBreakSpec& spec() const { return spec_; }
  const WallPoint& centre() const { return centre_; }

 private:
  RetinalBreakSpec spec_;
  WallPoint centre_;
};

}  // namespace anatomy
