// Reads one frame of a protocol run in a spherical cavity (an imported sphere, eye.kind = "mesh")
// and prints what the run's own coverage column cannot show (docs/validation.md, "SPH against the
// equilibrium in a sphere" and its open limits):
//  - the interface fitted as a sphere beyond 1.5, 2 and 3 spacings from the wall, and the angle
//    at which that sphere meets the cavity through the aqueous (the lens's shape without gravity;
//    under gravity the interface is no sphere and the angle is only indicative);
//  - without gravity, the oil share of the two fluid layers next to the wall against the share
//    the closed-form lens gives the same particles (where the contact line sits, read at the
//    particles' own distance from the wall);
//  - the coverage read below the spacing (sim/measure/wall_oil_extended.h) with the interface
//    taken 1.25 to 4 spacings from the wall and extended to it at the contact angle.
// The cavity's centre is the wall's surface layer's (frames' /static/wall), its radius given; the
// spacing is the run's. Eye scenes number the aqueous 0 and the tamponade 1.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include "protocols/io/frame_reader.h"
#include "sim/measure/sessile_contact_angle.h"
#include "sim/measure/wall_oil_extended.h"
#include "tests/sim/interface_fixtures.h"
#include "tests/sim/sphere_wall_reading.h"

using sim::Real;
using sim::Vec3;

namespace {

constexpr int kOilMaterial = 1;  // protocols/assembly/fluid_phases.cpp: aqueous 0, tamponade 1

struct Frame {
  std::vector<Vec3> x;              // [m]
  std::vector<std::uint8_t> isOil;  // 1 oil, 0 aqueous
};

struct Cavity {
  Vec3 centre = Vec3::Zero();  // [m]
  Real radius = 0;             // [m] of the surface the fluid fills
};

Frame readFrame(const protocols::FrameReader& reader, std::size_t index) {
  const protocols::FieldData x = reader.readField(index, "fluid", "position");
  const protocols::FieldData m = reader.readField(index, "fluid", "material");
  Frame f;
  for (std::size_t i = 0; i < x.rows; ++i) {
    f.x.emplace_back(x.real(i, 0), x.real(i, 1), x.real(i, 2));
    f.isOil.push_back(m.integer(i) == kOilMaterial ? 1 : 0);
  }
  return f;
}

// The centre is the mean of the wall's surface layer (its particles sit about half a spacing
// outside the surface the fluid fills); the radius is the mesh's, `radius` [m].
Cavity readCavity(const protocols::FrameReader& reader, Real radius) {
  const protocols::FieldData x = reader.readStaticField("wall", "position");
  const protocols::FieldData layer = reader.readStaticField("wall", "wall_layer");
  std::vector<Vec3> surface;
  for (std::size_t b = 0; b < x.rows; ++b)
    if (layer.integer(b) == 0) surface.emplace_back(x.real(b, 0), x.real(b, 1), x.real(b, 2));
  Cavity c;
  for (const Vec3& p : surface) c.centre += p;
  c.centre /= static_cast<Real>(surface.size());
  c.radius = radius;
  return c;
}

// [m] The oil's centroid relative to the cavity's centre (zero without oil).
Vec3 oilCentroid(const Frame& f, const Cavity& c) {
  Vec3 sum = Vec3::Zero();
  Real count = 0;
  for (std::size_t i = 0; i < f.x.size(); ++i)
    if (f.isOil[i]) sum += f.x[i] - c.centre, ++count;
  return count > 0 ? Vec3(sum / count) : Vec3::Zero();
}

// Midpoints of oil-aqueous pairs closer than 1.5 d (a hash grid of cell 1.5 d), relative to the
// cavity's centre.
std::vector<Vec3> interfaceMidpoints(const Frame& f, const Cavity& c, Real d) {
  const Real cell = 1.5 * d;
  // One key per cell (21 bits per axis: a million cells across, far beyond any eye scene), so a
  // cell's list holds only its own particles and no pair is found twice.
  auto key = [cell](const Vec3& p) {
    const auto k = [cell](Real v) {
      return static_cast<std::int64_t>(std::floor(v / cell)) + (std::int64_t(1) << 20);
    };
    return (k(p.x()) << 42) | (k(p.y()) << 21) | k(p.z());
  };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> aqueousCells;
  for (std::size_t i = 0; i < f.x.size(); ++i)
    if (!f.isOil[i]) aqueousCells[key(f.x[i])].push_back(i);
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < f.x.size(); ++i) {
    if (!f.isOil[i]) continue;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = aqueousCells.find(key(f.x[i] + cell * Vec3(dx, dy, dz)));
          if (found == aqueousCells.end()) continue;
          for (const std::size_t j : found->second)
            if ((f.x[i] - f.x[j]).norm() < cell)
              points.push_back(0.5 * (f.x[i] + f.x[j]) - c.centre);
        }
  }
  return points;
}

// The sphere through the interface points more than `margin` from the wall and the angle at which
// it meets the cavity through the aqueous [deg]; NaN when fewer than 8 points remain.
Real fittedAngle(const std::vector<Vec3>& all, const Frame& f, const Cavity& c, Real margin) {
  std::vector<Vec3> points;
  for (const Vec3& p : all)
    if (p.norm() < c.radius - margin) points.push_back(p);
  if (points.size() < 8) return std::nan("");
  const sim::SphereFit s = sim::fitSphereGeometric(points, sim::fitSphere(points));
  // Through the aqueous: the supplement of the angle through the oil.
  return 180 - sim::testing::cavityAngleThroughOil(s, c.radius, oilCentroid(f, c));
}

// The coverage read below the spacing with the interface taken 1.25 to 4 spacings from the wall.
void printExtendedCoverage(const Frame& f, const Cavity& c, Real d, Real angleDeg) {
  const testref::SphereWallReading reading(c.radius, d);
  std::vector<Vec3> x;
  for (const Vec3& p : f.x) x.push_back(p - c.centre);
  reading.printCoverageByOffset(x, f.isOil, angleDeg * std::numbers::pi / 180);
}

// Without gravity the oil at volume fraction v is the closed-form lens (tests/sim/
// interface_fixtures.h, lensCoverage): the cavity inside a sphere of radius r whose centre lies c
// along the oil's axis. Prints, per fluid layer next to the wall (the k-th spacing inside it), the
// oil share of the run's particles there and of the same particles classified by that lens: where
// the run's contact line sits against the lens's, read at the particles' own distance from the
// wall (no reading below the spacing). Nothing when the oil is no lens at this angle and volume.
void printLayerShares(const Frame& f, const Cavity& c, Real d, Real angleDeg) {
  const Vec3 axis = oilCentroid(f, c);
  const Real oil = static_cast<Real>(std::count(f.isOil.begin(), f.isOil.end(), 1));
  const auto lens = sim::testing::lensCoverage(oil / static_cast<Real>(f.x.size()), 180 - angleDeg);
  if (lens.radius > 100 || axis.norm() == 0) return;  // the flat limit: no lens
  const Vec3 ballCentre = lens.distance * c.radius * axis.normalized();
  const Real ballRadius = lens.radius * c.radius;
  for (int layer = 1; layer <= 2; ++layer) {
    Real count = 0, runOil = 0, lensOil = 0;
    for (std::size_t i = 0; i < f.x.size(); ++i) {
      const Vec3 x = f.x[i] - c.centre;
      const Real depth = c.radius - x.norm();  // [m] from the wall
      if (depth < (layer - 1) * d || depth >= layer * d) continue;
      ++count;
      runOil += f.isOil[i];
      lensOil += (x - ballCentre).norm() < ballRadius ? 1 : 0;
    }
    std::printf(
        "fluid layer %d next to the wall (%.0f particles): oil share %.4f, the %.0f deg "
        "lens's %.4f (lens wall coverage %.4f)\n",
        layer, count, runOil / count, angleDeg, lensOil / count, lens.coverage);
  }
}

int usage(int code) {
  std::fprintf(
      code == 0 ? stdout : stderr,
      "usage: sphere_run_reading FRAMES.h5 --angle DEG --radius MM [--frame first|last|N]\n"
      "  FRAMES.h5  a run's frames (tamponade run ... --out DIR: DIR/frames.h5) in a\n"
      "             spherical cavity (eye.kind = \"mesh\" with a sphere)\n"
      "  --angle    the protocol's contact angle through the aqueous [deg], in (0, 180)\n"
      "  --radius   the sphere's radius [mm] (12 for data/meshes/test/sphere_r12mm.stl)\n"
      "  --frame    which frame to read (default last)\n");
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  std::string path, frameName = "last";
  Real angle = std::nan(""), radius = std::nan("");  // [deg], [mm]
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--help") return usage(0);
    if (a == "--angle" && k + 1 < argc) {
      angle = std::strtod(argv[++k], nullptr);
    } else if (a == "--radius" && k + 1 < argc) {
      radius = std::strtod(argv[++k], nullptr);
    } else if (a == "--frame" && k + 1 < argc) {
      frameName = argv[++k];
    } else if (a.rfind("--", 0) != 0 && path.empty()) {
      path = a;
    } else {
      std::fprintf(stderr, "sphere_run_reading: %s '%s'\n",
                   a == "--angle" || a == "--radius" || a == "--frame" ? "needs a value:"
                                                                       : "unexpected argument",
                   a.c_str());
      return usage(2);
    }
  }
  if (path.empty()) {
    std::fprintf(stderr, "sphere_run_reading: give the run's frames file\n");
    return usage(2);
  }
  if (!(angle > 0 && angle < 180)) {
    std::fprintf(stderr, "sphere_run_reading: --angle: give the contact angle in (0, 180) deg\n");
    return usage(2);
  }
  if (!(radius > 0)) {
    std::fprintf(stderr, "sphere_run_reading: --radius: give the cavity's radius in mm (> 0)\n");
    return usage(2);
  }
  try {
    const protocols::FrameReader reader(path);
    const std::size_t count = reader.frames().size();
    std::size_t index = count == 0 ? 0 : count - 1;
    if (frameName == "first")
      index = 0;
    else if (frameName != "last") {
      char* end = nullptr;
      const long n = std::strtol(frameName.c_str(), &end, 10);
      if (*end != '\0' || n < 0 || static_cast<std::size_t>(n) >= count) {
        std::fprintf(stderr, "sphere_run_reading: --frame %s: %s has frames 0 to %zu\n",
                     frameName.c_str(), path.c_str(), count == 0 ? 0 : count - 1);
        return 2;
      }
      index = static_cast<std::size_t>(n);
    }
    if (count == 0) {
      std::fprintf(stderr, "sphere_run_reading: %s holds no complete frame\n", path.c_str());
      return 1;
    }
    const protocols::RunInfo info = reader.runInfo();
    const auto spacing = info.numbers.find("particle_spacing [m]");
    if (spacing == info.numbers.end()) {
      std::fprintf(stderr, "sphere_run_reading: %s does not record the particle spacing\n",
                   path.c_str());
      return 1;
    }
    const Real d = spacing->second;
    const Frame frame = readFrame(reader, index);
    const Cavity cavity = readCavity(reader, radius * 1e-3);
    std::printf(
        "%s, frame %zu of %zu (t = %.4g s): %zu fluid particles, cavity radius %.3f mm, "
        "spacing %.3g mm\n",
        path.c_str(), index, count, reader.frames()[index].time, frame.x.size(),
        cavity.radius * 1e3, d * 1e3);
    const std::vector<Vec3> points = interfaceMidpoints(frame, cavity, d);
    for (const Real margin : {1.5, 2.0, 3.0}) {
      const Real fitted = fittedAngle(points, frame, cavity, margin * d);
      std::printf("interface fitted as a sphere beyond %.1f spacings of the wall: ", margin);
      if (std::isnan(fitted))
        std::printf("fewer than 8 interface points there\n");
      else
        std::printf("%.1f deg through the aqueous\n", fitted);
    }
    printLayerShares(frame, cavity, d, angle);
    printExtendedCoverage(frame, cavity, d, angle);
  } catch (const std::exception& error) {
    const std::string message = error.what();  // the reader's own messages name the file
    std::fprintf(stderr, "sphere_run_reading: %s%s\n",
                 message.find(path) == std::string::npos ? (path + ": ").c_str() : "",
                 message.c_str());
    return 1;
  }
  return 0;
}
