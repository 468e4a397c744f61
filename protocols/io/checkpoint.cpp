#include "protocols/io/checkpoint.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <set>

#include "protocols/io/field_dataset.h"
#include "protocols/io/frame_file_layout.h"
#include "protocols/io/hdf5_support.h"

namespace protocols {

using hdf5::check;
using hdf5::checked;
using hdf5::Handle;
using hdf5::Place;

namespace {

Handle checkpointAccess(const Place& place) {
  Handle access = checked(H5Pcreate(H5P_FILE_ACCESS), place, "cannot create file properties");
  // Checksummed v1.8 metadata: a damaged checkpoint is reported, not silently misread.
  check(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), place,
        "cannot select the HDF5 file format version");
  check(H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG), place,
        "cannot set the file close mode");
  return access;
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
  return out;
}

void requireValidName(const std::string& what, const std::string& name, const Place& place) {
  if (name.empty() || name == "." || name.find('/') != std::string::npos)
    throw IoError(place.file, place.object, what + " name '" + name + "' is not usable in HDF5",
                  "use a non-empty name without '/'");
}

// Word-wise FNV-1a: each 8-byte word (then each remaining byte) is xor-ed in and multiplied by
// the FNV prime; fast enough for checkpoints of millions of particles.
class Checksum {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::size_t k = 0;
    for (; k + 8 <= bytes; k += 8) {
      std::uint64_t word = 0;
      std::memcpy(&word, p + k, 8);
      mix(word);
    }
    for (; k < bytes; ++k) mix(p[k]);
    mix(bytes);  // lengths too, so that moving bytes between items changes the sum
  }
  void add(const std::string& text) { add(text.data(), text.size()); }
  template <class T>
  void addValue(const T& value) {
    add(&value, sizeof value);
  }
  std::uint64_t value() const { return hash_; }

 private:
  void mix(std::uint64_t word) { hash_ = (hash_ ^ word) * 1099511628211ull; }
  std::uint64_t hash_ = 14695981039346656037ull;
};

std::size_t scalarBytes(sim::ScalarKind kind) {
  return kind == sim::ScalarKind::kReal ? sizeof(sim::Real) : sizeof(std::int32_t);
}

void writeContents(hid_t file, const CheckpointState& state, const Place& root) {
  hdf5::writeAttribute(file, "format", std::string(layout::kCheckpointFormat), root);
  hdf5::writeAttribute(file, "format_version", layout::kCheckpointFormatVersion, root);
  hdf5::writeAttribute(file, "toolkit_version", std::string(TAMPONADE_VERSION), root);
  hdf5::writeAttribute(file, "time", state.time, root);
  hdf5::writeAttribute(file, "step", state.step, root);
  hdf5::writeAttribute(file, "dt", state.dt, root);
  hdf5::writeAttribute(file, "checksum", std::bit_cast<std::int64_t>(contentChecksum(state)), root);

  Handle counters = hdf5::openOrCreateGroup(file, "counters", root);
  const Place counterPlace = root.at("counters");
  for (const auto& [name, value] : state.realCounters)
    hdf5::writeAttribute(counters.get(), name, value, counterPlace);
  for (const auto& [name, value] : state.integerCounters) {
    if (state.realCounters.count(name))
      throw IoError(root.file, counterPlace.object,
                    "counter '" + name + "' is both a real and an integer counter",
                    "give each counter one name");
    hdf5::writeAttribute(counters.get(), name, value, counterPlace);
  }

  Handle blobs = hdf5::openOrCreateGroup(file, "blobs", root);
  for (const auto& [name, bytes] : state.blobs) {
    const Place place = root.at("blobs/" + name);
    requireValidName("blob", name, root.at("blobs"));
    const hsize_t size = bytes.size();
    Handle space = checked(H5Screate_simple(1, &size, nullptr), place, "cannot create dataspace");
    Handle dataset = checked(H5Dcreate2(blobs.get(), name.c_str(), H5T_STD_U8LE, space.get(),
                                        H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                             place, "cannot create dataset");
    if (size > 0)
      check(H5Dwrite(dataset.get(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()),
            place, "cannot write dataset", "check free disk space");
  }

  Handle groups = hdf5::openOrCreateGroup(file, "groups", root);
  const hdf5::FieldDatasetOptions exact{false, 0};  // float64, contiguous: bit-exact and fast
  for (const auto& [name, registry] : state.groups) {
    requireValidName("group", name, root.at("groups"));
    if (!registry)
      throw IoError(root.file, "/groups/" + name, "no field registry given",
                    "pass &particles.fields");
    Handle group = hdf5::openOrCreateGroup(groups.get(), name, root.at("groups"));
    hdf5::writeAttribute(group.get(), "particles", static_cast<std::int64_t>(registry->size()),
                         root.at("groups/" + name));
    for (const auto& field : *registry)
      if (field->info().checkpointed)
        hdf5::writeFieldDataset(group.get(), *field, exact, root.at("groups/" + name));
  }
}

}  // namespace

std::uint64_t contentChecksum(const CheckpointState& state) {
  Checksum sum;
  sum.addValue(state.time);
  sum.addValue(state.step);
  sum.addValue(state.dt);
  for (const auto& [name, value] : state.realCounters) {
    sum.add(name);
    sum.addValue(value);
  }
  for (const auto& [name, value] : state.integerCounters) {
    sum.add(name);
    sum.addValue(value);
  }
  for (const auto& [name, bytes] : state.blobs) {
    sum.add(name);
    sum.add(bytes.data(), bytes.size());
  }
  for (const auto& [name, registry] : state.groups) {
    sum.add(name);
    if (registry == nullptr) continue;
    for (const auto& field : *registry) {
      if (!field->info().checkpointed) continue;
      sum.add(field->info().name);
      sum.add(field->rawData(), field->size() * static_cast<std::size_t>(field->components()) *
                                    scalarBytes(field->kind()));
    }
  }
  return sum.value();
}

std::uint64_t textChecksum(const std::string& text) {
  Checksum sum;
  sum.add(text);
  return sum.value();
}

void writeCheckpoint(const std::filesystem::path& path, const CheckpointState& state) {
  hdf5::silenceErrorPrinting();
  const std::string temporary = path.string() + ".tmp";
  const Place root{temporary, "/"};
  try {
    {
      Handle access = checkpointAccess(root);
      // TRUNC replaces a stale .tmp that a killed writer may have left.
      Handle file =
          checked(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), root,
                  "cannot create checkpoint", "check that the run folder exists and is writable");
      writeContents(file.get(), state, root);
      check(file.close(), root, "cannot close checkpoint", "check free disk space");
    }
    // Durable before visible: the new file's bytes reach the disk before the rename publishes
    // it, and the folder is synced so the rename itself survives a power loss.
    hdf5::fsyncPath(temporary, false);
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw IoError(path.string(), "", "cannot replace the previous checkpoint",
                    "check that the run folder is writable");
    const std::filesystem::path folder =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    hdf5::fsyncPath(folder.string(), true);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

namespace {

struct StoredField {
  sim::ScalarKind kind;
  hsize_t rows;
  hsize_t components;
};

StoredField describeStored(hid_t group, const std::string& name, const Place& groupPlace) {
  const Place place = groupPlace.at(name);
  Handle dataset =
      checked(H5Dopen2(group, name.c_str(), H5P_DEFAULT), place, "cannot open dataset");
  Handle type = checked(H5Dget_type(dataset.get()), place, "cannot read dataset type");
  const auto [rows, components] = hdf5::datasetShape(dataset.get(), place);
  const bool isReal = H5Tget_class(type.get()) == H5T_FLOAT;
  if (isReal && H5Tget_size(type.get()) != 8)
    throw IoError(place.file, place.object, "stored with less than float64 precision",
                  "checkpoints must be written by writeCheckpoint");
  return {isReal ? sim::ScalarKind::kReal : sim::ScalarKind::kInt32, rows, components};
}

}  // namespace

namespace {

// Opens the file and checks that it is a checkpoint of this toolkit's format version.
Handle openCheckpoint(const std::filesystem::path& path, const Place& root) {
  if (!std::filesystem::exists(path))
    throw IoError(root.file, "", "no checkpoint at this path",
                  "resume a run folder that holds a checkpoint.h5");
  Handle access = checkpointAccess(root);
  Handle file = checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()), root,
                        "cannot open checkpoint", "the checkpoint is damaged or not HDF5");
  if (!hdf5::hasAttribute(file.get(), "format", root) ||
      hdf5::readStringAttribute(file.get(), "format", root) != layout::kCheckpointFormat)
    throw IoError(root.file, "", "not a checkpoint of this toolkit (no format attribute)",
                  "resume a run folder that holds a checkpoint.h5");
  const std::int64_t version = hdf5::readInt64Attribute(file.get(), "format_version", root);
  if (version != layout::kCheckpointFormatVersion)
    throw IoError(root.file, "",
                  "checkpoint format version " + std::to_string(version) +
                      " is not this toolkit's (" +
                      std::to_string(layout::kCheckpointFormatVersion) + ")",
                  "resume with the toolkit version that wrote it");
  return file;
}

// The counters group's attributes, integer or real by their stored type.
void readCounters(hid_t file, const Place& root, CheckpointState& state) {
  Handle counters = hdf5::openGroup(file, "counters", root);
  const Place counterPlace = root.at("counters");
  for (const std::string& name : hdf5::attributeNames(counters.get(), counterPlace)) {
    Handle attribute = checked(H5Aopen(counters.get(), name.c_str(), H5P_DEFAULT), counterPlace,
                               "cannot open counter '" + name + "'");
    Handle type = checked(H5Aget_type(attribute.get()), counterPlace, "cannot read counter type");
    if (H5Tget_class(type.get()) == H5T_INTEGER)
      state.integerCounters[name] = hdf5::readInt64Attribute(counters.get(), name, counterPlace);
    else
      state.realCounters[name] = hdf5::readDoubleAttribute(counters.get(), name, counterPlace);
  }
}

void readBlobs(hid_t file, const Place& root, CheckpointState& state) {
  Handle blobs = hdf5::openGroup(file, "blobs", root);
  for (const std::string& name : hdf5::linkNames(blobs.get(), root.at("blobs"))) {
    const Place place = root.at("blobs/" + name);
    Handle dataset =
        checked(H5Dopen2(blobs.get(), name.c_str(), H5P_DEFAULT), place, "cannot open blob");
    auto& bytes = state.blobs[name];
    bytes.resize(hdf5::datasetShape(dataset.get(), place).first);
    if (!bytes.empty())
      check(H5Dread(dataset.get(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()),
            place, "cannot read blob");
  }
}

// Checks that a stored group holds exactly the fields `registry` checkpoints, each of the same
// kind, width and particle count; returns the opened group.
Handle validateGroup(hid_t groups, const std::string& name, const sim::FieldRegistry& registry,
                     const Place& groupsPlace) {
  const Place place = groupsPlace.at(name);
  Handle group = hdf5::openGroup(groups, name, groupsPlace);
  const std::vector<std::string> storedFields = hdf5::linkNames(group.get(), place);
  std::vector<std::string> missing;
  std::vector<std::string> wanted;
  for (const auto& field : registry) {
    if (!field->info().checkpointed) continue;
    wanted.push_back(field->info().name);
    if (std::find(storedFields.begin(), storedFields.end(), field->info().name) ==
        storedFields.end())
      missing.push_back(field->info().name);
  }
  if (!missing.empty())
    throw IoError(place.file, place.object,
                  "field(s) " + joinNames(missing) +
                      " are checkpointed by this run but absent from the checkpoint",
                  "the checkpoint was written with other effects active; resume with the "
                  "protocol and toolkit version that wrote it, or start the run afresh");
  std::vector<std::string> extra;
  for (const auto& stored : storedFields)
    if (std::find(wanted.begin(), wanted.end(), stored) == wanted.end()) extra.push_back(stored);
  if (!extra.empty())
    throw IoError(place.file, place.object,
                  "field(s) " + joinNames(extra) +
                      " are in the checkpoint but this run does not checkpoint them",
                  "resume with the protocol and toolkit version that wrote the checkpoint");
  for (const auto& field : registry) {
    if (!field->info().checkpointed) continue;
    const StoredField s = describeStored(group.get(), field->info().name, place);
    const Place fieldPlace = place.at(field->info().name);
    if (s.kind != field->kind() || s.components != static_cast<hsize_t>(field->components()))
      throw IoError(place.file, fieldPlace.object,
                    "stored as " + hdf5::elementName(s.kind, static_cast<int>(s.components)) +
                        " but this run's field is " +
                        hdf5::elementName(field->kind(), field->components()),
                    "resume with the toolkit version that wrote the checkpoint");
    if (s.rows != registry.size())
      throw IoError(place.file, fieldPlace.object,
                    "holds " + std::to_string(s.rows) + " particles but this run has " +
                        std::to_string(registry.size()),
                    "resume with the protocol (and accuracy) that wrote the checkpoint");
  }
  return group;
}

// Validates every group and field before anything is restored, so that a mismatch leaves the
// registries untouched; returns the opened groups in the order of `restoreInto`.
std::vector<Handle> validateGroups(hid_t file, const Place& root,
                                   const std::map<std::string, sim::FieldRegistry*>& restoreInto) {
  Handle groups = hdf5::openGroup(file, "groups", root);
  const Place groupsPlace = root.at("groups");
  const std::vector<std::string> stored = hdf5::linkNames(groups.get(), groupsPlace);
  std::vector<std::string> extraGroups;
  for (const auto& name : stored)
    if (!restoreInto.count(name)) extraGroups.push_back(name);
  if (!extraGroups.empty())
    throw IoError(
        root.file, "/groups",
        "holds particle group(s) " + joinNames(extraGroups) + " that this run does not have",
        "resume with the protocol that wrote the checkpoint");
  std::vector<Handle> groupHandles;
  for (const auto& [name, registry] : restoreInto) {
    const Place place = groupsPlace.at(name);
    if (!registry)
      throw IoError(root.file, place.object, "no field registry given", "pass &particles.fields");
    if (std::find(stored.begin(), stored.end(), name) == stored.end())
      throw IoError(root.file, place.object, "particle group is not in the checkpoint",
                    "resume with the protocol that wrote the checkpoint");
    groupHandles.push_back(validateGroup(groups.get(), name, *registry, groupsPlace));
  }
  return groupHandles;
}

}  // namespace

CheckpointState readCheckpoint(const std::filesystem::path& path,
                               const std::map<std::string, sim::FieldRegistry*>& restoreInto) {
  hdf5::silenceErrorPrinting();
  const Place root{path.string(), "/"};
  Handle file = openCheckpoint(path, root);
  CheckpointState state;
  state.time = hdf5::readDoubleAttribute(file.get(), "time", root);
  state.step = hdf5::readInt64Attribute(file.get(), "step", root);
  state.dt = hdf5::readDoubleAttribute(file.get(), "dt", root);
  const std::int64_t storedChecksum = hdf5::readInt64Attribute(file.get(), "checksum", root);
  state.groups = restoreInto;
  readCounters(file.get(), root, state);
  readBlobs(file.get(), root, state);
  const std::vector<Handle> groupHandles = validateGroups(file.get(), root, restoreInto);
  std::size_t k = 0;
  for (const auto& [name, registry] : restoreInto) {
    const Place place = root.at("groups").at(name);
    for (const auto& field : *registry)
      if (field->info().checkpointed)
        hdf5::restoreFieldDataset(groupHandles[k].get(), *field, place);
    ++k;
  }
  if (std::bit_cast<std::uint64_t>(storedChecksum) != contentChecksum(state))
    throw IoError(root.file, "",
                  "the checkpoint's contents do not match its checksum: it was damaged after it "
                  "was written",
                  "start the run afresh (remove the folder or choose another --out)");
  return state;
}

}  // namespace protocols
