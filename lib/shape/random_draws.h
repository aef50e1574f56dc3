/* -*- c++ -*- ----------------------------------------------------------
   NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
   spheropolyhedra coupled to elastic wires.

   Copyright (2026) the NSCD package developers. This software is
   distributed under the GNU General Public License, version 2, the
   licence of LAMMPS. See the LICENSE file in the top-level directory
   of the package.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: the NSCD package developers
------------------------------------------------------------------------- */

// Random numbers keyed by (seed, item, stream) instead of drawn from a sequence: item k's
// draws do not depend on how many items came before or which MPI rank draws them, so
// shapes, orientations and positions come out the same on any rank count.
#pragma once

#include <cmath>
#include <cstdint>

namespace nscd {

// Uniform in [0, 1) from (seed, item, stream): a splitmix64 finaliser applied twice.
inline double hashed_uniform(std::uint64_t seed, std::uint64_t item, std::uint64_t stream)
{
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL ^ (item + 0x632BE59BD9B4E019ULL * (stream + 1));
  for (int round = 0; round < 2; round++) {
    z += 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
  }
  return (z >> 11) * 0x1.0p-53;
}

// Uniformly random rotation (Shoemake 1992) from three uniform numbers; q = (w, x, y, z).
inline void random_quaternion(double u1, double u2, double u3, double q[4])
{
  const double two_pi = 6.283185307179586;
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  q[0] = b * std::cos(two_pi * u3);
  q[1] = a * std::sin(two_pi * u2);
  q[2] = a * std::cos(two_pi * u2);
  q[3] = b * std::sin(two_pi * u3);
}

}    // namespace nscd
