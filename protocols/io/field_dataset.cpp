#include "protocols/io/field_dataset.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

namespace protocols::hdf5 {

namespace {

// Chunks of about 512 KiB: large enough that per-chunk index overhead is negligible and deflate
// (32 KiB window) compresses as well as it can, small enough to fit HDF5's default 1 MiB
// per-dataset chunk cache, so reading a frame back goes through the cache.
constexpr std::size_t kChunkBytes = 512 * 1024;

hid_t memoryType(sim::ScalarKind kind) {
  return kind == sim::ScalarKind::kReal ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT32;
}

// Writes the chunks of a 2-D chunked, shuffle + deflate dataset with the compression done on all
// OpenMP threads: HDF5's filter pipeline runs on the calling thread only, and deflate is ~95 % of
// a frame's write time (README). Produces what HDF5's filters would: the shuffle filter's byte
// transposition (byte b of element e goes to b * elements + e) then a zlib stream as compress2()
// makes it, which is what H5Z_FILTER_DEFLATE decodes. Stored types equal the memory types
// (float64 / int32, little-endian), so no conversion is involved.
void writeChunksInParallel(hid_t dataset, const sim::FieldBase& field, hsize_t chunkRows,
                           int gzipLevel, const Place& place) {
  const std::size_t rows = field.size();
  const std::size_t components = static_cast<std::size_t>(field.components());
  const std::size_t scalarBytes = field.kind() == sim::ScalarKind::kReal ? 8 : 4;
  const std::size_t rowBytes = components * scalarBytes;
  const std::size_t chunkBytes = chunkRows * rowBytes;
  const std::size_t elements = chunkRows * components;
  const std::size_t chunks = (rows + chunkRows - 1) / chunkRows;
  const auto* source = static_cast<const unsigned char*>(field.rawData());
  std::vector<std::vector<unsigned char>> compressed(chunks);
  std::vector<int> zlibStatus(chunks, Z_OK);

#pragma omp parallel
  {
    std::vector<unsigned char> shuffled(chunkBytes);
#pragma omp for schedule(dynamic)
    for (std::size_t k = 0; k < chunks; ++k) {
      const std::size_t firstRow = k * chunkRows;
      const std::size_t validBytes = std::min<std::size_t>(chunkRows, rows - firstRow) * rowBytes;
      const unsigned char* chunk = source + firstRow * rowBytes;
      // The edge chunk is padded with zeros to the full chunk size, as HDF5 stores it.
      for (std::size_t e = 0; e < elements; ++e)
        for (std::size_t b = 0; b < scalarBytes; ++b) {
          const std::size_t from = e * scalarBytes + b;
          shuffled[b * elements + e] = from < validBytes ? chunk[from] : 0;
        }
      uLongf size = compressBound(static_cast<uLong>(chunkBytes));
      compressed[k].resize(size);
      zlibStatus[k] = compress2(compressed[k].data(), &size, shuffled.data(),
                                static_cast<uLong>(chunkBytes), gzipLevel);
      compressed[k].resize(size);
    }
  }
  for (std::size_t k = 0; k < chunks; ++k) {
    if (zlibStatus[k] != Z_OK)
      throw IoError(place.file, place.object,
                    "zlib failed to compress chunk " + std::to_string(k) + " (status " +
                        std::to_string(zlibStatus[k]) + ")",
                    "check free memory");
    const hsize_t offset[2] = {k * chunkRows, 0};
    check(
        H5Dwrite_chunk(dataset, H5P_DEFAULT, 0, offset, compressed[k].size(), compressed[k].data()),
        place, "cannot write chunk " + std::to_string(k), "check free disk space");
  }
}

}  // namespace

std::string elementName(sim::ScalarKind kind, int components) {
  if (kind == sim::ScalarKind::kInt32)
    return components == 1 ? "int32" : "int32[" + std::to_string(components) + "]";
  switch (components) {
    case 1: return "double";
    case 3: return "Vec3";
    case 9: return "Mat3 (column-major)";
    default: return "real[" + std::to_string(components) + "]";
  }
}

void writeFieldDataset(hid_t parent, const sim::FieldBase& field,
                       const FieldDatasetOptions& options, const Place& parentPlace) {
  const std::string& name = field.info().name;
  const Place place = parentPlace.at(name);
  const hsize_t rows = field.size();
  hsize_t chunkRows = 0;
  const hsize_t components = static_cast<hsize_t>(field.components());
  const bool isReal = field.kind() == sim::ScalarKind::kReal;
  const hid_t fileType =
      isReal ? (options.realsAsFloat32 ? H5T_IEEE_F32LE : H5T_IEEE_F64LE) : H5T_STD_I32LE;

  const hsize_t dims[2] = {rows, components};
  Handle space = checked(H5Screate_simple(2, dims, nullptr), place, "cannot create dataspace");
  Handle creation = checked(H5Pcreate(H5P_DATASET_CREATE), place, "cannot create properties");
  if (options.gzipLevel > 0) {
    const std::size_t scalarBytes = isReal && !options.realsAsFloat32 ? 8 : 4;
    chunkRows = std::clamp<hsize_t>(kChunkBytes / (components * scalarBytes), 1,
                                    std::max<hsize_t>(rows, 1));
    const hsize_t chunk[2] = {chunkRows, components};
    check(H5Pset_chunk(creation.get(), 2, chunk), place, "cannot set chunking");
    // Shuffle groups the bytes of equal significance, which is what lets deflate compress
    // floating-point particle data at all (sign/exponent bytes repeat, mantissa tails do not).
    check(H5Pset_shuffle(creation.get()), place, "cannot enable the shuffle filter");
    check(H5Pset_deflate(creation.get(), static_cast<unsigned>(options.gzipLevel)), place,
          "cannot enable gzip compression", "check that HDF5 was built with zlib");
  }
  Handle dataset =
      checked(H5Dcreate2(parent, name.c_str(), fileType, space.get(), H5P_DEFAULT, creation.get(),
                         H5P_DEFAULT),
              place, "cannot create dataset", "field names must be unique within a group");
  const bool exactTypes =
      std::endian::native == std::endian::little && !(isReal && options.realsAsFloat32);
  if (options.gzipLevel > 0 && exactTypes && rows > chunkRows)
    writeChunksInParallel(dataset.get(), field, chunkRows, options.gzipLevel, place);
  else if (rows > 0)
    check(H5Dwrite(dataset.get(), memoryType(field.kind()), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                   field.rawData()),
          place, "cannot write dataset", "check free disk space");
  writeAttribute(dataset.get(), "unit", field.info().unit, place);
  writeAttribute(dataset.get(), "element", elementName(field.kind(), field.components()), place);
}

namespace {

struct OpenedField {
  Handle dataset;
  sim::ScalarKind kind;
  hsize_t rows;
  hsize_t components;
};

OpenedField openField(hid_t parent, const std::string& name, const Place& place) {
  if (!hasLink(parent, name, place))
    throw IoError(place.file, place.at(name).object, "no such field dataset",
                  "check the field name (it must be a registered field with the written or "
                  "checkpointed flag)");
  const Place here = place.at(name);
  OpenedField opened{
      checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), here, "cannot open dataset"),
      sim::ScalarKind::kReal, 0, 0};
  Handle type = checked(H5Dget_type(opened.dataset.get()), here, "cannot read dataset type");
  switch (H5Tget_class(type.get())) {
    case H5T_FLOAT: opened.kind = sim::ScalarKind::kReal; break;
    case H5T_INTEGER: opened.kind = sim::ScalarKind::kInt32; break;
    default:
      throw IoError(here.file, here.object, "dataset is neither float nor integer",
                    "the file was not written by this toolkit");
  }
  const auto [rows, components] = datasetShape(opened.dataset.get(), here);
  opened.rows = rows;
  opened.components = components;
  return opened;
}

}  // namespace

FieldData readFieldDataset(hid_t parent, const std::string& name, const Place& parentPlace) {
  const Place place = parentPlace.at(name);
  OpenedField opened = openField(parent, name, parentPlace);
  FieldData data;
  data.name = name;
  data.kind = opened.kind;
  data.rows = opened.rows;
  data.components = static_cast<int>(opened.components);
  if (hasAttribute(opened.dataset.get(), "unit", place))
    data.unit = readStringAttribute(opened.dataset.get(), "unit", place);
  const std::size_t count = opened.rows * opened.components;
  void* buffer = nullptr;
  if (opened.kind == sim::ScalarKind::kReal) {
    data.reals.resize(count);
    buffer = data.reals.data();
  } else {
    data.integers.resize(count);
    buffer = data.integers.data();
  }
  if (count > 0)
    check(H5Dread(opened.dataset.get(), memoryType(opened.kind), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                  buffer),
          place, "cannot read dataset", "the file may be damaged (a run killed while writing?)");
  return data;
}

void restoreFieldDataset(hid_t parent, sim::FieldBase& field, const Place& parentPlace) {
  const std::string& name = field.info().name;
  const Place place = parentPlace.at(name);
  OpenedField opened = openField(parent, name, parentPlace);
  if (opened.kind != field.kind() || opened.components != static_cast<hsize_t>(field.components()))
    throw IoError(place.file, place.object,
                  "stored as " + elementName(opened.kind, static_cast<int>(opened.components)) +
                      " but this run's field is " + elementName(field.kind(), field.components()),
                  "resume with the toolkit version and protocol that wrote the checkpoint");
  if (opened.rows != field.size())
    throw IoError(place.file, place.object,
                  "holds " + std::to_string(opened.rows) + " particles but this run has " +
                      std::to_string(field.size()),
                  "resume with the protocol (and accuracy) that wrote the checkpoint");
  if (opened.rows > 0)
    check(H5Dread(opened.dataset.get(), memoryType(field.kind()), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                  field.rawData()),
          place, "cannot read dataset", "the checkpoint is damaged; use an older one");
}

}  // namespace protocols::hdf5
