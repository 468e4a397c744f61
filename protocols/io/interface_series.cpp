#include "protocols/io/interface_series.h"

#include <cstdio>

#include <fmt/format.h>

#include "protocols/io/hdf5_support.h"
#include "protocols/io/xdmf_document.h"

namespace protocols {
namespace {

using hdf5::check;
using hdf5::checked;
using hdf5::Handle;
using hdf5::Place;

constexpr std::int64_t kFormatVersion = 1;

// Writes rows x 3 values of `memoryType` from `data` as dataset `parent/name` of `fileType`.
void writeTable(hid_t parent, const std::string& name, hsize_t rows, hid_t fileType,
                hid_t memoryType, const void* data, const Place& place) {
  const hsize_t dims[2] = {rows, 3};
  Handle space = checked(H5Screate_simple(2, dims, nullptr), place, "cannot create dataspace");
  Handle dataset = checked(H5Dcreate2(parent, name.c_str(), fileType, space.get(), H5P_DEFAULT,
                                      H5P_DEFAULT, H5P_DEFAULT),
                           place, "cannot create dataset");
  if (rows > 0)
    check(H5Dwrite(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), place,
          "cannot write dataset", "check free disk space");
}

// One posture's group; returns its grid for the sidecar.
XdmfGrid writePosture(hid_t postures, std::size_t index, const PostureInterface& p,
                      const Place& place) {
  const std::string name = fmt::format("{:03d}", index);
  const Place at = place.at(name);
  Handle group = checked(H5Gcreate2(postures, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         at, "cannot create group");
  hdf5::writeAttribute(group.get(), "name", p.posture, at);
  hdf5::writeAttribute(group.get(), "time", p.time, at);
  // sim::Vec3 is three contiguous doubles (Eigen's fixed-size storage), std::array<int, 3> three
  // contiguous ints: the vectors are already row-major tables.
  writeTable(group.get(), "vertices", p.vertices.size(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
             p.vertices.data(), at.at("vertices"));
  writeTable(group.get(), "triangles", p.triangles.size(), H5T_STD_I32LE, H5T_NATIVE_INT,
             p.triangles.data(), at.at("triangles"));
  XdmfGrid grid;
  grid.name = p.posture;
  grid.position = {"position", at.object + "/vertices", p.vertices.size(),
                   3,          sim::ScalarKind::kReal,  8};
  grid.triangles = XdmfDataset{"triangles", at.object + "/triangles", p.triangles.size(),
                               3,           sim::ScalarKind::kInt32,  4};
  return grid;
}

}  // namespace

void writeInterfaceSeries(const std::filesystem::path& folder,
                          const std::vector<PostureInterface>& postures) {
  bool any = false;
  for (const PostureInterface& p : postures) any = any || !p.triangles.empty();
  if (!any) return;
  hdf5::silenceErrorPrinting();
  const std::filesystem::path path = folder / kInterfaceSeriesFile;
  const std::string temporary = path.string() + ".tmp";
  const Place root{temporary, "/"};
  std::vector<std::string> frames;
  try {
    {
      Handle file = checked(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                            root, "cannot create", "check that the run folder is writable");
      hdf5::writeAttribute(file.get(), "format", std::string("tamponade-interfaces"), root);
      hdf5::writeAttribute(file.get(), "format_version", kFormatVersion, root);
      Handle group = hdf5::openOrCreateGroup(file.get(), "postures", root);
      for (std::size_t k = 0; k < postures.size(); ++k) {
        if (postures[k].triangles.empty()) continue;
        XdmfFrame frame;
        frame.time = postures[k].time;
        frame.step = static_cast<std::int64_t>(k);
        frame.grids.push_back(writePosture(group.get(), k, postures[k], root.at("postures")));
        frames.push_back(formatXdmfFrame(frame, kInterfaceSeriesFile));
      }
      group.close();
      check(file.close(), root, "cannot close", "check free disk space");
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw IoError(path.string(), "", "cannot replace the previous file",
                    "check that the run folder is writable");
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  replaceFileAtomically(folder / kInterfaceSeriesSidecar, formatXdmfDocument(frames, "interfaces"));
}

}  // namespace protocols
