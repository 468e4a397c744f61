#include "protocols/tissue/tissue_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "meshing/mesh_query.h"
#include "meshing/point_index.h"
#include "protocols/coverage/frame_coverage.h"
#include "protocols/report/report_format.h"
#include "protocols/tissue/tissue_sampling.h"

namespace protocols {

namespace {

// TissueMeasures::fluidInTissue / fluidThroughTissue / deepestFluid (criteria in the header).
void countFluidInTissue(const Scenario& s, const std::vector<sim::Vec3>& x,
                        const std::vector<std::int32_t>& ids, TissueMeasures& m) {
  const RetinaSamples& r = s.retinaSamples;
  const TissueBody* sclera = nullptr;
  for (const TissueBody& t : s.tissues)
    if (t.name == "sclera" && t.count > 0) sclera = &t;
  if (!sclera || r.scleraLayer.size() != r.restPositions.size()) return;
  const double d = s.accuracy.particleSpacing;  // [m]
  const auto inBody = [](const TissueBody& t, std::int32_t id) {
    return id >= t.firstId && id < t.firstId + static_cast<std::int32_t>(t.count);
  };
  std::vector<char> tissue(x.size(), 0);
  std::vector<sim::Vec3> scleraNow;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (const TissueBody& t : s.tissues)
      if (t.count > 0 && inBody(t, ids[i])) {
        tissue[i] = 1;
        if (&t == sclera) scleraNow.push_back(x[i]);
      }
  const meshing::MeshQuery cavity(s.cavity);
  const meshing::PointIndex scleraGrid(scleraNow, 1.5 * d);
  const meshing::PointIndex samples(r.restPositions, d);
  std::vector<double> depth(scleraNow.size(), std::numeric_limits<double>::quiet_NaN());
  const auto depthOf = [&](std::size_t j) {  // [m] signed: > 0 outside the rest cavity surface
    if (std::isnan(depth[j])) {
      const double dist = std::sqrt(cavity.squaredDistance(scleraNow[j]));
      depth[j] = cavity.isInside(scleraNow[j]) ? -dist : dist;
    }
    return depth[j];
  };
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (tissue[i] || cavity.isInside(x[i])) continue;
    const double depthHere = std::sqrt(cavity.squaredDistance(x[i]));  // [m]
    m.deepestFluid = std::max(m.deepestFluid, depthHere);
    const std::vector<std::size_t> near = scleraGrid.within(x[i], 1.5 * d);
    bool in = near.empty() ? depthHere > d
                           : std::any_of(near.begin(), near.end(),
                                         [&](std::size_t j) { return depthOf(j) < depthHere - d; });
    const long w = samples.nearest(cavity.closestPoint(x[i]), 2.0 * d);
    const double layer = w >= 0 ? r.scleraLayer[static_cast<std::size_t>(w)] : 0.0;  // [m]
    const bool through = depthHere > std::max(layer, d);
    in = in || through;
    m.fluidInTissue += in ? 1 : 0;
    m.fluidThroughTissue += through ? 1 : 0;
  }
}

}  // namespace

std::vector<sim::Vec3> retinaPositions(const Scenario& s, const std::vector<sim::Vec3>& x,
                                       const std::vector<std::int32_t>& ids) {
  const RetinaSamples& r = s.retinaSamples;
  std::vector<sim::Vec3> out = r.restPositions;
  if (!r.moves()) return out;
  std::vector<std::size_t> indexOfId(x.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] >= 0 && static_cast<std::size_t>(ids[i]) < indexOfId.size())
      indexOfId[static_cast<std::size_t>(ids[i])] = i;
  for (const TissueBody& t : s.tissues) {
    if (t.count == 0) continue;
    for (std::size_t w = 0; w < out.size(); ++w) {
      const std::int32_t id = r.followsId[w];
      if (id < t.firstId || id >= t.firstId + static_cast<std::int32_t>(t.count)) continue;
      const sim::Vec3 u = x[indexOfId[static_cast<std::size_t>(id)]] -
                          t.restPositions[static_cast<std::size_t>(id - t.firstId)];
      out[w] += u;
    }
  }
  return out;
}

void updateTissueDisplacement(const Scenario& s, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids, std::vector<sim::Vec3>& out) {
  out.assign(x.size(), sim::Vec3::Zero());
  for (const TissueBody& t : s.tissues)
    for (std::size_t i = 0; i < x.size(); ++i)
      if (ids[i] >= t.firstId && ids[i] < t.firstId + static_cast<std::int32_t>(t.count))
        out[i] = x[i] - t.restPositions[static_cast<std::size_t>(ids[i] - t.firstId)];
}

TissueMeasures measureTissues(const Scenario& s, const std::vector<sim::Vec3>& x,
                              const std::vector<std::int32_t>& ids) {
  TissueMeasures m;
  m.maxDisplacement.assign(s.tissues.size(), 0.0);
  std::vector<sim::Vec3> u;
  updateTissueDisplacement(s, x, ids, u);
  for (std::size_t k = 0; k < s.tissues.size(); ++k) {
    const TissueBody& t = s.tissues[k];
    for (std::size_t i = 0; i < x.size(); ++i)
      if (ids[i] >= t.firstId && ids[i] < t.firstId + static_cast<std::int32_t>(t.count))
        m.maxDisplacement[k] = std::max(m.maxDisplacement[k], u[i].norm());
  }
  const std::vector<sim::Vec3> now = retinaPositions(s, x, ids);
  const RetinaSamples& r = s.retinaSamples;
  std::vector<double> area(kReportedRegions.size(), 0.0), outward(kReportedRegions.size(), 0.0);
  for (std::size_t w = 0; w < now.size(); ++w) {
    const sim::Vec3 uw = now[w] - r.restPositions[w];
    const double normal = r.normals[w].dot(uw);  // [m] outward
    m.retinaMaxDisplacement = std::max(m.retinaMaxDisplacement, uw.norm());
    m.cavityVolumeChange += s.retina.areas[w] * normal;
    for (std::size_t k = 0; k < kReportedRegions.size(); ++k)
      if ((s.retina.regions[w] & kReportedRegions[k].bit) != 0) {
        area[k] += s.retina.areas[w];
        outward[k] += s.retina.areas[w] * normal;
      }
  }
  m.regionMeanOutward.resize(kReportedRegions.size());
  for (std::size_t k = 0; k < area.size(); ++k)
    m.regionMeanOutward[k] = area[k] > 0.0 ? outward[k] / area[k] : 0.0;
  countFluidInTissue(s, x, ids, m);
  return m;
}

std::vector<std::string> tissueReportLines(const Scenario& s, const TissueMeasures& last,
                                           double lastTime, double meanTimeStep) {
  std::vector<std::string> lines;
  const double d = s.accuracy.particleSpacing;
  if (s.tissues.empty()) return {"no tissue in the protocol: rigid cavity wall"};
  const bool anyElastic = std::any_of(s.tissues.begin(), s.tissues.end(),
                                      [](const TissueBody& t) { return t.decision.elastic; });
  if (!anyElastic) {
    // Each tissue with why it is rigid: below the threshold, forced, or behind a rigid sclera.
    std::ostringstream line;
    line << "tissue rigid (";
    for (std::size_t k = 0; k < s.tissues.size(); ++k) {
      const TissueBody& t = s.tissues[k];
      const double ratio = t.estimatedDisplacement / d;  // [1]
      line << (k ? "; " : "") << t.name << " estimate " << mm(t.estimatedDisplacement) << " = "
           << formatNumber(ratio, 3) << " d";
      if (t.decision.forced)
        line << ", forced rigid";
      else if (ratio < sim::kElasticDisplacementFraction)
        line << " < " << formatNumber(sim::kElasticDisplacementFraction, 2) << " d";
      else
        line << ", behind the rigid sclera";
    }
    line << ")";
    return {line.str()};
  }
  const std::string at = " at t = " + formatNumber(lastTime, 4) + " s";
  for (std::size_t k = 0; k < s.tissues.size(); ++k) {
    const TissueBody& t = s.tissues[k];
    if (!t.decision.elastic) {
      lines.push_back(t.name + ": rigid (estimate " + mm(t.estimatedDisplacement) + " = " +
                      formatNumber(t.estimatedDisplacement / d, 3) + " d)");
      continue;
    }
    const double u = k < last.maxDisplacement.size() ? last.maxDisplacement[k] : 0.0;
    lines.push_back(t.name + ": elastic, maximum displacement " + mm(u) + " = " +
                    formatNumber(u / d, 3) + " d" + at + " (estimate " +
                    mm(t.estimatedDisplacement) + ")");
    const double wdt = t.thicknessModeFrequency * meanTimeStep;  // [1]
    if (wdt > 1.0)
      lines.push_back(t.name + ": its displacement is an upper bound, up to " +
                      formatNumber(1.0 + wdt * wdt, 2) + "x the physical one: the mean step " +
                      formatNumber(meanTimeStep * 1e3, 3) +
                      " ms does not resolve the layer's thickness mode (" +
                      formatNumber(t.thicknessModeFrequency, 3) +
                      " rad/s); the coverage does not depend on it (docs/methods/elasticity.md)");
  }
  if (!s.retinaSamples.scleraLayer.empty()) {
    // Fluid that entered or passed the tissue (TissueMeasures): a leaking run says so.
    std::string line =
        "fluid in the tissue: " + std::to_string(last.fluidInTissue) +
        " particles more than d behind a sclera particle near them, " +
        std::to_string(last.fluidThroughTissue) + " beyond the sampled layer (deepest fluid " +
        formatNumber(last.deepestFluid / d, 3) + " d outside the cavity surface)" + at;
    if (last.fluidInTissue > 0)
      line = "warning: " + line + "; the tissue leaks, its numbers are suspect";
    lines.push_back(line);
  }
  lines.push_back("retina maximum displacement " + mm(last.retinaMaxDisplacement) + at);
  lines.push_back("cavity volume change " + formatNumber(last.cavityVolumeChange * 1e9, 3) +
                  " uL = " + formatNumber(100.0 * last.cavityVolumeChange / s.cavityVolume, 3) +
                  " %" + at);
  std::ostringstream regions;
  regions << "mean outward retina displacement by region:";
  for (std::size_t k = 0; k < kReportedRegions.size() && k < last.regionMeanOutward.size(); ++k)
    regions << (k ? ";" : "") << " " << kReportedRegions[k].name << " "
            << formatNumber(last.regionMeanOutward[k] * 1e6, 3) << " um";
  lines.push_back(regions.str());
  return lines;
}

}  // namespace protocols
