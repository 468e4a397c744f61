#include "anatomy/posture.h"

#include <cmath>

#include "anatomy/anatomy_error.h"

namespace anatomy {

Vec3 gravityDirection(Posture posture) {
  switch (posture) {
    case Posture::kUpright: return {0.0, -1.0, 0.0};
    case Posture::kSupine: return {0.0, 0.0, -1.0};
    case Posture::kFaceDown: return {0.0, 0.0, 1.0};
    case Posture::kLeftSide: return {1.0, 0.0, 0.0};
    case Posture::kRightSide: return {-1.0, 0.0, 0.0};
  }
  throw AnatomyError("gravityDirection: unknown posture value");
}

Vec3 gravityFromHeadAngles(double pitch, double roll) {
  return {std::cos(pitch) * std::sin(roll), -std::cos(pitch) * std::cos(roll), std::sin(pitch)};
}

Posture parsePosture(std::string_view name) {
  if (name == "upright") return Posture::kUpright;
  if (name == "supine") return Posture::kSupine;
  if (name == "face-down" || name == "prone") return Posture::kFaceDown;
  if (name == "left-side") return Posture::kLeftSide;
  if (name == "right-side") return Posture::kRightSide;
  throw AnatomyError("unknown posture '" + std::string(name) +
                     "': use upright, supine, face-down (or prone), left-side or right-side, "
                     "or give head angles / a gravity vector");
}

std::string toString(Posture posture) {
  switch (posture) {
    case Posture::kUpright: return "upright";
    case Posture::kSupine: return "supine";
    case Posture::kFaceDown: return "face-down";
    case Posture::kLeftSide: return "left-side";
    case Posture::kRightSide: return "right-side";
  }
  return "?";
}

}  // namespace anatomy
