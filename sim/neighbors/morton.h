// Morton (Z-order) code of 3D cell coordinates: interleaves the bits of x, y, z (21 bits each).
#pragma once

#include <cstdint>

namespace sim {

inline std::uint64_t spreadBits21(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

inline std::uint64_t mortonCode(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return spreadBits21(x) | (spreadBits21(y) << 1) | (spreadBits21(z) << 2);
}

}  // namespace sim
