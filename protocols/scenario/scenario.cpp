#include "protocols/scenario/scenario.h"

#include <algorithm>
#include <sstream>

#include "protocols/report/report_format.h"

namespace protocols {

namespace {

std::string mm(double metres) { return formatNumber(metres * 1e3, 3) + " mm"; }

}  // namespace

std::vector<std::uint8_t> Scenario::tamponadeFlags() const {
  std::vector<std::uint8_t> flags(world->particles.size());
  const int tamponade = phases[1].materialIndex;
  for (std::size_t i = 0; i < flags.size(); ++i)
    flags[i] = world->particles.material[i] == tamponade ? 1 : 0;
  return flags;
}

double Scenario::totalDuration() const {
  double t = 0.0;
  for (const auto& p : schedule) t += p.duration;
  return t;
}

std::string TissueBody::describe() const {
  std::ostringstream s;
  s << name << " (E " << formatNumber(youngsModulus * 1e-3, 4) << " kPa, t " << mm(thickness)
    << ", load " << formatNumber(loadPressure, 3)
    << " Pa): " << (decision.elastic ? "elastic" : "rigid") << ", " << decision.reason;
  if (decision.elastic && count > 0) {
    s << "; " << count << " particles, " << anchored << " anchored";
    if (simulatedModulus != youngsModulus)
      s << "; layer thickened to " << mm(layerThickness) << " (2 particle layers), E scaled to "
        << formatNumber(simulatedModulus * 1e-3, 4) << " kPa to keep the membrane stiffness E t";
  }
  return s.str();
}

bool RetinaSamples::moves() const {
  return std::any_of(followsId.begin(), followsId.end(), [](std::int32_t id) { return id >= 0; });
}

}  // namespace protocols
