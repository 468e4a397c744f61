// The oil-aqueous interface of each posture at equilibrium as one time series that ParaView opens:
// interfaces.h5 (one triangle surface per posture) and its XDMF sidecar interfaces.xmf, a Temporal
// collection with one Triangle grid per posture at the posture's time on the schedule's clock.
//
// Layout of interfaces.h5:
//   /                          attributes format = "tamponade-interfaces", format_version
//   /postures/NNN              attributes name (the posture's), time [s]
//   /postures/NNN/vertices     V x 3 float64 [m], eye frame
//   /postures/NNN/triangles    T x 3 int32, vertex indices, counter-clockwise seen from the oil
// A posture whose interface is empty (a full fill) is left out.
//
// Both files are written to a temporary name and renamed, so a run stopped while writing leaves
// the previous files or none, never a partial one. Open interfaces.xmf by a path with a directory
// part ("./interfaces.xmf"), as for frames.xmf: docs/getting-started.md.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/core/types.h"

namespace protocols {

struct PostureInterface {
  std::string posture;  // the posture's name
  double time = 0.0;    // [s] where the posture starts on the schedule's clock
  std::vector<sim::Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Writes `folder`/interfaces.h5 and `folder`/interfaces.xmf (replacing earlier ones). Throws
// IoError naming the file and what to fix. Does nothing when no posture has an interface.
void writeInterfaceSeries(const std::filesystem::path& folder,
                          const std::vector<PostureInterface>& postures);

inline constexpr const char* kInterfaceSeriesFile = "interfaces.h5";
inline constexpr const char* kInterfaceSeriesSidecar = "interfaces.xmf";

}  // namespace protocols
