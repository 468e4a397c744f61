#include "protocols/io/frame_reader.h"

#include <algorithm>
#include <cstdlib>

#include "protocols/io/field_dataset.h"
#include "protocols/io/frame_file_layout.h"
#include "protocols/io/hdf5_support.h"

namespace protocols {

using hdf5::check;
using hdf5::checked;
using hdf5::Handle;
using hdf5::Place;

std::vector<double> SeriesData::column(const std::string& columnName) const {
  const auto it = std::find(columns.begin(), columns.end(), columnName);
  if (it == columns.end())
    throw IoError("", "/series/" + name, "no column named '" + columnName + "'",
                  "the table's columns are listed in its `columns` attribute");
  const std::size_t c = static_cast<std::size_t>(it - columns.begin());
  std::vector<double> out(rows);
  for (std::size_t r = 0; r < rows; ++r) out[r] = values[r * columns.size() + c];
  return out;
}

struct FrameReader::Impl {
  Handle file;
  Place root;
  std::vector<FrameInfo> frames;
  std::vector<std::string> unreadable;

  const FrameInfo& frame(std::size_t index) const {
    for (const auto& f : frames)
      if (f.index == index) return f;
    throw IoError(root.file, "/frames", "has no complete frame " + std::to_string(index),
                  frames.empty() ? "the run wrote no frame yet"
                                 : "frames are numbered " + std::to_string(frames.front().index) +
                                       " to " + std::to_string(frames.back().index));
  }

  static std::string frameName(std::size_t index) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%06zu", index);
    return buffer;
  }

  // The complete frames, by index; the names of those that cannot be read go to `unreadable`.
  void listFrames() {
    Handle all = hdf5::openGroup(file.get(), "frames", root);
    for (const std::string& name : hdf5::linkNames(all.get(), root.at("frames"))) {
      const Place place = root.at("frames/" + name);
      try {
        char* end = nullptr;
        const unsigned long long index = std::strtoull(name.c_str(), &end, 10);
        if (name.empty() || *end != '\0')
          throw IoError(place.file, place.object, "not a frame number", "");
        Handle frame =
            checked(H5Gopen2(all.get(), name.c_str(), H5P_DEFAULT), place, "cannot open frame");
        if (!hdf5::hasAttribute(frame.get(), "complete", place))
          throw IoError(place.file, place.object, "frame is incomplete", "");
        FrameInfo info;
        info.index = static_cast<std::size_t>(index);
        info.time = hdf5::readDoubleAttribute(frame.get(), "time", place);
        info.step = hdf5::readInt64Attribute(frame.get(), "step", place);
        info.groups = hdf5::linkNames(frame.get(), place);
        frames.push_back(std::move(info));
      } catch (const IoError&) {
        H5Eclear2(H5E_DEFAULT);
        unreadable.push_back(name);
      }
    }
    std::sort(frames.begin(), frames.end(),
              [](const FrameInfo& a, const FrameInfo& b) { return a.index < b.index; });
  }

  Handle openFrameGroup(std::size_t index, const std::string& group, Place& place) const {
    frame(index);
    const std::string name = frameName(index);
    Handle all = hdf5::openGroup(file.get(), "frames", root);
    Handle f = hdf5::openGroup(all.get(), name, root.at("frames"));
    place = root.at("frames/" + name);
    Handle g = hdf5::openGroup(f.get(), group, place);
    place = place.at(group);
    return g;
  }
};

namespace {

// The file opened read-only without waiting for a writer's lock.
Handle openReadOnly(const std::filesystem::path& h5Path, const Place& root) {
  Handle access = checked(H5Pcreate(H5P_FILE_ACCESS), root, "cannot create file properties");
  // Without the lock, a run still writing (it holds an exclusive lock) can be read; the reader
  // then sees the file as of the writer's last flush (see frame_writer.h).
  check(H5Pset_file_locking(access.get(), false, true), root, "cannot disable file locking");
  // The writer's close degree: HDF5 requires it to match when the file is open in-process.
  check(H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG), root,
        "cannot set the file close mode");
  hid_t id = H5Fopen(h5Path.c_str(), H5F_ACC_RDONLY, access.get());
  if (id < 0) {
    // If this process itself has the file open (a FrameWriter), HDF5 shares that open file and
    // insists on the writer's locking setting: retry with the default one, and if that fails
    // too, report the first reason.
    const std::string firstReason = hdf5::takeErrorStack();
    check(H5Pset_file_locking(access.get(), true, true), root, "cannot set file locking");
    id = H5Fopen(h5Path.c_str(), H5F_ACC_RDONLY, access.get());
    H5Eclear2(H5E_DEFAULT);
    if (id < 0)
      throw IoError(root.file, "", "cannot open as HDF5 [" + firstReason + "]",
                    "give the frames.h5 of a run folder");
  }
  return Handle(id);
}

void requireFramesFormat(const Handle& file, const Place& root) {
  if (!hdf5::hasAttribute(file.get(), "format", root) ||
      hdf5::readStringAttribute(file.get(), "format", root) != layout::kFramesFormat)
    throw IoError(root.file, "", "not a frames file of this toolkit (no format attribute)",
                  "give the frames.h5 of a run folder");
  const std::int64_t version = hdf5::readInt64Attribute(file.get(), "format_version", root);
  if (version > layout::kFramesFormatVersion)
    throw IoError(root.file, "",
                  "format version " + std::to_string(version) + " is newer than this toolkit's",
                  "read it with a newer tamponade");
}

}  // namespace

FrameReader::FrameReader(const std::filesystem::path& h5Path) : impl_(std::make_unique<Impl>()) {
  hdf5::silenceErrorPrinting();
  Impl& s = *impl_;
  s.root = Place{h5Path.string(), "/"};
  if (!std::filesystem::exists(h5Path))
    throw IoError(s.root.file, "", "no such file", "give the frames.h5 of a run folder");
  s.file = openReadOnly(h5Path, s.root);
  requireFramesFormat(s.file, s.root);
  s.listFrames();
}

FrameReader::~FrameReader() = default;
FrameReader::FrameReader(FrameReader&&) noexcept = default;
FrameReader& FrameReader::operator=(FrameReader&&) noexcept = default;

const std::vector<FrameInfo>& FrameReader::frames() const { return impl_->frames; }
const std::vector<std::string>& FrameReader::unreadableFrames() const { return impl_->unreadable; }

std::vector<std::string> FrameReader::fieldNames(std::size_t frameIndex,
                                                 const std::string& group) const {
  hdf5::silenceErrorPrinting();
  Place place;
  Handle g = impl_->openFrameGroup(frameIndex, group, place);
  return hdf5::linkNames(g.get(), place);
}

FieldData FrameReader::readField(std::size_t frameIndex, const std::string& group,
                                 const std::string& field) const {
  hdf5::silenceErrorPrinting();
  Place place;
  Handle g = impl_->openFrameGroup(frameIndex, group, place);
  return hdf5::readFieldDataset(g.get(), field, place);
}

std::vector<std::string> FrameReader::staticGroups() const {
  hdf5::silenceErrorPrinting();
  Handle statics = hdf5::openGroup(impl_->file.get(), "static", impl_->root);
  return hdf5::linkNames(statics.get(), impl_->root.at("static"));
}

std::vector<std::string> FrameReader::staticFieldNames(const std::string& group) const {
  hdf5::silenceErrorPrinting();
  Handle statics = hdf5::openGroup(impl_->file.get(), "static", impl_->root);
  Handle g = hdf5::openGroup(statics.get(), group, impl_->root.at("static"));
  return hdf5::linkNames(g.get(), impl_->root.at("static/" + group));
}

FieldData FrameReader::readStaticField(const std::string& group, const std::string& field) const {
  hdf5::silenceErrorPrinting();
  Handle statics = hdf5::openGroup(impl_->file.get(), "static", impl_->root);
  Handle g = hdf5::openGroup(statics.get(), group, impl_->root.at("static"));
  return hdf5::readFieldDataset(g.get(), field, impl_->root.at("static/" + group));
}

std::vector<std::string> FrameReader::seriesNames() const {
  hdf5::silenceErrorPrinting();
  Handle series = hdf5::openGroup(impl_->file.get(), "series", impl_->root);
  return hdf5::linkNames(series.get(), impl_->root.at("series"));
}

SeriesData FrameReader::readSeries(const std::string& name) const {
  hdf5::silenceErrorPrinting();
  const Impl& s = *impl_;
  Handle series = hdf5::openGroup(s.file.get(), "series", s.root);
  const Place place = s.root.at("series/" + name);
  if (!hdf5::hasLink(series.get(), name, s.root.at("series")))
    throw IoError(place.file, place.object, "no such series",
                  "the run wrote no table of that name (see seriesNames())");
  Handle dataset =
      checked(H5Dopen2(series.get(), name.c_str(), H5P_DEFAULT), place, "cannot open series");
  SeriesData data;
  data.name = name;
  data.columns = hdf5::readStringArrayAttribute(dataset.get(), "columns", place);
  data.units = hdf5::readStringArrayAttribute(dataset.get(), "units", place);
  const auto [rows, width] = hdf5::datasetShape(dataset.get(), place);
  if (width != data.columns.size())
    throw IoError(place.file, place.object, "column names do not match the table width",
                  "the file is damaged");
  data.rows = rows;
  data.values.resize(rows * width);
  if (!data.values.empty())
    check(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                  data.values.data()),
          place, "cannot read series");
  return data;
}

RunInfo FrameReader::runInfo() const {
  hdf5::silenceErrorPrinting();
  const Impl& s = *impl_;
  RunInfo info;
  Handle meta = hdf5::openGroup(s.file.get(), "metadata", s.root);
  const Place place = s.root.at("metadata");
  info.toolkitVersion = hdf5::readStringAttribute(meta.get(), "toolkit_version", place);
  info.hdf5Version = hdf5::readStringAttribute(meta.get(), "hdf5_version", place);
  info.createdUtc = hdf5::readStringAttribute(meta.get(), "created_utc", place);
  info.protocolText = hdf5::readStringDataset(meta.get(), "protocol", place);
  Handle run = hdf5::openGroup(meta.get(), "run", place);
  const Place runPlace = place.at("run");
  for (const std::string& key : hdf5::attributeNames(run.get(), runPlace)) {
    Handle attribute = checked(H5Aopen(run.get(), key.c_str(), H5P_DEFAULT), runPlace,
                               "cannot open attribute '" + key + "'");
    Handle type = checked(H5Aget_type(attribute.get()), runPlace, "cannot read attribute type");
    if (H5Tget_class(type.get()) == H5T_STRING)
      info.strings[key] = hdf5::readStringAttribute(run.get(), key, runPlace);
    else
      info.numbers[key] = hdf5::readDoubleAttribute(run.get(), key, runPlace);
  }
  if (hdf5::hasLink(meta.get(), "units", place)) {
    Handle units = hdf5::openGroup(meta.get(), "units", place);
    for (const std::string& group : hdf5::linkNames(units.get(), place.at("units"))) {
      Handle g = hdf5::openGroup(units.get(), group, place.at("units"));
      const Place groupPlace = place.at("units/" + group);
      for (const std::string& field : hdf5::attributeNames(g.get(), groupPlace))
        info.units[group][field] = hdf5::readStringAttribute(g.get(), field, groupPlace);
    }
  }
  return info;
}

}  // namespace protocols
