// FrameReader: reads back what FrameWriter wrote (for the report, `tamponade report DIR`, and
// tests): the list of complete frames, any field of a frame or of /static, the series tables and
// the run's metadata. Opens the file read-only without HDF5's file lock, so a running (or killed)
// run's file can be read: it sees the state of the writer's last flush.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "protocols/io/field_data.h"
#include "protocols/io/frame_writer.h"

namespace protocols {

// One /series table: rows x columns, row-major; column 0 is "time" [s].
struct SeriesData {
  std::string name;
  std::vector<std::string> columns;
  std::vector<std::string> units;  // "" where the writer gave none
  std::size_t rows = 0;
  std::vector<double> values;
  // The values of one column, top to bottom; IoError if there is no such column.
  std::vector<double> column(const std::string& columnName) const;
};

struct RunInfo {
  std::string toolkitVersion;
  std::string hdf5Version;
  std::string createdUtc;  // ISO 8601
  std::string protocolText;
  std::map<std::string, std::string> strings;
  std::map<std::string, double> numbers;
  std::map<std::string, std::map<std::string, std::string>> units;  // group -> field -> unit
};

class FrameReader {
 public:
  // Throws IoError if the file is missing, not HDF5 or not a frames file of this toolkit.
  explicit FrameReader(const std::filesystem::path& h5Path);
  ~FrameReader();
  FrameReader(FrameReader&&) noexcept;
  FrameReader& operator=(FrameReader&&) noexcept;

  // Complete frames in index order. A frame a killed run left half-written is not listed; its
  // group name is in unreadableFrames().
  const std::vector<FrameInfo>& frames() const;
  const std::vector<std::string>& unreadableFrames() const;

  std::vector<std::string> fieldNames(std::size_t frameIndex, const std::string& group) const;
  FieldData readField(std::size_t frameIndex, const std::string& group,
                      const std::string& field) const;

  std::vector<std::string> staticGroups() const;
  std::vector<std::string> staticFieldNames(const std::string& group) const;
  FieldData readStaticField(const std::string& group, const std::string& field) const;

  std::vector<std::string> seriesNames() const;
  SeriesData readSeries(const std::string& name) const;

  RunInfo runInfo() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace protocols
