// Shared fixtures of the io tests: particle sets filled with awkward doubles
// (so "bit-identical" means something), bitwise comparison, and a small strict XML checker.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "protocols/io/field_data.h"
#include "sim/core/particle_set.h"

namespace iotest {

// Fills `particles` with n particles whose values depend on (seed, i): random bit patterns over
// the full double range plus signed zeros, subnormals and extremes. Registers the extra fields
// "stress" (Mat3, Pa, checkpointed + written), "oil_fraction" (double, written only) and
// "scratch" (double, neither) if absent, to check that output iterates the registry.
void fillFluid(sim::DynamicParticles& particles, std::size_t n, std::uint64_t seed);
void fillWall(sim::WallParticles& walls, std::size_t n, std::uint64_t seed);

// True when `data` holds exactly the bits of registry field `field`.
bool sameBits(const protocols::FieldData& data, const sim::FieldBase& field);
// True when two registries hold bitwise equal values in every field.
bool sameBits(const sim::FieldRegistry& a, const sim::FieldRegistry& b);

// A minimal well-formedness check of XML 1.0 as written by the toolkit: one root element,
// matching start/end tags, quoted and unique attributes, only predefined or numeric entities,
// no '<' in text. Returns "" if well-formed, else the first problem with its byte offset.
struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;  // entity-decoded
  std::string text;                               // entity-decoded, trimmed
  std::vector<std::string> path;                  // names of the ancestors, root first
};
std::string checkXml(const std::string& text, std::vector<XmlElement>* elements);

std::string readFile(const std::filesystem::path& path);

// Shape and class of dataset `path` in the open HDF5 file `file`; rows = -1 if it does not exist.
struct DatasetCheck {
  long long rows = -1;
  long long columns = -1;
  bool isInteger = false;
  std::size_t bytes = 0;
};
DatasetCheck inspectDataset(std::int64_t file, const std::string& path);

}  // namespace iotest
