// The fundus-style map of oil coverage: the retina unrolled around the posterior pole by an
// azimuthal equidistant projection (Snyder 1987, "Map Projections - A Working Manual", USGS PP
// 1395, ch. 25), as inline SVG.
//
// A wall point p (eye frame: +z anterior, +y superior, +x the patient's left) is drawn at
//   r = theta = atan2(hypot(x, y), -z)   (angle from the posterior axis through the cavity
//                                         centroid, in degrees),
//   azimuth = atan2(y, x),
// so angles from the posterior pole are true along every meridian. On a sphere that is the exact
// azimuthal equidistant map (radial distances = arc lengths / R); on the ellipsoidal cavity
// distances are angles, not millimetres. The map is seen from the front, as the surgeon sees the
// fundus without the indirect ophthalmoscope's inversion: superior up, the patient's left
// (+x) on the right, hence nasal right for OD and left for OS.
#pragma once

#include <string>

#include "protocols/report/report_input.h"

namespace protocols {

// Map coordinates [deg] of an eye-frame point: (right, up).
std::array<double, 2> projectFundus(const sim::Vec3& point);

// `<svg ...>...</svg>`: one dot per retinal wall particle coloured by its wetting (oil, aqueous,
// dry), the outlines, quadrant boundaries, breaks with their names, and a legend.
std::string renderFundusMap(const ReportInput& input);

}  // namespace protocols
