#include "io_test_support.h"

#include <hdf5.h>

#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

namespace iotest {

namespace {

// A double from 64 random bits, excluding NaN (NaN != NaN would make Eigen-based checks in
// other code awkward; bit identity is tested with memcmp anyway) plus fixed special values.
double awkwardDouble(std::mt19937_64& random, std::size_t i) {
  switch (i % 11) {
    case 0: return -0.0;
    case 1: return 4.9406564584124654e-324;  // smallest subnormal
    case 2: return 1.7976931348623157e308;   // largest finite
    case 3: return 0.1 + 0.2;                // not representable exactly in decimal
    default: break;
  }
  for (;;) {
    std::uint64_t bits = random();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    if (value == value) return value;
  }
}

}  // namespace

void fillFluid(sim::DynamicParticles& particles, std::size_t n, std::uint64_t seed) {
  auto& fields = particles.fields;
  fields.addOrGet<sim::Mat3>({"stress", "Pa", true, true});
  fields.addOrGet<sim::Real>({"oil_fraction", "1", false, true});
  fields.addOrGet<sim::Real>({"scratch", "1", false, false});
  std::mt19937_64 random(seed);
  if (particles.size() != n) {
    fields.resize(0);
    for (std::size_t i = 0; i < n; ++i) particles.add(sim::Vec3::Zero(), sim::Vec3::Zero(), 0, 0);
  }
  for (const auto& field : fields) {
    if (field->kind() == sim::ScalarKind::kReal) {
      auto* values = static_cast<double*>(field->rawData());
      const std::size_t count = field->size() * static_cast<std::size_t>(field->components());
      for (std::size_t k = 0; k < count; ++k) values[k] = awkwardDouble(random, k);
    } else {
      auto* values = static_cast<std::int32_t*>(field->rawData());
      for (std::size_t k = 0; k < field->size(); ++k)
        values[k] = static_cast<std::int32_t>(random());
    }
  }
}

void fillWall(sim::WallParticles& walls, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> coordinate(-0.012, 0.012);  // [m] an eye-sized box
  walls.fields.resize(0);
  for (std::size_t i = 0; i < n; ++i) {
    const sim::Vec3 x(coordinate(random), coordinate(random), coordinate(random));
    walls.add(x, x.normalized(), static_cast<int>(i % 5));
    walls.volume[i] = 1e-12 * (1.0 + static_cast<double>(i % 7));
  }
}

bool sameBits(const protocols::FieldData& data, const sim::FieldBase& field) {
  if (data.kind != field.kind() || data.components != field.components() ||
      data.rows != field.size())
    return false;
  const std::size_t count = data.rows * static_cast<std::size_t>(data.components);
  if (data.kind == sim::ScalarKind::kReal)
    return data.reals.size() == count &&
           std::memcmp(data.reals.data(), field.rawData(), count * sizeof(double)) == 0;
  return data.integers.size() == count &&
         std::memcmp(data.integers.data(), field.rawData(), count * sizeof(std::int32_t)) == 0;
}

bool sameBits(const sim::FieldRegistry& a, const sim::FieldRegistry& b) {
  if (a.size() != b.size() || a.fieldCount() != b.fieldCount()) return false;
  for (const auto& field : a) {
    const sim::FieldBase* other = b.find(field->info().name);
    if (!other || other->kind() != field->kind() || other->components() != field->components())
      return false;
    const std::size_t bytes = field->size() * static_cast<std::size_t>(field->components()) *
                              (field->kind() == sim::ScalarKind::kReal ? 8 : 4);
    if (std::memcmp(field->rawData(), other->rawData(), bytes) != 0) return false;
  }
  return true;
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

namespace {

bool isNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
         c == ':';
}

// Decodes entities; returns false on an unknown or unterminated one.
bool decode(const std::string& raw, std::string& out) {
  out.clear();
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '<') return false;
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    const std::size_t end = raw.find(';', i);
    if (end == std::string::npos) return false;
    const std::string entity = raw.substr(i + 1, end - i - 1);
    if (entity == "amp")
      out += '&';
    else if (entity == "lt")
      out += '<';
    else if (entity == "gt")
      out += '>';
    else if (entity == "quot")
      out += '"';
    else if (entity == "apos")
      out += '\'';
    else if (entity.size() > 1 && entity[0] == '#')
      out += static_cast<char>(std::stoi(entity.substr(1)));
    else
      return false;
    i = end;
  }
  return true;
}

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r\n") - begin + 1);
}

}  // namespace

std::string checkXml(const std::string& text, std::vector<XmlElement>* elements) {
  std::vector<std::size_t> open;  // indices into `all` of the open elements
  std::vector<XmlElement> all;
  bool rootSeen = false;
  std::size_t i = 0;
  auto problem = [&](const std::string& what) { return what + " at byte " + std::to_string(i); };
  std::string pendingText;
  while (i < text.size()) {
    if (text[i] != '<') {
      pendingText += text[i++];
      continue;
    }
    // Text between tags: must decode, and outside the root only whitespace is allowed.
    std::string decoded;
    if (!decode(pendingText, decoded)) return problem("bad text or entity");
    if (open.empty() && !trim(decoded).empty()) return problem("text outside the root");
    if (!open.empty()) all[open.back()].text += decoded;
    pendingText.clear();

    if (text.compare(i, 5, "<?xml") == 0) {
      if (i != 0) return problem("XML declaration not at the start");
      const std::size_t end = text.find("?>", i);
      if (end == std::string::npos) return problem("unterminated XML declaration");
      i = end + 2;
      continue;
    }
    if (text.compare(i, 4, "<!--") == 0) {
      const std::size_t end = text.find("-->", i);
      if (end == std::string::npos) return problem("unterminated comment");
      i = end + 3;
      continue;
    }
    const bool closing = i + 1 < text.size() && text[i + 1] == '/';
    std::size_t j = i + (closing ? 2 : 1);
    std::string name;
    while (j < text.size() && isNameChar(text[j])) name += text[j++];
    if (name.empty()) return problem("tag without a name");
    if (closing) {
      while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j >= text.size() || text[j] != '>') return problem("malformed end tag");
      if (open.empty() || all[open.back()].name != name)
        return problem("end tag </" + name + "> does not match");
      all[open.back()].text = trim(all[open.back()].text);
      open.pop_back();
      i = j + 1;
      continue;
    }
    if (open.empty() && rootSeen) return problem("second root element");
    XmlElement element;
    element.name = name;
    for (std::size_t k : open) element.path.push_back(all[k].name);
    bool selfClosing = false;
    for (;;) {
      const std::size_t before = j;
      while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j >= text.size()) return problem("unterminated tag <" + name + ">");
      if (text[j] == '>') {
        ++j;
        break;
      }
      if (text.compare(j, 2, "/>") == 0) {
        selfClosing = true;
        j += 2;
        break;
      }
      if (j == before) return problem("attributes must be separated by whitespace");
      std::string key;
      while (j < text.size() && isNameChar(text[j])) key += text[j++];
      if (key.empty() || j >= text.size() || text[j] != '=') return problem("malformed attribute");
      ++j;
      if (j >= text.size() || (text[j] != '"' && text[j] != '\''))
        return problem("unquoted attribute " + key);
      const char quote = text[j++];
      const std::size_t end = text.find(quote, j);
      if (end == std::string::npos) return problem("unterminated attribute " + key);
      std::string value;
      if (!decode(text.substr(j, end - j), value)) return problem("bad entity in " + key);
      if (!element.attributes.emplace(key, value).second)
        return problem("duplicate attribute " + key);
      j = end + 1;
    }
    rootSeen = true;
    all.push_back(std::move(element));
    if (!selfClosing) open.push_back(all.size() - 1);
    i = j;
  }
  if (!trim(pendingText).empty()) return problem("text after the root");
  if (!open.empty()) return problem("element <" + all[open.back()].name + "> never closed");
  if (!rootSeen) return problem("no root element");
  if (elements) *elements = std::move(all);
  return "";
}

DatasetCheck inspectDataset(std::int64_t file, const std::string& path) {
  DatasetCheck result;
  H5E_BEGIN_TRY {
    if (H5Oexists_by_name(file, path.c_str(), H5P_DEFAULT) <= 0) return result;
  }
  H5E_END_TRY;
  hid_t dataset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  hid_t space = H5Dget_space(dataset);
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  hid_t type = H5Dget_type(dataset);
  result.rows = static_cast<long long>(dims[0]);
  result.columns = static_cast<long long>(dims[1]);
  result.isInteger = H5Tget_class(type) == H5T_INTEGER;
  result.bytes = H5Tget_size(type);
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(dataset);
  return result;
}

}  // namespace iotest
