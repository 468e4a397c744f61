// The eye the protocol tests run, as protocol text, and the particles' reading of its retina: the
// emmetropic right eye with silicone oil 1000 at the draft preset, the options the tests vary
// given by name and everything else fixed, so that a change to the protocol format is made once.
#pragma once

#include <string>
#include <vector>

#include "protocols/coverage/frame_coverage.h"
#include "protocols/coverage/wall_oil_fraction.h"
#include "protocols/run/rebuild_report.h"
#include "protocols/scenario/scenario.h"

namespace tamponade_test {

struct EyeProtocolOptions {
  std::string title;               // the protocol's title; empty: none
  bool superiorBreak = false;      // a 2 mm tear at 12 o'clock, 14 mm behind the limbus
  std::string fill = "90 %";       // of silicone oil
  std::string tamponadeKeys;       // more lines of the [tamponade] table
  std::string schedule;            // the [schedule] table and its postures, as written
  std::string spacing = "1.2 mm";  // accuracy.particle_spacing
  std::string outputs;             // the [outputs] table, or nothing
};

inline std::string eyeProtocolText(const EyeProtocolOptions& o) {
  std::string text = "format_version = 1\n";
  if (!o.title.empty()) text += "title = \"" + o.title + "\"\n";
  text += "[eye]\nkind = \"emmetropic\"\nside = \"OD\"\n";
  if (o.superiorBreak)
    text +=
        "[[eye.breaks]]\nname = \"superior tear\"\nclock_hour = 12\n"
        "posterior_to_limbus = \"14 mm\"\ndiameter = \"2 mm\"\n";
  text += "[tamponade]\nagent = \"silicone_oil_1000\"\nfill = \"" + o.fill + "\"\n" +
          o.tamponadeKeys + o.schedule + "[accuracy]\npreset = \"draft\"\nparticle_spacing = \"" +
          o.spacing + "\"\n" + o.outputs;
  return text;
}

// One [[schedule.postures]] entry.
inline std::string posture(const std::string& name, const std::string& duration) {
  return "[[schedule.postures]]\nname = \"" + name + "\"\nduration = \"" + duration + "\"\n";
}

// Every reported region's oil-covered share as the particles of `s` read it now (the retina
// first, as FrameCoverage orders them).
inline std::vector<double> particleReading(const protocols::Scenario& s) {
  const auto& particles = s.world->particles;
  const protocols::WallOilFractions f =
      protocols::measureWallFractions(s, particles.x, particles.material, particles.id);
  const protocols::FrameCoverage c = protocols::measureFrameCoverage(s.retina, f, 0.0);
  std::vector<double> out;
  for (const auto& r : c.regions) out.push_back(r.fraction);
  return out;
}

}  // namespace tamponade_test
