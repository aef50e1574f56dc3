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

// Bytes a container holds on the heap, for the memory_usage() of the LAMMPS styles (LAMMPS'
// "Per MPI rank memory allocation"): a vector's capacity, not its size, since that is what
// stays allocated between steps.
#pragma once

#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

namespace nscd {

template <class T, class A> std::size_t capacity_bytes(const std::vector<T, A> &v)
{
  return v.capacity() * sizeof(T);
}

// An estimate for a hash map: its bucket array, and per entry the key and value with the
// node's link and cached hash (as libstdc++ lays them out).
template <class K, class V, class H, class E, class A>
std::size_t capacity_bytes(const std::unordered_map<K, V, H, E, A> &m)
{
  return m.bucket_count() * sizeof(void *) + m.size() * (sizeof(std::pair<const K, V>) + 2 * sizeof(void *));
}

}    // namespace nscd
