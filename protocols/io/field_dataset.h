// Internal to protocols/io: one registry field <-> one HDF5 dataset of shape rows x components,
// with `unit` and `element` attributes. Shared by the frame writer, the reader and checkpoints so
// that all three agree on the layout.
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <string>

#include <utility>  // before field_registry.h, which uses std::as_const without it
#include "protocols/io/field_data.h"
#include "protocols/io/hdf5_support.h"

#include "sim/core/field_registry.h"

namespace protocols::hdf5 {

struct FieldDatasetOptions {
  bool realsAsFloat32 = false;  // store kReal fields as IEEE float32 (ints are always int32)
  int gzipLevel = 0;            // 0: contiguous, no filters; 1..9: chunked, shuffle + deflate
};

// Writes every row of `field` as dataset `parent/<field name>`.
void writeFieldDataset(hid_t parent, const sim::FieldBase& field,
                       const FieldDatasetOptions& options, const Place& parentPlace);

// Reads dataset `parent/name` (any layout written above, or by h5py with the same shape).
FieldData readFieldDataset(hid_t parent, const std::string& name, const Place& parentPlace);

// Overwrites `field`'s values with dataset `parent/<field name>` bit for bit. The dataset must
// have the field's row count, component count and scalar kind (IoError otherwise).
void restoreFieldDataset(hid_t parent, sim::FieldBase& field, const Place& parentPlace);

// "double", "Vec3", "Mat3", "int32" or "real[N]"/"int32[N]": the `element` attribute text.
std::string elementName(sim::ScalarKind kind, int components);

}  // namespace protocols::hdf5
