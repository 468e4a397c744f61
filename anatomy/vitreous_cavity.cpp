#include "anatomy/vitreous_cavity.h"

#include <string>

#include "anatomy/anatomy_error.h"
#include "anatomy/mesh_properties.h"

namespace anatomy {

namespace {

constexpr double kMm = 1e-3;  // [m]
// Atchison posterior-chamber ellipsoid (gkaModelEye modelEyeParameters.m; see the header).
constexpr double kAxialRadius0 = 10.176e-3;                                  // [m]
constexpr double kHorizontalRadius0 = 11.456e-3;                             // [m]
constexpr double kVerticalRadius0 = 11.377e-3;                               // [m]
constexpr double kAxialRadiusSlope = -0.1495e-3;                             // [m/D]
constexpr double kHorizontalRadiusSlope = -0.0393e-3;                        // [m/D]
constexpr double kVerticalRadiusSlope = -0.0864e-3;                          // [m/D]
constexpr double kEmmetropicAxialLength = 23.58e-3;                          // [m] Atchison 2006
constexpr double kApexDepth = kEmmetropicAxialLength - 2.0 * kAxialRadius0;  // [m] 3.228 mm

void requireRange(double value, double lo, double hi, const std::string& what) {
  require(value >= lo && value <= hi,
          what + " " + mmText(value) + " is out of range: use " + mmText(lo) + " .. " + mmText(hi));
}

void validateAnterior(const AnteriorBoundary& a) {
  requireRange(a.lensPosteriorDepth, 5.0 * kMm, 10.0 * kMm, "lens/IOL posterior depth");
  requireRange(a.capSag, 0.0, 3.0 * kMm, "anterior cap sag");
}

CavityGeometry atchisonGeometry(double refraction, double apexDepth, const AnteriorBoundary& a) {
  CavityGeometry g;
  g.semiAxisAxial = kAxialRadius0 + kAxialRadiusSlope * refraction;
  g.semiAxisHorizontal = kHorizontalRadius0 + kHorizontalRadiusSlope * refraction;
  g.semiAxisVertical = kVerticalRadius0 + kVerticalRadiusSlope * refraction;
  g.apexDepth = apexDepth;
  g.capPlaneDepth = a.lensPosteriorDepth - a.capSag;
  g.capSag = a.capSag;
  return g;
}

VitreousCavity finish(std::string type, const CavityGeometry& g, int resolution) {
  CavityShape shape(g);
  meshing::TriangleMesh mesh = shape.triangulate(resolution);
  const MeshProperties measures = measureMesh(mesh);
  VitreousCavity result{std::move(type), shape, std::move(mesh)};
  result.axialLength = shape.axialLength();
  result.axialDepth = shape.axialDepth();
  result.volume = measures.signedVolume;
  result.analyticVolume = shape.volume();
  result.area = measures.area;
  return result;
}

}  // namespace

double refractionForAxialLength(double axialLength) {
  return -(axialLength - kEmmetropicAxialLength) / (-2.0 * kAxialRadiusSlope);
}

CavityGeometry emmetropicGeometry(const EmmetropicCavityParameters& p) {
  requireRange(p.axialLength, 20.0 * kMm, 26.0 * kMm, "emmetropic axial length");
  validateAnterior(p.anterior);
  CavityGeometry g = atchisonGeometry(0.0, kApexDepth, p.anterior);
  const double scale = (p.axialLength - kApexDepth) / (2.0 * kAxialRadius0);
  g.semiAxisAxial *= scale;
  g.semiAxisHorizontal *= scale;
  g.semiAxisVertical *= scale;
  return g;
}

CavityGeometry myopicGeometry(const MyopicCavityParameters& p) {
  requireRange(p.axialLength, 24.0 * kMm, 34.0 * kMm, "myopic axial length");
  validateAnterior(p.anterior);
  return atchisonGeometry(refractionForAxialLength(p.axialLength), kApexDepth, p.anterior);
}

CavityGeometry staphylomaGeometry(const StaphylomaCavityParameters& p) {
  requireRange(p.axialLength, 24.0 * kMm, 36.0 * kMm, "staphyloma axial length");
  requireRange(p.staphylomaDepth, 0.2 * kMm, 6.0 * kMm, "staphyloma depth");
  validateAnterior(p.anterior);
  const double baseAxialLength = p.axialLength - p.staphylomaDepth;
  require(baseAxialLength >= 22.0 * kMm, "staphyloma: axial length " + mmText(p.axialLength) +
                                             " minus depth " + mmText(p.staphylomaDepth) +
                                             " leaves a globe shorter than 22 mm");
  CavityGeometry g =
      atchisonGeometry(refractionForAxialLength(baseAxialLength), kApexDepth, p.anterior);
  g.staphylomaDepth = p.staphylomaDepth;
  g.staphylomaWidth = p.staphylomaWidth;
  return g;  // width limits depend on the globe: checked by CavityShape
}

VitreousCavity makeEmmetropicCavity(const EmmetropicCavityParameters& p) {
  return finish("emmetropic", emmetropicGeometry(p), p.resolution);
}

VitreousCavity makeMyopicCavity(const MyopicCavityParameters& p) {
  return finish("myopic", myopicGeometry(p), p.resolution);
}

VitreousCavity makeStaphylomaCavity(const StaphylomaCavityParameters& p) {
  return finish("staphyloma", staphylomaGeometry(p), p.resolution);
}

}  // namespace anatomy
