#include "anatomy/laterality.h"

#include <algorithm>
#include <cctype>

#include "anatomy/anatomy_error.h"

namespace anatomy {

Vec3 nasalDirection(Laterality eye) {
  return eye == Laterality::kRight ? Vec3(1.0, 0.0, 0.0) : Vec3(-1.0, 0.0, 0.0);
}

Laterality parseLaterality(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "od" || lower == "right") return Laterality::kRight;
  if (lower == "os" || lower == "left") return Laterality::kLeft;
  throw AnatomyError("unknown eye '" + std::string(name) +
                     "': use OD (right eye) or OS (left eye)");
}

std::string toString(Laterality eye) { return eye == Laterality::kRight ? "OD" : "OS"; }

}  // namespace anatomy
