// The one error type of protocols/io: every failed HDF5, XDMF or file-system call becomes an
// IoError that names the file, the object inside it (dataset, group, attribute) and how to fix it.
#pragma once

#include <stdexcept>
#include <string>

namespace protocols {

class IoError : public std::runtime_error {
 public:
  // `file`: the file on disk; `object`: the path inside it ("" for the file itself);
  // `what`: what went wrong (with HDF5's own reason where there is one); `fix`: what to do.
  IoError(std::string file, std::string object, const std::string& what, const std::string& fix)
      : std::runtime_error(compose(file, object, what, fix)),
        file_(std::move(file)),
        object_(std::move(object)) {}

  const std::string& file() const { return file_; }
  const std::string& object() const { return object_; }

 private:
  static std::string compose(const std::string& file, const std::string& object,
                             const std::string& what, const std::string& fix) {
    std::string message = file;
    if (!object.empty()) message += ":" + object;
    message += ": " + what;
    if (!fix.empty()) message += " — " + fix;
    return message;
  }

  std::string file_;
  std::string object_;
};

}  // namespace protocols
