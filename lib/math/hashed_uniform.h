// Random numbers drawn from a key instead of a stream: the same value for the same (seed,
// key, stream) on any machine, rank count or order of evaluation, so per-atom and
// per-element choices do not depend on how a system is split across ranks.
#pragma once

#include <cstdint>

namespace nscd {

// A uniform number in [0, 1) from (seed, key, stream): splitmix64's finaliser, twice.
inline double hashed_uniform(std::uint64_t seed, std::uint64_t key, std::uint64_t stream)
{
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL ^ (key + 0x632BE59BD9B4E019ULL * (stream + 1));
  for (int round = 0; round < 2; round++) {
    z += 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
  }
  return (z >> 11) * 0x1.0p-53;
}

}    // namespace nscd
