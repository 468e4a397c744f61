// Internal helpers of protocols/io over the HDF5 C API: an owning handle, checked calls that turn
// failures into IoError (naming file, object and HDF5's own reason), attributes and 2-D datasets.
// Only protocols/io .cpp files include this; public headers stay free of <hdf5.h>.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "protocols/io/io_error.h"

namespace protocols::hdf5 {

// Where an HDF5 call acts: the file on disk and the object path inside it.
struct Place {
  std::string file;
  std::string object;
  Place at(const std::string& child) const {
    return {file, object.empty() || object == "/" ? "/" + child : object + "/" + child};
  }
};

// Turns off HDF5's printing of error stacks to stderr (for the calling thread; the Debian build is
// thread-safe, where the setting is per thread). Our IoError carries the reason instead.
void silenceErrorPrinting();

// The current thread's HDF5 error stack in one line (outermost call, then the innermost cause),
// and clears the stack. Empty if the stack is empty.
std::string takeErrorStack();

[[noreturn]] void fail(const Place& place, const std::string& what, const std::string& fix);

// Owns one HDF5 identifier of any kind and closes it with the matching H5?close.
class Handle {
 public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  ~Handle() { close(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      close();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now and reports failure (a file close flushes, so it can fail); the destructor
  // closes silently.
  herr_t close();

 private:
  hid_t id_ = H5I_INVALID_HID;
};

// Wraps an id-returning call: throws IoError(place, what) if `id` < 0.
Handle checked(hid_t id, const Place& place, const std::string& what, const std::string& fix = "");
// Throws IoError(place, what) if `status` < 0.
void check(herr_t status, const Place& place, const std::string& what, const std::string& fix = "");

bool hasLink(hid_t parent, const std::string& name, const Place& place);
bool hasAttribute(hid_t object, const std::string& name, const Place& place);

// Scalar attributes: float64, int64, fixed-length UTF-8 string, and a 1-D array of strings.
void writeAttribute(hid_t object, const std::string& name, double value, const Place& place);
void writeAttribute(hid_t object, const std::string& name, std::int64_t value, const Place& place);
void writeAttribute(hid_t object, const std::string& name, const std::string& value,
                    const Place& place);
void writeAttribute(hid_t object, const std::string& name, const std::vector<std::string>& values,
                    const Place& place);
double readDoubleAttribute(hid_t object, const std::string& name, const Place& place);
std::int64_t readInt64Attribute(hid_t object, const std::string& name, const Place& place);
std::string readStringAttribute(hid_t object, const std::string& name, const Place& place);
std::vector<std::string> readStringArrayAttribute(hid_t object, const std::string& name,
                                                  const Place& place);
// Names of all attributes of `object`, in creation order when tracked, else by name.
std::vector<std::string> attributeNames(hid_t object, const Place& place);
// Names of all links in group `group`, sorted by name.
std::vector<std::string> linkNames(hid_t group, const Place& place);

Handle openGroup(hid_t parent, const std::string& name, const Place& place);
// Opens the group if it exists, else creates it.
Handle openOrCreateGroup(hid_t parent, const std::string& name, const Place& place);

// Shape of a rank-1 or rank-2 dataset as (rows, columns); rank 1 gives columns = 1.
std::pair<hsize_t, hsize_t> datasetShape(hid_t dataset, const Place& place);

// Writes a string as a scalar fixed-length string dataset (for texts too long for an attribute,
// such as the protocol file).
void writeStringDataset(hid_t parent, const std::string& name, const std::string& value,
                        const Place& place);
std::string readStringDataset(hid_t parent, const std::string& name, const Place& place);

// Makes `path` durable: fsync of the file (and, for a rename, of its directory).
void fsyncPath(const std::string& path, bool isDirectory);

}  // namespace protocols::hdf5
