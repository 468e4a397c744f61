#include "protocols/io/xdmf_document.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "protocols/io/io_error.h"
#include "protocols/io/xml_escape.h"

namespace protocols {

namespace {

// Shortest text that reads back as the same double (%.17g round-trips every IEEE double).
std::string exactNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

const char* attributeType(int components) {
  switch (components) {
    case 1: return "Scalar";
    case 3: return "Vector";
    case 9: return "Tensor";
    default: return "Matrix";
  }
}

void appendDataItem(std::string& out, const XdmfDataset& dataset, const std::string& h5FileName,
                    const char* indent) {
  // Plain appends: GCC 12 reports a false -Wrestrict on `" " + std::to_string(...)` here.
  out += indent;
  out += "<DataItem Dimensions=\"";
  // Always "rows components", also for scalars (rows x 1): the exact shape of the HDF5 dataset,
  // which XDMF readers compare with what they read.
  out += std::to_string(dataset.rows);
  out += ' ';
  out += std::to_string(dataset.components);
  out += "\" NumberType=\"";
  out += dataset.kind == sim::ScalarKind::kReal ? "Float" : "Int";
  out += "\" Precision=\"";
  out += std::to_string(dataset.bytesPerScalar);
  out += "\" Format=\"HDF\">";
  out += escapeXml(h5FileName);
  out += ':';
  out += escapeXml(dataset.path);
  out += "</DataItem>\n";
}

}  // namespace

std::string formatXdmfFrame(const XdmfFrame& frame, const std::string& h5FileName) {
  std::string out;
  out += "      <Grid Name=\"step " + std::to_string(frame.step) +
         "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
  out += "        <Time Value=\"" + exactNumber(frame.time) + "\"/>\n";
  for (const XdmfGrid& grid : frame.grids) {
    const std::string count = std::to_string(grid.position.rows);
    out += "        <Grid Name=\"" + escapeXml(grid.name) + "\" GridType=\"Uniform\">\n";
    if (grid.triangles) {
      out += "          <Topology TopologyType=\"Triangle\" NumberOfElements=\"" +
             std::to_string(grid.triangles->rows) + "\">\n";
      appendDataItem(out, *grid.triangles, h5FileName, "            ");
      out += "          </Topology>\n";
    } else {
      out += "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + count +
             "\" NodesPerElement=\"1\"/>\n";
    }
    out += "          <Geometry GeometryType=\"XYZ\">\n";
    appendDataItem(out, grid.position, h5FileName, "            ");
    out += "          </Geometry>\n";
    for (const XdmfDataset& attribute : grid.attributes) {
      out += "          <Attribute Name=\"" + escapeXml(attribute.name) + "\" AttributeType=\"" +
             attributeType(attribute.components) + "\" Center=\"Node\">\n";
      appendDataItem(out, attribute, h5FileName, "            ");
      out += "          </Attribute>\n";
    }
    out += "        </Grid>\n";
  }
  out += "      </Grid>\n";
  return out;
}

std::string formatXdmfDocument(const std::vector<std::string>& frameTexts,
                               const std::string& name) {
  std::size_t size = 512;
  for (const auto& text : frameTexts) size += text.size();
  std::string out;
  out.reserve(size);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<Xdmf Version=\"3.0\">\n";
  out += "  <Domain>\n";
  out += "    <Grid Name=\"" + escapeXml(name) +
         "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& text : frameTexts) out += text;
  out += "    </Grid>\n";
  out += "  </Domain>\n";
  out += "</Xdmf>\n";
  return out;
}

void replaceFileAtomically(const std::filesystem::path& path, const std::string& text) {
  const std::string target = path.string();
  const std::string temporary = target + ".tmp";
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file)
    throw IoError(temporary, "", std::string("cannot create: ") + std::strerror(errno),
                  "check that the output folder exists and is writable");
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const int savedErrno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    std::remove(temporary.c_str());
    throw IoError(temporary, "", std::string("cannot write: ") + std::strerror(savedErrno),
                  "check free disk space");
  }
  // rename(2) replaces the target atomically: readers see the old or the new file, never a mix.
  if (std::rename(temporary.c_str(), target.c_str()) != 0)
    throw IoError(target, "", std::string("cannot replace: ") + std::strerror(errno),
                  "check that the output folder is writable");
}

}  // namespace protocols
