// Clock hours on the fundus <-> directions in the eye frame.
//
// Convention (docs/conventions.md): the clock face is the one the surgeon sees when facing the
// patient and looking into the eye: 12 o'clock superior (+y), hours increasing clockwise as the
// surgeon sees them.
//
// Derivation. The surgeon looks along -z (into the eye, from in front) with +y up. The surgeon's
// right-hand direction is forward x up = (-z) x (+y) = +x, i.e. the patient's left. A clock read
// clockwise from 12 at the top therefore reaches 3 o'clock at +x (the patient's left) and
// 9 o'clock at -x (the patient's right):
//     direction(h) = (sin(30 deg * h), cos(30 deg * h), 0).
// This is the same for both eyes. What changes with the eye is which side is nasal
// (laterality.h): the patient's left is toward the nose for OD and away from it for OS, so
//     OD: 3 o'clock nasal, 9 o'clock temporal;  OS: 3 o'clock temporal, 9 o'clock nasal.
// That is the clinical convention for fundus drawings and operation notes (e.g. the common
// superotemporal tears of a right eye are written "10-11 o'clock").
//
// About the words "3 = left side of the image" in docs/conventions.md: they hold when "left" is the
// patient's left (+x), which is where 3 o'clock lies in this derivation. Read as the left of the
// surgeon's field of view they would put 3 o'clock at the patient's right and make it temporal
// in OD, contradicting the clinical convention above; the code follows the clinical convention.
#pragma once

#include "meshing/triangle_mesh.h"

namespace anatomy {

using Vec3 = meshing::Vec3;

// Unit vector in the x-y plane pointing from the optical axis toward clock hour `hour`
// (any real number; 12 == 0, 3 == +x, 6 == -y, 9 == -x).
Vec3 clockHourDirection(double hour);

// Clock hour in (0, 12] of the direction of `point` projected on the x-y plane (12 o'clock is
// returned as 12, not 0). Throws AnatomyError for a point on the optical axis (no clock hour).
double clockHourOf(const Vec3& point);

// The shortest signed difference a - b on the clock, in (-6, 6] hours.
double clockHourDifference(double a, double b);

}  // namespace anatomy
