#include "protocols/io/frame_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <set>
#include <utility>

#include "protocols/io/field_dataset.h"
#include "protocols/io/frame_file_layout.h"
#include "protocols/io/hdf5_support.h"
#include "protocols/io/xdmf_document.h"

namespace protocols {

using hdf5::check;
using hdf5::checked;
using hdf5::Handle;
using hdf5::Place;

namespace {

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  gmtime_r(&now, &parts);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &parts);
  return buffer;
}

// File access for the writer: checksummed (v1.8) metadata, and a metadata cache that never
// evicts between flushes (see the header: the file changes metadata only at H5Fflush).
Handle writerAccess(const Place& place) {
  Handle access = checked(H5Pcreate(H5P_FILE_ACCESS), place, "cannot create file properties");
  // v1.8 object headers and B-trees carry checksums, so damaged metadata is detected instead of
  // misread. Not v1.10: its superblock marks the file "open for writing" and a killed run's file
  // then refuses to open without h5clear. Every HDF5 >= 1.8 (ParaView, h5py) reads v1.8.
  check(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), place,
        "cannot select the HDF5 file format version");
  H5AC_cache_config_t cache{};
  cache.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  check(H5Pget_mdc_config(access.get(), &cache), place, "cannot read metadata cache settings");
  cache.evictions_enabled = false;  // requires every automatic resize mode off
  cache.incr_mode = H5C_incr__off;
  cache.flash_incr_mode = H5C_flash_incr__off;
  cache.decr_mode = H5C_decr__off;
  check(H5Pset_mdc_config(access.get(), &cache), place, "cannot configure the metadata cache");
  check(H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG), place,
        "cannot set the file close mode");
  return access;
}

void requireValidName(const std::string& what, const std::string& name, const Place& place) {
  if (name.empty() || name == "." || name.find('/') != std::string::npos)
    throw IoError(place.file, place.object, what + " name '" + name + "' is not usable in HDF5",
                  "use a non-empty name without '/'");
}

std::string frameGroupName(std::size_t index) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%06zu", index);
  return buffer;
}

// Bytes per stored scalar of a dataset (for the XDMF Precision attribute).
int storedScalarBytes(hid_t dataset, const Place& place) {
  Handle type = checked(H5Dget_type(dataset), place, "cannot read dataset type");
  return static_cast<int>(H5Tget_size(type.get()));
}

// Describes an existing dataset for the sidecar.
XdmfDataset describeDataset(hid_t parent, const std::string& name, const std::string& h5Path,
                            const Place& parentPlace) {
  const Place place = parentPlace.at(name);
  Handle dataset =
      checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), place, "cannot open dataset");
  Handle type = checked(H5Dget_type(dataset.get()), place, "cannot read dataset type");
  XdmfDataset d;
  d.name = name;
  d.path = h5Path + "/" + name;
  const auto [rows, components] = hdf5::datasetShape(dataset.get(), place);
  d.rows = rows;
  d.components = static_cast<int>(components);
  d.kind =
      H5Tget_class(type.get()) == H5T_INTEGER ? sim::ScalarKind::kInt32 : sim::ScalarKind::kReal;
  d.bytesPerScalar = storedScalarBytes(dataset.get(), place);
  return d;
}

}  // namespace

struct FrameWriter::Impl {
  // Metadata cache bounds before a reopen. The entry count is what matters: the cache's own size
  // undercounts its heap about tenfold (massif: ~260 kB of heap per frame of 7 chunked datasets,
  // most of it chunk B-tree nodes, while the cache reported ~20 kB), and 512 entries (~45 such
  // frames) kept the writer within ~10 MB of its starting RSS over 1000 frames.
  static constexpr std::size_t kMaxCacheBytes = 16u << 20;  // [bytes]
  static constexpr int kMaxCacheEntries = 512;

  // The datasets of one group written in one frame, in registry order.
  struct GroupRecord {
    std::string name;
    std::vector<XdmfDataset> datasets;
  };
  struct FrameRecord {
    FrameInfo info;
    std::vector<GroupRecord> groups;
  };
  struct Series {
    hsize_t rows = 0;
    std::vector<std::string> columns;  // including "time"
  };

  std::filesystem::path h5Path;
  std::filesystem::path xdmfPath;
  std::string h5FileName;  // relative name used by the sidecar
  FrameWriterOptions options;
  Handle file;
  Place root;
  std::vector<FrameInfo> frames;
  std::vector<FrameRecord> records;
  std::vector<std::string> frameTexts;  // formatted sidecar frames, parallel to records
  std::vector<GroupRecord> statics;
  std::map<std::string, std::set<std::string>> unitsRecorded;
  std::map<std::string, Series> series;

  hdf5::FieldDatasetOptions datasetOptions() const {
    return {options.precision == FramePrecision::kFloat32, options.gzipLevel};
  }

  const GroupRecord* findStatic(const std::string& group) const {
    for (const auto& s : statics)
      if (s.name == group) return &s;
    return nullptr;
  }

  void flushFile() {
    check(H5Fflush(file.get(), H5F_SCOPE_LOCAL), root, "cannot flush to disk",
          "check free disk space");
  }

  // Call only with no object of the file open.
  void boundCache() {
    // With evictions off the metadata cache keeps every entry it ever loaded. Once it passes the
    // bounds, close and reopen the file: everything is flushed, so this only empties the cache
    // and bounds the writer's memory.
    std::size_t maxSize = 0, minClean = 0, currentSize = 0;
    int entries = 0;
    check(H5Fget_mdc_size(file.get(), &maxSize, &minClean, &currentSize, &entries), root,
          "cannot read the metadata cache size");
    if (currentSize > kMaxCacheBytes || entries > kMaxCacheEntries) {
      check(file.close(), root, "cannot close the frames file", "check free disk space");
      Handle access = writerAccess(root);
      file = checked(H5Fopen(h5Path.c_str(), H5F_ACC_RDWR, access.get()), root,
                     "cannot reopen the frames file");
    }
  }

  // Records each field's unit once under /metadata/units/<group>.
  void recordUnits(const std::string& group, const sim::FieldRegistry& fields) {
    auto& known = unitsRecorded[group];
    Handle units;
    for (const auto& field : fields) {
      if (!field->info().written || known.count(field->info().name)) continue;
      if (!units.valid()) {
        Handle metadata = hdf5::openGroup(file.get(), "metadata", root);
        const Place place = root.at("metadata");
        Handle all = hdf5::openOrCreateGroup(metadata.get(), "units", place);
        units = hdf5::openOrCreateGroup(all.get(), group, place.at("units"));
      }
      hdf5::writeAttribute(units.get(), field->info().name, field->info().unit,
                           root.at("metadata/units/" + group));
      known.insert(field->info().name);
    }
  }

  // The sidecar view of one frame: each written group with its positions (from the frame or from
  // /static) and attributes; groups that only have static data appear in every frame too.
  XdmfFrame composeXdmf(const FrameRecord& record) const {
    XdmfFrame frame;
    frame.time = record.info.time;
    frame.step = record.info.step;
    auto addGrid = [&](const std::string& name, const std::vector<XdmfDataset>* dynamic) {
      XdmfGrid grid;
      grid.name = name;
      bool hasPosition = false;
      for (const auto* source :
           {findStatic(name) ? &findStatic(name)->datasets : nullptr, dynamic}) {
        if (!source) continue;
        for (const auto& d : *source) {
          if (d.name == layout::kPositionField) {
            grid.position = d;
            hasPosition = true;
          } else {
            grid.attributes.push_back(d);
          }
        }
      }
      // A group without positions cannot be drawn; it stays in the HDF5 file only.
      if (hasPosition) frame.grids.push_back(std::move(grid));
    };
    for (const auto& group : record.groups) addGrid(group.name, &group.datasets);
    for (const auto& s : statics) {
      const bool inFrame = std::any_of(record.groups.begin(), record.groups.end(),
                                       [&](const GroupRecord& g) { return g.name == s.name; });
      if (!inFrame) addGrid(s.name, nullptr);
    }
    return frame;
  }

  void rewriteXdmf() { replaceFileAtomically(xdmfPath, formatXdmfDocument(frameTexts)); }

  void reformatAllFrames() {
    frameTexts.clear();
    for (const auto& record : records)
      frameTexts.push_back(formatXdmfFrame(composeXdmf(record), h5FileName));
  }

  // Writes the `written` fields of `fields` (or those named in `only`, when given and not empty)
  // into `group`, skipping `skip`'s fields, and returns their sidecar descriptions.
  std::vector<XdmfDataset> writeFields(hid_t group, const std::string& groupPath,
                                       const sim::FieldRegistry& fields, const GroupRecord* skip,
                                       const std::vector<std::string>* only = nullptr) {
    const Place place{root.file, groupPath};
    const bool selected = only != nullptr && !only->empty();
    if (selected)
      for (const std::string& name : *only)
        if (!fields.has(name))
          throw IoError(root.file, groupPath, "no particle field '" + name + "' to write",
                        "name fields of the engine's registry (outputs.fields)");
    std::vector<XdmfDataset> written;
    const auto opts = datasetOptions();
    for (const auto& field : fields) {
      const sim::FieldInfo& info = field->info();
      if (selected ? std::find(only->begin(), only->end(), info.name) == only->end()
                   : !info.written)
        continue;
      if (skip && std::any_of(skip->datasets.begin(), skip->datasets.end(),
                              [&](const XdmfDataset& d) { return d.name == info.name; }))
        continue;
      requireValidName("field", info.name, place);
      hdf5::writeFieldDataset(group, *field, opts, place);
      XdmfDataset d;
      d.name = info.name;
      d.path = groupPath + "/" + info.name;
      d.rows = field->size();
      d.components = field->components();
      d.kind = field->kind();
      d.bytesPerScalar = field->kind() == sim::ScalarKind::kInt32 || opts.realsAsFloat32 ? 4 : 8;
      written.push_back(std::move(d));
    }
    return written;
  }
};

FrameWriter::FrameWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FrameWriter::~FrameWriter() = default;
FrameWriter::FrameWriter(FrameWriter&&) noexcept = default;
FrameWriter& FrameWriter::operator=(FrameWriter&&) noexcept = default;

FrameWriter::FrameWriter(const std::filesystem::path& h5Path, const RunMetadata& metadata,
                         FrameWriterOptions options)
    : impl_(std::make_unique<Impl>()) {
  hdf5::silenceErrorPrinting();
  Impl& s = *impl_;
  s.h5Path = h5Path;
  s.xdmfPath = std::filesystem::path(h5Path).replace_extension(".xmf");
  s.h5FileName = h5Path.filename().string();
  s.options = options;
  s.root = Place{h5Path.string(), "/"};
  if (options.gzipLevel < 0 || options.gzipLevel > 9)
    throw IoError(s.root.file, "",
                  "gzip level " + std::to_string(options.gzipLevel) + " is out of range",
                  "use 0 (off) to 9");
  if (!options.overwrite && std::filesystem::exists(h5Path))
    throw IoError(s.root.file, "", "the file exists already",
                  "choose another output folder, delete the old run, or resume it");

  // Checked before the file exists, so that bad metadata leaves nothing behind.
  for (const auto& [key, value] : metadata.numbers)
    if (metadata.strings.count(key) || key.empty())
      throw IoError(s.root.file, "/metadata/run",
                    "metadata key '" + key + "' is empty or given both as text and as number",
                    "give each metadata key once, non-empty");

  Handle access = writerAccess(s.root);
  s.file = checked(H5Fcreate(h5Path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), s.root,
                   "cannot create the frames file",
                   "check that the output folder exists and is writable");
  hdf5::writeAttribute(s.file.get(), "format", std::string(layout::kFramesFormat), s.root);
  hdf5::writeAttribute(s.file.get(), "format_version", layout::kFramesFormatVersion, s.root);

  Handle meta = hdf5::openOrCreateGroup(s.file.get(), "metadata", s.root);
  const Place metaPlace = s.root.at("metadata");
  hdf5::writeAttribute(meta.get(), "toolkit_version", std::string(TAMPONADE_VERSION), metaPlace);
  unsigned major = 0, minor = 0, release = 0;
  H5get_libversion(&major, &minor, &release);
  hdf5::writeAttribute(
      meta.get(), "hdf5_version",
      std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release),
      metaPlace);
  hdf5::writeAttribute(meta.get(), "created_utc", utcNow(), metaPlace);
  hdf5::writeStringDataset(meta.get(), "protocol", metadata.protocolText, metaPlace);
  Handle run = hdf5::openOrCreateGroup(meta.get(), "run", metaPlace);
  for (const auto& [key, value] : metadata.strings)
    hdf5::writeAttribute(run.get(), key, value, metaPlace.at("run"));
  for (const auto& [key, value] : metadata.numbers)
    hdf5::writeAttribute(run.get(), key, value, metaPlace.at("run"));
  for (const char* name : {"frames", "static", "series"})
    hdf5::openOrCreateGroup(s.file.get(), name, s.root);
  s.flushFile();
  s.rewriteXdmf();
}

FrameWriter FrameWriter::resume(const std::filesystem::path& h5Path, std::int64_t step, double time,
                                FrameWriterOptions options) {
  hdf5::silenceErrorPrinting();
  auto impl = std::make_unique<Impl>();
  Impl& s = *impl;
  s.h5Path = h5Path;
  s.xdmfPath = std::filesystem::path(h5Path).replace_extension(".xmf");
  s.h5FileName = h5Path.filename().string();
  s.options = options;
  s.root = Place{h5Path.string(), "/"};
  if (!std::filesystem::exists(h5Path))
    throw IoError(s.root.file, "", "no frames file to resume", "give the folder of a stopped run");
  Handle access = writerAccess(s.root);
  s.file = checked(H5Fopen(h5Path.c_str(), H5F_ACC_RDWR, access.get()), s.root,
                   "cannot reopen the frames file",
                   "check that no other run writes to this folder and that it is writable");
  if (!hdf5::hasAttribute(s.file.get(), "format", s.root) ||
      hdf5::readStringAttribute(s.file.get(), "format", s.root) != layout::kFramesFormat)
    throw IoError(s.root.file, "", "not a frames file of this toolkit",
                  "give the folder of a stopped run");

  // Frames: keep the leading run of complete frames up to `step`; delete the rest (later frames
  // will be written again, a frame a kill left half-written is dropped).
  Handle frames = hdf5::openGroup(s.file.get(), "frames", s.root);
  const Place framesPlace = s.root.at("frames");
  std::vector<std::string> names = hdf5::linkNames(frames.get(), framesPlace);
  std::size_t kept = 0;
  for (; kept < names.size(); ++kept) {
    const std::string& name = names[kept];
    const Place place = framesPlace.at(name);
    if (name != frameGroupName(kept)) break;
    Impl::FrameRecord record;
    try {
      Handle frame =
          checked(H5Gopen2(frames.get(), name.c_str(), H5P_DEFAULT), place, "cannot open frame");
      if (!hdf5::hasAttribute(frame.get(), "complete", place)) break;
      record.info.index = kept;
      record.info.time = hdf5::readDoubleAttribute(frame.get(), "time", place);
      record.info.step = hdf5::readInt64Attribute(frame.get(), "step", place);
      if (record.info.step > step) break;
      for (const std::string& group : hdf5::linkNames(frame.get(), place)) {
        Handle g = hdf5::openGroup(frame.get(), group, place);
        const Place groupPlace = place.at(group);
        Impl::GroupRecord groupRecord{group, {}};
        for (const std::string& field : hdf5::linkNames(g.get(), groupPlace))
          groupRecord.datasets.push_back(
              describeDataset(g.get(), field, groupPlace.object, groupPlace));
        record.info.groups.push_back(group);
        record.groups.push_back(std::move(groupRecord));
      }
    } catch (const IoError&) {
      H5Eclear2(H5E_DEFAULT);
      break;
    }
    s.frames.push_back(record.info);
    s.records.push_back(std::move(record));
  }
  for (std::size_t k = kept; k < names.size(); ++k)
    check(H5Ldelete(frames.get(), names[k].c_str(), H5P_DEFAULT), framesPlace.at(names[k]),
          "cannot remove a frame written after the checkpoint");

  Handle statics = hdf5::openGroup(s.file.get(), "static", s.root);
  const Place staticPlace = s.root.at("static");
  for (const std::string& group : hdf5::linkNames(statics.get(), staticPlace)) {
    Handle g = hdf5::openGroup(statics.get(), group, staticPlace);
    const Place groupPlace = staticPlace.at(group);
    Impl::GroupRecord record{group, {}};
    for (const std::string& field : hdf5::linkNames(g.get(), groupPlace))
      record.datasets.push_back(describeDataset(g.get(), field, groupPlace.object, groupPlace));
    s.statics.push_back(std::move(record));
  }

  Handle metadata = hdf5::openGroup(s.file.get(), "metadata", s.root);
  const Place metaPlace = s.root.at("metadata");
  if (hdf5::hasLink(metadata.get(), "units", metaPlace)) {
    Handle units = hdf5::openGroup(metadata.get(), "units", metaPlace);
    for (const std::string& group : hdf5::linkNames(units.get(), metaPlace.at("units"))) {
      Handle g = hdf5::openGroup(units.get(), group, metaPlace.at("units"));
      for (const std::string& field : hdf5::attributeNames(g.get(), metaPlace.at("units/" + group)))
        s.unitsRecorded[group].insert(field);
    }
  }

  // Series: drop the rows later than the checkpoint (rows are appended in time order).
  Handle series = hdf5::openGroup(s.file.get(), "series", s.root);
  const Place seriesPlace = s.root.at("series");
  for (const std::string& name : hdf5::linkNames(series.get(), seriesPlace)) {
    const Place place = seriesPlace.at(name);
    Impl::Series table;
    Handle dataset =
        checked(H5Dopen2(series.get(), name.c_str(), H5P_DEFAULT), place, "cannot open series");
    table.columns = hdf5::readStringArrayAttribute(dataset.get(), "columns", place);
    const auto [rows, width] = hdf5::datasetShape(dataset.get(), place);
    std::vector<double> values(rows * width);
    if (!values.empty())
      check(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
            place, "cannot read series");
    hsize_t keep = 0;
    while (keep < rows && values[keep * width] <= time) ++keep;
    const hsize_t dims[2] = {keep, width};
    check(H5Dset_extent(dataset.get(), dims), place,
          "cannot remove rows written after the checkpoint");
    table.rows = keep;
    s.series.emplace(name, std::move(table));
  }

  s.flushFile();
  s.reformatAllFrames();
  s.rewriteXdmf();
  return FrameWriter(std::move(impl));
}

void FrameWriter::writeStatic(const std::string& group, const sim::FieldRegistry& fields) {
  Impl& s = *impl_;
  hdf5::silenceErrorPrinting();
  requireValidName("group", group, s.root);
  if (s.findStatic(group))
    throw IoError(s.root.file, "/static/" + group, "static data was written already",
                  "write each group's static data once per run");
  Handle statics = hdf5::openGroup(s.file.get(), "static", s.root);
  Handle handle = hdf5::openOrCreateGroup(statics.get(), group, s.root.at("static"));
  Impl::GroupRecord record{group, s.writeFields(handle.get(), "/static/" + group, fields, nullptr)};
  handle.close();
  statics.close();
  s.recordUnits(group, fields);
  s.flushFile();
  s.boundCache();
  s.statics.push_back(std::move(record));
  s.reformatAllFrames();
  s.rewriteXdmf();
}

std::size_t FrameWriter::writeFrame(double time, std::int64_t step,
                                    const std::vector<RegistryGroup>& groups) {
  Impl& s = *impl_;
  hdf5::silenceErrorPrinting();
  const std::size_t index = s.frames.size();
  const std::string name = frameGroupName(index);
  const std::string framePath = "/frames/" + name;
  if (!std::isfinite(time))
    throw IoError(s.root.file, framePath, "frame time is not finite",
                  "the simulation diverged; check the time step bounds");
  std::set<std::string> seen;
  for (const auto& g : groups) {
    requireValidName("group", g.name, s.root);
    if (!g.fields)
      throw IoError(s.root.file, framePath, "group '" + g.name + "' has no field registry",
                    "pass &particles.fields");
    if (!seen.insert(g.name).second)
      throw IoError(s.root.file, framePath, "group '" + g.name + "' given twice",
                    "give each particle group once per frame");
  }

  Handle frames = hdf5::openGroup(s.file.get(), "frames", s.root);
  Impl::FrameRecord record;
  record.info = FrameInfo{index, time, step, {}};
  try {
    Handle frame =
        checked(H5Gcreate2(frames.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                s.root.at("frames/" + name), "cannot create frame group");
    const Place framePlace{s.root.file, framePath};
    for (const auto& g : groups) {
      Handle group = hdf5::openOrCreateGroup(frame.get(), g.name, framePlace);
      const std::string groupPath = framePath + "/" + g.name;
      record.groups.push_back({g.name, s.writeFields(group.get(), groupPath, *g.fields,
                                                     s.findStatic(g.name), &g.only)});
      record.info.groups.push_back(g.name);
    }
    hdf5::writeAttribute(frame.get(), "time", time, framePlace);
    hdf5::writeAttribute(frame.get(), "step", static_cast<std::int64_t>(step), framePlace);
    // Written last: a reader takes a frame without it as one a killed run left unfinished.
    hdf5::writeAttribute(frame.get(), "complete", std::int64_t{1}, framePlace);
  } catch (...) {
    // Leave no half-written frame behind, so the next writeFrame can reuse the index.
    H5Ldelete(frames.get(), name.c_str(), H5P_DEFAULT);
    H5Eclear2(H5E_DEFAULT);
    throw;
  }
  for (const auto& g : groups) s.recordUnits(g.name, *g.fields);
  frames.close();
  s.flushFile();
  s.boundCache();

  s.frameTexts.push_back(formatXdmfFrame(s.composeXdmf(record), s.h5FileName));
  s.frames.push_back(record.info);
  s.records.push_back(std::move(record));
  s.rewriteXdmf();
  return index;
}

void FrameWriter::appendSeries(const std::string& name, double time,
                               const std::vector<double>& values,
                               const std::vector<std::string>& columnNames,
                               const std::vector<std::string>& columnUnits) {
  Impl& s = *impl_;
  hdf5::silenceErrorPrinting();
  requireValidName("series", name, s.root);
  const Place place = s.root.at("series/" + name);
  if (values.size() != columnNames.size())
    throw IoError(place.file, place.object,
                  std::to_string(values.size()) + " values for " +
                      std::to_string(columnNames.size()) + " column names",
                  "give one name per value");
  if (!columnUnits.empty() && columnUnits.size() != columnNames.size())
    throw IoError(place.file, place.object, "column units do not match the column names",
                  "give one unit per column, or none");
  std::vector<std::string> columns{layout::kTimeColumn};
  columns.insert(columns.end(), columnNames.begin(), columnNames.end());
  const hsize_t width = columns.size();

  Handle group = hdf5::openGroup(s.file.get(), "series", s.root);
  Handle dataset;
  auto it = s.series.find(name);
  if (it == s.series.end()) {
    const hsize_t dims[2] = {0, width};
    const hsize_t maxDims[2] = {H5S_UNLIMITED, width};
    // 64 rows per chunk: a coverage table of a few dozen columns is a few KiB per chunk.
    const hsize_t chunk[2] = {64, width};
    Handle space = checked(H5Screate_simple(2, dims, maxDims), place, "cannot create dataspace");
    Handle creation = checked(H5Pcreate(H5P_DATASET_CREATE), place, "cannot create properties");
    check(H5Pset_chunk(creation.get(), 2, chunk), place, "cannot set chunking");
    Impl::Series series;
    dataset = checked(H5Dcreate2(group.get(), name.c_str(), H5T_IEEE_F64LE, space.get(),
                                 H5P_DEFAULT, creation.get(), H5P_DEFAULT),
                      place, "cannot create the series table");
    std::vector<std::string> units{"s"};
    if (columnUnits.empty())
      units.resize(width, "");
    else
      units.insert(units.end(), columnUnits.begin(), columnUnits.end());
    hdf5::writeAttribute(dataset.get(), "columns", columns, place);
    hdf5::writeAttribute(dataset.get(), "units", units, place);
    series.columns = columns;
    it = s.series.emplace(name, std::move(series)).first;
  } else if (it->second.columns != columns) {
    throw IoError(place.file, place.object, "columns differ from the table's first row",
                  "append rows with the same column names every time");
  } else {
    dataset = checked(H5Dopen2(group.get(), name.c_str(), H5P_DEFAULT), place,
                      "cannot open the series table");
  }
  Impl::Series& series = it->second;
  const hsize_t newDims[2] = {series.rows + 1, width};
  check(H5Dset_extent(dataset.get(), newDims), place, "cannot extend the table");
  Handle fileSpace = checked(H5Dget_space(dataset.get()), place, "cannot select row");
  const hsize_t start[2] = {series.rows, 0};
  const hsize_t count[2] = {1, width};
  check(H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start, nullptr, count, nullptr), place,
        "cannot select row");
  Handle memorySpace = checked(H5Screate_simple(2, count, nullptr), place, "cannot select row");
  std::vector<double> row{time};
  row.insert(row.end(), values.begin(), values.end());
  check(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, memorySpace.get(), fileSpace.get(), H5P_DEFAULT,
                 row.data()),
        place, "cannot write row", "check free disk space");
  series.rows += 1;
  dataset.close();
  group.close();
  s.flushFile();
  s.boundCache();
}

void FrameWriter::flush() {
  hdf5::silenceErrorPrinting();
  impl_->flushFile();
}

void FrameWriter::close() {
  hdf5::silenceErrorPrinting();
  Impl& s = *impl_;
  s.series.clear();
  check(s.file.close(), s.root, "cannot close the frames file", "check free disk space");
}

const std::filesystem::path& FrameWriter::h5Path() const { return impl_->h5Path; }
const std::filesystem::path& FrameWriter::xdmfPath() const { return impl_->xdmfPath; }
const std::vector<FrameInfo>& FrameWriter::frames() const { return impl_->frames; }

}  // namespace protocols
