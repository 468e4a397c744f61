// Head postures -> the gravity direction in the eye frame (+z anterior, +y superior, +x toward the
// patient's left), with the eye looking straight ahead in the head (so head frame = eye frame).
//
// Derivations (gravity points toward the floor):
//   upright (sitting or standing, head erect): the floor is toward the feet          -> -y
//   supine (lying on the back, face up): the floor is behind the head (posterior)     -> -z
//   face-down / prone (face toward the floor): the floor is in front of the face      -> +z
//   left-side (left lateral decubitus, lying on the left side): the floor is to the
//     patient's left                                                                  -> +x
//   right-side (right lateral decubitus)                                              -> -x
//
// Head angles, starting from upright: `pitch` is forward flexion (chin toward the chest; +90 deg
// is face-down, -90 deg is supine), applied first about the head's left-right axis; `roll` is a
// tilt toward the patient's left shoulder (+90 deg is left-side-down), applied after it about the
// head's antero-posterior axis. With R = Rx(pitch) Rz(-roll) taking head axes into the world,
// gravity in the head frame is R^T (0, -1, 0):
//     g = (cos(pitch) sin(roll), -cos(pitch) cos(roll), sin(pitch)).
// It reproduces every named posture: (0,0) upright, (90,0) face-down, (-90,0) supine,
// (0,90) left-side, (0,-90) right-side.
#pragma once

#include <string>
#include <string_view>

#include "meshing/triangle_mesh.h"

namespace anatomy {

using Vec3 = meshing::Vec3;

enum class Posture { kUpright, kSupine, kFaceDown, kLeftSide, kRightSide };

// Unit gravity direction in the eye frame for a named posture.
Vec3 gravityDirection(Posture posture);

// Unit gravity direction for head angles [rad] (see the header comment for their meaning).
Vec3 gravityFromHeadAngles(double pitch, double roll);

// Names: "upright", "supine", "face-down" (or "prone"), "left-side", "right-side".
// Throws AnatomyError listing the valid names otherwise.
Posture parsePosture(std::string_view name);
std::string toString(Posture posture);

}  // namespace anatomy
