#include "protocols/assembly/wall_wetting_notes.h"

#include <cmath>

namespace protocols {

std::string contactAngleRangeNote(double throughTamponadeDeg) {
  if (throughTamponadeDeg >= kTestedContactAngleMin &&
      throughTamponadeDeg <= kTestedContactAngleMax)
    return "";
  const std::string angle =
      std::to_string(std::lround(throughTamponadeDeg)) + " deg through the tamponade";
  const std::string tested = "outside the " + std::to_string(std::lround(kTestedContactAngleMin)) +
                             "-" + std::to_string(std::lround(kTestedContactAngleMax)) +
                             " deg that the wall model holds within 5 deg on a flat wall";
  if (throughTamponadeDeg > kTestedContactAngleMax)
    return "contact angle " + angle + " is " + tested +
           ": 150 deg settles up to 8 deg flatter than asked, so the oil's edge is uncertain by "
           "several degrees (docs/validation.md)";
  return "contact angle " + angle + " is " + tested +
         ": 18 deg reads 25.7-27.6 deg, so a thin film may spread less than asked "
         "(docs/validation.md)";
}

std::string contactAngleWallModelNote(RetinaWall wall) {
  if (wall == RetinaWall::kLayered)
    return "layered eye wall (accuracy.wall_model): in a spherical cavity a 150 deg lens reads "
           "155-157 deg; the oil's edge on the retina is uncertain by about 5 deg "
           "(docs/validation.md)";
  const std::string surface =
      wall == RetinaWall::kElasticSclera
          ? "retina over the elastic sclera: 18 deg through the aqueous reads 28.9 deg on a tissue "
            "floor, so the oil's edge there is uncertain by about 10 deg; the lens cap is one "
            "layer of wall particles"
          : "single-layer eye wall (accuracy.wall_model = \"single_layer\"): 18 deg through "
            "the aqueous reads 34.4 deg, 150 deg 127-151 deg, so the oil's edge is uncertain by "
            "10-20 deg";
  return surface + " (docs/validation.md)";
}

}  // namespace protocols
