// The XDMF 3 sidecar that lets ParaView (and VisIt) open the HDF5 frames as a time series:
// a Temporal collection with one Spatial collection per frame, holding one Polyvertex grid per
// particle group (fluid, wall, ...), each field an Attribute pointing into the HDF5 file by a
// RELATIVE file name, so the run folder can be moved or copied as a whole.
//
// Format: https://www.xdmf.org/index.php/XDMF_Model_and_Format (Grid, Topology "Polyvertex",
// Geometry "XYZ", Attribute "Scalar"/"Vector"/"Tensor", DataItem Format="HDF").
// ParaView note (../shared/STACK.md section 6): open the .xmf by a path with a directory part
// ("./frames.xmf" or absolute); a bare "frames.xmf" makes Xdmf3 mis-join the relative h5 name.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <utility>  // before field_registry.h, which uses std::as_const without it

#include "sim/core/field_registry.h"

namespace protocols {

// One HDF5 dataset of shape rows x components.
struct XdmfDataset {
  std::string name;  // field name, shown in ParaView
  std::string path;  // absolute path inside the HDF5 file, e.g. "/frames/000003/fluid/velocity"
  std::size_t rows = 0;
  int components = 1;
  sim::ScalarKind kind = sim::ScalarKind::kReal;
  int bytesPerScalar = 8;  // 8 float64, 4 float32 or int32
};

// One particle group at one time: its positions and every other field as an attribute. With
// `triangles` (T x 3 vertex indices) the grid is a triangle surface on those points instead.
struct XdmfGrid {
  std::string name;  // "fluid", "wall", ...
  XdmfDataset position;
  std::vector<XdmfDataset> attributes;
  std::optional<XdmfDataset> triangles;
};

struct XdmfFrame {
  double time = 0;  // [s]
  std::int64_t step = 0;
  std::vector<XdmfGrid> grids;
};

// The <Grid> element text of one frame (cached by the writer: frames never change once written).
std::string formatXdmfFrame(const XdmfFrame& frame, const std::string& h5FileName);

// The whole document around already formatted frames; `name` names the temporal collection.
std::string formatXdmfDocument(const std::vector<std::string>& frameTexts,
                               const std::string& name = "particles");

// Writes `text` to `path` through `path`.tmp and a rename, so a reader (or a crash) never sees a
// half-written sidecar. Throws IoError.
void replaceFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace protocols
