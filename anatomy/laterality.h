// Which eye: OD (oculus dexter, right) or OS (oculus sinister, left), and where nasal lies in the
// eye frame (+z anterior, +y superior, +x toward the patient's left; docs/conventions.md).
//
// The nose is between the eyes. For the right eye it is toward the patient's left (+x); for the
// left eye toward the patient's right (-x). Temporal is the opposite side.
#pragma once

#include <string>
#include <string_view>

#include "meshing/triangle_mesh.h"

namespace anatomy {

using Vec3 = meshing::Vec3;

enum class Laterality { kRight, kLeft };  // OD, OS

// Unit vector toward the nose in the eye frame: +x for OD, -x for OS.
Vec3 nasalDirection(Laterality eye);
inline Vec3 temporalDirection(Laterality eye) { return -nasalDirection(eye); }

// Accepts "OD", "right", "OS", "left" (case-insensitive); throws AnatomyError otherwise.
Laterality parseLaterality(std::string_view name);
std::string toString(Laterality eye);  // "OD" or "OS"

}  // namespace anatomy
