// One particle field as read back from a frame or /static: a rows x components table of float64
// or int32 values, with its name and SI unit. Row-major: value(i, c) = data[i * components + c].
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <utility>  // before field_registry.h, which uses std::as_const without it

#include "sim/core/field_registry.h"

namespace protocols {

struct FieldData {
  std::string name;
  std::string unit;  // SI unit as registered in sim::FieldInfo ("1" for dimensionless)
  sim::ScalarKind kind = sim::ScalarKind::kReal;
  std::size_t rows = 0;       // particles
  int components = 1;         // 1 scalar, 3 Vec3, 9 Mat3 (column-major, as Eigen stores it)
  std::vector<double> reals;  // rows * components when kind == kReal (float32 files
                              // are widened exactly)
  std::vector<std::int32_t> integers;  // rows * components when kind == kInt32

  double real(std::size_t i, int c = 0) const { return reals[i * components + c]; }
  std::int32_t integer(std::size_t i, int c = 0) const { return integers[i * components + c]; }
};

}  // namespace protocols
