// Retinal regions of a wall point, as a bit set. The retina lines the wall posterior to the ora
// serrata (eye.h); a point on the lens/IOL cap or on the wall anterior to the ora belongs to no
// region (empty set).
//
// Regions (a retinal point is in kRetina plus):
//  * one quadrant by clock hour, each 3 hours wide and centred on 12 (superior), 6 (inferior)
//    and the nasal / temporal hour (3 / 9 for OD, 9 / 3 for OS; clock_hour.h); sectors are
//    half-open [centre - 1.5 h, centre + 1.5 h). Points on the optical axis have no quadrant;
//  * kMacula: within maculaDiameter / 2 (chord) of the fovea; kOpticDisc likewise for the disc;
//  * kPosteriorPole: within posteriorPoleRadius (chord) of the fovea;
//  * kPeriphery: between the ora serrata and the equator (the widest section of the base
//    ellipsoid, theta = 90 deg); kMidPeriphery: posterior to the equator and outside the
//    posterior pole. Every retinal point is in exactly one of kPosteriorPole, kMidPeriphery,
//    kPeriphery.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "anatomy/eye.h"

namespace anatomy {

using RegionSet = std::uint32_t;

enum RetinalRegion : RegionSet {
  kRetina = 1u << 0,
  kSuperior = 1u << 1,
  kInferior = 1u << 2,
  kNasal = 1u << 3,
  kTemporal = 1u << 4,
  kMacula = 1u << 5,
  kOpticDisc = 1u << 6,
  kPosteriorPole = 1u << 7,
  kMidPeriphery = 1u << 8,
  kPeriphery = 1u << 9,
};

// Regions of the wall point nearest to `point`; `normal` (optional) settles points at the rim
// between wall and cap.
RegionSet regionsAt(const Eye& eye, const Vec3& point, const Vec3* normal = nullptr);

// Regions of many points (e.g. wall particles); `normals` may be empty or of the same size.
std::vector<RegionSet> assignRegions(const Eye& eye, const std::vector<Vec3>& points,
                                     const std::vector<Vec3>& normals = {});

// "retina|superior|macula|..." for reports and messages; "none" for the empty set.
std::string describeRegions(RegionSet regions);

}  // namespace anatomy
