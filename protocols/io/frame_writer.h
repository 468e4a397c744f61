// FrameWriter: one HDF5 file per run (frames.h5) with the run's metadata, particle frames, static
// data and time-series tables, plus an XDMF sidecar (frames.xmf) for ParaView.
//
// Layout (every dataset rows x components, attributes `unit` and `element`):
//   /                      attributes format = "tamponade-frames", format_version
//   /metadata              attributes toolkit_version, hdf5_version, created_utc;
//                          dataset protocol (the protocol text verbatim)
//   /metadata/run          the caller's key/value strings and numbers as attributes
//   /metadata/units/<g>    one attribute per field of group g: its SI unit
//   /static/<g>/<field>    written once (wall positions, normals, ...)
//   /frames/NNNNNN         attributes time [s], step, complete; one subgroup per particle group
//   /frames/NNNNNN/<g>/<field>
//   /series/<name>         T x (1 + K) float64, column 0 = time [s]; attributes columns, units
//
// Output iterates the field registry: every field whose `written` flag is set goes into a frame,
// so a field added by a new effect is written without touching this code.
//
// Crash safety (docs/developer-guide.md principle 6): every writeFrame/appendSeries/writeStatic
// ends with H5Fflush, and the metadata cache is told never to evict (write) entries between
// flushes, so the file on disk only changes metadata at a flush; a run killed between flushes
// leaves the file of the last flush plus unreferenced bytes past its end. Series are uncompressed
// so that appending a row rewrites the last chunk in place instead of moving it (a moved chunk
// could reuse space the flushed file still points to).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <utility>  // before field_registry.h, which uses std::as_const without it

#include "sim/core/field_registry.h"

namespace protocols {

// What the run records about itself besides the frames.
struct RunMetadata {
  std::string protocolText;                    // the protocol file, verbatim
  std::map<std::string, std::string> strings;  // e.g. {"protocol_file", "eye.toml"}
  std::map<std::string, double> numbers;       // e.g. {"particle_spacing [m]", 2e-4}
};

enum class FramePrecision {
  // Default: bit-identical to the simulation state, so frames can be compared between runs
  // (resume == continuous), and `tamponade report` can recompute metrics from frames exactly.
  kFloat64,
  // Halves the file for long visualisation-only runs; positions keep ~7 digits (0.1 um at 1 m).
  kFloat32,
};

struct FrameWriterOptions {
  FramePrecision precision = FramePrecision::kFloat64;
  // gzip level for frame and static datasets (0 = uncompressed). Level 4 with shuffle: measured
  // in tests/io (see the README) to be near level 9's ratio at a fraction of its time.
  int gzipLevel = 4;
  bool overwrite = false;  // false: refuse to replace an existing file (nothing is lost)
};

// A particle group to write: a name ("fluid", "wall") and the registry holding its fields.
struct RegistryGroup {
  std::string name;
  const sim::FieldRegistry* fields = nullptr;
  // Fields to write (the protocol's outputs.fields), whatever their `written` flag; empty = every
  // field marked `written`. A name the registry does not hold is an IoError.
  std::vector<std::string> only = {};
};

// A frame as recorded in the file.
struct FrameInfo {
  std::size_t index = 0;  // NNNNNN in /frames/NNNNNN
  double time = 0;        // [s]
  std::int64_t step = 0;
  std::vector<std::string> groups;
};

class FrameWriter {
 public:
  // Creates `h5Path` (conventionally <run folder>/frames.h5) and its sidecar, the same path with
  // extension .xmf. Throws IoError if the file exists and !options.overwrite.
  FrameWriter(const std::filesystem::path& h5Path, const RunMetadata& metadata,
              FrameWriterOptions options = {});

  // Reopens the file of a stopped run to continue it from a checkpoint taken at `step`: frames
  // with a larger step and series rows later than `time` [s] are removed (they will be written
  // again by the resumed run), and the sidecar is rebuilt from the file.
  static FrameWriter resume(const std::filesystem::path& h5Path, std::int64_t step, double time,
                            FrameWriterOptions options = {});

  ~FrameWriter();
  FrameWriter(FrameWriter&&) noexcept;
  FrameWriter& operator=(FrameWriter&&) noexcept;

  // Writes every `written` field of `fields` once, under /static/<group>. Those fields are
  // declared constant for the run: later frames of the same group skip them and the sidecar
  // points every frame's grid at /static (docs/developer-guide.md principle 2: the wall never
  // moves).
  void writeStatic(const std::string& group, const sim::FieldRegistry& fields);

  // Writes one frame: every `written` field of each group (except its static ones), the time [s]
  // and step, flushes the file and rewrites the sidecar. Returns the frame's index.
  std::size_t writeFrame(double time, std::int64_t step, const std::vector<RegistryGroup>& groups);

  // Appends one row (time [s], values...) to table /series/<name>, creating it on first use.
  // `columnNames` (and `columnUnits`, if given) must be the same on every call. Flushes.
  void appendSeries(const std::string& name, double time, const std::vector<double>& values,
                    const std::vector<std::string>& columnNames,
                    const std::vector<std::string>& columnUnits = {});

  void flush();
  // Closes the file now, reporting errors (the destructor closes silently).
  void close();

  const std::filesystem::path& h5Path() const;
  const std::filesystem::path& xdmfPath() const;
  const std::vector<FrameInfo>& frames() const;

 private:
  struct Impl;
  explicit FrameWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace protocols
