// Internal to meshing/: a small counter-based random stream (splitmix64, Steele et al. 2014) so
// that every face or lattice block gets its own reproducible stream, independent of the thread
// that processes it and of the standard library's distribution implementations.
#pragma once

#include <cstdint>

namespace meshing::detail {

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t stream)
      : state_(seed ^ (stream * 0x9E3779B97F4A7C15ull)) {
    next();
  }
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  std::uint64_t state_;
};

}  // namespace meshing::detail
