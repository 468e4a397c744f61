#include "protocols/io/hdf5_support.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace protocols::hdf5 {

void silenceErrorPrinting() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

namespace {

struct StackEntry {
  std::string description;
  std::string minor;
};

herr_t collectEntry(unsigned, const H5E_error2_t* error, void* data) {
  auto* entries = static_cast<std::vector<StackEntry>*>(data);
  StackEntry entry;
  if (error->desc) entry.description = error->desc;
  char minor[256] = {0};
  if (H5Eget_msg(error->min_num, nullptr, minor, sizeof minor) > 0) entry.minor = minor;
  entries->push_back(std::move(entry));
  return 0;
}

}  // namespace

std::string takeErrorStack() {
  std::vector<StackEntry> entries;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collectEntry, &entries);
  H5Eclear2(H5E_DEFAULT);
  if (entries.empty()) return "";
  // Downward walk: first entry is the API call, last is the innermost cause.
  const StackEntry& outer = entries.front();
  const StackEntry& inner = entries.back();
  std::string text = "HDF5: " + outer.description;
  if (entries.size() > 1) text += "; cause: " + inner.description;
  if (!inner.minor.empty()) text += " (" + inner.minor + ")";
  return text;
}

void fail(const Place& place, const std::string& what, const std::string& fix) {
  const std::string stack = takeErrorStack();
  throw IoError(place.file, place.object, stack.empty() ? what : what + " [" + stack + "]", fix);
}

herr_t Handle::close() {
  if (id_ < 0) return 0;
  herr_t status = -1;
  switch (H5Iget_type(id_)) {
    case H5I_FILE: status = H5Fclose(id_); break;
    case H5I_GROUP: status = H5Gclose(id_); break;
    case H5I_DATASET: status = H5Dclose(id_); break;
    case H5I_DATASPACE: status = H5Sclose(id_); break;
    case H5I_DATATYPE: status = H5Tclose(id_); break;
    case H5I_ATTR: status = H5Aclose(id_); break;
    case H5I_GENPROP_LST: status = H5Pclose(id_); break;
    default: status = H5Idec_ref(id_) < 0 ? -1 : 0; break;
  }
  id_ = H5I_INVALID_HID;
  return status;
}

Handle checked(hid_t id, const Place& place, const std::string& what, const std::string& fix) {
  if (id < 0) fail(place, what, fix);
  return Handle(id);
}

void check(herr_t status, const Place& place, const std::string& what, const std::string& fix) {
  if (status < 0) fail(place, what, fix);
}

bool hasLink(hid_t parent, const std::string& name, const Place& place) {
  const htri_t exists = H5Lexists(parent, name.c_str(), H5P_DEFAULT);
  if (exists < 0) fail(place.at(name), "cannot check whether this object exists", "");
  return exists > 0;
}

bool hasAttribute(hid_t object, const std::string& name, const Place& place) {
  const htri_t exists = H5Aexists(object, name.c_str());
  if (exists < 0) fail(place, "cannot check for attribute '" + name + "'", "");
  return exists > 0;
}

namespace {

Handle fixedStringType(std::size_t length, const Place& place) {
  Handle type = checked(H5Tcopy(H5T_C_S1), place, "cannot create a string type");
  // Size includes the terminating NUL (H5T_STR_NULLTERM); at least 1 so "" is representable.
  check(H5Tset_size(type.get(), std::max<std::size_t>(length + 1, 1)), place,
        "cannot size a string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), place, "cannot set string padding");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), place, "cannot set string character set");
  return type;
}

// Replaces an existing attribute so that writers can update metadata without a special case.
Handle createAttribute(hid_t object, const std::string& name, hid_t type, hid_t space,
                       const Place& place) {
  if (hasAttribute(object, name, place))
    check(H5Adelete(object, name.c_str()), place, "cannot replace attribute '" + name + "'");
  return checked(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), place,
                 "cannot create attribute '" + name + "'");
}

template <class T>
void writeScalarAttribute(hid_t object, const std::string& name, hid_t fileType, hid_t memType,
                          const T& value, const Place& place) {
  Handle space = checked(H5Screate(H5S_SCALAR), place, "cannot create a scalar dataspace");
  Handle attribute = createAttribute(object, name, fileType, space.get(), place);
  check(H5Awrite(attribute.get(), memType, &value), place, "cannot write attribute '" + name + "'");
}

Handle openAttribute(hid_t object, const std::string& name, const Place& place) {
  if (!hasAttribute(object, name, place))
    throw IoError(place.file, place.object, "attribute '" + name + "' is missing",
                  "the file was not written by this toolkit or is damaged");
  return checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), place,
                 "cannot open attribute '" + name + "'");
}

template <class T>
T readScalarAttribute(hid_t object, const std::string& name, hid_t memType, const Place& place) {
  Handle attribute = openAttribute(object, name, place);
  Handle space = checked(H5Aget_space(attribute.get()), place, "cannot read attribute shape");
  if (H5Sget_simple_extent_npoints(space.get()) != 1)
    throw IoError(place.file, place.object, "attribute '" + name + "' is not a single value",
                  "the file was not written by this toolkit");
  T value{};
  check(H5Aread(attribute.get(), memType, &value), place,
        "cannot read attribute '" + name + "' as a number");
  return value;
}

// Reads `count` strings of the (fixed or variable length) string type `fileType` from an
// attribute or dataset through `read(memType, buffer)`.
template <class ReadFn>
std::vector<std::string> readStrings(hid_t fileType, std::size_t count, const Place& place,
                                     ReadFn read) {
  if (H5Tget_class(fileType) != H5T_STRING)
    throw IoError(place.file, place.object, "expected text, found another type",
                  "the file was not written by this toolkit");
  std::vector<std::string> values(count);
  if (H5Tis_variable_str(fileType) > 0) {
    Handle memType = checked(H5Tcopy(H5T_C_S1), place, "cannot create a string type");
    check(H5Tset_size(memType.get(), H5T_VARIABLE), place, "cannot size a string type");
    // HDF5 converts strings only between equal character sets.
    check(H5Tset_cset(memType.get(), H5Tget_cset(fileType)), place, "cannot set character set");
    std::vector<char*> pointers(count, nullptr);
    check(read(memType.get(), pointers.data()), place, "cannot read text");
    for (std::size_t k = 0; k < count; ++k) {
      if (pointers[k]) values[k] = pointers[k];
      H5free_memory(pointers[k]);
    }
    return values;
  }
  const std::size_t size = H5Tget_size(fileType);
  Handle memType = checked(H5Tcopy(H5T_C_S1), place, "cannot create a string type");
  check(H5Tset_size(memType.get(), size), place, "cannot size a string type");
  check(H5Tset_strpad(memType.get(), H5T_STR_NULLTERM), place, "cannot set string padding");
  check(H5Tset_cset(memType.get(), H5Tget_cset(fileType)), place, "cannot set character set");
  std::vector<char> buffer(size * count + 1, '\0');
  check(read(memType.get(), buffer.data()), place, "cannot read text");
  for (std::size_t k = 0; k < count; ++k) {
    const char* begin = buffer.data() + k * size;
    values[k].assign(begin, strnlen(begin, size));
  }
  return values;
}

}  // namespace

void writeAttribute(hid_t object, const std::string& name, double value, const Place& place) {
  writeScalarAttribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, value, place);
}

void writeAttribute(hid_t object, const std::string& name, std::int64_t value, const Place& place) {
  writeScalarAttribute(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, value, place);
}

void writeAttribute(hid_t object, const std::string& name, const std::string& value,
                    const Place& place) {
  Handle type = fixedStringType(value.size(), place);
  Handle space = checked(H5Screate(H5S_SCALAR), place, "cannot create a scalar dataspace");
  Handle attribute = createAttribute(object, name, type.get(), space.get(), place);
  std::vector<char> buffer(value.begin(), value.end());
  buffer.push_back('\0');
  check(H5Awrite(attribute.get(), type.get(), buffer.data()), place,
        "cannot write attribute '" + name + "'");
}

void writeAttribute(hid_t object, const std::string& name, const std::vector<std::string>& values,
                    const Place& place) {
  std::size_t longest = 0;
  for (const auto& v : values) longest = std::max(longest, v.size());
  Handle type = fixedStringType(longest, place);
  const hsize_t count = values.size();
  Handle space = checked(H5Screate_simple(1, &count, nullptr), place, "cannot create dataspace");
  Handle attribute = createAttribute(object, name, type.get(), space.get(), place);
  std::vector<char> buffer((longest + 1) * values.size(), '\0');
  for (std::size_t k = 0; k < values.size(); ++k)
    std::memcpy(buffer.data() + k * (longest + 1), values[k].data(), values[k].size());
  if (!values.empty())
    check(H5Awrite(attribute.get(), type.get(), buffer.data()), place,
          "cannot write attribute '" + name + "'");
}

double readDoubleAttribute(hid_t object, const std::string& name, const Place& place) {
  return readScalarAttribute<double>(object, name, H5T_NATIVE_DOUBLE, place);
}

std::int64_t readInt64Attribute(hid_t object, const std::string& name, const Place& place) {
  return readScalarAttribute<std::int64_t>(object, name, H5T_NATIVE_INT64, place);
}

std::string readStringAttribute(hid_t object, const std::string& name, const Place& place) {
  auto values = readStringArrayAttribute(object, name, place);
  if (values.size() != 1)
    throw IoError(place.file, place.object, "attribute '" + name + "' is not a single text",
                  "the file was not written by this toolkit");
  return values.front();
}

std::vector<std::string> readStringArrayAttribute(hid_t object, const std::string& name,
                                                  const Place& place) {
  Handle attribute = openAttribute(object, name, place);
  Handle type = checked(H5Aget_type(attribute.get()), place, "cannot read attribute type");
  Handle space = checked(H5Aget_space(attribute.get()), place, "cannot read attribute shape");
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) fail(place, "cannot read the size of attribute '" + name + "'", "");
  if (count == 0) return {};
  return readStrings(
      type.get(), static_cast<std::size_t>(count), place,
      [&](hid_t memType, void* buffer) { return H5Aread(attribute.get(), memType, buffer); });
}

namespace {

herr_t collectName(hid_t, const char* name, const H5A_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

herr_t collectLink(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

}  // namespace

std::vector<std::string> attributeNames(hid_t object, const Place& place) {
  std::vector<std::string> names;
  hsize_t position = 0;
  check(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &position, collectName, &names), place,
        "cannot list attributes");
  return names;
}

std::vector<std::string> linkNames(hid_t group, const Place& place) {
  std::vector<std::string> names;
  hsize_t position = 0;
  check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &position, collectLink, &names), place,
        "cannot list the members of this group");
  return names;
}

Handle openGroup(hid_t parent, const std::string& name, const Place& place) {
  if (!hasLink(parent, name, place))
    throw IoError(place.file, place.at(name).object, "group is missing",
                  "the file was not written by this toolkit, or the run stopped before it was "
                  "written");
  return checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), place.at(name), "cannot open group");
}

Handle openOrCreateGroup(hid_t parent, const std::string& name, const Place& place) {
  if (hasLink(parent, name, place))
    return checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), place.at(name),
                   "cannot open group");
  return checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 place.at(name), "cannot create group");
}

std::pair<hsize_t, hsize_t> datasetShape(hid_t dataset, const Place& place) {
  Handle space = checked(H5Dget_space(dataset), place, "cannot read dataset shape");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1 || rank > 2)
    throw IoError(place.file, place.object,
                  "dataset has rank " + std::to_string(rank) + ", expected 1 or 2",
                  "the file was not written by this toolkit");
  hsize_t dims[2] = {0, 1};
  check(H5Sget_simple_extent_dims(space.get(), dims, nullptr), place, "cannot read dataset shape");
  return {dims[0], rank == 2 ? dims[1] : 1};
}

void writeStringDataset(hid_t parent, const std::string& name, const std::string& value,
                        const Place& place) {
  const Place here = place.at(name);
  Handle type = fixedStringType(value.size(), here);
  Handle space = checked(H5Screate(H5S_SCALAR), here, "cannot create a scalar dataspace");
  Handle dataset = checked(H5Dcreate2(parent, name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                                      H5P_DEFAULT, H5P_DEFAULT),
                           here, "cannot create dataset");
  std::vector<char> buffer(value.begin(), value.end());
  buffer.push_back('\0');
  check(H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()), here,
        "cannot write dataset");
}

std::string readStringDataset(hid_t parent, const std::string& name, const Place& place) {
  const Place here = place.at(name);
  if (!hasLink(parent, name, place))
    throw IoError(here.file, here.object, "dataset is missing",
                  "the file was not written by this toolkit");
  Handle dataset =
      checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), here, "cannot open dataset");
  Handle type = checked(H5Dget_type(dataset.get()), here, "cannot read dataset type");
  auto values = readStrings(type.get(), 1, here, [&](hid_t memType, void* buffer) {
    return H5Dread(dataset.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer);
  });
  return values.front();
}

void fsyncPath(const std::string& path, bool isDirectory) {
  const int fd = ::open(path.c_str(), (isDirectory ? O_DIRECTORY : 0) | O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw IoError(path, "", std::string("cannot open to sync: ") + std::strerror(errno),
                  "check that the folder exists and is writable");
  const int status = ::fsync(fd);
  const int savedErrno = errno;
  ::close(fd);
  if (status != 0)
    throw IoError(path, "", std::string("fsync failed: ") + std::strerror(savedErrno),
                  "check free disk space and the file system");
}

}  // namespace protocols::hdf5
