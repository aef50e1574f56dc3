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

// Persistent ids of contact features and of feature pairs (the ContactPoint::key).
//
// A feature is 32 bits: 2 bits of type, 30 bits of index.
//   vertex k        -> index k
//   edge (a, b)     -> index min(a,b) | max(a,b) << 15   (vertex ids below 2^15)
//   face f          -> index f
//   wall            -> index 0 (a plane or cylinder has one smooth feature)
// A key is (feature of body i) << 32 | (feature of body j). It names the touching features
// only, never the order in which they were found, so it is the same from step to step as
// long as the same features touch.
#pragma once

#include <cstdint>

namespace nscd {

enum class FeatureType : std::uint32_t { Vertex = 0, Edge = 1, Face = 2, Wall = 3 };

// Largest vertex count whose edges fit in the 30-bit feature index.
constexpr int kMaxKeyedVertices = 1 << 15;

constexpr std::uint32_t make_feature(FeatureType type, std::uint32_t index)
{
  return (static_cast<std::uint32_t>(type) << 30) | (index & 0x3fffffffu);
}
constexpr std::uint32_t vertex_feature(int k) { return make_feature(FeatureType::Vertex, static_cast<std::uint32_t>(k)); }
constexpr std::uint32_t face_feature(int f) { return make_feature(FeatureType::Face, static_cast<std::uint32_t>(f)); }
constexpr std::uint32_t wall_feature() { return make_feature(FeatureType::Wall, 0); }
constexpr std::uint32_t edge_feature(int a, int b)
{
  const auto lo = static_cast<std::uint32_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint32_t>(a < b ? b : a);
  return make_feature(FeatureType::Edge, lo | (hi << 15));
}

constexpr FeatureType feature_type(std::uint32_t feature) { return static_cast<FeatureType>(feature >> 30); }
constexpr std::uint32_t feature_index(std::uint32_t feature) { return feature & 0x3fffffffu; }

constexpr std::uint64_t make_key(std::uint32_t feature_i, std::uint32_t feature_j)
{
  return (static_cast<std::uint64_t>(feature_i) << 32) | feature_j;
}
constexpr std::uint32_t key_feature_i(std::uint64_t key) { return static_cast<std::uint32_t>(key >> 32); }
constexpr std::uint32_t key_feature_j(std::uint64_t key) { return static_cast<std::uint32_t>(key & 0xffffffffu); }
// The key of the same feature pair seen as contact(j, i).
constexpr std::uint64_t swapped_key(std::uint64_t key) { return make_key(key_feature_j(key), key_feature_i(key)); }

}    // namespace nscd
