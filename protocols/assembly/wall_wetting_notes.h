// What a scenario's notes say about the contact angle on the eye's wall: where the wall-wetting
// model was validated (docs/methods/interface.md, docs/validation.md) and how it errs outside.
#pragma once

#include <string>

namespace protocols {

// Contact angles through the tamponade [deg] at which the wall-wetting model holds the requested
// angle within 5 deg on a flat wall of layered wall particles (docs/methods/interface.md,
// validation 3: tests at 30, 60, 90 and 120). The library's oils (18 deg through the aqueous, 162
// through the oil) lie outside it, where the sessile benchmarks did not settle at the requested
// angle.
inline constexpr double kTestedContactAngleMin = 30.0;
inline constexpr double kTestedContactAngleMax = 120.0;
// The scenario note for a contact angle outside that range, saying how the model errs there;
// empty inside it.
std::string contactAngleRangeNote(double throughTamponadeDeg);
// What the retina is made of in a scene: the layered cavity wall (accuracy.wall_model, the wall
// the range above was measured on), one layer of wall particles, or an elastic sclera's lattice.
enum class RetinaWall { kLayered, kSingleLayer, kElasticSclera };
// The scenario note for any contact angle on the eye's wall: how well that wall holds it
// (docs/methods/interface.md, validations 3 and 5).
std::string contactAngleWallModelNote(RetinaWall wall);

}  // namespace protocols
