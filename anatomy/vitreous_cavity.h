// Parametric vitreous cavities: emmetropic, axial myopia, posterior staphyloma. Each generator
// validates its parameters, builds the analytic CavityShape (cavity_shape.h) and its mesh, and
// reports axial length, volume and area. Lengths in metres.
//
// Shape data (reference-data.md 4.3): the Atchison posterior-chamber ellipsoid as fitted in
// gkaModelEye (modelEyeParameters.m, citing Atchison et al., IOVS 2005;46(8):2698 and Vision Res
// 2006;46:2236): semi-axes (axial, horizontal, vertical) = (10.176, 11.456, 11.377) mm
// + (-0.1495, -0.0393, -0.0864) mm/D x SR, SR the spherical refraction [D] (negative = myopia),
// with the ellipsoid's anterior apex a constant 3.228 mm behind the corneal apex (so the
// emmetropic axial length is 23.58 mm, Atchison 2006). Hence AL = 23.58 mm - 0.299 mm/D x SR.
//  * emmetropic: the SR = 0 ellipsoid (oblate, wider than long) scaled uniformly so the axial
//    length is as requested (the same scaling gkaModelEye applies for a given axial length);
//  * myopic: SR = -(AL - 23.58 mm) / 0.299 mm/D, radii from the linear fit: longer than wide
//    beyond AL 27.1 mm (SR -11.6 D), longer than high beyond 29.3 mm (SR -19 D), i.e. prolate
//    in both planes from there; far beyond the fit's data range this is a linear extrapolation;
//  * staphyloma: the myopic eye of axial length AL - depth plus a posterior outpouching of the
//    given depth and base width, so that the requested AL is the biometric one (to the bottom of
//    the staphyloma). Depth/width are not in the reference data ([U]: a few mm deep, 10-15 mm
//    wide).
// Anterior boundary: the lens/IOL side. Its posterior pole lies `lensPosteriorDepth` behind the
// corneal apex ([U] 7.6 mm: anterior chamber ~3.6 mm + lens ~4.0 mm, typical schematic-eye
// values) and it dents `capSag` into the cavity ([U] 1 mm; 0 = flat, e.g. aphakic).
//
// Emmetropic result: 5.0 mL (reference-data.md 4.1 gives 4.3 mL (Zhou 2020) to 5.4 mL (Feng 2011)).
#pragma once

#include <string>

#include "anatomy/cavity_shape.h"
#include "meshing/triangle_mesh.h"

namespace anatomy {

struct AnteriorBoundary {
  double lensPosteriorDepth = 7.6e-3;  // [m] corneal apex to the lens/IOL posterior pole [U]
  double capSag = 1.0e-3;              // [m] dent of the cap into the cavity [U]
};

struct EmmetropicCavityParameters {
  double axialLength = 23.58e-3;  // [m] biometric, corneal apex to retina; 20..26 mm
  AnteriorBoundary anterior;
  int resolution = 96;  // segments around the optical axis
};

struct MyopicCavityParameters {
  double axialLength = 28.0e-3;  // [m] 24..34 mm (the brief's clinical range is 26..32 mm)
  AnteriorBoundary anterior;
  int resolution = 96;
};

struct StaphylomaCavityParameters {
  double axialLength = 29.0e-3;      // [m] biometric, including the staphyloma; 24..36 mm
  double staphylomaDepth = 2.0e-3;   // [m] 0.2..6 mm
  double staphylomaWidth = 12.0e-3;  // [m] base diameter, 2 mm..70 % of the eye's width
  AnteriorBoundary anterior;
  int resolution = 96;
};

struct VitreousCavity {
  std::string type;             // "emmetropic", "myopic", "staphyloma"
  CavityShape shape;            // the analytic surface, eye frame
  meshing::TriangleMesh mesh;   // closed, outward, eye frame [m]
  double axialLength = 0.0;     // [m] corneal apex to posterior pole (analytic)
  double axialDepth = 0.0;      // [m] cavity length on the axis, cap to posterior pole
  double volume = 0.0;          // [m^3] of the mesh
  double analyticVolume = 0.0;  // [m^3] of the defining surface
  double area = 0.0;            // [m^2] of the mesh
};

// Spherical refraction [D] that the Atchison fit associates with an axial length [m].
double refractionForAxialLength(double axialLength);

// The analytic shapes alone (no mesh).
CavityGeometry emmetropicGeometry(const EmmetropicCavityParameters& p);
CavityGeometry myopicGeometry(const MyopicCavityParameters& p);
CavityGeometry staphylomaGeometry(const StaphylomaCavityParameters& p);

// Shape + mesh + measures. Throw AnatomyError naming the parameter, its value and its range.
VitreousCavity makeEmmetropicCavity(const EmmetropicCavityParameters& p);
VitreousCavity makeMyopicCavity(const MyopicCavityParameters& p);
VitreousCavity makeStaphylomaCavity(const StaphylomaCavityParameters& p);

}  // namespace anatomy
